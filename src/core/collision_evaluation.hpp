#pragma once

// Fidelity::kCollision of evaluate(): the design's collision solved
// (collision.hpp) and folded into an Evaluation. Private to the core.

#include "sweetspot/evaluate.hpp"

namespace sweetspot {

// See evaluate() for Fidelity::kCollision. Throws std::invalid_argument naming
// the design's JSON path when the design cannot be solved.
Evaluation evaluate_collision(const Design& design, double rel_tol, ModeCache& cache);

}  // namespace sweetspot
