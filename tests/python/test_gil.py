"""evaluate_many releases the GIL: Python runs beside it, and a second call
runs while the first is inside."""

import threading
import time

import numpy as np
import sweetspot
from conftest import ROOT

BASE = str(ROOT / "designs/table1/row1.json")
ROWS = 200_000


def columns():
    rng = np.random.default_rng(11)
    return {"implement.mass_kg": rng.uniform(0.2, 0.4, ROWS),
            "impact.from_tip_m": rng.uniform(0.0, 0.3, ROWS)}


def test_python_runs_while_rows_are_evaluated():
    data = columns()
    done = threading.Event()
    ticks_during = 0

    def work():
        sweetspot.evaluate_many(BASE, data, threads=1)
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    # Held, the GIL would leave this loop no turn until the call returned.
    while not done.is_set():
        ticks_during += 1
        time.sleep(0)
    worker.join()
    assert ticks_during > 100


def test_a_second_call_runs_while_the_first_is_inside():
    # Two calls inside the module at once: while one Python thread is in a long
    # evaluate_many, this thread completes short calls of its own. Held by the
    # first call (the GIL, or a lock of the module's around its caches), the
    # second could not begin until the first returned: at most the calls begun
    # before the first went in would finish. How fast either runs is the
    # benchmark's (python/benchmark.py), not a test's.
    data = columns()
    few = {k: v[:8] for k, v in data.items()}
    wanted = ["swingweight_kg_cm2", "apparent_cor", "peak_wrist_force_N"]
    inside = threading.Event()
    done = threading.Event()

    def work():
        inside.set()
        sweetspot.evaluate_many(BASE, data, threads=1, outputs=wanted)
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    inside.wait()
    finished_during = 0
    while not done.is_set():
        result = sweetspot.evaluate_many(BASE, few, threads=1, outputs=wanted)
        assert result["ok"].all()
        if not done.is_set():
            finished_during += 1
    worker.join()
    assert finished_during > 20
