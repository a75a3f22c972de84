#pragma once

// A design's frame (flexible_frame) built once and handed to each solve that
// needs it, so that an evaluation solves each mode set once: response_model()
// and evaluate_modes() are these on a frame they build themselves; ModeCache
// keeps the frame and the free modes between them. Private to the core.

#include "sweetspot/frame_modes.hpp"
#include "sweetspot/impact_response.hpp"

namespace sweetspot::detail {

// response_model(design, options) on `frame` == flexible_frame(design), with
// options already validated. `exact_free`, when given, is set to whether the
// free modes are the exact solver's (their first is then, bit for bit, the
// fundamental a one-mode exact solve gives).
ResponseModel response_model_on(const Design& design, const FlexibleFrame& frame,
                                const ResponseOptions& options, bool* exact_free = nullptr);

// evaluate_modes(design, rel_tol) on `frame` == flexible_frame(design).
// `free_fundamental`: the free fundamental when already solved exactly on this
// frame (response_model_on's first mode with exact_free), else nullptr.
ModalOutputs evaluate_modes_on(const Design& design, const FlexibleFrame& frame, double rel_tol,
                               const Mode* free_fundamental = nullptr);

}  // namespace sweetspot::detail
