"""sweetspot.evaluate_many: row by row what evaluate() gives, at every fidelity,
and what `sweetspot evaluate --batch` writes for the same catalogue."""

import copy
import csv
import io
import json
import math

import numpy as np
import pytest
import sweetspot
from conftest import ROOT, run_cli

# Base design, fidelity, rows and each column's range (some rows outside the
# design's valid range, so that failed rows are compared too).
CASES = {
    "rigid": ("designs/table1/row1.json", 40, {
        "implement.length_m": (0.55, 0.75),
        "implement.mass_kg": (-0.02, 0.4),
        "implement.head_to_handle_mass_ratio": (0.5, 1.2),
        "impact.from_tip_m": (0.0, 0.3),
        "hand.mass_kg": (0.3, 0.6),
        "ball.speed_m_s": (20.0, 60.0),
    }),
    "modal": ("designs/racquets/tour-100.json", 12, {
        "implement.mass_g": (280.0, 340.0),
        "implement.swingweight_kg_cm2": (290.0, 340.0),
        "frame.fundamental_free_Hz": (120.0, 180.0),
        "impact.from_tip_m": (0.05, 0.25),
    }),
    "response": ("designs/racquets/tour-100.json", 12, {
        "implement.mass_g": (280.0, 340.0),
        "frame.fundamental_free_Hz": (120.0, 180.0),
        "impact.from_tip_m": (0.05, 0.25),
    }),
    "collision": ("designs/racquets/tour-100-strung.json", 6, {
        "strings.tension_N": (200.0, 280.0),
        "impact.from_tip_m": (0.1, 0.22),
    }),
}


def columns_of(case, seed):
    _, rows, ranges = CASES[case]
    rng = np.random.default_rng(seed)
    return {field: rng.uniform(lo, hi, rows) for field, (lo, hi) in ranges.items()}


def base_of(case):
    return json.loads((ROOT / CASES[case][0]).read_text())


def document_at(base, columns, i):
    """The row as a design file: the base with each column's value at its key."""
    document = copy.deepcopy(base)
    for field, values in columns.items():
        *objects, key = field.split(".")
        node = document
        for name in objects:
            node = node.setdefault(name, {})
        node[key] = float(values[i])
    return document


def same(a, b):
    """Bit for bit: the same double, or NaN where evaluate() gives None."""
    if b is None:
        return math.isnan(a)
    return a == b or (math.isnan(a) and math.isnan(b))


def detail_of(message):
    """A message without its source: 'row 3: /implement/mass_kg: ...' -> '/implement/mass_kg: ...'."""
    return message.split(": ", 1)[1]


@pytest.mark.parametrize("case", list(CASES))
def test_rows_equal_evaluate(case):
    base, columns = base_of(case), columns_of(case, seed=len(case))
    many = sweetspot.evaluate_many(base, columns, fidelity=case, threads=2)
    names = [o["name"] for o in sweetspot.outputs()]
    rows = len(next(iter(columns.values())))
    failed = 0
    for i in range(rows):
        try:
            outputs = sweetspot.evaluate(document_at(base, columns, i), fidelity=case)["outputs"]
        except (sweetspot.InputError, sweetspot.ModelRefusal) as e:
            failed += 1
            assert not many["ok"][i]
            assert detail_of(many["error"][i]) == detail_of(str(e))
            assert many["error"][i].startswith(f"row {i}: {e.path}")
            assert all(math.isnan(many[name][i]) for name in names)
            continue
        assert many["ok"][i] and many["error"][i] == "", many["error"][i]
        for name in names:
            assert same(many[name][i], outputs[name]), (i, name, many[name][i], outputs[name])
    if case == "rigid":
        assert 0 < failed < rows  # bad rows and good rows both compared


@pytest.mark.parametrize("case", ["rigid", "modal", "collision"])
def test_rows_equal_the_command_lines_batch(case, tmp_path):
    base, columns = base_of(case), columns_of(case, seed=7)
    (tmp_path / "base.json").write_text(json.dumps(base))
    rows = len(next(iter(columns.values())))
    with open(tmp_path / "rows.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(columns)
        for i in range(rows):
            writer.writerow([repr(float(v[i])) for v in columns.values()])
    done = run_cli("evaluate", "--batch", tmp_path / "rows.csv", "--base", tmp_path / "base.json",
                   "--fidelity", case, "--format", "csv", "--threads", "1", check=False)
    assert done.returncode in (0, 1), done.stderr
    many = sweetspot.evaluate_many(tmp_path / "base.json", columns, fidelity=case, threads=1)
    table = list(csv.DictReader(io.StringIO(done.stdout)))
    assert len(table) == rows
    for i, row in enumerate(table):
        assert int(row["line"]) == i + 2
        if row["error"]:
            assert detail_of(many["error"][i]) == detail_of(row["error"])
            continue
        assert many["ok"][i], many["error"][i]
        for o in sweetspot.outputs():
            cell = row[o["name"]]
            assert same(many[o["name"]][i], float(cell) if cell else None), (i, o["name"])


def test_threads_and_layouts_give_the_same_rows():
    base, columns = base_of("rigid"), columns_of("rigid", seed=3)
    one = sweetspot.evaluate_many(base, columns, threads=1)
    # Strided views, float32 and Python lists are read as the same numbers.
    strided = {k: np.repeat(v, 2)[::2] for k, v in columns.items()}
    assert not next(iter(strided.values())).flags["C_CONTIGUOUS"]
    listed = {k: [float(x) for x in v] for k, v in columns.items()}
    for other in (sweetspot.evaluate_many(base, columns, threads=3),
                  sweetspot.evaluate_many(base, strided, threads=2),
                  sweetspot.evaluate_many(base, listed)):
        for name, values in one.items():
            if values.dtype == float:
                assert np.array_equal(values, other[name], equal_nan=True), name
            else:
                assert (values == other[name]).all(), name


def test_a_scalar_column_stands_for_every_row():
    base = base_of("rigid")
    many = sweetspot.evaluate_many(base, {"impact.from_tip_m": np.array([0.05, 0.1]),
                                          "hand.mass_kg": 0.5})
    assert many["peak_wrist_force_N"].shape == (2,)
    assert many["peak_wrist_force_N"][0] == sweetspot.evaluate(base)["outputs"]["peak_wrist_force_N"]


def test_a_non_finite_cell_is_a_failed_row():
    many = sweetspot.evaluate_many(base_of("rigid"),
                                   {"implement.mass_kg": np.array([0.25, np.nan, np.inf])})
    assert list(many["ok"]) == [True, False, False]
    assert many["error"][1] == "row 1: /implement/mass_kg: expected a finite number, got nan"
    assert math.isnan(many["peak_wrist_force_N"][2])


@pytest.mark.parametrize("column, got", [
    (np.array([True, False]), "bool"),
    ([True, False], "bool"),
    (np.array([0.3 + 5j, 0.3]), "complex128"),
    (np.array([None, 0.3], dtype=object), "object"),
    (np.ma.masked_array([0.31, 0.3], mask=[True, False]), "masked array"),
])
def test_a_column_of_what_is_not_a_number_is_refused(column, got):
    """A design file takes numbers only; so does a column: NumPy's casts would
    make a bool 1 kg, drop a complex number's imaginary part, read a masked
    row's hidden value and an object column's None as nan."""
    with pytest.raises(sweetspot.InputError, match=r"column \"implement\.mass_kg\": expected an array "
                       r"of numbers.*" + got):
        sweetspot.evaluate_many(base_of("rigid"), {"implement.mass_kg": column})


def test_numpy_values_in_a_design_are_the_values_they_hold():
    base = base_of("rigid")
    as_float = copy.deepcopy(base)
    as_float["implement"]["mass_kg"] = np.array(base["implement"]["mass_kg"])  # 0-d
    assert sweetspot.evaluate(as_float)["outputs"] == sweetspot.evaluate(base)["outputs"]
    as_bool = copy.deepcopy(base)
    as_bool["implement"]["mass_kg"] = np.True_
    with pytest.raises(sweetspot.InputError, match="/implement/mass_kg: expected a number, got true"):
        sweetspot.evaluate(as_bool)


class Frame:
    """What evaluate_many reads of a pandas DataFrame (not installed here):
    items() giving each column's name and a Series, an object with __array__."""

    class Series:
        def __init__(self, values):
            self.values = values

        def __array__(self, dtype=None):
            return np.asarray(self.values, dtype=dtype)

    def __init__(self, columns):
        self.columns = columns

    def items(self):
        return ((name, Frame.Series(values)) for name, values in self.columns.items())


def test_a_frame_like_pandas_is_read_by_its_columns():
    base, columns = base_of("rigid"), columns_of("rigid", seed=5)
    a = sweetspot.evaluate_many(base, columns)
    b = sweetspot.evaluate_many(base, Frame(columns))
    assert np.array_equal(a["peak_wrist_force_N"], b["peak_wrist_force_N"], equal_nan=True)
    assert list(a["error"]) == list(b["error"])


# ------------------------------------------------- the column-wise path

PAPER_OUTPUTS = ["effective_mass_kg", "apparent_cor", "rebound_speed_m_s", "impulse_N_s",
                 "peak_impact_force_N", "wrist_force_ratio", "peak_wrist_force_N", "cor",
                 "impact_duration_s"]


def paper_columns(rows, seed, hostile=False):
    rng = np.random.default_rng(seed)
    columns = {
        "implement.length_m": rng.uniform(0.3, 1.0, rows),
        "implement.mass_g": rng.uniform(100.0, 500.0, rows),
        "implement.head_to_handle_mass_ratio": rng.uniform(0.3, 2.0, rows),
        "hand.mass_kg": rng.uniform(0.0, 0.8, rows),
        "forearm.equivalent_mass_kg": rng.uniform(0.0, 1.0, rows),
        "ball.speed_km_h": rng.uniform(20.0, 250.0, rows),
        "frame.cor": rng.uniform(0.5, 1.0, rows),
        "strings.impact_duration_ms": rng.uniform(2.0, 8.0, rows),
        "impact.from_tip_m": rng.uniform(0.0, 0.3, rows),
    }
    if hostile:  # every few rows a value the design file refuses, or its bounds
        for values, bad in ((columns["implement.length_m"], [0.0, -0.7, np.nan, 101.0]),
                            (columns["frame.cor"], [1.0, 0.0, 1.01, np.inf]),
                            (columns["impact.from_tip_m"], [0.0, -1e-9, 2.0, np.nan]),
                            (columns["hand.mass_kg"], [0.0, -0.1, 2e6, np.nan])):
            picks = rng.choice(rows, rows // 10, replace=False)
            values[picks] = rng.choice(bad, picks.size)
    return columns


@pytest.mark.parametrize("hostile,swung", [(False, False), (True, False), (False, True)])
def test_columnwise_equals_every_output_path(hostile, swung):
    """The paper's outputs alone (the column-wise path) equal, bit for bit and error for
    error, the same rows evaluated with every output (one design at a time); a swung
    racquet's rows too, each solved at the speed its ball and racquet meet."""
    base = ROOT / "designs" / "table1" / "row1.json"
    if swung:
        base = json.loads(base.read_text())
        base["swing"] = {"angular_speed_rad_s": 20.0, "pivot_beyond_butt_m": 0.6}
    columns = paper_columns(3000, 7, hostile)
    fast = sweetspot.evaluate_many(base, columns, threads=2, outputs=PAPER_OUTPUTS)
    full = sweetspot.evaluate_many(base, columns, threads=1)
    assert sorted(fast) == sorted(PAPER_OUTPUTS + ["ok", "error"])
    assert np.array_equal(fast["ok"], full["ok"])
    assert list(fast["error"]) == list(full["error"])
    for name in PAPER_OUTPUTS:
        assert np.array_equal(fast[name], full[name], equal_nan=True), name
    assert fast["ok"].sum() > (2000 if hostile else 2999)
    if hostile:
        assert not fast["ok"].all()


def test_columnwise_against_numpy_closed_forms():
    """The module against the paper's equations written in NumPy (python/numpy_model.py):
    the same model to round-off."""
    import sys
    sys.path.insert(0, str(ROOT / "python"))
    import numpy_model
    rng = np.random.default_rng(2004)
    n = 20000
    L, M = rng.uniform(0.6, 0.75, n), rng.uniform(0.2, 0.4, n)
    r, tip = rng.uniform(0.6, 1.2, n), rng.uniform(0.0, 0.3, n)
    columns = {"implement.length_m": L, "implement.mass_kg": M,
               "implement.head_to_handle_mass_ratio": r, "impact.from_tip_m": tip}
    wanted = ["effective_mass_kg", "apparent_cor", "peak_impact_force_N", "wrist_force_ratio",
              "peak_wrist_force_N"]
    got = sweetspot.evaluate_many(ROOT / "designs" / "table1" / "row1.json", columns,
                                  outputs=wanted)
    assert got["ok"].all()
    expected = numpy_model.paper_rigid(L, M, r, tip)
    scale = {"effective_mass_kg": 0.4, "apparent_cor": 1.0, "peak_impact_force_N": 1000.0,
             "wrist_force_ratio": 1.0, "peak_wrist_force_N": 1000.0}
    for name in wanted:
        np.testing.assert_allclose(got[name], expected[name], rtol=1e-12,
                                   atol=1e-12 * scale[name], err_msg=name)


def test_outputs_argument_is_checked():
    base = ROOT / "designs" / "table1" / "row1.json"
    columns = {"implement.mass_kg": np.array([0.25, 0.3])}
    with pytest.raises(sweetspot.InputError, match='unknown output "speed"'):
        sweetspot.evaluate_many(base, columns, outputs=["speed"])
    with pytest.raises(sweetspot.InputError, match="given twice"):
        sweetspot.evaluate_many(base, columns, outputs=["apparent_cor", "apparent_cor"])
    with pytest.raises(sweetspot.InputError, match="at least one"):
        sweetspot.evaluate_many(base, columns, outputs=[])
    # Outputs the column-wise path does not answer take the design path, same numbers.
    some = sweetspot.evaluate_many(base, columns, outputs=["swingweight_kg_cm2", "apparent_cor"])
    every = sweetspot.evaluate_many(base, columns)
    assert np.array_equal(some["swingweight_kg_cm2"], every["swingweight_kg_cm2"])
    assert np.array_equal(some["apparent_cor"], every["apparent_cor"])


@pytest.mark.parametrize("hostile", [False, True])
def test_columnwise_with_the_settings_of_the_base(hostile):
    """Only the racquet and the impact point varied (the settings the base's, checked once
    for every row): the column-wise path equals every output's, error for error."""
    base = ROOT / "designs" / "table1" / "row1.json"
    every = paper_columns(3000, 11, hostile)
    columns = {k: every[k] for k in ("implement.length_m", "implement.mass_g",
                                     "implement.head_to_handle_mass_ratio", "impact.from_tip_m")}
    fast = sweetspot.evaluate_many(base, columns, threads=1, outputs=PAPER_OUTPUTS)
    full = sweetspot.evaluate_many(base, columns, threads=1)
    assert np.array_equal(fast["ok"], full["ok"])
    assert list(fast["error"]) == list(full["error"])
    for name in PAPER_OUTPUTS:
        assert np.array_equal(fast[name], full[name], equal_nan=True), name
    assert fast["ok"].sum() > (2000 if hostile else 2999)


def test_out_arrays_are_written_and_returned():
    """out= takes the caller's arrays: the same numbers as fresh ones, in those arrays."""
    base = ROOT / "designs" / "table1" / "row1.json"
    columns = paper_columns(1000, 5, hostile=True)
    fresh = sweetspot.evaluate_many(base, columns, outputs=PAPER_OUTPUTS)
    out = {name: np.full(1000, 7.0) for name in PAPER_OUTPUTS[:2]}
    given = sweetspot.evaluate_many(base, columns, outputs=PAPER_OUTPUTS, out=out)
    for name in PAPER_OUTPUTS:
        assert np.array_equal(given[name], fresh[name], equal_nan=True), name
    for name, array in out.items():
        assert given[name] is array
    assert list(given["error"]) == list(fresh["error"])


def test_out_arrays_refused_with_the_reason():
    base = ROOT / "designs" / "table1" / "row1.json"
    columns = paper_columns(10, 5)
    name = PAPER_OUTPUTS[0]
    for bad, words in ((np.zeros(10, dtype=np.float32), "float64"),
                       (np.zeros(20)[::2], "contiguous"),
                       (np.zeros(9), "9 elements, expected 10"),
                       ([0.0] * 10, "NumPy array"),
                       (columns["implement.length_m"], "shares memory with the column")):
        with pytest.raises(sweetspot.InputError, match=words):
            sweetspot.evaluate_many(base, columns, outputs=PAPER_OUTPUTS, out={name: bad})
    frozen = np.zeros(10)
    frozen.setflags(write=False)
    with pytest.raises(sweetspot.InputError, match="writable"):
        sweetspot.evaluate_many(base, columns, outputs=PAPER_OUTPUTS, out={name: frozen})
    shared = np.zeros(10)
    with pytest.raises(sweetspot.InputError, match="shares memory with another output"):
        sweetspot.evaluate_many(base, columns, outputs=PAPER_OUTPUTS[:2],
                                out={PAPER_OUTPUTS[0]: shared, PAPER_OUTPUTS[1]: shared})
    with pytest.raises(sweetspot.InputError, match="not an output asked for"):
        sweetspot.evaluate_many(base, columns, outputs=PAPER_OUTPUTS[:1],
                                out={"cor": np.zeros(10)})


def test_error_column_is_read_only():
    base = ROOT / "designs" / "table1" / "row1.json"
    for hostile in (False, True):
        got = sweetspot.evaluate_many(base, paper_columns(50, 3, hostile), outputs=PAPER_OUTPUTS)
        assert got["error"].shape == (50,)
        assert not got["error"].flags.writeable
        assert all(isinstance(e, str) for e in got["error"])
        assert [e == "" for e in got["error"]] == list(got["ok"])


def test_columnwise_with_a_scalar_setting():
    """A scalar column (one ball speed for every row) is the same as that speed in an array."""
    base = ROOT / "designs" / "table1" / "row1.json"
    columns = paper_columns(700, 13, hostile=True)
    racquet = {k: columns[k] for k in ("implement.length_m", "implement.mass_g",
                                       "implement.head_to_handle_mass_ratio",
                                       "impact.from_tip_m")}
    for speed in (30.0, 0.0, 2e4):  # in range, and refused for every row
        scalar = sweetspot.evaluate_many(base, {**racquet, "ball.speed_m_s": speed},
                                         outputs=PAPER_OUTPUTS)
        array = sweetspot.evaluate_many(base, {**racquet, "ball.speed_m_s": np.full(700, speed)},
                                        outputs=PAPER_OUTPUTS)
        assert np.array_equal(scalar["ok"], array["ok"])
        assert list(scalar["error"]) == list(array["error"])
        for name in PAPER_OUTPUTS:
            assert np.array_equal(scalar[name], array[name], equal_nan=True), name
        assert scalar["ok"].any() == (speed == 30.0)


def test_large_outputs_reuse_no_live_array():
    """Outputs of 2 MB and more come from mappings kept for reuse once their arrays are
    freed: a later call never writes into an array still held, and a reused mapping is
    written whole (the numbers of a fresh evaluation, not the last call's)."""
    base = ROOT / "designs" / "table1" / "row1.json"
    n = 300_000  # 2.4 MB an output
    rng = np.random.default_rng(26)

    def columns():
        return {"implement.length_m": rng.uniform(0.6, 0.75, n),
                "implement.mass_kg": rng.uniform(0.2, 0.4, n),
                "impact.from_tip_m": rng.uniform(0.0, 0.3, n)}

    first_columns, second_columns = columns(), columns()
    first = sweetspot.evaluate_many(base, first_columns, outputs=PAPER_OUTPUTS)
    kept = {name: first[name].copy() for name in PAPER_OUTPUTS}
    second = sweetspot.evaluate_many(base, second_columns, outputs=PAPER_OUTPUTS)
    for name in PAPER_OUTPUTS:
        assert np.array_equal(first[name], kept[name]), name
        assert not np.shares_memory(first[name], second[name]), name
        assert first[name].flags.writeable and first[name].flags.c_contiguous
    del first
    again = sweetspot.evaluate_many(base, first_columns, outputs=PAPER_OUTPUTS)
    for name in PAPER_OUTPUTS:
        assert np.array_equal(again[name], kept[name]), name
        assert not np.shares_memory(again[name], second[name]), name
