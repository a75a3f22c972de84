"""Peer of `sweetspot sweep` on 1000 hand masses x 1000 forearm masses: the
Table I racquet (row 1), the peak wrist force at every point, written as CSV
with round-trip precision. Usage: sweep_every_point.py OUT.csv [POINTS]"""
import sys

import numpy as np

from rigid_model import outcomes, paper_racquet

out = sys.argv[1]
n = int(sys.argv[2]) if len(sys.argv) > 2 else 1000
hand = np.linspace(0.3, 0.6, n)
forearm = np.linspace(0.1, 1.0, n)
H, F = np.meshgrid(hand, forearm)  # the first variable fastest, as sweetspot writes it
M, c, I = paper_racquet(0.7, 0.25, 0.8)
force = outcomes(M, c, I, 0.07, H, F, 0.057, 50.0, 0.8, 0.004, 0.65)[6]
table = np.column_stack([H.ravel(), F.ravel(), force.ravel()])
np.savetxt(out, table, fmt="%.17g,%.17g,%.17g,", comments="",
           header="/hand/mass_kg,/forearm/equivalent_mass_kg,peak_wrist_force_N,error")
