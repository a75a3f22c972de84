#include "studies/design_page.hpp"

#include <stdexcept>

#include "studies/sweet_spots.hpp"

namespace sweetspot::studies {

PageMaps page_maps(const io::DesignFile& file, Fidelity fidelity) {
  PageMaps maps;
  // A bat or a beam has no string bed to map: a drawn racquet's head would be
  // an answer about an implement the file does not describe.
  maps.racquet = is_racquet(file);
  if (!maps.racquet) return maps;
  Design d = file.design;
  maps.head_assumed = !d.head && !d.twistweight_kg_m2;
  if (maps.head_assumed) {
    d.head = racquet_head(d);  // the string bed's size, else 100 sq in
  }
  StringBedMapOptions options;
  try {
    // The maps are drawn at the fidelity of the page's answer: the solved
    // collision when the answer is solved, so the power map agrees with the
    // best rebound in the sentences above.
    options.fidelity = fidelity == Fidelity::kRigid || fidelity == Fidelity::kCollision
                           ? fidelity
                           : Fidelity::kModal;
    maps.map = string_bed_map(d, options);
  } catch (const std::invalid_argument& e) {
    maps.refused = e.what();
  }
  return maps;
}

DesignPage design_page(const io::DesignFile& file) {
  require_player_file(file, "the design's page (its sweet spots, the wrist, the shot)");
  DesignPage page;
  page.evaluation = io::evaluate_design_file(file, "", kPageRelTol);
  page.span = hit_span(file);
  page.curve = frame_curves(file.design, kFrameCurveStep_m, frame_curve_fidelity(page.evaluation),
                            page.span);
  page.spots = find_sweet_spots(file, page.evaluation, kPageRelTol);
  page.maps = page_maps(file, fidelity_of(page.evaluation));
  return page;
}

}  // namespace sweetspot::studies
