// Reports only render: no file in src/reports/ computes. The analyses live in
// src/studies/ and return plain records; a report takes a record and writes
// Markdown, CSV, JSON, HTML or a plot. This test reads the sources: it fails
// when a report includes a header of the model's solvers or of the optimiser,
// or calls one of the functions that evaluate, solve, search or sweep.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The headers whose business is computing: evaluate's doors, the solved
// collision, the modes, the impact response, the equations of the rigid model,
// the string bed's duration, root finding, the invariants, the mode cache, and
// the optimiser. A report may still use the types they define through a
// studies/ record that holds them.
const std::vector<std::string>& banned_headers() {
  static const std::vector<std::string> headers{"sweetspot/evaluate.hpp",
                                                "sweetspot/collision.hpp",
                                                "sweetspot/frame_modes.hpp",
                                                "sweetspot/beam_modes.hpp",
                                                "sweetspot/impact_response.hpp",
                                                "sweetspot/rigid_impact.hpp",
                                                "sweetspot/string_bed.hpp",
                                                "sweetspot/roots.hpp",
                                                "sweetspot/invariants.hpp",
                                                "sweetspot/mode_cache.hpp",
                                                "optimizer/",
                                                "core/"};
  return headers;
}

// Functions and types that compute: the core's (evaluate's doors, the
// collision, the modes, the response, the equations a report would otherwise
// redo), the optimiser's, and the studies' analyses (a report is handed their
// records; it does not run them).
const std::vector<std::string>& banned_names() {
  static const std::vector<std::string> names{
      // The core.
      "evaluate", "evaluate_unchecked", "evaluate_rigid_outcome", "rigid_case", "rigid_outcomes",
      "ImpactSweep", "DesignCollision", "collide", "ModeCache", "free_modes", "hand_held_modes",
      "flexible_frame", "hand_held_fundamental", "response_model", "impact_response",
      "with_fundamental", "derive_cor", "fundamental_for_cor", "tension_impact_duration",
      "tension_for_duration", "find_root", "effective_mass", "velocity_ratio",
      "free_conjugate_from_butt", "hand_held_rotation_axis_from_butt", "hand_held_system",
      // The optimiser.
      "minimize",
      // io's door to evaluate.
      "evaluate_design_file",
      // The studies' analyses.
      "run_optimization", "run_sweep", "string_bed_map", "find_sweet_spots", "best_rebound_on_axis",
      "frame_curves", "design_page", "page_maps", "compare_one", "compute_table1", "figure5_data",
      "figure11_data", "figure11_crossing", "paper_results", "compute_modes", "compute_response",
      "paper_beam_responses", "cor_from_stiffness", "duration_from_tension", "response_reports",
      "tension_study"};
  return names;
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The code of a C++ source without its comments and the contents of its
// string and character literals (raw strings included), so that a sentence
// saying "sweetspot evaluate" is not a call.
std::string code_only(const std::string& source) {
  std::string code;
  for (std::size_t i = 0; i < source.size();) {
    if (source.compare(i, 2, "//") == 0) {
      i = source.find('\n', i);
      if (i == std::string::npos) break;
    } else if (source.compare(i, 2, "/*") == 0) {
      const std::size_t end = source.find("*/", i + 2);
      i = end == std::string::npos ? source.size() : end + 2;
    } else if (source.compare(i, 2, "R\"") == 0) {
      const std::size_t open = source.find('(', i);
      const std::string close = ")" + source.substr(i + 2, open - i - 2) + "\"";
      const std::size_t end = source.find(close, open);
      code += "\"\"";
      i = end == std::string::npos ? source.size() : end + close.size();
    } else if (source[i] == '"' || source[i] == '\'') {
      const char quote = source[i];
      std::size_t j = i + 1;
      while (j < source.size() && source[j] != quote) j += source[j] == '\\' ? 2 : 1;
      code += quote;
      code += quote;
      i = j + 1;
    } else {
      code += source[i++];
    }
  }
  return code;
}

// Every #include of `source` (the path between the quotes or brackets).
std::vector<std::string> includes(const std::string& source) {
  static const std::regex include(R"(^\s*#\s*include\s*["<]([^">]+)[">])");
  std::vector<std::string> found;
  std::istringstream lines(source);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (std::regex_search(line, m, include)) found.push_back(m[1]);
  }
  return found;
}

// What a source does that a report must not: "includes X" or "uses Y", one each.
std::vector<std::string> computing(const std::string& source) {
  std::vector<std::string> faults;
  for (const std::string& header : includes(source)) {
    for (const std::string& banned : banned_headers()) {
      if (header.rfind(banned, 0) == 0) faults.push_back("includes " + header);
    }
  }
  const std::string code = code_only(source);
  for (const std::string& name : banned_names()) {
    // The name as a whole identifier (any namespace before it), not a member
    // of an object (`.`, `->`) nor part of a longer name.
    const std::regex use("(^|[^A-Za-z0-9_.>])" + name + "([^A-Za-z0-9_]|$)");
    if (std::regex_search(code, use)) faults.push_back("uses " + name);
  }
  return faults;
}

TEST_CASE("The scan finds an include and a call, and not the same words in comments or strings") {
  CHECK(computing("#include \"sweetspot/collision.hpp\"\n") ==
        std::vector<std::string>{"includes sweetspot/collision.hpp"});
  CHECK(computing("#include \"optimizer/optimize.hpp\"\n") ==
        std::vector<std::string>{"includes optimizer/optimize.hpp"});
  CHECK(computing("auto e = sweetspot::evaluate(design, Fidelity::kCollision);\n") ==
        std::vector<std::string>{"uses evaluate"});
  CHECK(computing("const studies::DesignPage page = studies::design_page(file);") ==
        std::vector<std::string>{"uses design_page"});
  CHECK(computing("std::optional<DesignCollision> c;") ==
        std::vector<std::string>{"uses DesignCollision"});
  // Words, not calls: comments, strings (raw ones too), members and longer names.
  CHECK(computing("// evaluate(design)\n/* minimize(p) */\n"
                  "std::string s = \"sweetspot evaluate(x)\";\n"
                  "auto r = R\"(collide())\";\n"
                  "auto v = o.value(e); double evaluated = x.evaluate; evaluate_thing(1);\n"
                  "#include \"studies/design_page.hpp\"\n#include \"sweetspot/design.hpp\"\n")
            .empty());
}

TEST_CASE("Every name the scan bans is declared by the core, the optimiser, io or studies") {
  // So the list cannot rot into names nobody declares any more.
  std::string declared;
  for (const char* folder : {"include/sweetspot", "src/optimizer", "src/io", "src/studies"}) {
    for (const auto& entry : fs::directory_iterator(fs::path(SWEETSPOT_SOURCE_DIR) / folder)) {
      if (entry.path().extension() == ".hpp") declared += code_only(read(entry.path()));
    }
  }
  for (const std::string& name : banned_names()) {
    INFO(name);
    CHECK(std::regex_search(declared, std::regex("[^A-Za-z0-9_]" + name + "[^A-Za-z0-9_]")));
  }
}

TEST_CASE("Reports only render: no file in src/reports/ evaluates, solves, searches or sweeps") {
  const fs::path folder = fs::path(SWEETSPOT_SOURCE_DIR) / "src" / "reports";
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".cpp" && ext != ".hpp") continue;
    ++files;
    INFO(entry.path().filename().string());
    CHECK(computing(read(entry.path())) == std::vector<std::string>{});
  }
  CHECK(files >= 20);  // the folder was found and read
}

}  // namespace
