"""Peer of rigid_outcomes(): the rigid model on a million distinct designs
(mass, balance, head/handle ratio, hand mass and impact point vary), as NumPy
arrays, timed in-process. Prints one JSON line: median seconds and ns per design.
Usage: rigid_kernel.py [REPEATS]"""
import json
import sys
import time

import numpy as np

from rigid_model import outcomes, paper_racquet

n = 1_000_000
i = np.arange(n)
M, c, I = paper_racquet(0.68 + 0.001 * (i % 7), 0.25 + 0.001 * (i % 97), 0.8 + 0.01 * (i % 41))
hand = 0.3 + 0.05 * (i % 5)
x = 0.30 + 0.003 * (i % 113)
repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
seconds = []
for _ in range(repeats):
    t = time.perf_counter()
    result = outcomes(M, c, I, 0.07, hand, 0.5, 0.057, 50.0, 0.8, 0.004, x)
    seconds.append(time.perf_counter() - t)
s = float(np.median(seconds))
print(json.dumps({"seconds": s, "ns_per_design": s / n * 1e9}))
