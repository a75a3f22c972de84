#include "io/plot.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include "file_helpers.hpp"
#include "io/format.hpp"
#include "io/outputs.hpp"

namespace sweetspot::io {
namespace {

Plot two_points(const std::string& title) {
  return Plot{title,        "x_label (m)",
              "y (N)",      std::nullopt,
              std::nullopt, {PlotSeries{"peak_wrist_force_N", {0.0, 1.0}, {1.0, 2.0}}},
              {},           {}};
}

TEST_CASE("Labels print underscores literally while file names are left alone") {
  const std::string script =
      gnuplot_script(two_points("peak_wrist_force_N"), "/tmp/out_dir/a_b.png");
  CHECK(script.find("set output '/tmp/out_dir/a_b.png'") != std::string::npos);
  CHECK(script.find("set title 'peak\\_wrist\\_force\\_N'") != std::string::npos);
  CHECK(script.find("title 'peak\\_wrist\\_force\\_N'") != std::string::npos);
}

TEST_CASE("Text from a user's file never runs as a command: gnuplot strings are single-quoted") {
  // gnuplot runs `commands` in backquotes inside double-quoted strings.
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_plot_backquote_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string witness = (dir / "ran").string();
  const std::string name = "`touch " + witness + "` it's \"quoted\"\nand {odd}";
  const std::string script = gnuplot_script(two_points(name), "");
  CHECK(script.find("set title '`touch") != std::string::npos);  // inside single quotes
  CHECK(script.find("it''s") != std::string::npos);              // a quote is written twice
  CHECK(script.find("\"quoted\" and") != std::string::npos);     // the newline became a space
  std::string why;
  CHECK(render_png(two_points(name), (dir / "p.png").string(), &why));
  CHECK_FALSE(std::filesystem::exists(witness));
  std::filesystem::remove_all(dir);
}

TEST_CASE("A plot renders to a real PNG at a path with underscores") {
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_plot_test";
  std::filesystem::create_directories(dir);
  const std::string png = (dir / "plot_with_underscores.png").string();
  std::string why;
  REQUIRE(render_png(two_points("a_b"), png, &why));
  std::ifstream in(png, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  CHECK(std::string(signature + 1, 3) == "PNG");
  CHECK(std::filesystem::file_size(png) > 1000);
  std::filesystem::remove_all(dir);
}

using testing::FifoReader;
using testing::slurp;

// Runs `f` with this process's standard output going to a file; returns what reached it.
template <typename F>
std::string standard_output_of(const std::string& file, F f) {
  std::fflush(stdout);
  const int saved = ::dup(1);
  const int into = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  ::dup2(into, 1);
  ::close(into);
  f();
  std::fflush(stdout);
  ::dup2(saved, 1);
  ::close(saved);
  return slurp(file);
}

TEST_CASE(
    "A plot gnuplot cannot draw fails with its message on one line, no file and nothing on "
    "stdout") {
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_plot_fail_test";
  std::filesystem::create_directories(dir);
  const std::string png = (dir / "empty.png").string();
  // No point at all: gnuplot warns "Skipping data file with no valid points", then fails.
  const Plot empty{
      "empty", "x (m)", "y (N)", std::nullopt, std::nullopt, {PlotSeries{"none", {}, {}}}, {}, {}};
  std::string why;
  bool rendered = true;
  const std::string printed = standard_output_of((dir / "stdout").string(),
                                                 [&] { rendered = render_png(empty, png, &why); });
  CHECK_FALSE(rendered);
  CHECK(printed.empty());
  CHECK(why.find("gnuplot failed (exit status 1)") == 0);
  CHECK(why.find("no valid points") != std::string::npos);
  CHECK(why.find('\n') == std::string::npos);
  CHECK(why.find("/dev/stdin") == std::string::npos);  // how gnuplot got its script is not news
  CHECK_FALSE(std::filesystem::exists(png));
  CHECK(std::distance(std::filesystem::directory_iterator(dir), {}) == 1);  // stdout only
  std::filesystem::remove_all(dir);
}

TEST_CASE("A plot onto a FIFO is the whole PNG, and the FIFO stays one") {
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_plot_fifo_test";
  std::filesystem::create_directories(dir);
  const std::string fifo = (dir / "plot.png").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  FifoReader reader(fifo);
  std::string why;
  CHECK(render_png(two_points("through a pipe"), fifo, &why));
  const std::string received = reader.finish();
  REQUIRE(received.size() > 1000);
  CHECK(received.compare(0, 4, "\x89PNG") == 0);
  CHECK(received.compare(received.size() - 8, 4, "IEND") == 0);
  struct stat info {};
  REQUIRE(::lstat(fifo.c_str(), &info) == 0);
  CHECK(S_ISFIFO(info.st_mode));
  std::filesystem::remove_all(dir);
}

TEST_CASE("Axes read as words with one unit, never a JSON pointer or a doubled unit") {
  // The labels issue 13 quotes, and what a reader should see instead.
  CHECK(pointer_axis("/implement/point_masses/0/mass_g").label == "lead mass 1 (g)");
  CHECK(pointer_axis("/implement/point_masses/2/from_tip_cm").label ==
        "lead mass 3 from the tip (cm)");
  CHECK(pointer_axis("/hand/mass_kg").label == "hand mass (kg)");
  // Lead tape is weighed in grams, whatever unit the file uses.
  const AxisQuantity lead = pointer_axis("/implement/point_masses/0/mass_kg");
  CHECK(lead.label == "lead mass 1 (g)");
  CHECK(lead.factor == 1000.0);
  CHECK(pointer_axis("/implement/head_to_handle_mass_ratio").label == "head to handle mass ratio");
  const AxisQuantity impact = pointer_axis("/impact/from_tip_m");
  CHECK(impact.label == "impact from the tip (cm)");  // metres shown as centimetres
  CHECK(impact.factor == 100.0);
  CHECK(impact.name == "impact from the tip");
  CHECK(impact.unit == "cm");
  for (const OutputSpec& o : output_specs()) {
    const AxisQuantity axis = output_axis(o);
    INFO(o.name << " -> " << axis.label);
    CHECK(axis.label.find('_') == std::string::npos);
    // A '/' only inside a unit (m/s, rad/s), never in the words (a pointer).
    CHECK(axis.name.find('/') == std::string::npos);
    CHECK((axis.label.find('/') == std::string::npos || axis.unit.find('/') != std::string::npos));
    // The unit once: the name's suffix is gone when the unit is shown.
    if (!axis.unit.empty()) CHECK(axis.name.find(axis.unit) == std::string::npos);
  }
  CHECK(output_axis(*find_output("peak_wrist_force_N")).label == "peak wrist force (N)");
  CHECK(output_axis(*find_output("cop_hand_from_tip_m")).label == "COP hand from the tip (cm)");
  CHECK(output_axis(*find_output("cop_node_gap_m")).label == "COP–node gap (cm)");
  CHECK(output_axis(*find_output("apparent_cor")).label == "apparent COR");
}

TEST_CASE("Twelve series get twelve different colours, in the order they are plotted") {
  Plot plot = two_points("colours");
  for (int i = 1; i < 12; ++i) plot.series.push_back(plot.series.front());
  const std::string script = gnuplot_script(plot, "");
  std::set<std::string> colours;
  for (std::size_t i = 0; i < 12; ++i) {
    colours.insert(plot_color(i));
    CHECK(script.find("$series" + std::to_string(i) + " using 1:2 with lines lw 2 lc rgb '" +
                      plot_color(i) + "'") != std::string::npos);
  }
  CHECK(colours.size() == 12);
  CHECK(plot_color(12) == plot_color(0));
}

TEST_CASE("A second x axis in another unit is linked to the first, with tics at its own steps") {
  Plot plot = two_points("tension");
  plot.x2 = SecondXAxis{"tension (lb)", 1.0 / 4.4482216152605, 10.0};
  plot.integer_x_tics = true;
  const std::string script = gnuplot_script(plot, "");
  CHECK(script.find("set link x2 via x*0.224808943") != std::string::npos);
  CHECK(script.find("set x2tics 10\n") != std::string::npos);
  CHECK(script.find("set xtics 1\n") != std::string::npos);
}

TEST_CASE("A plot as inline SVG: no XML prologue, its ids prefixed so two plots share a page") {
  std::string why;
  const auto svg = render_svg(two_points("svg"), "first-", &why);
  REQUIRE(svg);
  CHECK(svg->rfind("<svg", 0) == 0);
  CHECK(svg->size() > 6);
  CHECK(svg->compare(svg->size() - 6, 6, "</svg>") == 0);
  CHECK(svg->find("<?xml") == std::string::npos);
  CHECK(svg->find("id='gpPt") == std::string::npos);  // every id carries the prefix
  CHECK(svg->find("id='first-gpPt") != std::string::npos);
  CHECK(svg->find("gnuplot_canvas") == std::string::npos);
  CHECK(svg->find("<script") == std::string::npos);
}

TEST_CASE(
    "An '&' in a title or a key is escaped as an entity in the SVG, and entities stay as they "
    "are") {
  Plot plot = two_points("Smith & Sons <pro>");
  plot.series[0].title = "lead & tape";
  std::string why;
  const auto svg = render_svg(plot, "amp-", &why);
  REQUIRE(svg);
  // Every '&' starts one of XML's entities or a character reference.
  for (std::size_t at = svg->find('&'); at != std::string::npos; at = svg->find('&', at + 1)) {
    const std::string_view rest = std::string_view(*svg).substr(at, 8);
    INFO(rest);
    CHECK((rest.rfind("&amp;", 0) == 0 || rest.rfind("&lt;", 0) == 0 ||
           rest.rfind("&gt;", 0) == 0 || rest.rfind("&quot;", 0) == 0 ||
           rest.rfind("&apos;", 0) == 0 || rest.rfind("&#", 0) == 0));
  }
  CHECK(svg->find("Sons") != std::string::npos);
  // A name that holds an entity shows it as typed; "]]>" cannot end a section.
  const auto typed = render_svg(two_points("Tom &amp; Jerry ]]> again"), "typed-", &why);
  REQUIRE(typed);
  CHECK(typed->find("Tom &amp;amp; Jerry") != std::string::npos);
  CHECK(typed->find("]]>") == std::string::npos);
  CHECK(typed->find("]]&gt; again") != std::string::npos);
}

TEST_CASE("An SVG plot holds only characters XML 1.0 allows, whatever its title and keys hold") {
  // U+FFFE and U+FFFF (not XML characters), a C1 control and a byte that is not UTF-8.
  Plot plot = two_points("title \xef\xbf\xbe\xef\xbf\xbf end");
  plot.series[0].title = "key \xc2\x85 \xff end";
  std::string why;
  const auto svg = render_svg(plot, "xml-", &why);
  REQUIRE(svg);
  CHECK(svg->find("\xef\xbf\xbe") == std::string::npos);
  CHECK(svg->find("\xef\xbf\xbf") == std::string::npos);
  CHECK(svg->find("\xc2\x85") == std::string::npos);
  CHECK(svg->find('\xff') == std::string::npos);
  CHECK(*svg == xml_chars(*svg));
  CHECK(svg->find("title \xef\xbf\xbd\xef\xbf\xbd end") != std::string::npos);
}

// Plots as a page draws them: settings that would carry over from one plot
// to the next in one gnuplot (a log scale, a fixed aspect ratio, a palette,
// labels, arrows, data blocks), a text that spells the tag between plots.
std::vector<SvgPlot> page_of_plots() {
  Plot logged = two_points("logged");
  logged.log_y = true;
  logged.vertical_lines = {{0.5, "COP"}};
  logged.markers = {PlotMarker{0.25, 1.5, "here"}};
  // A heat map as the string bed's are drawn: an image with its colour box,
  // labelled, and a line in the key below.
  const std::string image =
      "set terminal svg size 300,360 dynamic enhanced font 'DejaVu Sans,12' background "
      "'#ffffff'\nset title 'a map'\nset xlabel 'across (cm)'\nset ylabel 'along (cm)'\n"
      "set cblabel 'value'\nset palette defined (0 '#1a9850', 1 '#d73027')\n"
      "set size ratio -1\nset key below box opaque\n"
      "$grid << EOD\n0 0 1\n0 1 2\n\n1 0 3\n1 1 4\nEOD\n$outline << EOD\n0 0\n1 1\nEOD\n"
      "plot $grid using 1:2:3 with image notitle, $outline using 1:2 with lines lw 2 lc rgb "
      "'gray20' title 'bed'\n";
  return {{gnuplot_svg_script(logged, 960, 560), "a-"},
          {image, "b-"},
          {gnuplot_svg_script(two_points("plain after the others"), 520, 460), "c-"},
          {gnuplot_svg_script(two_points("<sweetspot-plot-end/> in a title"), 520, 460), "d-"},
          {gnuplot_svg_script(two_points("last"), 960, 560), "e-"}};
}

// The full path of the first gnuplot on PATH.
std::string gnuplot_on_path() {
  std::istringstream path(std::getenv("PATH") ? std::getenv("PATH") : "");
  for (std::string dir; std::getline(path, dir, ':');) {
    const auto candidate = std::filesystem::path(dir) / "gnuplot";
    if (!dir.empty() && ::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return "";
}

TEST_CASE("A page's plots are drawn by one gnuplot, each SVG the same as drawn alone") {
  const std::vector<SvgPlot> plots = page_of_plots();
  std::vector<std::string> alone;
  for (const SvgPlot& plot : plots) {
    std::string why;
    const auto svg = render_script_svg(plot.script, plot.id_prefix, &why);
    INFO(why);
    REQUIRE(svg);
    alone.push_back(*svg);
  }
  // gnuplot on PATH is a script that counts its starts, then runs gnuplot.
  const std::string gnuplot = gnuplot_on_path();
  REQUIRE_FALSE(gnuplot.empty());
  const auto dir = std::filesystem::temp_directory_path() / "sweetspot_plot_one_gnuplot_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto starts = dir / "starts";
  {
    std::ofstream counter(dir / "gnuplot");
    counter << "#!/bin/sh\necho start >> '" << starts.string() << "'\nexec '" << gnuplot
            << "' \"$@\"\n";
  }
  std::filesystem::permissions(dir / "gnuplot", std::filesystem::perms::owner_all);
  const std::string path = std::getenv("PATH");
  ::setenv("PATH", (dir.string() + ":" + path).c_str(), 1);
  const std::vector<RenderedSvg> together = render_svgs(plots);
  ::setenv("PATH", path.c_str(), 1);
  std::ifstream counted(starts);
  const std::string log((std::istreambuf_iterator<char>(counted)),
                        std::istreambuf_iterator<char>());
  CHECK(log == "start\n");
  REQUIRE(together.size() == plots.size());
  for (std::size_t i = 0; i < plots.size(); ++i) {
    INFO(i << ": " << together[i].why);
    REQUIRE(together[i].svg);
    CHECK(*together[i].svg == alone[i]);
  }
  CHECK(alone[3].find("&lt;sweetspot-plot-end/>") != std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST_CASE("A plot gnuplot cannot draw among a page's loses only itself, and says why") {
  std::vector<SvgPlot> plots = page_of_plots();
  const Plot empty{
      "empty", "x (m)", "y (N)", std::nullopt, std::nullopt, {PlotSeries{"none", {}, {}}}, {}, {}};
  plots.insert(plots.begin() + 2, SvgPlot{gnuplot_svg_script(empty), "empty-"});
  const std::vector<RenderedSvg> drawn = render_svgs(plots);
  REQUIRE(drawn.size() == plots.size());
  for (std::size_t i = 0; i < plots.size(); ++i) {
    INFO(i);
    if (i == 2) {
      CHECK_FALSE(drawn[i].svg);
      CHECK(drawn[i].why.find("gnuplot failed (exit status 1)") == 0);
      CHECK(drawn[i].why.find("no valid points") != std::string::npos);
      continue;
    }
    std::string why;
    const auto alone = render_script_svg(plots[i].script, plots[i].id_prefix, &why);
    REQUIRE(alone);
    REQUIRE(drawn[i].svg);
    CHECK(*drawn[i].svg == *alone);
    CHECK(drawn[i].why.empty());
  }
}

TEST_CASE("A gnuplot that stops early on a long script is a failure said, not a SIGPIPE") {
  // An unknown command on line 2, then 4 MB more of script than a pipe holds:
  // gnuplot has gone long before the script is written.
  std::string script = "set terminal svg\nno_such_command\n";
  while (script.size() < (4u << 20)) script += "# a line of comment to fill the pipe\n";
  std::string why;
  const auto svg = render_script_svg(script, "early-", &why);
  CHECK_FALSE(svg);
  CHECK(why.find("gnuplot failed (exit status 1)") == 0);
  CHECK(why.find("line 2") != std::string::npos);
}

TEST_CASE("Every output's axis shows its own unit, in people's units, and the factor to it") {
  // People's units as the README promises them: g and kg·cm², not kg and kg·m².
  // The unit a person reads for each SI unit the outputs table uses, with the
  // factor from SI: what the name's suffix says must be what the value is.
  const std::map<std::string_view, std::pair<std::string_view, double>> kShown{
      {"", {"", 1.0}},           {"m", {"cm", 100.0}},        {"s", {"ms", 1000.0}},
      {"kg", {"g", 1000.0}},     {"kg m^2", {"kg·cm²", 1e4}}, {"kg cm^2", {"kg·cm²", 1.0}},
      {"N", {"N", 1.0}},         {"N s", {"N·s", 1.0}},       {"N m", {"N·m", 1.0}},
      {"J", {"J", 1.0}},         {"Hz", {"Hz", 1.0}},         {"m/s", {"m/s", 1.0}},
      {"rad/s", {"rad/s", 1.0}}, {"km/h", {"km/h", 1.0}},     {"mph", {"mph", 1.0}},
      {"1/s^2", {"1/s²", 1.0}},  {"N/m", {"N/m", 1.0}},       {"lb/in", {"lb/in", 1.0}}};
  for (const OutputSpec& o : output_specs()) {
    INFO(o.name << " in " << o.unit);
    const auto shown = kShown.find(o.unit);
    REQUIRE(shown != kShown.end());
    const AxisQuantity axis = output_axis(o);
    if (o.name.find("tension") != std::string_view::npos) {
      // A string tension is read in pounds, as a stringing machine is set:
      // 1 lbf = 0.45359237 kg x 9.80665 m/s^2.
      CHECK(axis.unit == "lb");
      CHECK(axis.factor == Approx(1.0 / (0.45359237 * 9.80665)).epsilon(1e-15));
    } else {
      CHECK(axis.unit == shown->second.first);
      CHECK(axis.factor == shown->second.second);
    }
    // The words carry no unit of their own ("twist rate", not "twist rate rad").
    CHECK(axis.name.find(" rad") == std::string::npos);
  }
}

TEST_CASE("A line that leaves the y range runs to its edge, a jump across a pole is not drawn") {
  Plot plot = two_points("edges");
  plot.y_range = std::pair{-4.0, 4.0};
  // Rising through the top edge between x = 2 (y = 2) and x = 3 (y = 10): it reaches 4 at 2.25,
  // and comes back down through it between x = 4 (y = 12) and x = 5 (y = 0) at 4 + 8/12.
  plot.series = {PlotSeries{"rise", {0, 1, 2, 3, 4, 5, 6}, {0.0, 1.0, 2.0, 10.0, 12.0, 0.0, -1.0}}};
  const std::string rise = gnuplot_script(plot, "");
  CHECK(rise.find("1 1\n2 2\n2.25 4\n\n") != std::string::npos);
  CHECK(rise.find(fmt::format("{} 4\n5 0\n", 4.0 + 8.0 / 12.0)) != std::string::npos);
  // A pole: rising to 3, then -50 on its far side: no line drawn down to the bottom edge.
  plot.series = {PlotSeries{"pole", {0, 1, 2, 3, 4}, {1.0, 2.0, 3.0, -50.0, -3.0}}};
  const std::string pole = gnuplot_script(plot, "");
  CHECK(pole.find("-4\n") == std::string::npos);
  CHECK(pole.find("2 3\n\n") != std::string::npos);
}

}  // namespace
}  // namespace sweetspot::io
