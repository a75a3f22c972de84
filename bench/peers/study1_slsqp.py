"""Peer of study 1 (designs/studies/1-lowest-wrist-force-table1-ranges.json):
the lowest peak wrist force over the six ranges of Table I with
scipy.optimize.minimize(method="SLSQP"), timed in-process. Prints one JSON
line: median seconds per optimisation, evaluations, objective.
Usage: study1_slsqp.py [REPEATS]"""
import json
import sys
import time

import numpy as np
from scipy.optimize import minimize

from rigid_model import outcomes, paper_racquet


def force(v):
    mass, ratio, cor, duration_ms, hand, forearm = v
    M, c, I = paper_racquet(0.7, mass, ratio)
    return outcomes(M, c, I, 0.07, hand, forearm, 0.057, 50.0, cor, duration_ms * 1e-3, 0.65)[6]


bounds = [(0.25, 0.40), (0.8, 1.2), (0.6, 0.8), (4.0, 6.0), (0.4, 0.5), (0.4, 0.5)]
start = np.array([0.25, 0.8, 0.8, 4.0, 0.5, 0.5])
repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
seconds = []
for _ in range(repeats):
    t = time.perf_counter()
    result = minimize(force, start, method="SLSQP", bounds=bounds)
    seconds.append(time.perf_counter() - t)
print(json.dumps({"seconds": float(np.median(seconds)), "evaluations": int(result.nfev),
                  "objective": float(result.fun)}))
