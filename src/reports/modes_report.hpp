#pragma once

// `sweetspot modes`: the first vibration modes of a design, free and held in
// the hand, with their nodes and shapes, as a report, CSV and plot, from
// studies::compute_modes().

#include <string>

#include "io/design_reader.hpp"
#include "io/format.hpp"
#include "io/plot.hpp"
#include "studies/modes.hpp"

namespace sweetspot::reports {

// md: frequencies, damping and nodes; json: the same; csv: the shape table
// (x from the butt, then w of each free mode, then each hand-held mode).
std::string modes_report(const studies::ModesData& data, io::Format format);

// Mode shapes along the implement, free and hand-held, with the COPs and the
// fundamental's nodes marked.
io::Plot modes_plot(const studies::ModesData& data);

}  // namespace sweetspot::reports
