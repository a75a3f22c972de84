"""The rigid model of Cross (2004) in NumPy, vectorised: the peer the module's
column-wise path is timed against (python/benchmark.py) and an oracle its
numbers are checked against (tests/python/test_evaluate_many.py), written from
the paper's equations, not from the library's code.

A Table I racquet: two uniform halves of length L/2, head mass M r / (1 + r)
beyond the handle's M / (1 + r), the hand a point mass at hand_x from the butt,
the wrist at the butt, the ball hitting on the long axis from_tip from the tip."""

import numpy as np


def paper_rigid(L, M, r, from_tip, hand_kg=0.5, hand_x=0.07, forearm_kg=0.5, ball_kg=0.057,
                speed=50.0, cor=0.8, duration=0.004):
    """Eqs. (11), (13), (15)-(17): effective mass, apparent COR, peak force, wrist force ratio
    and peak wrist force, one array each."""
    handle = M / (1.0 + r)
    head = M * r / (1.0 + r)
    h = 0.5 * L
    com = (handle * 0.5 * h + head * 1.5 * h) / M
    inertia = (handle * (h * h / 12.0 + (0.5 * h - com) ** 2)
               + head * (h * h / 12.0 + (1.5 * h - com) ** 2))
    x = L - from_tip
    b = x - com
    m_eff = M / (1.0 + M * b * b / inertia)                          # Eq. (17)
    e_a = (cor * m_eff - ball_kg) / (m_eff + ball_kg)                 # Eq. (16)
    f0 = np.pi * ball_kg * (1.0 + e_a) * speed / (2.0 * duration)     # Eq. (15)
    total = M + hand_kg                                               # with the hand, Eq. (14)
    h_sys = com - hand_kg * (com - hand_x) / total
    i_sys = inertia + M * (com - h_sys) ** 2 + hand_kg * (hand_x - h_sys) ** 2
    x_cop = h_sys + i_sys / (total * h_sys)                           # Eq. (13)
    ratio = (forearm_kg * total * h_sys * (x - x_cop)
             / (forearm_kg * total * h_sys * h_sys + i_sys * (forearm_kg + total)))  # Eq. (11)
    return {"effective_mass_kg": m_eff, "apparent_cor": e_a, "peak_impact_force_N": f0,
            "wrist_force_ratio": ratio, "peak_wrist_force_N": np.abs(ratio) * f0}
