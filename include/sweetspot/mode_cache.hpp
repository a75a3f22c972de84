#pragma once

// The frame's modes kept from one evaluation to the next. A catalogue's rows,
// a sweep's points or a study's iterations that change only the impact, the
// ball or the strings share the frame, and solving its modes is most of an
// evaluation's time (at collision fidelity the exact free modes are about half
// of one, the hand-held fundamental about a quarter). A ModeCache holds the
// last frame's modes and solves them again only when an input they depend on
// differs, bit for bit, so an evaluation through it gives the same numbers as
// one without it. Within one evaluation it shares the frame (flexible_frame)
// between the free response model and the modal outputs, and hands the
// latter the free fundamental the former solved exactly: each mode set is
// solved once.
//
// Not thread-safe: one per thread. It holds one frame (the last one).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "sweetspot/design.hpp"
#include "sweetspot/frame_modes.hpp"
#include "sweetspot/impact_response.hpp"

namespace sweetspot {

class ModeCache {
 public:
  // evaluate_modes(design, rel_tol): the free and hand-held fundamentals and
  // their nodes. Depends on the implement, its stiffness, the hand and rel_tol.
  const ModalOutputs& modal_outputs(const Design& design, double rel_tol);

  // response_model(design, options). Depends on the same and the options.
  const ResponseModel& response_model(const Design& design, const ResponseOptions& options);

  // How many mode sets were solved and how many were reused, over the
  // cache's life (for tests and benchmarks).
  std::size_t solves() const { return solves_; }
  std::size_t reuses() const { return reuses_; }

 private:
  // The design's flexible frame, built once for both mode sets.
  const FlexibleFrame& frame(const Design& design, const std::vector<std::uint64_t>& key);

  std::vector<std::uint64_t> frame_key_;
  std::optional<FlexibleFrame> frame_;
  std::vector<std::uint64_t> modal_key_;
  std::optional<ModalOutputs> modal_;
  std::vector<std::uint64_t> response_key_;
  std::optional<ResponseModel> response_;
  std::vector<std::uint64_t> response_frame_key_;
  bool response_free_exact_ = false;  // free modes from the exact solver
  std::size_t solves_ = 0;
  std::size_t reuses_ = 0;
};

}  // namespace sweetspot
