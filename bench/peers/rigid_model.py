"""The rigid model of Cross (2004) in NumPy, written the obvious way: the
peer sweetspot's benchmarks compare with (`sweetspot bench speed`)."""
import numpy as np

SWINGWEIGHT_AXIS_M = 0.10


def paper_racquet(length_m, mass_kg, ratio):
    """Two uniform halves, head/handle mass ratio: mass, centre of mass, I_cm."""
    handle = mass_kg / (1.0 + ratio)
    head = mass_kg * ratio / (1.0 + ratio)
    half = 0.5 * length_m
    com = (handle * 0.5 * half + head * (half + 0.5 * half)) / mass_kg
    inertia = (handle * (half * half / 12.0 + (0.5 * half - com) ** 2)
               + head * (half * half / 12.0 + (1.5 * half - com) ** 2))
    return mass_kg, com, inertia


def from_specs(mass_kg, balance_m, swingweight_kg_m2):
    return mass_kg, balance_m, swingweight_kg_m2 - mass_kg * (balance_m - SWINGWEIGHT_AXIS_M) ** 2


def outcomes(M, c, I, hand_x, hand_m, Me, ball_m, ball_v, cor, T, x):
    """Effective mass, apparent COR, impulse, F0, the hand-held COP, F_w/F and
    the peak wrist force (Eqs. 11-17), element by element."""
    total = M + hand_m
    com = c - hand_m * (c - hand_x) / total
    Is = I + M * (c - com) ** 2 + hand_m * (hand_x - com) ** 2
    b = x - c
    m_eff = M / (1.0 + M * b * b / I)
    e_a = (cor * m_eff - ball_m) / (m_eff + ball_m)
    impulse = ball_m * (1.0 + e_a) * ball_v
    f0 = np.pi * impulse / (2.0 * T)
    cop = com + Is / (total * com)
    ratio = Me * total * com * (x - cop) / (Me * total * com * com + Is * (Me + total))
    return m_eff, e_a, impulse, f0, cop, ratio, np.abs(ratio) * f0
