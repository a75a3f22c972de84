#pragma once

// Everything the HTML page of one design shows, computed: the design's own
// evaluation, its sweet spots, the curves along the frame and the maps over
// the string bed. reports/html_report.hpp draws it; nothing is computed there.

#include <optional>
#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "io/json_reader.hpp"
#include "studies/frame_curves.hpp"
#include "studies/string_bed_map.hpp"
#include "studies/sweet_spots.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::studies {

// The hand-held modes' relative tolerance on the page (evaluate's default).
inline constexpr double kPageRelTol = 1e-6;

// The string-bed maps of a page: computed over the design (its head assumed,
// racquet_head(): the string bed's size, else 100 sq in, when neither a head
// nor a twistweight is given), or why not.
struct PageMaps {
  bool racquet = true;  // false: no head nor strings (a bat, a beam), so no maps
  bool head_assumed = false;
  std::optional<StringBedMap> map;
  std::string refused;  // why there is no map (the refusal's text)
};

// The page's numbers.
struct DesignPage {
  // The design at its own impact (io::evaluate_design_file, the fidelity
  // "auto" picks, the modes to kPageRelTol).
  Evaluation evaluation;
  // Its sweet spots at that fidelity (find_sweet_spots()).
  SweetSpots spots;
  // Where the curves run: a racquet's string bed, else the whole implement.
  AxisSpan span;
  // Over `span` every kFrameCurveStep_m, at frame_curve_fidelity().
  std::vector<FramePoint> curve;
  // Over the string bed: the rigid model, the modal one (kModal and
  // kResponse answers) or the solved collision, as the answer is.
  PageMaps maps;
};

// The maps of the page at the fidelity of its answer (a collision answer
// gives collision maps, so the power map agrees with the best rebound).
PageMaps page_maps(const io::DesignFile& file, Fidelity fidelity);

// Computes the page of `file`. Throws like io::evaluate_design_file and
// frame_curves(); a design the maps refuse has its reason in maps.refused.
DesignPage design_page(const io::DesignFile& file);

}  // namespace sweetspot::studies
