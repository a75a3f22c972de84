#pragma once

// Mode shapes as analytic pieces (Krylov functions), their normalisation and
// nodes. Internal to the beam-mode solvers.

#include "sweetspot/beam_modes.hpp"

namespace sweetspot::beam_detail {

inline constexpr double kPi = 3.14159265358979323846;

// S(z), T(z)/z, U(z)/z^2, V(z)/z^3 with S, U = (cosh z +- cos z)/2 and
// T, V = (sinh z +- sin z)/2: finite at z = 0 (1, 1, 1/2, 1/6).
struct Krylov {
  double s, t1, u2, v3;
};

Krylov krylov(double z);

// w at xi from a piece's start values (see ShapePiece).
double evaluate_piece(const ShapePiece& p, double xi);

// Scales `mode.shape` to max |w| = 1 (sampled) with w(L) > 0 and locates its
// interior zeros on the analytic pieces. Returns the factor applied.
double normalise_and_find_nodes(Mode& mode);

// Fills the result's plotting table: `samples` points butt to tip (none if 0).
void fill_shape_table(ModalResult& result, double length_m, int samples);

}  // namespace sweetspot::beam_detail
