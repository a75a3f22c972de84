#include "reports/html_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "io/design_reader.hpp"
#include "reports/comparison.hpp"
#include "reports/optimization_report.hpp"
#include "studies/comparison.hpp"
#include "studies/design_page.hpp"
#include "studies/optimization.hpp"
#include "studies/string_bed_map.hpp"
#include "studies/study.hpp"
#include "studies/sweet_spots.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot::reports {
namespace {

io::DesignFile tour_100() {
  return io::load_design(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100.json");
}

std::size_t count(const std::string& text, const std::string& piece) {
  std::size_t n = 0;
  for (auto at = text.find(piece); at != std::string::npos; at = text.find(piece, at + 1)) ++n;
  return n;
}

TEST_CASE("Every user string is escaped: markup in a racquet's name is shown, never run") {
  CHECK(reports::html_escape("<script>alert('x')</script> & \"Pro\"") ==
        "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;Pro&quot;");
  // Characters XML 1.0 does not allow (and HTML's controls) are U+FFFD, shown, not dropped.
  CHECK(reports::html_escape(std::string("a\x01"
                                         "b\x7f"
                                         "c\td\n",
                                         8)) == "a\uFFFDb\uFFFDc\td\n");
  CHECK(reports::html_escape("\xef\xbf\xbe<\xef\xbf\xbf") == "\uFFFD&lt;\uFFFD");
  io::Json document = io::read_json_file(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100.json");
  document["name"] = "<img src=x onerror=alert(1)> & Co";
  document["description"] = "</style><script>x()</script>";
  const io::DesignFile file = io::read_design(document, "<b>file</b>.json");
  const std::string page = reports::design_html_report(file, document, studies::design_page(file));
  CHECK(page.find("<img") == std::string::npos);
  CHECK(page.find("<script") == std::string::npos);
  CHECK(page.find("<b>file</b>") == std::string::npos);
  CHECK(page.find("&lt;img src=x onerror=alert(1)&gt; &amp; Co") != std::string::npos);
  CHECK(count(page, "</style>") == 1);
}

TEST_CASE("The page is self-contained: nothing fetched, no script, one stylesheet inline") {
  const io::DesignFile file = tour_100();
  const std::string page = reports::design_html_report(
      file, io::read_json_file(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100.json"),
      studies::design_page(file));
  CHECK(page.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(page.find("http://") == page.find("http://www.w3.org"));  // only SVG's namespaces
  CHECK(page.find("https://") == std::string::npos);
  CHECK(page.find("<link") == std::string::npos);
  CHECK(page.find("@import") == std::string::npos);
  CHECK(page.find("<script") == std::string::npos);
  CHECK(page.find("name=\"viewport\"") != std::string::npos);
  CHECK(page.find("@media (max-width") != std::string::npos);
  CHECK(page.find("<!-- sweetspot:maps -->") != std::string::npos);
}

TEST_CASE("The drawing is to scale: the racquet's length and each marker where the model puts it") {
  const io::DesignFile file = tour_100();
  const Evaluation e = evaluate(file.design);
  const double L_cm = file.design.implement.length_m() * 100.0;
  const std::string top = reports::racquet_top_svg(file, e, 100 * 0.00064516);
  // The ruler runs the whole length, in centimetres from the tip.
  CHECK(top.find(fmt::format("x2=\"{:.2f}\"", L_cm)) != std::string::npos);
  REQUIRE(e.cop_hand_from_butt_m);
  CHECK(top.find(fmt::format("<circle class=\"cop\" cx=\"{:.2f}\"",
                             L_cm - *e.cop_hand_from_butt_m * 100.0)) != std::string::npos);
  CHECK(top.find(fmt::format("<path class=\"balance\" d=\"M{:.2f} ",
                             L_cm - e.balance_from_butt_m * 100.0)) != std::string::npos);
  // A head of 100 sq in drawn as an ellipse of that area: pi a b / 4 = 645.16 cm^2.
  const auto rx_at = top.find("<ellipse class=\"bed\"");
  REQUIRE(rx_at != std::string::npos);
  double cx = 0, rx = 0, ry = 0;
  REQUIRE(std::sscanf(top.c_str() + rx_at,
                      "<ellipse class=\"bed\" cx=\"%lf\" cy=\"0\" rx=\"%lf\" ry=\"%lf\"", &cx, &rx,
                      &ry) == 3);
  CHECK(M_PI * rx * ry == Approx(645.16).epsilon(1e-3));  // two decimals drawn
  CHECK(reports::drawn_head_area_m2(file) == Approx(100 * 0.00064516));
}

// One head, one size: the drawing, the map's grid and the twist take the
// head's size wherever the file gives it, the implement's or the string bed's.
TEST_CASE("The head drawn, mapped and twisted is the size the file gives, in either place") {
  io::Json implement_head =
      io::read_json_file(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100-strung.json");
  implement_head["strings"].erase("head_size_in2");
  implement_head["implement"]["headsize_sq_in"] = 98;
  io::Json bed_head = implement_head;
  bed_head["implement"].erase("headsize_sq_in");
  bed_head["strings"]["head_size_in2"] = 98;
  const io::DesignFile a = io::read_design(implement_head, "implement.json");
  const io::DesignFile b = io::read_design(bed_head, "strings.json");
  CHECK(reports::drawn_head_area_m2(a) == Approx(98 * 0.00064516).epsilon(1e-12));
  CHECK(reports::drawn_head_area_m2(b) == reports::drawn_head_area_m2(a));
  REQUIRE(polar_inertia_kg_m2(a.design));
  REQUIRE(polar_inertia_kg_m2(b.design));
  CHECK(*polar_inertia_kg_m2(b.design) == *polar_inertia_kg_m2(a.design));
  studies::StringBedMapOptions options;
  options.columns = 4;
  options.rows = 3;
  options.fidelity = Fidelity::kRigid;
  const studies::StringBedMap map_a = studies::string_bed_map(a.design, options);
  const studies::StringBedMap map_b = studies::string_bed_map(b.design, options);
  CHECK(map_b.bed.semi_length_m == map_a.bed.semi_length_m);
  CHECK(map_b.bed.center_from_butt_m == map_a.bed.center_from_butt_m);
  REQUIRE(map_b.points.size() == map_a.points.size());
  for (std::size_t i = 0; i < map_a.points.size(); ++i)
    CHECK(map_b.points[i].peak_wrist_force_N == map_a.points[i].peak_wrist_force_N);
  // No size anywhere: the strings' default bed, on which the map lays its grid
  // and the impact must land.
  io::Json no_size = bed_head;
  no_size["strings"].erase("head_size_in2");
  no_size["implement"]["twistweight_kg_cm2"] = 15;
  const io::DesignFile c = io::read_design(no_size, "none.json");
  const studies::StringBedMap map_c = studies::string_bed_map(c.design, options);
  const HeadEllipse bed = string_bed(racquet_head(c.design), c.design.implement.length_m());
  CHECK(map_c.bed.semi_length_m == bed.semi_length_m);
  CHECK(racquet_head(c.design).area_m2 ==
        Approx(M_PI * c.design.strings->head_radius_m * c.design.strings->head_radius_m));
}

TEST_CASE("The drawing's caption gives the head's size in the unit the file gave it") {
  io::Json document = io::read_json_file(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100.json");
  document["implement"]["headsize_sq_in"] = 98;
  const auto caption = [](const io::Json& json) {
    const io::DesignFile file = io::read_design(json, "d.json");
    const std::string page = reports::design_html_report(file, json, studies::design_page(file));
    const auto at = page.find("The head is drawn as an ellipse of ");
    REQUIRE(at != std::string::npos);
    return page.substr(at, page.find(';', at) - at);
  };
  CHECK(caption(document) == "The head is drawn as an ellipse of 98 sq in (as given)");
  document["implement"].erase("headsize_sq_in");
  document["implement"]["headsize_cm2"] = 632;
  CHECK(caption(document) == "The head is drawn as an ellipse of 632 cm² (as given)");
}

TEST_CASE("A bat's page draws no string bed and calls it neither a racquet nor strung") {
  // One design, one meaning: the page of an implement without head or strings
  // has no maps over a head it would have to invent.
  const io::Json json = io::read_json_file(SWEETSPOT_SOURCE_DIR "/designs/bats/wood-bat-34.json");
  const io::DesignFile file = io::read_design(json, "bat.json");
  REQUIRE_FALSE(studies::is_racquet(file));
  const studies::DesignPage page = studies::design_page(file);
  CHECK_FALSE(page.maps.racquet);
  CHECK_FALSE(page.maps.map);
  const std::string html = reports::design_html_report(file, json, page);
  CHECK(html.find("id=\"maps\"") == std::string::npos);
  CHECK(html.find("sq in") == std::string::npos);
  CHECK(html.find("racquet (Eq. 5)") == std::string::npos);
  CHECK(html.find("the implement when free (Eq. 5)") != std::string::npos);
  CHECK(html.find("force on the strings") == std::string::npos);
  CHECK(html.find("The share of the force of the impact that reaches the wrist") !=
        std::string::npos);
  CHECK(html.find("from the tip of the implement.") != std::string::npos);
  // Every number but the string bed's, which a bat cannot have.
  CHECK(html.find("id=\"out-string_bed_tension_N\"") == std::string::npos);
  CHECK(html.find("id=\"out-peak_string_deflection_m\"") == std::string::npos);
  CHECK(html.find("id=\"out-peak_wrist_force_N\"") != std::string::npos);
}

// A page that needs nothing but itself: no script, nothing fetched (the
// only URLs are SVG's namespaces), one inline stylesheet, a phone's viewport.
void check_self_contained(const std::string& page) {
  CHECK(page.rfind("<!DOCTYPE html>", 0) == 0);
  std::size_t from = 0;
  while ((from = page.find("http://", from)) != std::string::npos) {
    CHECK(page.compare(from, 18, "http://www.w3.org/") == 0);
    ++from;
  }
  CHECK(page.find("https://") == std::string::npos);
  CHECK(page.find("<link") == std::string::npos);
  CHECK(page.find("@import") == std::string::npos);
  CHECK(page.find("<script") == std::string::npos);
  CHECK(page.find(" src=") == std::string::npos);
  CHECK(count(page, "<style>") == 1);
  CHECK(page.find("name=\"viewport\"") != std::string::npos);
  CHECK(page.rfind("</html>\n") == page.size() - 8);
}

const std::string kHostile = "<script>alert(1)</script> & \"Pro\" <b>'98'</b>";
const std::string kHostileEscaped =
    "&lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;Pro&quot; &lt;b&gt;&#39;98&#39;&lt;/b&gt;";

TEST_CASE("A bat by its profile is drawn as its diameters, hollow or solid, not as a racquet") {
  // Two diameters, 3 cm for the handle and 6 cm for the barrel, a 4 cm taper between: the
  // outline's half-widths are 1.5 and 3 cm, read back from the drawn path. A shell (an
  // aluminium bat) looks from the side as wide as a solid bat of its diameters.
  for (const char* wall : {"", R"(, "wall_cm": 0.3)"}) {
    INFO("wall: " << wall);
    const io::Json document = io::parse_json(std::string(R"({"implement": {"profile": [
      {"from_butt_cm": 0, "diameter_cm": 3}, {"from_butt_cm": 40, "diameter_cm": 3},
      {"from_butt_cm": 44, "diameter_cm": 6}, {"from_butt_cm": 80, "diameter_cm": 6}],
      "density_kg_m3": 650, "youngs_modulus_GPa": 12)") +
                                                 wall + R"(}, "impact": {"from_tip_cm": 15}})",
                                             "bat.json");
    const io::DesignFile file = io::read_design(document, "bat.json");
    const Evaluation e = evaluate(file.design);
    const std::string svg = implement_side_svg(file, e);
    const auto at = svg.find("class=\"shaft\" d=\"");
    REQUIRE(at != std::string::npos);
    std::string path = svg.substr(at + 18, svg.find('"', at + 18) - at - 18);
    for (char& c : path) {
      if (c == 'M' || c == 'L' || c == 'Z') c = ' ';
    }
    std::istringstream in(path);
    double x = 0.0, y = 0.0, widest = 0.0, narrowest = 1e9;
    while (in >> x >> y) {
      widest = std::max(widest, std::abs(y));
      narrowest = std::min(narrowest, std::abs(y));
    }
    CHECK(widest == Approx(3.0).epsilon(1e-3));
    CHECK(narrowest == Approx(1.5).epsilon(1e-3));
    // The page draws the implement, not a head, and gives its inertia about
    // the bat standards' pivot: I_cm + M (B - 6 in)^2.
    const std::string page = design_html_report(file, document, studies::design_page(file));
    CHECK(page.find("The implement, to scale") != std::string::npos);
    CHECK(page.find("class=\"bed\"") == std::string::npos);
    const double arm = e.balance_from_butt_m - 6 * 0.0254;
    CHECK(page.find(fmt::format("moment of inertia {:.0f} kg·cm² about a pivot 6 in",
                                (e.I_cm_kg_m2 + e.mass_kg * arm * arm) * 1e4)) !=
          std::string::npos);
  }
}

TEST_CASE("Backticked names become code, everything else in a sentence is escaped") {
  CHECK(reports::html_with_code("The `a<b` is 3 & `c`.") ==
        "The <code>a&lt;b</code> is 3 &amp; <code>c</code>.");
  CHECK(reports::html_with_code("an odd ` stays") == "an odd ` stays");
  CHECK(reports::html_with_code("") == "");
  // A plot's title keeps what it says; XML cannot hold control characters.
  CHECK(reports::plot_text_for_html(kHostile) == kHostile);
  CHECK(reports::plot_text_for_html("a\x01"
                                    "b\nc\x7f") == "abc");
}

TEST_CASE("A comparison applies each format's rule to its names: CSV, Markdown and HTML") {
  io::Json hostile =
      io::read_json_file(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100-lead-at-tip.json");
  hostile["name"] = "@cmd\n# injected \x1b[2J\xef\xbf\xbe";
  std::vector<reports::ComparedDesign> designs;
  designs.push_back(studies::compare_one(tour_100(), "", 1e-6, true));
  designs.push_back(studies::compare_one(io::read_design(hostile, "=b.json"), "", 1e-6, true));
  const std::string csv = reports::comparison_report(designs, io::Format::kCsv);
  CHECK(csv.find("\n\"'@cmd\n# injected \\x1b[2J\xef\xbf\xbe\",\"'=b.json\",") !=
        std::string::npos);
  const std::string md = reports::comparison_report(designs, io::Format::kMarkdown);
  CHECK(md.find("\n# injected") == std::string::npos);
  CHECK(md.find('\x1b') == std::string::npos);
  CHECK(md.find("@cmd\\n# injected \\x1b[2J") != std::string::npos);
  const std::string page = reports::comparison_html(designs);
  CHECK(page.find("\xef\xbf\xbe") == std::string::npos);
  CHECK(page.find('\x1b') == std::string::npos);
  CHECK(page.find("@cmd\n# injected \xef\xbf\xbd[2J\xef\xbf\xbd") != std::string::npos);
}

TEST_CASE(
    "A comparison's page is self-contained, escapes every name and shows the table's numbers") {
  io::Json hostile =
      io::read_json_file(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100-lead-at-tip.json");
  hostile["name"] = kHostile;
  std::vector<reports::ComparedDesign> designs;
  designs.push_back(studies::compare_one(tour_100(), "", 1e-6, true));
  designs.push_back(
      studies::compare_one(io::read_design(hostile, "<i>b</i>.json"), "", 1e-6, true));
  const std::string page = reports::comparison_html(designs);
  check_self_contained(page);
  CHECK(page.find("<h1 id=\"name\">Compared: Modern 100 sq in tour racquet (typical strung specs) "
                  "and " +
                  kHostileEscaped + "</h1>") != std::string::npos);
  CHECK(page.find("<i>b</i>") == std::string::npos);
  CHECK(page.find("alert(1)</") == std::string::npos);
  // Each difference in words, escaped, in the answer.
  for (const std::string& sentence : reports::differences(designs[0], designs[1]))
    CHECK(page.find(reports::html_escape(sentence)) != std::string::npos);
  // The mass side by side: grams to four figures, kilograms under them.
  const double mass_kg = designs[1].spots.asked.evaluation.mass_kg;
  CHECK(page.find(fmt::format("<td class=\"num\">{}<span class=\"si\">{} kg</span></td>",
                              io::significant(mass_kg * 1000, 4), io::significant(mass_kg, 6))) !=
        std::string::npos);
  // Two drawings with their own title ids, and the positions behind them.
  CHECK(count(page, "<svg class=\"drawing\"") == 2);
  CHECK(page.find("id=\"drawing-1-title\"") != std::string::npos);
  CHECK(page.find("id=\"drawing-2-title\"") != std::string::npos);
  CHECK(page.find("<table id=\"drawing-positions\">") != std::string::npos);
}

TEST_CASE("Racquets of different lengths are drawn to one scale") {
  const io::DesignFile long_one = tour_100();  // 27 in
  io::DesignFile short_one =
      io::load_design(SWEETSPOT_SOURCE_DIR "/designs/table1/row1.json");  // 0.7 m
  const double a_cm = long_one.design.implement.length_m() * 100;
  const double b_cm = short_one.design.implement.length_m() * 100;
  REQUIRE(a_cm != b_cm);
  const Evaluation ea = evaluate(long_one.design), eb = evaluate(short_one.design);
  const std::string html =
      reports::racquets_to_scale_html({{&long_one, &ea, "a"}, {&short_one, &eb, "b"}}, "d");
  // Each drawing's viewBox is its length + 4 cm wide; its share of the page
  // is that over the longest's, so one centimetre is as long in both.
  const double longest = std::max(a_cm, b_cm);
  CHECK(html.find(fmt::format("<div style=\"width: {:.2f}%\">",
                              100 * (a_cm + 4) / (longest + 4))) != std::string::npos);
  CHECK(html.find(fmt::format("<div style=\"width: {:.2f}%\">",
                              100 * (b_cm + 4) / (longest + 4))) != std::string::npos);
  CHECK(html.find(fmt::format("<tr id=\"d-length\"><td>length</td><td class=\"num\">{:.1f}</td>"
                              "<td class=\"num\">{:.1f}</td></tr>",
                              a_cm, b_cm)) != std::string::npos);
}

TEST_CASE(
    "A study's page is self-contained, escapes its name and question, and shows the optimum") {
  studies::Study study = studies::load_study(
      SWEETSPOT_SOURCE_DIR "/designs/studies/1-lowest-wrist-force-table1-ranges.json");
  study.name = kHostile;
  study.question = kHostile + " `not code`";
  const studies::OptimizationResult r = run_optimization(study);
  REQUIRE(r.outcome == studies::Outcome::kOptimum);
  REQUIRE(r.best_outputs);
  const std::string page = reports::optimization_html(study, r);
  check_self_contained(page);
  CHECK(page.find("<h1 id=\"name\">" + kHostileEscaped + "</h1>") != std::string::npos);
  // The question is the user's text, shown as typed (no code spans made of it).
  CHECK(page.find(kHostileEscaped + " `not code`</p>") != std::string::npos);
  CHECK(page.find("alert(1)</") == std::string::npos);
  // The answer is the Markdown report's, its output's name as code.
  const std::string md = reports::optimization_report(study, r, io::Format::kMarkdown, false);
  const std::size_t answer = md.find("**Answer.** ") + 12;
  CHECK(page.find(reports::html_with_code(md.substr(answer, md.find("\n", answer) - answer))) !=
        std::string::npos);
  CHECK(page.find("<code>peak_wrist_force_N</code>") != std::string::npos);
  // Every variable's best value as the file writes it.
  for (std::size_t i = 0; i < study.variables.size(); ++i)
    CHECK(page.find(fmt::format("<span class=\"si\">{}</span></td></tr>",
                                io::significant(r.summary.x[i], 6))) != std::string::npos);
  // The outputs at the start and at the optimum, in people's units.
  const io::OutputSpec& wrist = *io::find_output("peak_wrist_force_N");
  CHECK(page.find(fmt::format("<tr id=\"out-peak_wrist_force_N\"><td>peak wrist force<div "
                              "class=\"means\"><code>peak_wrist_force_N</code></div></td><td "
                              "class=\"num\">{}</td><td class=\"num\">{}</td>",
                              io::significant(*wrist.value(*r.start_outputs), 4),
                              io::significant(*wrist.value(*r.best_outputs), 4))) !=
        std::string::npos);
  // The best design as a file, escaped.
  CHECK(page.find("<pre id=\"best-design\">") != std::string::npos);
}

}  // namespace
}  // namespace sweetspot::reports

namespace sweetspot::reports {
namespace {

TEST_CASE("The every-number table gives each output in people's units, as evaluate does") {
  // The README's promise: g, cm, kg·cm², ms, never kg, m, kg·m² or s; the
  // value through the same table `evaluate --units people` reads.
  const io::DesignFile file = io::load_design(SWEETSPOT_SOURCE_DIR
                                              "/designs/racquets/"
                                              "tour-100-strung.json");
  const studies::DesignPage computed = studies::design_page(file);
  const std::string page = reports::design_html_report(
      file, io::read_json_file(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100-strung.json"),
      computed);
  for (const io::OutputSpec& o : io::output_specs()) {
    INFO(o.name);
    const std::size_t row = page.find(fmt::format("<tr id=\"out-{}\">", o.name));
    REQUIRE(row != std::string::npos);
    const std::string cells = page.substr(row, page.find("</tr>", row) - row);
    const io::PeopleUnit unit = io::people_unit(o.unit, o.name);
    CHECK(cells.find(fmt::format("</td><td>{}</td><td><code>", html_escape(unit.unit))) !=
          std::string::npos);
    for (const char* si : {"kg", "kg·m²", "m", "s"})
      CHECK(cells.find(fmt::format("</td><td>{}</td>", si)) == std::string::npos);
    if (const auto v = o.value(computed.evaluation))
      CHECK(cells.find(fmt::format("<td class=\"num\">{}</td>",
                                   io::significant(*v * unit.factor, 4))) != std::string::npos);
  }
}

}  // namespace
}  // namespace sweetspot::reports

namespace sweetspot::reports {
namespace {

TEST_CASE(
    "A racquet's curves run over its string bed, and the caption's highest rebound is there") {
  // The coach's racquet peaked at the throat (52 cm from the tip) when the
  // curve ran the whole length; the answer's best rebound is on the strings.
  const io::DesignFile file =
      io::load_design(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100-strung.json");
  const studies::DesignPage computed = studies::design_page(file);
  REQUIRE(computed.span.string_bed);
  const HeadShape head = studies::head_shape_of(file);
  const double bed_length = 2.0 * std::sqrt(head.area_m2 * head.aspect_ratio / M_PI);
  CHECK(computed.span.from_tip_m == head.hoop_width_m);
  CHECK(computed.span.to_tip_m == Approx(head.hoop_width_m + bed_length));
  REQUIRE(!computed.curve.empty());
  CHECK(computed.curve.front().from_tip_m == computed.span.from_tip_m);
  CHECK(computed.curve.back().from_tip_m == computed.span.to_tip_m);
  const auto most = std::max_element(
      computed.curve.begin(), computed.curve.end(),
      [](const auto& a, const auto& b) { return a.apparent_cor < b.apparent_cor; });
  REQUIRE(computed.spots.best_rebound);
  // The curve's 1 cm grid against the golden-section search's 0.5 cm.
  CHECK(std::abs(most->from_tip_m - computed.spots.best_rebound->from_tip_m) <= 0.01);
  const std::string page = reports::design_html_report(
      file, io::read_json_file(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100-strung.json"),
      computed);
  CHECK(page.find(fmt::format("highest {} cm from the tip", html_cm(most->from_tip_m))) !=
        std::string::npos);
}

TEST_CASE("Implements drawn to one scale: a racquet from above, a bat from the side") {
  const io::DesignFile racquet =
      io::load_design(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100.json");
  const io::DesignFile bat = io::load_design(SWEETSPOT_SOURCE_DIR "/designs/bats/wood-bat-34.json");
  const Evaluation e_racquet = evaluate(racquet.design, Fidelity::kRigid);
  const Evaluation e_bat = evaluate(bat.design, Fidelity::kRigid);
  const std::string bat_only = racquets_to_scale_html({{&bat, &e_bat, "bat"}}, "drawing");
  CHECK(bat_only.find("from the side, to scale") != std::string::npos);
  CHECK(bat_only.find("class=\"bed\"") == std::string::npos);  // no string bed on a bat
  const std::string both =
      racquets_to_scale_html({{&racquet, &e_racquet, "racquet"}, {&bat, &e_bat, "bat"}}, "drawing");
  CHECK(both.find("class=\"bed\"") != std::string::npos);
  CHECK(both.find("id=\"drawing-1-title\"") != std::string::npos);
  CHECK(both.find("id=\"drawing-2-title\"") != std::string::npos);
}
}  // namespace
}  // namespace sweetspot::reports
