#pragma once

// The report a coach opens: one self-contained HTML page for a design (no
// network, no scripts, no fonts fetched; CSS inline; plots are gnuplot's SVG
// inlined), readable on a phone. Everything the page shows is computed by
// studies::design_page() (studies/design_page.hpp) and only drawn here; the
// command line writes it (`sweetspot report DESIGN.json --html FILE`).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/design_reader.hpp"
#include "io/json_reader.hpp"
#include "reports/html_page.hpp"
#include "studies/design_page.hpp"

namespace sweetspot::reports {

// The head's size used for the drawing [m^2]: the strings' head size when the
// design has strings, the design's head shape (`implement.headsize_sq_in`)
// when it has one, `implement.headsize_sq_in` of `document` otherwise, else
// 100 sq in, a mid-size tennis head.
double drawn_head_area_m2(const io::DesignFile& design);

// The racquet drawn to scale from above and from the side, as inline SVG
// (centimetres as user units): outline from the length and the head's size,
// the hand, the balance point, the hand-held COP, the node (when known), the
// impact point and the lead tape.
// `id` names the drawing's title element (unique on a page).
std::string racquet_top_svg(const io::DesignFile& design, const Evaluation& evaluation,
                            double head_area_m2, const std::string& id = "top");
std::string racquet_side_svg(const io::DesignFile& design, const Evaluation& evaluation);
// An implement that is not a racquet (the paper's beam, a bat) from the
// side, to scale along its length: an implement given by its profile at the
// profile's outer diameters (a hollow one too, as a tube looks from the
// side), another at widths following the square root of its sections' mass
// per length. `id` names the drawing's title element, unique on its page.
std::string implement_side_svg(const io::DesignFile& design, const Evaluation& evaluation,
                               const std::string& id = "side");

// A racquet to draw beside others: its file, its evaluation (both outlive
// the call) and a caption (markup).
struct DrawnRacquet {
  const io::DesignFile* file = nullptr;
  const Evaluation* evaluation = nullptr;
  std::string caption_html;
};

// Racquets drawn from above to one scale, one above the other (each drawing
// as wide on the page as its length), in figures with ids `id`-1, `id`-2...,
// then the table of the numbers behind them (<table id="`id`-positions">):
// the length, the balance point, the hand-held COP, the node, the impact and
// the lead, in cm from the tip, one column per racquet.
std::string racquets_to_scale_html(const std::vector<DrawnRacquet>& racquets,
                                   const std::string& id);

// The whole page for `design` (read from `document`, the file as written, for
// its inputs in the units they were given; its impact as every command takes
// it, io::default_impact()) from its numbers, `page` =
// studies::design_page(design). Plots that gnuplot cannot draw
// are replaced by a sentence saying why; the tables are always there.
std::string design_html_report(const io::DesignFile& design, const io::Json& document,
                               const studies::DesignPage& page);

}  // namespace sweetspot::reports
