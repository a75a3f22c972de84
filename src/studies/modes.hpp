#pragma once

// `sweetspot modes`, its numbers: the first vibration modes of a design, free
// and held in the hand (or on its rig: the handle clamped, a pivot), with
// their nodes and shapes, and the rigid model's centres of percussion beside
// them (a player's only). reports/modes_report.hpp writes them.

#include <optional>

#include "io/design_reader.hpp"
#include "sweetspot/beam_modes.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::studies {

// Points along the implement in the shape table and plot.
inline constexpr int kShapeSamples = 145;

struct ModesData {
  io::DesignFile design;
  Evaluation rigid;
  ModalResult free;
  ModalResult held;  // empty without a hand, or on a rig
  // On a rig that lets the frame vibrate (handle clamped, a pivot): its modes
  // (supported_modes(), finite elements); empty otherwise.
  ModalResult rig;
  // The hand-held fundamental among `held` (hand_held_fundamental(): the
  // first mode the frame, not the hand, carries); absent without one.
  std::optional<Mode> held_fundamental;
  bool mass_distribution_fitted = false;
};

// The first `modes` free modes (exact solver unless Timoshenko or `method`
// says FE) and the hand-held ones (FE to `rel_tol`). Throws InputError at the
// design's JSON path when the design cannot give modes.
ModesData compute_modes(const io::DesignFile& design, int modes, double rel_tol,
                        ModeOptions::Method method);

}  // namespace sweetspot::studies
