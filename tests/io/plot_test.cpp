#include "io/plot.hpp"

#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>

namespace sweetspot::io {
namespace {

Plot two_points(const std::string& title) {
  return Plot{title, "x_label (m)", "y (N)", std::nullopt, std::nullopt,
              {PlotSeries{"peak_wrist_force_N", {0.0, 1.0}, {1.0, 2.0}}}, {}, {}};
}

TEST_CASE("Labels print underscores literally while file names are left alone") {
  const std::string script = gnuplot_script(two_points("peak_wrist_force_N"), "/tmp/out_dir/a_b.png");
  CHECK(script.find("set output \"/tmp/out_dir/a_b.png\"") != std::string::npos);
  CHECK(script.find("set title \"peak\\\\_wrist\\\\_force\\\\_N\"") != std::string::npos);
  CHECK(script.find("title \"peak\\\\_wrist\\\\_force\\\\_N\"") != std::string::npos);
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

}  // namespace
}  // namespace sweetspot::io
