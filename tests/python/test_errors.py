"""Errors: sweetspot.InputError (a ValueError) and sweetspot.ModelRefusal carry the
JSON path, the value and what was expected, in the command line's words."""

import json

import numpy as np
import pytest
import sweetspot
from conftest import ROOT, run_cli

ROW1 = json.loads((ROOT / "designs/table1/row1.json").read_text())

# What the command line refuses, and the path it names.
BAD = [
    ({"hand": {"mass_kg": -0.5}}, "/hand/mass_kg", 2),
    ({"implement": {"mass_kg": 0}}, "/implement/mass_kg", 2),
    ({"ball": {"speed_m_s": "fast"}}, "/ball/speed_m_s", 2),
    ({"impact": {"from_tip_m": 2.0}}, "/impact/from_tip_m", 2),
    ({"hand": {"colour": 1}}, "/hand/colour", 2),
]


def patched(patch):
    document = json.loads(json.dumps(ROW1))
    for part, values in patch.items():
        document.setdefault(part, {}).update(values)
    return document


@pytest.mark.parametrize("patch,path,status", BAD)
def test_same_words_as_the_command_line(patch, path, status, tmp_path):
    file = tmp_path / "d.json"
    file.write_text(json.dumps(patched(patch)))
    done = run_cli("evaluate", file, "--format", "json", check=False)
    assert done.returncode == status
    with pytest.raises(sweetspot.InputError) as caught:
        sweetspot.evaluate(str(file))
    e = caught.value
    assert isinstance(e, ValueError)
    assert done.stderr == f"sweetspot: {e}\n"
    assert e.path == path and e.source == str(file)
    assert str(e) == f"{file}: {path}: {e.detail}"
    if e.value is not None:
        assert e.detail == f"{e.expected}, got {e.value}"
    # The same design as a dict says the same after its source.
    with pytest.raises(sweetspot.InputError) as as_dict:
        sweetspot.evaluate(patched(patch))
    assert str(as_dict.value) == f"<dict>: {path}: {e.detail}"


def test_value_and_expected():
    with pytest.raises(sweetspot.InputError) as caught:
        sweetspot.evaluate(patched({"hand": {"mass_kg": -0.5}}))
    e = caught.value
    assert e.path == "/hand/mass_kg"
    assert e.value == "-0.5 kg"
    assert e.expected.startswith("must be in [")


def test_model_refusal_is_exit_status_3(tmp_path):
    design = {"implement": {"length_in": 27, "mass_g": 305, "balance_cm": 32.5,
                            "swingweight_kg_cm2": 320, "headsize_sq_in": 100},
              "frame": {"fundamental_free_Hz": 5}, "strings": {"tension_N": 250},
              "impact": {"from_tip_m": 0.16}}
    file = tmp_path / "d.json"
    file.write_text(json.dumps(design))
    done = run_cli("evaluate", file, "--format", "json", check=False)
    assert done.returncode == 3
    with pytest.raises(sweetspot.ModelRefusal) as caught:
        sweetspot.evaluate(str(file))
    assert done.stderr == f"sweetspot: {caught.value}\n"
    assert caught.value.path == "/frame/fundamental_free_Hz"


def test_what_json_cannot_hold():
    with pytest.raises(sweetspot.InputError, match=r"^<dict>: /hand/mass_kg: expected a finite number, got nan$"):
        sweetspot.evaluate(patched({"hand": {"mass_kg": float("nan")}}))
    with pytest.raises(sweetspot.InputError, match=r"^<dict>: /hand: expected keys that are str"):
        sweetspot.evaluate(patched({"hand": {1: 0.5}}))
    with pytest.raises(sweetspot.InputError, match=r"^<dict>: /hand/mass_kg: expected a JSON value"):
        sweetspot.evaluate(patched({"hand": {"mass_kg": object()}}))
    with pytest.raises(sweetspot.InputError, match=r"^<JSON text>: "):
        sweetspot.evaluate('{"implement": ')
    with pytest.raises(sweetspot.InputError, match="duplicate"):
        sweetspot.evaluate('{"implement": {}, "implement": {}}')
    with pytest.raises(TypeError):
        sweetspot.evaluate(3)


def test_arguments():
    for call in (lambda: sweetspot.evaluate(ROW1, fidelity="fast"),
                 lambda: sweetspot.evaluate(ROW1, tol=0),
                 lambda: sweetspot.evaluate_many(ROW1, {"hand.mass_kg": [0.5]}, threads=0),
                 lambda: sweetspot.modes(ROW1, count=0)):
        with pytest.raises(ValueError):
            call()


def test_columns_are_checked_as_a_catalogues_header(tmp_path):
    # The command line's words for the same header.
    (tmp_path / "c.csv").write_text("implement.weight\n0.3\n")
    done = run_cli("evaluate", "--batch", tmp_path / "c.csv", check=False)
    assert done.returncode == 2
    with pytest.raises(sweetspot.InputError) as caught:
        sweetspot.evaluate_many(ROW1, {"implement.weight": np.array([0.3])})
    assert caught.value.source == "columns"
    assert done.stderr.split(": ", 2)[2] == str(caught.value).split(": ", 1)[1] + "\n"
    with pytest.raises(sweetspot.InputError, match="implement.mass_g"):
        sweetspot.evaluate_many(ROW1, {"implement.mass_kg": [0.3], "implement.mass_g": [300.0]})
    with pytest.raises(sweetspot.InputError, match="2 rows, expected 3"):
        sweetspot.evaluate_many(ROW1, {"hand.mass_kg": np.ones(3), "ball.mass_kg": np.ones(2)})
    with pytest.raises(sweetspot.InputError, match="holds text"):
        sweetspot.evaluate_many(ROW1, {"name": np.ones(1)})
    with pytest.raises(sweetspot.InputError, match="one dimension"):
        sweetspot.evaluate_many(ROW1, {"hand.mass_kg": np.ones((2, 2))})
    # An entry past the end of a list is the column's fault, as in a catalogue.
    with pytest.raises(sweetspot.InputError,
                       match=r'column 1 "implement.point_masses.4.mass_g": the list is empty'):
        sweetspot.evaluate_many(ROW1, {"implement.point_masses.4.mass_g": np.full(3, 5.0)})
    # A base that is not a design on its own, as --base.
    with pytest.raises(sweetspot.InputError, match=r"^<dict>: /implement: missing"):
        sweetspot.evaluate_many({"hand": {"mass_kg": 0.5}}, {"hand.mass_kg": [0.5]})


def test_a_bad_row_never_raises():
    mass = np.full(1000, 0.3)
    mass[::7] = -1.0
    many = sweetspot.evaluate_many(ROW1, {"implement.mass_kg": mass})
    assert (~many["ok"]).sum() == len(mass[::7])
    assert many["error"][7] == "row 7: /implement/mass_kg: must be > 0 kg, got -1 kg"
    assert np.isnan(many["peak_wrist_force_N"][~many["ok"]]).all()
    assert not np.isnan(many["peak_wrist_force_N"][many["ok"]]).any()
