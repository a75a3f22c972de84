"""The free-free beam's fundamental by finite elements in NumPy/SciPy, written
the obvious way: the peer of sweetspot's free finite-element modes
(`sweetspot bench speed`). Cross (2004)'s beam: 0.72 m, 0.328 kg, uniform,
EI for a free fundamental of 193 Hz; Hermite cubic elements (the consistent
mass matrix), scipy.linalg.eigh on the assembled K and M (the two rigid-body
modes come first), only the lowest flexible mode asked for.

Usage: free_fe_eigh.py ELEMENTS REPEATS  ->  JSON {"seconds", "f1_Hz"} on stdout,
the median time of one assembly and solve."""
import json
import sys
import time

import numpy as np
import scipy.linalg

LENGTH_M, MASS_KG, F1_HZ = 0.72, 0.328, 193.0
# Free-free beam: beta_1 L = 4.730040744862704 (cos z cosh z = 1).
BETA1_L = 4.730040744862704


def assemble(elements, EI):
    h = LENGTH_M / elements
    mu = MASS_KG / LENGTH_M
    n = 2 * (elements + 1)
    K = np.zeros((n, n))
    M = np.zeros((n, n))
    k = EI / h**3 * np.array([[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                              [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]])
    m = mu * h / 420 * np.array([[156, 22 * h, 54, -13 * h], [22 * h, 4 * h * h, 13 * h, -3 * h * h],
                                 [54, 13 * h, 156, -22 * h], [-13 * h, -3 * h * h, -22 * h, 4 * h * h]])
    for e in range(elements):
        i = 2 * e
        K[i:i + 4, i:i + 4] += k
        M[i:i + 4, i:i + 4] += m
    return K, M


def main():
    elements, repeats = int(sys.argv[1]), int(sys.argv[2])
    # EI from the closed form f1 = (beta_1 L)^2 / (2 pi L^2) sqrt(EI / mu).
    mu = MASS_KG / LENGTH_M
    EI = (2 * np.pi * F1_HZ * LENGTH_M**2 / BETA1_L**2) ** 2 * mu
    times = []
    for _ in range(max(repeats, 1)):
        inner = 50
        start = time.perf_counter()
        for _ in range(inner):
            K, M = assemble(elements, EI)
            w2, _ = scipy.linalg.eigh(K, M, subset_by_index=[2, 2])
        times.append((time.perf_counter() - start) / inner)
    print(json.dumps({"seconds": float(np.median(times)),
                      "f1_Hz": float(np.sqrt(w2[0]) / (2 * np.pi))}))


if __name__ == "__main__":
    main()
