#pragma once

// `sweetspot tune`, rendered: the specs before, asked and reached, the lead at
// each place in grams and in strips of tape, and what the change does to the
// sweet spots, the wrist force and the recoil weight (the tuned racquet
// compared with the original, reports/comparison.hpp).

#include <string>
#include <vector>

#include "io/format.hpp"
#include "studies/comparison.hpp"
#include "studies/tune.hpp"

namespace sweetspot::reports {

// One racquet's tune with its evaluations before and after.
struct TunedRacquet {
  studies::TuneResult result;
  studies::ComparedDesign before;
  studies::ComparedDesign after;  // the tuned design (the nearest when !result.exact)
  std::string written;            // the file the tuned design went to, "" when none
};

// The report in `format`: Markdown (tables in g, cm, kg·cm², then the
// changes in words) or JSON ({"before", "targets", "reached", "lead",
// "added_g", "reachable", "why", "strip_g", "effect", "written"}, people's
// units in the keys' suffixes). `strip_kg` (> 0) is the strip of tape the
// lead is counted in; `rule` (may be empty) says how common targets were chosen.
std::string tune_report(const std::vector<TunedRacquet>& racquets, double strip_kg,
                        io::Format format, const std::string& rule = "");

}  // namespace sweetspot::reports
