#pragma once

// Fidelity::kCollision of evaluate(): the design's collision solved
// (collision.hpp) and folded into an Evaluation. Private to the core.

#include "sweetspot/evaluate.hpp"

namespace sweetspot {

// Flexible modes of the free frame the collision uses (the exact solver's
// most; convergence: tests/collision_test.cpp, truncation < 1e-4 in e_A).
inline constexpr int kCollisionModes = 6;

// See evaluate() for Fidelity::kCollision. Throws std::invalid_argument naming
// the design's JSON path when the design cannot be solved.
Evaluation evaluate_collision(const Design& design, double rel_tol);

}  // namespace sweetspot
