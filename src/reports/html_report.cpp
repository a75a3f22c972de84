#include "reports/html_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "io/format.hpp"
#include "io/json_reader.hpp"
#include "io/outputs.hpp"
#include "io/plot.hpp"
#include "reports/html_page.hpp"
#include "reports/string_bed_map_report.hpp"
#include "reports/summary.hpp"
#include "studies/design_page.hpp"

namespace sweetspot::reports {
namespace {

// The drawn head: an ellipse this much longer than wide (a 100 sq in head is
// about 34 cm by 25 cm).
constexpr double kHeadAspect = 1.35;
// Drawing sizes [cm]: the frame's rim, the handle's width, the throat's
// length, the profile's depth (the ball is drawn at the design's diameter).
constexpr double kRim_cm = 1.5;  // as reports/summary.hpp places the centre of the strings
constexpr double kHandleWidth_cm = 2.8;
constexpr double kThroat_cm = 14.0;
constexpr double kBeamDepth_cm = 2.4;

// A number for an SVG attribute (centimetres, two decimals are plenty).
std::string n(double v) { return fmt::format("{:.2f}", v); }

// Every leaf of the file as written: JSON pointer, value, unit.
void flatten(const io::Json& value, const std::string& pointer, std::string& rows) {
  if (value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it) {
      if (pointer.empty() && (it.key() == "$schema" || it.key() == "name" ||
                              it.key() == "description" || it.key() == "reference"))
        continue;
      flatten(it.value(), pointer + "/" + it.key(), rows);
    }
    return;
  }
  if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      flatten(value[i], pointer + "/" + std::to_string(i), rows);
    return;
  }
  const std::string key = pointer.substr(pointer.rfind('/') + 1);
  const std::string shown = value.is_string()
                                ? value.get<std::string>()
                                : value.dump(-1, ' ', false, io::Json::error_handler_t::replace);
  rows += fmt::format("<tr><td><code>{}</code></td><td class=\"num\">{}</td><td>{}</td></tr>\n",
                      html_escape(pointer), html_escape(shown), html_escape(io::unit_of_key(key)));
}

// The answer in sentences (reports/summary.hpp, the same as `evaluate`'s
// Markdown opens with), one paragraph each, then what the rigid model gives
// at the COP, which the drawing marks.
std::string answer_html(const io::DesignFile& file, const studies::SweetSpots& spots) {
  std::string html;
  for (const std::string& sentence : reports::sweet_spot_sentences(file, spots))
    html += "<p>" + html_escape(sentence) + "</p>\n";
  return html;
}

// A marker along the racquet: where (cm from the tip), its symbol and label.
struct Mark {
  double x_cm;
  std::string label;
  std::string symbol;  // SVG drawn at (x, y)
};

std::vector<Mark> marks(const io::DesignFile& file, const Evaluation& e, double y) {
  const double L = file.design.implement.length_m();
  std::vector<Mark> out;
  const double bx = (L - e.balance_from_butt_m) * 100.0;
  out.push_back(
      {bx, "balance",
       fmt::format("<path class=\"balance\" d=\"M{} {} l-1.3 2.4 h2.6 z\"/>", n(bx), n(y + 0.2))});
  if (e.cop_hand_from_butt_m) {
    const double x = (L - *e.cop_hand_from_butt_m) * 100.0;
    out.push_back({x, "COP (hand-held)",
                   fmt::format("<circle class=\"cop\" cx=\"{}\" cy=\"{}\" r=\"1\"/>", n(x), n(y))});
  }
  if (e.modal && e.modal->node_hand_from_butt_m) {
    const double x = (L - *e.modal->node_hand_from_butt_m) * 100.0;
    out.push_back(
        {x, "node",
         fmt::format("<path class=\"node\" d=\"M{} {} l1.1 1.1 l-1.1 1.1 l-1.1 -1.1 z\"/>", n(x),
                     n(y - 1.1))});
  }
  return out;
}

// Labels above the drawing, one row per label when neighbours would touch,
// each with a leader line down to its marker at height `y`.
std::string labels(std::vector<Mark> ms, double y, double top) {
  std::sort(ms.begin(), ms.end(), [](const Mark& a, const Mark& b) { return a.x_cm < b.x_cm; });
  std::string svg;
  std::vector<double> row_end;
  for (const Mark& m : ms) {
    // Laid out for the phone's larger text (font 2.4 cm): about 1.35 cm a letter.
    const double width = 1.35 * static_cast<double>(m.label.size()) + 1.0;
    std::size_t row = 0;
    while (row < row_end.size() && row_end[row] > m.x_cm - 0.5) ++row;
    if (row == row_end.size()) row_end.push_back(0.0);
    row_end[row] = m.x_cm + width;
    const double ty = top + 3.0 * static_cast<double>(row);
    svg += fmt::format(
        "<line class=\"leader\" x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\"/>"
        "<text x=\"{3}\" y=\"{1}\">{4}</text>\n",
        n(m.x_cm), n(ty), n(y), n(m.x_cm + 0.3), html_escape(m.label));
  }
  return svg;
}

std::string ruler(double length_cm, double y) {
  std::string svg = fmt::format("<line class=\"ruler\" x1=\"0\" y1=\"{0}\" x2=\"{1}\" y2=\"{0}\"/>",
                                n(y), n(length_cm));
  for (int t = 0; t <= static_cast<int>(length_cm); t += 10) {
    svg += fmt::format(
        "<line class=\"ruler\" x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\"/>"
        "<text class=\"tick\" x=\"{0}\" y=\"{3}\">{4}</text>",
        t, n(y), n(y + 1.0), n(y + 3.0), t);
  }
  return svg + fmt::format("<text class=\"tick\" x=\"{}\" y=\"{}\">cm from the tip</text>\n",
                           n(length_cm / 2), n(y + 5.6));
}

std::string hand_and_tape(const io::DesignFile& file, double half_height, bool profile) {
  const Design& d = file.design;
  const double L = d.implement.length_m() * 100.0;
  std::string svg;
  if (d.hand.mass_kg > 0) {
    const double cx = L - d.hand.center_from_butt_m * 100.0;
    svg += fmt::format(
        "<ellipse class=\"hand\" cx=\"{}\" cy=\"0\" rx=\"{}\" ry=\"{}\"><title>the hand, {} cm "
        "from the butt</title></ellipse>\n",
        n(cx), n(d.hand.grip_length_m * 50.0 + 1.0), n(profile ? 4.0 : 4.8),
        html_cm(d.hand.center_from_butt_m));
  }
  for (const PointMass& p : d.implement.point_masses()) {
    if (!(p.mass_kg > 0.0)) continue;  // a place for lead with none there (a study's start)
    const double x = L - p.from_butt_m * 100.0;
    const double off_cm = p.off_axis_m * 100.0;
    if (!profile && off_cm != 0.0) {
      // Seen face on, lead on the hoop at 3 or 9 o'clock is a patch where it
      // sits (3 o'clock up, as the ball is drawn), not a strip across the head.
      svg += fmt::format(
          "<rect class=\"tape\" x=\"{}\" y=\"{}\" width=\"1.6\" height=\"1.2\"><title>lead, "
          "{:.0f} g, {} cm from the tip, {} cm off the axis toward {} o'clock</title></rect>\n",
          n(std::clamp(x - 0.8, 0.0, L - 1.6)), n(-off_cm - 0.6), p.mass_kg * 1000.0,
          html_cm(d.implement.length_m() - p.from_butt_m), n(std::fabs(off_cm)),
          off_cm > 0 ? 3 : 9);
      continue;
    }
    // Lead on the axis sits on the frame: from the side across its
    // thickness; face on, a band around the handle's width (on the hoop at 12
    // o'clock, in the throat or under the grip), not a strip across the head.
    const double band = profile ? half_height : std::min(half_height, kHandleWidth_cm / 2 + 0.2);
    svg += fmt::format(
        "<rect class=\"tape\" x=\"{}\" y=\"{}\" width=\"1.6\" height=\"{}\"><title>lead, {:.0f} g, "
        "{} cm from the tip</title></rect>\n",
        n(std::clamp(x - 0.8, 0.0, L - 1.6)), n(-band), n(2 * band), p.mass_kg * 1000.0,
        html_cm(d.implement.length_m() - p.from_butt_m));
  }
  return svg;
}

void tape_marks(const io::DesignFile& file, std::vector<Mark>& ms) {
  const double L = file.design.implement.length_m();
  // A pair at one place along the axis (3 and 9 o'clock) is one mark: "lead 2 × 5 g".
  const auto& masses = file.design.implement.point_masses();
  for (std::size_t k = 0; k < masses.size(); ++k) {
    const PointMass& p = masses[k];
    if (!(p.mass_kg > 0.0)) continue;
    if (k > 0 && masses[k - 1].from_butt_m == p.from_butt_m && masses[k - 1].mass_kg == p.mass_kg &&
        masses[k - 1].off_axis_m == -p.off_axis_m && p.off_axis_m != 0.0)
      continue;
    const bool pair = k + 1 < masses.size() && masses[k + 1].from_butt_m == p.from_butt_m &&
                      masses[k + 1].mass_kg == p.mass_kg &&
                      masses[k + 1].off_axis_m == -p.off_axis_m && p.off_axis_m != 0.0;
    ms.push_back({(L - p.from_butt_m) * 100.0,
                  pair ? fmt::format("lead 2 × {:.0f} g", p.mass_kg * 1000.0)
                       : fmt::format("lead {:.0f} g", p.mass_kg * 1000.0),
                  ""});
  }
}

// The table under the maps takes every kMapTableStep-th grid point, from the
// third, along and across (a 50 x 50 grid gives 10 x 10, those on the bed).
constexpr int kMapTableStep = 5;
constexpr int kMapTableFirst = 2;

// The heat maps' plots, one per quantity of map_quantities(), for io::render_svgs().
std::vector<io::SvgPlot> map_svg_plots(const studies::PageMaps& maps, double length_m) {
  std::vector<io::SvgPlot> plots;
  if (!maps.map) return plots;
  for (const MapQuantity q : map_quantities(*maps.map))
    plots.push_back({string_bed_heat_map_svg_script(*maps.map, q, length_m, ""),
                     "map-" + map_quantity_name(q) + "-"});
  return plots;
}

// The sentence under each map naming its lines: the hand-held COP, the node.
std::string map_lines_text(const studies::StringBedMap& map, double L) {
  std::string lines;
  if (map.cop_hand_from_butt_m)
    lines += fmt::format("the solid line across the head is the hand-held COP, {} cm from the tip",
                         html_cm(L - *map.cop_hand_from_butt_m));
  if (map.node_free_from_butt_m)
    lines += fmt::format(
        "{}the dashed line the node of the free frame's fundamental, {} cm from "
        "the tip",
        lines.empty() ? "" : "; ", html_cm(L - *map.node_free_from_butt_m));
  if (lines.empty()) lines = "neither the COP nor the node falls on the string bed";
  return lines;
}

// What the map of `q` shows, for its caption.
std::string map_caption(const studies::StringBedMap& map, MapQuantity q, double L) {
  switch (q) {
    case MapQuantity::kPower: {
      // The point of most power on the bed, which the power caption names.
      studies::StringBedMapPoint best_power;
      best_power.apparent_cor = -1.0;
      for (const studies::StringBedMapPoint& p : map.points) {
        if (p.on_bed && p.apparent_cor > best_power.apparent_cor) best_power = p;
      }
      return fmt::format(
          "{}, highest {} cm from the tip ({:.2f}){}",
          map.fidelity == Fidelity::kCollision
              ? "Power: how fast the ball comes back from the solved collision of ball, "
                "strings and flexible frame (with the twist about the long axis)"
              : "Power: how fast the ball comes back (the apparent COR, Eq. 16 at the frame's "
                "given COR, with the twist about the long axis)",
          html_cm(L - best_power.from_butt_m), best_power.apparent_cor,
          map.fidelity == Fidelity::kCollision
              ? ""
              : "; the frame's vibration losses are in its COR, not in the map, so the "
                "highest lies towards the throat");
    }
    case MapQuantity::kShock:
      return "Shock: the peak force on the wrist, least along the hand-held COP";
    case MapQuantity::kFeel:
      return "Feel: the vibration energy the hit leaves in the frame, least near the node";
  }
  return "";
}

// The maps' figures, one per quantity, each its SVG (or why not) and caption.
std::string map_figures_html(const studies::StringBedMap& map, double L,
                             std::span<const io::RenderedSvg> svgs) {
  const std::string lines = map_lines_text(map, L);
  std::string html = "<div class=\"maps\">\n";
  const std::vector<MapQuantity> quantities = map_quantities(map);
  for (std::size_t k = 0; k < quantities.size(); ++k) {
    const MapQuantity q = quantities[k];
    const io::RenderedSvg& svg = svgs[k];
    html += fmt::format(
        "<figure id=\"map-{}\">{}<figcaption>{}; {}.</figcaption></figure>\n", map_quantity_name(q),
        svg.svg ? *svg.svg : "<p class=\"missing\">Map not drawn: " + html_escape(svg.why) + "</p>",
        map_caption(map, q, L), lines);
  }
  return html + "</div>\n";
}

// The numbers behind the maps: every kMapTableStep-th grid point on the bed.
std::string map_numbers_html(const studies::StringBedMap& map, double L) {
  const bool feel = map.fidelity != Fidelity::kRigid;
  std::string html;
  if (!feel) {
    html +=
        "<p>No feel map: the vibration a hit excites needs the frame's stiffness; give "
        "<code>frame.fundamental_free_Hz</code> (or <code>frame.RA</code>, or "
        "<code>frame.EI_N_m2</code>).</p>\n";
  }
  html += fmt::format(
      "<details><summary>The numbers behind these maps</summary><p>Every {}th grid point along "
      "and across, from the {}rd, where it is on the strings (the CSV of <code>sweetspot map"
      "</code> has them all).</p><div class=\"table-wrap\"><table id=\"map-numbers\"><thead>"
      "<tr><th class=\"num\">from the tip (cm)</th><th class=\"num\">off the axis (cm)</th>"
      "<th class=\"num\">apparent COR</th><th class=\"num\">peak wrist force (N)</th>{}</tr>"
      "</thead><tbody>\n",
      kMapTableStep, kMapTableFirst + 1, feel ? "<th class=\"num\">vibration energy (J)</th>" : "");
  for (int j = kMapTableFirst; j < map.rows; j += kMapTableStep) {
    for (int i = kMapTableFirst; i < map.columns; i += kMapTableStep) {
      const studies::StringBedMapPoint& p =
          map.points[static_cast<std::size_t>(j) * map.columns + i];
      if (!p.on_bed) continue;
      html += fmt::format(
          "<tr><td class=\"num\">{:.1f}</td><td class=\"num\">{:.1f}</td><td class=\"num\">"
          "{:.3f}</td><td class=\"num\">{:.0f}</td>",
          (L - p.from_butt_m) * 100.0, p.off_axis_m * 100.0, p.apparent_cor, p.peak_wrist_force_N);
      if (feel)
        html += "<td class=\"num\">" +
                (p.vibration_energy_J ? io::significant(*p.vibration_energy_J, 3) : "—") + "</td>";
      html += "</tr>\n";
    }
  }
  return html + "</tbody></table></div></details>\n";
}

// The string-bed maps (power, shock and, with the frame's stiffness, feel):
// gnuplot's heat maps as inline SVG (`svgs`, as drawn from map_svg_plots()),
// a caption each, the numbers behind them. Without a head size the drawing's
// mid-size head is assumed, and said.
std::string maps_html(const io::DesignFile& file, const studies::PageMaps& maps,
                      std::span<const io::RenderedSvg> svgs) {
  if (!maps.racquet) return "";
  const double L = file.design.implement.length_m();
  std::string html = "<section id=\"maps\"><h2>Over the string bed</h2>\n<!-- sweetspot:maps -->\n";
  if (!maps.map) {
    return html + "<p class=\"missing\">No maps for this design: " + html_escape(maps.refused) +
           "</p>\n</section>\n";
  }
  const studies::StringBedMap& map = *maps.map;
  html += fmt::format(
      "<p>The head seen from the front, tip up, for a hit anywhere on the strings ({} by {} "
      "points over the bed's ellipse{}). Warm colours are more of what each map shows.</p>\n",
      map.columns, map.rows,
      maps.head_assumed
          ? ": the head's size is not given, so a 100 sq in head is assumed, as in the drawing; "
            "give <code>implement.headsize_sq_in</code> for yours"
          : "");
  html += map_figures_html(map, L, svgs);
  return html + map_numbers_html(map, L) + "</section>\n";
}

}  // namespace

double drawn_head_area_m2(const io::DesignFile& file) { return racquet_head(file.design).area_m2; }

std::string racquet_top_svg(const io::DesignFile& file, const Evaluation& e, double head_area_m2,
                            const std::string& id) {
  const double L = file.design.implement.length_m() * 100.0;
  // The head's string bed: an ellipse of the head's area, a = kHeadAspect b,
  // no longer than half the implement.
  const double area_cm2 = std::max(head_area_m2, 0.0) * 1e4;
  double a = std::sqrt(4.0 * area_cm2 * kHeadAspect / M_PI);
  a = std::min(a, 0.5 * L);
  const double b = a > 0 ? 4.0 * area_cm2 / (M_PI * a) : 0.0;
  const double head_cx = kRim_cm + a / 2;
  const double head_end = kRim_cm + a;
  const double throat_end = std::min(head_end + kThroat_cm, L * 0.75);
  const double half = b / 2 + kRim_cm;
  std::vector<Mark> ms = marks(file, e, 0.0);
  tape_marks(file, ms);
  const double impact = L - file.design.impact_from_butt_m * 100.0;
  ms.push_back({impact, "impact", ""});
  // Room above the head for a few rows of labels, below for the ruler.
  const double top = -half - 13.0;
  const double bottom = half + 8.0;
  std::string svg = fmt::format(
      "<svg class=\"drawing\" viewBox=\"-2 {0} {1} {2}\" role=\"img\" "
      "aria-labelledby=\"{3}-title\" "
      "xmlns=\"http://www.w3.org/2000/svg\"><title id=\"{3}-title\">{4} from above, to "
      "scale</title>\n",
      n(top), n(L + 4), n(bottom - top), html_escape(id),
      id == "top" ? std::string("The racquet") : html_escape(file.name));
  // Shaft and throat, then the head over them.
  svg += fmt::format(
      "<rect class=\"shaft\" x=\"{0}\" y=\"{1}\" width=\"{2}\" height=\"{3}\" rx=\"0.6\"/>\n"
      "<path class=\"frame\" d=\"M{4} {5} Q{6} {7} {0} {8} M{4} {9} Q{6} {10} {0} {11}\"/>\n",
      n(throat_end), n(-kHandleWidth_cm / 2), n(L - throat_end), n(kHandleWidth_cm),
      n(head_end - a * 0.12), n(-b * 0.42), n((head_end + throat_end) / 2), n(-b * 0.12),
      n(-kHandleWidth_cm / 2 + 0.3), n(b * 0.42), n(b * 0.12), n(kHandleWidth_cm / 2 - 0.3));
  svg += fmt::format(
      "<ellipse class=\"bed\" cx=\"{0}\" cy=\"0\" rx=\"{1}\" ry=\"{2}\"/>"
      "<ellipse class=\"frame\" cx=\"{0}\" cy=\"0\" rx=\"{3}\" ry=\"{4}\"/>\n",
      n(head_cx), n(a / 2), n(b / 2), n(a / 2 + kRim_cm / 2), n(b / 2 + kRim_cm / 2));
  svg += hand_and_tape(file, half, false);
  // Off the axis towards 3 o'clock is up in this view (the face seen with the
  // tip on the left); a hit on the axis is drawn and titled as before.
  const double off_cm = file.design.impact_off_axis_m * 100.0;
  const double ball_cm = file.design.ball.diameter_m * 100.0;  // the file's ball, to scale
  svg += fmt::format(
      "<circle class=\"ball\" cx=\"{}\" cy=\"{}\" r=\"{}\"><title>the ball at the impact, {} cm "
      "from the tip{}</title></circle>\n",
      n(impact), n(off_cm == 0.0 ? 0.0 : -off_cm), n(ball_cm / 2), n(impact),
      off_cm == 0.0 ? std::string()
                    : fmt::format(", {} cm off the axis toward {} o'clock", n(std::fabs(off_cm)),
                                  off_cm > 0 ? 3 : 9));
  for (const Mark& m : marks(file, e, 0.0)) svg += m.symbol + "\n";
  svg += labels(ms, 0.0, top + 1.8);
  svg += ruler(L, half + 1.5);
  return svg + "</svg>\n";
}

namespace {

// A drawing from the side, to scale: `body` (the implement's outline,
// `half` cm either side of the axis), the hand, the tape, the ball arriving
// on the face (from above in this view), the marks and the ruler.
std::string side_view_svg(const io::DesignFile& file, const Evaluation& e, double half,
                          const std::string& title_html, const std::string& body,
                          const std::string& id = "side") {
  const double L = file.design.implement.length_m() * 100.0;
  std::vector<Mark> ms = marks(file, e, 0.0);
  tape_marks(file, ms);
  const double impact = L - file.design.impact_from_butt_m * 100.0;
  ms.push_back({impact, "impact", ""});
  const double ball_cm = file.design.ball.diameter_m * 100.0;  // the file's ball, to scale
  const double top = -half - ball_cm - 12.0;
  const double bottom = half + 9.0;
  std::string svg = fmt::format(
      "<svg class=\"drawing\" viewBox=\"-2 {0} {1} {2}\" role=\"img\" "
      "aria-labelledby=\"{4}-title\" xmlns=\"http://www.w3.org/2000/svg\"><title "
      "id=\"{4}-title\">{3} from the side, to scale</title>\n",
      n(top), n(L + 4), n(bottom - top), title_html, html_escape(id));
  svg += body;
  svg += hand_and_tape(file, half, true);
  svg += fmt::format(
      "<circle class=\"ball\" cx=\"{}\" cy=\"{}\" r=\"{}\"><title>the ball at the impact</title>"
      "</circle>\n",
      n(impact), n(-half - ball_cm / 2), n(ball_cm / 2));
  for (const Mark& m : marks(file, e, 0.0)) svg += m.symbol + "\n";
  svg += labels(ms, 0.0, top + 1.8);
  svg += ruler(L, half + 3.0);
  return svg + "</svg>\n";
}

}  // namespace

std::string racquet_side_svg(const io::DesignFile& file, const Evaluation& e) {
  const double L = file.design.implement.length_m() * 100.0;
  return side_view_svg(
      file, e, kBeamDepth_cm / 2, "The racquet",
      fmt::format(
          "<rect class=\"shaft\" x=\"0\" y=\"{}\" width=\"{}\" height=\"{}\" rx=\"0.8\"/>\n",
          n(-kBeamDepth_cm / 2), n(L), n(kBeamDepth_cm)));
}

// An implement that is not a racquet (the paper's beam, a bat) from the
// side, to scale along its length: its outline from its sections. An
// implement given by its profile is drawn at the profile's outer diameter,
// a hollow one too (a tube seen from the side); otherwise the widths follow
// the square root of the mass per length, the widest kBeamDepth_cm.
std::string implement_side_svg(const io::DesignFile& file, const Evaluation& e,
                               const std::string& id) {
  const Implement& implement = file.design.implement;
  const std::optional<RoundProfile>& profile = implement.profile();
  const double L = implement.length_m() * 100.0;
  double widest_mu = 0.0;
  for (const Section& s : implement.sections())
    widest_mu = std::max(widest_mu, s.mass_kg / s.length_m);
  // A section's width, its middle `middle_m` from the butt.
  const auto width_cm = [&](const Section& s, double middle_m) {
    if (profile) return 100.0 * profile_diameter_m(*profile, middle_m);
    const double mu = s.mass_kg / s.length_m;
    return widest_mu > 0.0 ? kBeamDepth_cm * std::sqrt(mu / widest_mu) : kBeamDepth_cm;
  };
  std::string outline;  // the top edge tip to butt, then the bottom edge back
  std::string lower;
  double half = 0.0;
  double from_butt = L;
  const std::vector<Section>& sections = implement.sections();
  for (auto s = sections.rbegin(); s != sections.rend(); ++s) {
    const double x0 = L - from_butt, x1 = x0 + s->length_m * 100.0;
    const double w = width_cm(*s, (from_butt - 50.0 * s->length_m) / 100.0) / 2;
    half = std::max(half, w);
    outline +=
        fmt::format("{}{} {} L{} {} ", outline.empty() ? "M" : "L", n(x0), n(-w), n(x1), n(-w));
    lower = fmt::format("L{} {} L{} {} ", n(x1), n(w), n(x0), n(w)) + lower;
    from_butt -= s->length_m * 100.0;
  }
  return side_view_svg(file, e, half, html_escape(file.name),
                       fmt::format("<path class=\"shaft\" d=\"{}{}Z\"/>\n", outline, lower), id);
}

std::string racquets_to_scale_html(const std::vector<DrawnRacquet>& racquets,
                                   const std::string& id) {
  double longest_cm = 0.0;
  for (const DrawnRacquet& r : racquets)
    longest_cm = std::max(longest_cm, r.file->design.implement.length_m() * 100.0);
  // A racquet from above; an implement that is none (a bat) from the side, as
  // its own page draws it, a profile at its own diameters.
  const auto drawing = [](const DrawnRacquet& r, const std::string& drawing_id) {
    const io::DesignFile& file = *r.file;
    if (!studies::is_racquet(file) && file.design.implement.has_mass_distribution()) {
      return implement_side_svg(file, *r.evaluation, drawing_id);
    }
    return racquet_top_svg(file, *r.evaluation, drawn_head_area_m2(file), html_escape(drawing_id));
  };
  std::string html;
  for (std::size_t k = 0; k < racquets.size(); ++k) {
    const DrawnRacquet& r = racquets[k];
    const double L_cm = r.file->design.implement.length_m() * 100.0;
    // The viewBox is the length plus 4 cm wide: the same fraction of the
    // longest's keeps every drawing at one scale.
    html += fmt::format(
        "<figure class=\"drawing-figure\" id=\"{0}-{1}\"><div style=\"width: {2:.2f}%\">{3}</div>"
        "<figcaption>{4}</figcaption></figure>\n",
        html_escape(id), k + 1, 100.0 * (L_cm + 4.0) / (longest_cm + 4.0),
        drawing(r, fmt::format("{}-{}", id, k + 1)), r.caption_html);
  }
  // The numbers behind the drawings: where each marker sits, from the tip.
  html += fmt::format(
      "<div class=\"table-wrap\"><table id=\"{}-positions\"><thead><tr><th>from the tip (cm)</th>",
      html_escape(id));
  for (const DrawnRacquet& r : racquets)
    html += "<th class=\"num\">" + html_escape(r.file->name) + "</th>";
  html += "</tr></thead><tbody>\n";
  const auto row = [&](const char* key, const char* what,
                       const std::function<std::string(const DrawnRacquet&)>& cell) {
    std::string cells;
    bool any = false;
    for (const DrawnRacquet& r : racquets) {
      const std::string c = cell(r);
      any = any || !c.empty();
      cells += "<td class=\"num\">" + (c.empty() ? std::string("—") : c) + "</td>";
    }
    if (any) html += fmt::format("<tr id=\"{}-{}\"><td>{}</td>{}</tr>\n", id, key, what, cells);
  };
  const auto from_tip = [](const DrawnRacquet& r, double from_butt_m) {
    return html_cm(r.file->design.implement.length_m() - from_butt_m);
  };
  row("length", "length",
      [](const DrawnRacquet& r) { return html_cm(r.file->design.implement.length_m()); });
  row("balance", "balance point",
      [&](const DrawnRacquet& r) { return from_tip(r, r.evaluation->balance_from_butt_m); });
  row("cop", "hand-held COP", [&](const DrawnRacquet& r) {
    return r.evaluation->cop_hand_from_butt_m ? from_tip(r, *r.evaluation->cop_hand_from_butt_m)
                                              : std::string();
  });
  row("node", "node, held", [&](const DrawnRacquet& r) {
    return r.evaluation->modal && r.evaluation->modal->node_hand_from_butt_m
               ? from_tip(r, *r.evaluation->modal->node_hand_from_butt_m)
               : std::string();
  });
  row("impact", "impact",
      [&](const DrawnRacquet& r) { return from_tip(r, r.file->design.impact_from_butt_m); });
  row("lead", "lead (g at cm)", [&](const DrawnRacquet& r) {
    std::string cell;
    for (const PointMass& p : r.file->design.implement.point_masses())
      cell += fmt::format("{}{:.1f} g at {}", cell.empty() ? "" : "<br/>", p.mass_kg * 1000.0,
                          from_tip(r, p.from_butt_m));
    return cell;
  });
  return html + "</tbody></table></div>\n";
}

namespace {

// The file's own description, for the page's head.
std::string description_of(const io::Json& document) {
  return document.is_object() && document.contains("description") &&
                 document["description"].is_string()
             ? document["description"].get<std::string>()
             : std::string();
}

// The numbers behind the drawing: each marker from the tip and the butt.
std::string positions_table_html(const io::DesignFile& file, const Evaluation& e) {
  const Design& d = file.design;
  const double L = d.implement.length_m();
  std::string html =
      "<div class=\"table-wrap\"><table id=\"positions\"><thead><tr><th>where</th>"
      "<th class=\"num\">from the tip (cm)</th><th class=\"num\">from the butt (cm)</th>"
      "</tr></thead><tbody>\n";
  const auto row = [&](const char* id, const std::string& what, double from_butt_m,
                       const std::string& means) {
    html += fmt::format(
        "<tr id=\"pos-{}\"><td>{}<div class=\"means\">{}</div></td><td class=\"num\">{}</td>"
        "<td class=\"num\">{}</td></tr>\n",
        id, what, means, html_cm(L - from_butt_m), html_cm(from_butt_m));
  };
  row("balance", "balance point", e.balance_from_butt_m, "the centre of mass");
  if (e.cop_hand_from_butt_m)
    row("cop", "hand-held COP", *e.cop_hand_from_butt_m,
        "a hit here gives the wrist no jolt (Cross 2004, Eq. 13)");
  if (e.cop_free_from_butt_m)
    row("cop-free", "free COP", *e.cop_free_from_butt_m,
        fmt::format("the COP about the handle end of the {} when free (Eq. 5)",
                    studies::is_racquet(file) ? "racquet" : "implement"));
  if (e.modal && e.modal->node_hand_from_butt_m)
    row("node", "node, held", *e.modal->node_hand_from_butt_m,
        "a hit here excites the least vibration");
  row("impact", "impact", d.impact_from_butt_m, "the hit this report is about");
  if (d.hand.mass_kg > 0)
    row("hand", "hand centre", d.hand.center_from_butt_m, "where the hand holds");
  for (std::size_t i = 0; i < d.implement.point_masses().size(); ++i) {
    const PointMass& p = d.implement.point_masses()[i];
    row(fmt::format("lead{}", i + 1).c_str(), fmt::format("lead, {:.1f} g", p.mass_kg * 1000.0),
        p.from_butt_m, "added mass (tape)");
  }
  return html + "</tbody></table></div>\n";
}

// The racquet drawn to scale from above and from the side, and the numbers
// behind the drawing.
std::string racquet_html(const io::DesignFile& file, const Evaluation& e) {
  if (!studies::is_racquet(file) && file.design.implement.has_mass_distribution()) {
    const bool round = is_round(file.design);
    std::string html = "<section id=\"racquet\"><h2>The implement, to scale</h2>\n";
    html += "<figure class=\"drawing-figure\">" + implement_side_svg(file, e) +
            fmt::format(
                "<figcaption>From the side, the ball arriving from above. {}</figcaption>"
                "</figure>\n",
                round ? "The outline is the profile's diameter along its length."
                      : "Each section's width follows the square root of its mass per "
                        "length (its diameter, were it round and of one material); the "
                        "widths are a sketch, the positions are computed.");
    html += positions_table_html(file, e);
    // A bat's spec sheet (io/format.hpp), or the paper's swingweight axis.
    if (is_round(file.design)) {
      return html + fmt::format(
                        "<p>Length {} cm ({:.1f} in), mass {:.0f} g ({:.1f} oz), moment of "
                        "inertia {:.0f} kg·cm² about a pivot 6 in (15.24 cm) from the knob (the "
                        "bat standards' ASTM F2398).</p>\n</section>\n",
                        html_cm(file.design.implement.length_m()),
                        file.design.implement.length_m() / io::kInch_m, e.mass_kg * 1000.0,
                        e.mass_kg / io::kOunce_kg, io::bat_pivot_inertia_kg_m2(e) * 1e4);
    }
    return html + fmt::format(
                      "<p>Length {} cm, mass {:.0f} g, inertia about the axis 10 cm from the butt "
                      "{:.0f} kg·cm².</p>\n</section>\n",
                      html_cm(file.design.implement.length_m()), e.mass_kg * 1000.0,
                      e.swingweight_kg_m2 * 1e4);
  }
  const double head_area = drawn_head_area_m2(file);
  const bool head_given = file.design.head.has_value();
  // In the unit the file gave it (headsize_cm2, head_size_cm2), else in sq in.
  const auto head_key = file.keys.find("implement/headsize");
  const bool in_cm2 =
      head_given && head_key != file.keys.end() && head_key->second.pointer.ends_with("cm2");
  std::string html = "<section id=\"racquet\"><h2>The racquet, to scale</h2>\n";
  html += "<figure class=\"drawing-figure\">" + racquet_top_svg(file, e, head_area) +
          fmt::format(
              "<figcaption>From above. The head is drawn as an ellipse of {}{}; "
              "the outline is a sketch, the positions are computed.</figcaption></figure>\n",
              in_cm2 ? fmt::format("{:.0f} cm²", head_area * 1e4)
                     : fmt::format("{:.0f} sq in", head_area / io::kSquareInch_m2),
              head_given ? " (as given)" : " (not given: a mid-size head assumed)");
  html += "<figure class=\"drawing-figure\">" + racquet_side_svg(file, e) +
          "<figcaption>From the side, the ball arriving on the strings.</figcaption></figure>\n";
  html += positions_table_html(file, e);
  return html + fmt::format(
                    "<p>Length {} cm, mass {:.0f} g, swingweight {:.0f} kg·cm².</p>\n"
                    "</section>\n",
                    html_cm(file.design.implement.length_m()), e.mass_kg * 1000.0,
                    e.swingweight_kg_m2 * 1e4);
}

// The two plots along the frame: what the wrist feels and how the ball comes back.
struct FramePlots {
  io::Plot wrist, cor;
};

FramePlots frame_plots(const io::DesignFile& file, const Evaluation& e,
                       const std::vector<studies::FramePoint>& curve, studies::AxisSpan span) {
  const Design& d = file.design;
  const double L = d.implement.length_m();
  io::PlotSeries wrist{"wrist force / impact force, |F_w / F|", {}, {}, "lines lw 2.5"};
  io::PlotSeries cor{"apparent COR e_A", {}, {}, "lines lw 2.5"};
  cor.color = io::plot_color(1);
  for (const studies::FramePoint& p : curve) {
    wrist.x.push_back(p.from_tip_m * 100.0);
    wrist.y.push_back(std::abs(p.wrist_force_ratio));
    cor.x.push_back(p.from_tip_m * 100.0);
    cor.y.push_back(p.apparent_cor);
  }
  // The lines that fall where the curves run (a COP in the throat is off the strings).
  std::vector<std::pair<double, std::string>> lines;
  const auto line = [&](double from_butt_m, const char* what) {
    const double from_tip = L - from_butt_m;
    if (from_tip >= span.from_tip_m && from_tip <= span.to_tip_m)
      lines.push_back({from_tip * 100.0, what});
  };
  if (e.cop_hand_from_butt_m) line(*e.cop_hand_from_butt_m, "COP");
  if (e.modal && e.modal->node_hand_from_butt_m) line(*e.modal->node_hand_from_butt_m, "node");
  line(d.impact_from_butt_m, "impact");
  const char* along = span.string_bed ? "for a hit along the strings" : "for a hit along the frame";
  const std::pair range{span.from_tip_m * 100.0, span.to_tip_m * 100.0};
  FramePlots plots{io::Plot{fmt::format("What the wrist feels, {}", along),
                            "impact point from the tip (cm)",
                            span.string_bed ? "wrist force over the force on the strings"
                                            : "wrist force over the force of the impact",
                            range,
                            std::nullopt,
                            {wrist},
                            {},
                            lines},
                   io::Plot{fmt::format("How the ball comes back, {}", along),
                            "impact point from the tip (cm)",
                            "apparent COR (rebound over incoming speed)",
                            range,
                            std::nullopt,
                            {cor},
                            {},
                            lines}};
  plots.wrist.key_position = "off";
  plots.cor.key_position = "off";
  return plots;
}

// The curves along the frame (`svgs`: the wrist's plot wide and narrow, then
// the COR's) and the numbers behind them.
std::string frame_html(const Evaluation& e, const std::vector<studies::FramePoint>& curve,
                       studies::AxisSpan span, std::span<const io::RenderedSvg> svgs) {
  std::string html = fmt::format(
      "<section id=\"frame\"><h2>Along the {}</h2>\n{}", span.string_bed ? "strings" : "frame",
      span.string_bed
          ? fmt::format("<p>For a hit on the long axis of the string bed, {} to {} cm from the "
                        "tip, where a ball can land.</p>\n",
                        html_cm(span.from_tip_m), html_cm(span.to_tip_m))
          : std::string());
  // Zero at the hand-held COP: said where the curve shows it, else where it lies.
  std::string zero = "no hand-held COP on the implement, so never zero";
  if (e.cop_hand_from_butt_m) {
    const double cop_from_tip = e.length_m - *e.cop_hand_from_butt_m;
    zero = cop_from_tip >= span.from_tip_m && cop_from_tip <= span.to_tip_m
               ? fmt::format("zero at the hand-held COP, {} cm from the tip", html_cm(cop_from_tip))
               : fmt::format("zero only at the hand-held COP, {} cm from the tip, off the {}",
                             html_cm(cop_from_tip), span.string_bed ? "strings" : "frame");
  }
  html += html_figure(svgs[0], svgs[1], "plot-wrist",
                      fmt::format("The share of the force {} that reaches the wrist (Cross 2004, "
                                  "Eq. 11), rigid model: {}.",
                                  span.string_bed ? "on the strings" : "of the impact", zero));
  const auto most = std::max_element(
      curve.begin(), curve.end(), [](const studies::FramePoint& a, const studies::FramePoint& b) {
        return a.apparent_cor < b.apparent_cor;
      });
  html += html_figure(
      svgs[2], svgs[3], "plot-cor",
      most == curve.end()
          ? std::string("The apparent COR.")
          : fmt::format("{}, highest {} cm from the tip ({:.2f}).",
                        fidelity_of(e) == Fidelity::kCollision
                            ? "The ball's rebound over its speed from the solved collision of "
                              "ball, strings and flexible frame at each point"
                        : e.cor_derived
                            ? "The apparent COR (Eq. 16) at the COR derived at each point from "
                              "the rigid frame's and the vibration the impact leaves there"
                            : "The apparent COR (Eq. 16) at the frame's COR",
                        html_cm(most->from_tip_m), most->apparent_cor));
  html +=
      "<details><summary>The numbers behind these curves</summary><div class=\"table-wrap\">"
      "<table id=\"curve\"><thead><tr><th class=\"num\">impact from the tip (cm)</th>"
      "<th class=\"num\">|F_w / F|</th><th class=\"num\">wrist force (N)</th>"
      "<th class=\"num\">apparent COR</th></tr></thead><tbody>\n";
  for (const studies::FramePoint& p : curve) {
    html += fmt::format(
        "<tr><td class=\"num\">{}</td><td class=\"num\">{:.3f}</td><td class=\"num\">{:.0f}</td>"
        "<td class=\"num\">{:.3f}</td></tr>\n",
        html_cm(p.from_tip_m), std::abs(p.wrist_force_ratio), p.peak_wrist_force_N, p.apparent_cor);
  }
  return html + "</tbody></table></div></details>\n</section>\n";
}

// Every output, in people's units (but the string bed's on a bat, `strung`
// false: io::can_be_strung()).
std::string outputs_html(const Evaluation& e, bool strung) {
  std::string html =
      "<section id=\"outputs\"><h2>Every number</h2>\n<div class=\"table-wrap\"><table "
      "id=\"all-outputs\"><thead><tr><th>quantity</th><th class=\"num\">value</th><th>unit</th>"
      "<th>output</th></tr></thead><tbody>\n";
  for (const io::OutputSpec& o : io::output_specs()) {
    const auto value = o.value(e);
    if (!strung && !value && io::of_the_string_bed(o)) continue;
    const io::AxisQuantity axis = output_axis(o);
    const std::size_t open = axis.label.rfind(" (");
    const std::string words = open == std::string::npos ? axis.label : axis.label.substr(0, open);
    const std::string unit =
        open == std::string::npos ? "" : axis.label.substr(open + 2, axis.label.size() - open - 3);
    html += fmt::format(
        "<tr id=\"out-{}\"><td>{}</td><td class=\"num\">{}</td><td>{}</td><td><code>{}</code>"
        "</td></tr>\n",
        o.name, html_escape(words), value ? io::significant(*value * axis.factor, 4) : "—",
        html_escape(unit), o.name);
  }
  return html + "</tbody></table></div></section>\n";
}

// The inputs as the file gave them, then the defaults the model filled in.
std::string inputs_html(const io::DesignFile& file, const io::Json& document, const Evaluation& e) {
  std::string given;
  flatten(document, "", given);
  std::string html =
      "<section id=\"inputs\"><h2>The inputs</h2>\n<p>As the file gives them, in its units:</p>\n"
      "<div class=\"table-wrap\"><table id=\"inputs-given\"><thead><tr><th>input</th>"
      "<th class=\"num\">value</th><th>unit</th></tr></thead><tbody>\n" +
      given + "</tbody></table></div>\n";
  const io::Json inputs = evaluation_json(file, e)["inputs"];
  std::string defaults;
  for (auto it = inputs.begin(); it != inputs.end(); ++it) {
    if (!it.value().is_object() || it.value().value("provenance", "") != "default") continue;
    defaults +=
        fmt::format("<tr><td><code>{}</code></td><td class=\"num\">{}</td><td>{}</td></tr>\n",
                    html_escape(it.key()), io::significant(it.value()["value"].get<double>(), 4),
                    html_escape(it.value().value("unit", "")));
  }
  if (!defaults.empty()) {
    html +=
        "<p>Not in the file, so the model's defaults (the paper's player and ball):</p>\n"
        "<div class=\"table-wrap\"><table id=\"inputs-default\"><thead><tr><th>input</th>"
        "<th class=\"num\">value</th><th>unit</th></tr></thead><tbody>\n" +
        defaults + "</tbody></table></div>\n";
  }
  return html + "</section>\n";
}

}  // namespace

std::string design_html_report(const io::DesignFile& file, const io::Json& document,
                               const studies::DesignPage& page) {
  const Evaluation& e = page.evaluation;
  std::string html = html_page_open(file.name, description_of(document));
  html += "<section id=\"answer\"><h2>The answer</h2>\n<div class=\"answer\">\n" +
          answer_html(file, page.spots) + "</div></section>\n";
  html += racquet_html(file, e);
  // Every plot of the page drawn by one gnuplot: the two curves, each wide
  // and narrow, then the maps over the string bed.
  const FramePlots frame = frame_plots(file, e, page.curve, page.span);
  std::vector<io::SvgPlot> plots = figure_svg_plots(frame.wrist, "plot-wrist");
  for (io::SvgPlot& p : figure_svg_plots(frame.cor, "plot-cor")) plots.push_back(std::move(p));
  for (io::SvgPlot& p : map_svg_plots(page.maps, file.design.implement.length_m()))
    plots.push_back(std::move(p));
  const std::vector<io::RenderedSvg> svgs = io::render_svgs(plots);
  html += frame_html(e, page.curve, page.span, std::span(svgs).first(4));
  html += maps_html(file, page.maps, std::span(svgs).subspan(4));
  html += outputs_html(e, io::can_be_strung(file.design));
  html += inputs_html(file, document, e);
  return html + html_page_close(fmt::format(
                    "Computed by sweetspot ({} model) from <code>{}</code>, after R. Cross, "
                    "\"Center of percussion of hand-held implements\", Am. J. Phys. 72 (2004). "
                    "Positions are measured from the tip of the {}.",
                    to_string(fidelity_of(e)), html_escape(file.source),
                    studies::is_racquet(file) ? "racquet" : "implement"));
}

}  // namespace sweetspot::reports
