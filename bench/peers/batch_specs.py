"""Peer of `sweetspot evaluate --batch` on a CSV catalogue of racquets by
industry specs (name, length_in, mass_g, balance_cm, swingweight_kg_cm2,
impact from_tip_m): every rigid output per row, written as CSV with round-trip
precision. Usage: batch_specs.py CATALOGUE.csv OUT.csv"""
import sys

import numpy as np

from rigid_model import from_specs, outcomes

names = np.loadtxt(sys.argv[1], delimiter=",", skiprows=1, usecols=0, dtype=str)
L_in, mass_g, balance_cm, sw_kg_cm2, from_tip = np.loadtxt(sys.argv[1], delimiter=",", skiprows=1,
                                                           usecols=(1, 2, 3, 4, 5), unpack=True)
L = L_in * 0.0254
M, c, I = from_specs(mass_g * 0.001, balance_cm * 0.01, sw_kg_cm2 * 1e-4)
x = L - from_tip
hand_m, hand_x, Me, ball_m, ball_v, cor, T = 0.5, 0.07, 0.5, 0.057, 50.0, 0.8, 0.004
m_eff, e_a, impulse, f0, cop, ratio, fw = outcomes(M, c, I, hand_x, hand_m, Me, ball_m, ball_v, cor, T, x)
total = M + hand_m
h = c - hand_m * (c - hand_x) / total
Is = I + M * (c - h) ** 2 + hand_m * (hand_x - h) ** 2
sw = I + M * (c - 0.1) ** 2
cop_free = c + I / (c * M)
axis_free = c + I / ((c - x) * M)
axis_hand = (total * (x - h) * h - Is) / (total * (x - h) + Me * x)
n = len(L)
rows = np.empty((n, 26), dtype=object)
columns = [np.arange(2, n + 2), names, L, M, c, I, sw * 1e4, I * 1e4, L - x, x - c, np.full(n, cor), np.full(n, T),
           m_eff, e_a, e_a * ball_v, impulse, f0, ratio, fw, L - cop_free, L - cop, axis_free, axis_hand, total, h, Is]
for k, column in enumerate(columns):
    rows[:, k] = column
fmt = "%d,%s," + ",".join(["%.17g"] * 21) + ",,,,,,,,," + ",".join(["%.17g"] * 3) + ","
header = "line,name,length_m,mass_kg,...,error"
np.savetxt(sys.argv[2], rows, fmt=fmt, header=header, comments="")
