#pragma once

// `sweetspot modes`: the first vibration modes of a design, free and held in
// the hand, with their nodes and shapes, as a report, CSV and plot.

#include <string>

#include "io/design_reader.hpp"
#include "io/format.hpp"
#include "io/plot.hpp"
#include "sweetspot/beam_modes.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::reports {

// Points along the implement in the shape table and plot.
inline constexpr int kShapeSamples = 145;

struct ModesData {
  io::DesignFile design;
  Evaluation rigid;
  ModalResult free;
  ModalResult held;  // empty without a hand
  bool mass_distribution_fitted = false;
};

// The first `modes` free modes (exact solver unless Timoshenko or `method`
// says FE) and the hand-held ones (FE to `rel_tol`). Throws InputError at the
// design's JSON path when the design cannot give modes.
ModesData compute_modes(const io::DesignFile& design, int modes, double rel_tol,
                        ModeOptions::Method method);

// md: frequencies, damping and nodes; json: the same; csv: the shape table
// (x from the butt, then w of each free mode, then each hand-held mode).
std::string modes_report(const ModesData& data, io::Format format);

// Mode shapes along the implement, free and hand-held, with the COPs and the
// fundamental's nodes marked.
io::Plot modes_plot(const ModesData& data);

}  // namespace sweetspot::reports
