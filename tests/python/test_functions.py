"""modes, collide, string_bed_map and optimize against the command line and the
model's own identities."""

import csv
import io
import json
import math

import numpy as np
import pytest
import sweetspot
from conftest import ROOT, cli_json, run_cli

TOUR = str(ROOT / "designs/racquets/tour-100.json")
STRUNG = str(ROOT / "designs/racquets/tour-100-strung.json")
MAPPED = {"implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5,
                        "swingweight_kg_cm2": 325, "headsize_sq_in": 100},
          "frame": {"RA": 66}, "strings": {"tension_lb": 52}}


@pytest.mark.parametrize("count,method", [(3, "exact"), (2, "fe")])
def test_modes_are_the_command_lines(count, method):
    got = sweetspot.modes(TOUR, count=count, method=method)
    expected = cli_json("modes", TOUR, "--format", "json", "--modes", count, "--method", method)
    assert {k: got[k] for k in expected} == expected
    shapes = got["free_shapes"]
    assert shapes.shape == (len(expected["free"]), got["free_x_m"].size)
    # Each mode's nodes are where its sampled shape changes sign; w(L) > 0.
    x = got["free_x_m"]
    for k, mode in enumerate(expected["free"]):
        w = shapes[k]
        assert w[-1] > 0
        changes = np.flatnonzero(np.sign(w[1:]) != np.sign(w[:-1]))
        assert len(changes) == len(mode["nodes"])
        for i, node in zip(changes, mode["nodes"]):
            assert x[i] <= node["from_butt_m"] <= x[i + 1]


def test_modes_on_a_rig_are_the_command_lines():
    pivot = str(ROOT / "designs/lab/pivot-6in.json")
    got = sweetspot.modes(pivot, count=3)
    expected = cli_json("modes", pivot, "--format", "json", "--modes", 3)
    assert {k: got[k] for k in expected} == expected
    assert expected["support"] == "pivot" and len(expected["on_rig"]) == 3
    assert expected["hand_held"] == []
    assert got["on_rig_shapes"].shape == (3, got["on_rig_x_m"].size)
    # The pivot is a node of every mode.
    for mode in expected["on_rig"]:
        assert any(abs(n["from_butt_m"] - 0.1524) < 1e-9 for n in mode["nodes"])


def test_collide_closes_its_ledger():
    c = sweetspot.collide(STRUNG)
    assert c["evaluation"] == sweetspot.evaluate(STRUNG, fidelity="collision")
    outputs = c["evaluation"]["outputs"]
    assert c["contact_time_s"] == outputs["contact_time_s"]
    # The energy ledger: ball in = ball out + implement + vibration + losses.
    total = (c["ball_out_J"] + c["implement_rigid_J"] + c["vibration_J"] + c["ball_loss_J"]
             + c["strings_loss_J"])
    assert abs(total - c["ball_in_J"]) < 1e-9 * c["ball_in_J"]
    # The impulse is the force history's integral (trapezoids on the integrator's steps).
    t, f = c["time_s"], c["force_N"]
    assert t.size == f.size > 10
    integral = float(np.sum(np.diff(t) * (f[1:] + f[:-1]) / 2))
    assert abs(integral - c["impulse_N_s"]) < 1e-2 * c["impulse_N_s"]
    assert abs(f.max() - c["peak_force_N"]) <= 1e-2 * c["peak_force_N"]


def test_string_bed_map_is_the_command_lines(tmp_path):
    file = tmp_path / "d.json"
    file.write_text(json.dumps(MAPPED))
    m = sweetspot.string_bed_map(MAPPED, columns=6, rows=5, fidelity="modal", threads=2)
    done = run_cli("map", file, "--columns", 6, "--rows", 5, "--fidelity", "modal", "-q")
    table = list(csv.DictReader(io.StringIO(done.stdout)))
    on = m["on_bed"]
    assert m["from_butt_m"].shape == (5, 6) and len(table) == on.sum()
    keys = ["effective_mass_kg", "apparent_cor", "peak_wrist_force_N", "peak_twist_torque_N_m",
            "vibration_energy_J"]
    for row, (j, i) in zip(table, zip(*np.nonzero(on))):
        assert float(row["from_butt_m"]) == m["from_butt_m"][j, i]
        assert float(row["off_axis_m"]) == m["off_axis_m"][j, i]
        for key in keys:
            assert float(row[key]) == m[key][j, i], key
    assert np.isnan(m["peak_wrist_force_N"][~on]).all()
    # The map's rigid numbers are evaluate()'s at the same point.
    j, i = np.argwhere(on)[len(table) // 2]
    design = json.loads(json.dumps(MAPPED))
    design["impact"] = {"from_butt_m": float(m["from_butt_m"][j, i]),
                        "off_axis_m": float(m["off_axis_m"][j, i])}
    one = sweetspot.evaluate(design, fidelity="rigid")["outputs"]
    assert one["peak_wrist_force_N"] == pytest.approx(m["peak_wrist_force_N"][j, i], rel=1e-12)


def test_optimize_answers_with_a_design_evaluate_reads():
    study = ROOT / "designs/studies/7-lead-tape-for-power.json"
    r = sweetspot.optimize(str(study), threads=1)
    expected = cli_json("optimize", study, "--format", "json", "--threads", "1")
    assert r["outcome"] == "optimum" and r["inconsistency"] == ""
    assert r["best_design"] == expected["best_design"]
    assert r["report"]["best_design"] == expected["best_design"]
    # The answer is a design file: evaluated again, it gives the best outputs.
    again = sweetspot.evaluate(r["best_design"], fidelity="collision")
    assert again["outputs"] == r["best"]["outputs"]
    assert r["variables"] == ["/implement/point_masses/0/from_butt_m",
                              "/implement/point_masses/0/mass_kg"]
    assert r["x"].shape == (2,) and r["history"].size == r["evaluations"]
    swingweight = [c for c in r["constraints"] if c["name"].startswith("swingweight")][0]
    assert swingweight["satisfied"] and swingweight["value"] <= 335 + swingweight["tolerance"]
    assert r["best"]["outputs"]["rebound_speed_m_s"] >= r["start"]["outputs"]["rebound_speed_m_s"]


def test_tune_is_the_command_lines_and_its_design_has_the_specs(tmp_path):
    racquet = tmp_path / "racquet.json"
    racquet.write_text(json.dumps({
        "name": "Club racquet",
        "implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5,
                      "swingweight_kg_cm2": 325, "headsize_sq_in": 100},
        "frame": {"RA": 66}, "strings": {"tension_lb": 52}}))
    target = "mass_g=330,balance_cm=32,swingweight_kg_cm2=330"
    expected = cli_json("tune", racquet, "--target", target, "--places", "12,3/9,grip",
                        "--format", "json")
    r = sweetspot.tune(str(racquet), {"mass_g": 330, "balance_cm": 32, "swingweight_kg_cm2": 330},
                       places=["12", "3/9", "grip"])
    assert r["report"] == expected
    assert sweetspot.tune(str(racquet), target, places="12,3/9,grip")["report"] == expected
    assert r["exact"] and [lead["place"] for lead in r["lead"]] == ["12", "3/9", "grip"]
    assert math.isclose(r["added_kg"], sum(lead["mass_kg"] for lead in r["lead"]), rel_tol=1e-12)
    for lead in r["lead"]:
        assert lead["mass_kg"] >= 0
        assert math.isclose(sum(p["mass_kg"] for p in lead["pieces"]), lead["mass_kg"],
                            rel_tol=1e-12)
    # The tuned design file, evaluated, has the specs asked for.
    outputs = sweetspot.evaluate(r["tuned_design"])["outputs"]
    assert math.isclose(outputs["mass_kg"], 0.330, rel_tol=1e-9)
    assert math.isclose(outputs["balance_from_butt_m"], 0.32, rel_tol=1e-9)
    assert math.isclose(outputs["swingweight_kg_cm2"], 330, rel_tol=1e-9)
    # Lead only adds mass: a lighter racquet is a miss with its reason, not an error.
    lighter = sweetspot.tune(str(racquet), {"mass_g": 300}, places="12")
    # NumPy's numbers are numbers.
    assert sweetspot.tune(str(racquet), {"mass_g": np.int64(330)}, places="12")["exact"]
    assert not lighter["exact"] and lighter["tuned_design"] is None
    assert lighter["misses"][0]["spec"] == "mass"


@pytest.mark.parametrize("kwargs, source, words", [
    ({"target": {"mass_x": 3}, "places": "12"}, "target", 'unknown target "mass_x"'),
    ({"target": {"mass_g": True}, "places": "12"}, "target", "a spec's name and a number"),
    ({"target": {"mass_g": 330}, "places": "12,bogus"}, "places", '"bogus" is not a place'),
    ({"target": None, "places": "12"}, "target", "give the specs to reach"),
    ({"target": {}, "places": "12"}, "target", "give the specs to reach"),
    ({"target": {"mass_g=1,balance_cm": 33}, "places": "12"}, "target", "holds ',' or '='"),
    ({"target": {"mass_g": 10**400}, "places": "12"}, "target", "a spec's name and a number"),
    ({"target": {"mass_g": 330}, "places": ["12,3"]}, "places", "holds a comma"),
    ({"target": {"mass_g": 330}, "places": "\ud800"}, "places", "expected a str"),
    ({"target": {"mass_g": 330}, "places": None}, "places", "expected a str or a list of str"),
    ({"target": {"mass_g": 330}, "places": "12", "like": '{"bad": 1}'}, "like <JSON text>",
     "unknown key"),
    ({"target": {"mass_g": 330}, "places": "12", "strip_g": 0}, "strip_g", "[0.01, 100]"),
])
def test_tune_refuses_with_the_command_lines_words(kwargs, source, words):
    with pytest.raises(sweetspot.InputError) as error:
        sweetspot.tune(str(ROOT / "designs/racquets/tour-100-strung.json"), **kwargs)
    assert error.value.source == source and words in str(error.value)
