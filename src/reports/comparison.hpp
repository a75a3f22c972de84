#pragma once

// `sweetspot compare A.json B.json ...`: designs side by side (each at its
// own impact and at its sweet spots, as studies::compare_one() gives them),
// and what changes from the first to each of the others stated in words.

#include <string>
#include <string_view>
#include <vector>

#include "io/design_reader.hpp"
#include "io/format.hpp"
#include "studies/comparison.hpp"

namespace sweetspot::reports {

using studies::ComparedDesign;

// What changes from `before` to `after`, one sentence each: first every input
// of the read designs that differs (the implement in a player's words where
// they apply: lead, mass, balance, swingweight, tension, the frame's
// frequency; any other field of the implement, its frame, its strings, the
// hand, the forearm, the ball or the impact by name, "50 → 40 m/s"; "the same
// implement" only when none of the implement's differs), then what a player
// would notice: where the sweet spots move (0.5 cm or more) and
// how the wrist force (2 % or more) and the rebound (0.01 or more) change at
// the impact asked about and at the sweet spots. "No difference that matters"
// when nothing passes those thresholds.
std::vector<std::string> differences(const ComparedDesign& before, const ComparedDesign& after);

// "falls by 7 % (250 N → 230 N)", "rises by 2 % (275 N → 280 N)", or "is about
// the same (0.95 N·m → 0.95 N·m)" when the change is below `threshold`
// (relative) or rounds to 0 %: the two values to two significant figures, more
// where that takes for the printed pair to differ and to show the percentage
// stated.
std::string change_sentence(double before, double after, double threshold, std::string_view unit);

// The comparison in `format`: Markdown (a table in people's units, then the
// differences in words), JSON ({"designs": [...], "differences": [...]}, SI)
// or CSV (one row per design, SI).
std::string comparison_report(const std::vector<ComparedDesign>& designs, io::Format format);

// The comparison as one self-contained web page (reports/html_page.hpp): the
// differences in words first, each design's sweet spots, the table side by
// side (people's units, the SI value under each), the racquets drawn from
// above to one scale with the positions behind the drawing, and the peak
// wrist force along each frame overlaid, with its table (each design's
// curve: compare_one(..., along_frame = true)).
std::string comparison_html(const std::vector<ComparedDesign>& designs);

}  // namespace sweetspot::reports
