"""sweetspot.evaluate against the command line: the same dict, bit for bit."""

import json
import math
import os

import pytest
import sweetspot
from conftest import ROOT, cli_json, run_cli, shipped_designs

DESIGNS = shipped_designs()


def test_every_shipped_design_is_tested():
    assert len(DESIGNS) >= 15
    assert "designs/table1/row1.json" in DESIGNS


@pytest.mark.parametrize("design", DESIGNS)
def test_shipped_design_equals_the_command_line(design):
    expected = cli_json("evaluate", design, "--format", "json")
    # == on dicts compares every float exactly; a path is read as the program reads it.
    os.chdir(ROOT)
    assert sweetspot.evaluate(design) == expected
    # The same design given as a dict and as a JSON text: the same numbers (the
    # name differs only when the file gives none: it is then the source).
    document = json.loads((ROOT / design).read_text())
    for given in (document, json.dumps(document)):
        got = sweetspot.evaluate(given)
        if "name" not in document:
            got["name"] = expected["name"]
        assert got == expected


@pytest.mark.parametrize("fidelity", ["rigid", "modal", "response", "auto"])
def test_fidelity_is_the_command_lines(fidelity):
    design = "designs/racquets/tour-100.json"
    expected = cli_json("evaluate", design, "--format", "json", "--fidelity", fidelity)
    assert sweetspot.evaluate(str(ROOT / design), fidelity=fidelity) == expected


def test_table1_row1_wrist_force():
    # Cross (2004) Table I, row 1, as printed: F_w = 568 N.
    force = sweetspot.evaluate(str(ROOT / "designs/table1/row1.json"))["outputs"]["peak_wrist_force_N"]
    assert round(force) == 568


def test_outputs_are_evaluates():
    names = [o["name"] for o in sweetspot.outputs()]
    outputs = sweetspot.evaluate(str(ROOT / "designs/table1/row1.json"))["outputs"]
    assert set(names) == set(outputs)
    assert all(isinstance(o["unit"], str) for o in sweetspot.outputs())


def test_numpy_scalars_are_numbers():
    np = pytest.importorskip("numpy")
    document = json.loads((ROOT / "designs/table1/row1.json").read_text())
    plain = sweetspot.evaluate(document)
    document["implement"]["mass_kg"] = np.float64(0.25)
    document["ball"]["speed_m_s"] = np.float32(50.0)
    assert sweetspot.evaluate(document)["outputs"] == plain["outputs"]
    assert not math.isnan(plain["outputs"]["peak_wrist_force_N"])


def test_help_names_units():
    assert "peak_wrist_force_N" in sweetspot.evaluate.__doc__
    assert "GIL" in sweetspot.evaluate_many.__doc__
    stub = (ROOT / "python" / "sweetspot.pyi").read_text()
    for name in ("evaluate", "evaluate_many", "modes", "collide", "string_bed_map", "optimize",
                 "tune", "outputs", "InputError", "ModelRefusal"):
        assert hasattr(sweetspot, name)
        assert f"{name}" in stub
    assert run_cli("--version").returncode == 0
