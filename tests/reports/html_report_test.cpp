#include "reports/html_report.hpp"

#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>

#include "sweetspot/evaluate.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot::io {
namespace {

DesignFile tour_100() {
  return load_design(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100.json");
}

std::size_t count(const std::string& text, const std::string& piece) {
  std::size_t n = 0;
  for (auto at = text.find(piece); at != std::string::npos; at = text.find(piece, at + 1)) ++n;
  return n;
}

TEST_CASE("Every user string is escaped: markup in a racquet's name is shown, never run") {
  CHECK(html_escape("<script>alert('x')</script> & \"Pro\"") ==
        "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;Pro&quot;");
  CHECK(html_escape(std::string("a\x01"
                                "b\x7f"
                                "c\td\n",
                                8)) == "abc\td\n");
  Json document = read_json_file(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100.json");
  document["name"] = "<img src=x onerror=alert(1)> & Co";
  document["description"] = "</style><script>x()</script>";
  const DesignFile file = read_design(document, "<b>file</b>.json");
  const std::string page = design_html_report(file, document);
  CHECK(page.find("<img") == std::string::npos);
  CHECK(page.find("<script") == std::string::npos);
  CHECK(page.find("<b>file</b>") == std::string::npos);
  CHECK(page.find("&lt;img src=x onerror=alert(1)&gt; &amp; Co") != std::string::npos);
  CHECK(count(page, "</style>") == 1);
}

TEST_CASE("The page is self-contained: nothing fetched, no script, one stylesheet inline") {
  const DesignFile file = tour_100();
  const std::string page = design_html_report(
      file, read_json_file(SWEETSPOT_SOURCE_DIR "/designs/racquets/tour-100.json"));
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

TEST_CASE("The curves along the frame are the rigid model's, and zero wrist force at the COP") {
  const DesignFile file = tour_100();
  const Design& d = file.design;
  const std::vector<FramePoint> curve = frame_curves(d, 0.01);
  const double L = d.implement.length_m();
  REQUIRE(curve.size() == static_cast<std::size_t>(std::ceil(L / 0.01)) + 1);
  CHECK(curve.front().from_tip_m == 0.0);
  CHECK(curve.back().from_tip_m == L);
  // Each point is Eq. (11) and Eq. (16) at its impact, evaluated afresh.
  for (const FramePoint& p : {curve[5], curve[30], curve[60]}) {
    Design at = d;
    at.impact_from_butt_m = L - p.from_tip_m;
    const Evaluation e = evaluate(at, Fidelity::kRigid);
    CHECK(p.wrist_force_ratio == e.wrist_force_ratio);
    CHECK(p.apparent_cor == e.apparent_cor);
  }
  // The ratio changes sign across the hand-held COP (Eq. 13), and only there.
  const Evaluation e = evaluate(d, Fidelity::kRigid);
  REQUIRE(e.cop_hand_from_butt_m);
  const double cop_from_tip = L - *e.cop_hand_from_butt_m;
  for (std::size_t i = 1; i < curve.size(); ++i) {
    const bool crosses = curve[i - 1].wrist_force_ratio * curve[i].wrist_force_ratio < 0;
    const bool cop_between =
        curve[i - 1].from_tip_m < cop_from_tip && cop_from_tip < curve[i].from_tip_m;
    CHECK(crosses == cop_between);
  }
  CHECK_THROWS_AS(frame_curves(d, 0.0), std::invalid_argument);
}

TEST_CASE("The drawing is to scale: the racquet's length and each marker where the model puts it") {
  const DesignFile file = tour_100();
  const Evaluation e = evaluate(file.design);
  const double L_cm = file.design.implement.length_m() * 100.0;
  const std::string top = racquet_top_svg(file, e, 100 * 0.00064516);
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
  CHECK(drawn_head_area_m2(file, Json::object()) == Approx(100 * 0.00064516));
  CHECK(drawn_head_area_m2(file, Json{{"implement", {{"headsize_sq_in", 98}}}}) ==
        Approx(98 * 0.00064516));
}

}  // namespace
}  // namespace sweetspot::io
