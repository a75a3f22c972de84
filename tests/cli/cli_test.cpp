// The command line as a user meets it: every class of bad input gets one line
// on stderr naming the file and the JSON path, exit status 2, and no output
// file. SWEETSPOT_CLI is the path of the built executable.
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

struct Run {
  int status = -1;
  std::string out;
  std::string err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class Sandbox {
 public:
  Sandbox() : dir_(fs::temp_directory_path() / ("sweetspot-cli-" + std::to_string(::getpid()))) {
    fs::create_directories(dir_);
  }
  ~Sandbox() { fs::remove_all(dir_); }
  fs::path file(const std::string& name, const std::string& content) const {
    std::ofstream(dir_ / name, std::ios::binary) << content;
    return dir_ / name;
  }
  fs::path path(const std::string& name) const { return dir_ / name; }

  Run run(const std::string& arguments) const {
    const std::string command = std::string("\"") + SWEETSPOT_CLI + "\" " + arguments + " >\"" +
                                (dir_ / "stdout").string() + "\" 2>\"" + (dir_ / "stderr").string() +
                                "\" </dev/null";
    const int raw = std::system(command.c_str());
    return Run{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir_ / "stdout"),
               slurp(dir_ / "stderr")};
  }

 private:
  fs::path dir_;
};

constexpr const char* kImplement =
    R"("implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8})";

std::string with_implement(const std::string& rest) {
  return std::string("{") + kImplement + (rest.empty() ? "" : ", " + rest) + "}";
}

struct BadInput {
  const char* what;
  std::string content;
  const char* pointer;   // must appear in the message ("" for whole-file errors)
  const char* expected;  // must appear in the message too
};

TEST_CASE("Every class of bad design input exits 2 with one line naming file and JSON path") {
  const Sandbox box;
  const std::string deep = std::string(100, '[') + std::string(100, ']');
  const BadInput cases[] = {
      {"unknown key", with_implement(R"("colour": "red")"), "/colour", "unknown key"},
      {"unknown nested key", with_implement(R"("hand": {"mass_kg": 0.5, "grip": "firm"})"),
       "/hand/grip", "unknown key"},
      {"missing implement", R"({"frame": {"cor": 0.8}})", "/implement", "missing"},
      {"missing mass", R"({"implement": {"length_m": 0.7, "head_to_handle_mass_ratio": 1}})",
       "/implement", "missing mass_kg"},
      {"missing mass distribution", R"({"implement": {"length_m": 0.7, "mass_kg": 0.3}})",
       "/implement", "head_to_handle_mass_ratio, sections"},
      {"wrong type", R"({"implement": {"length_m": 0.7, "mass_kg": "heavy",
        "head_to_handle_mass_ratio": 1}})", "/implement/mass_kg", "expected a number, got \"heavy\""},
      {"wrong container type", with_implement(R"("hand": [0.5])"), "/hand", "expected a JSON object"},
      {"out of range", with_implement(R"("hand": {"mass_kg": -0.5})"), "/hand/mass_kg",
       "must be in [0, 1e+06] kg, got -0.5"},
      {"out of range COR", with_implement(R"("frame": {"cor": 1.2})"), "/frame/cor",
       "must be in [0, 1], got 1.2"},
      {"non-finite number", with_implement(R"("ball": {"speed_m_s": 1e999})"), "/ball/speed_m_s",
       "finite"},
      {"negative duration in ms", with_implement(R"("strings": {"impact_duration_ms": -4})"),
       "/strings/impact_duration_ms", "must be in [1e-09, 10] s, got -0.004 s"},
      {"contradictory units", R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "mass_g": 250,
        "head_to_handle_mass_ratio": 0.8}})", "/implement/mass_g", "contradicts /implement/mass_kg"},
      {"contradictory forearm", with_implement(R"("forearm": {"mass_kg": 1.5,
        "equivalent_mass_kg": 0.5})"), "/forearm/", "give only one"},
      {"contradictory impact", with_implement(R"("impact": {"from_tip_m": 0.05,
        "from_butt_m": 0.6})"), "/impact", "once"},
      {"duplicate key", R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "mass_kg": 0.3,
        "head_to_handle_mass_ratio": 0.8}})", "/implement/mass_kg", "duplicate key"},
      {"point mass beyond the tip", R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
        "head_to_handle_mass_ratio": 0.8, "point_masses": [{"from_butt_m": 0.75, "mass_g": 5}]}})",
       "/implement/point_masses/0/from_butt_m", "must be in [0, 0.7] m, got 0.75"},
      {"balance outside the length", R"({"implement": {"length_in": 27, "mass_g": 300,
        "balance_cm": 80, "swingweight_kg_cm2": 320}})", "/implement/balance_cm",
       "inside the length"},
      {"swingweight below mass at balance", R"({"implement": {"length_in": 27, "mass_g": 300,
        "balance_cm": 32, "swingweight_kg_cm2": 100}})", "/implement/swingweight_kg_cm2",
       "must be in"},
      {"impact off the implement", with_implement(R"("impact": {"from_tip_m": 0.9})"),
       "/impact/from_tip_m", "must be in [0, 0.7] m"},
      {"zero-length section", R"({"implement": {"sections": [{"length_m": 0, "mass_kg": 0.3}]}})",
       "/implement/sections/0/length_m", "must be > 0 m"},
      {"non-positive EI", R"({"implement": {"sections": [{"length_m": 0.7, "mass_kg": 0.3,
        "EI_N_m2": -5}]}})", "/implement/sections/0/EI_N_m2", "must be > 0 N m^2"},
      {"unknown reference output", with_implement(R"("reference": {"peak_force": 3})"),
       "/reference/peak_force", "unknown key"},
      {"malformed JSON", R"({"implement": {"length_m": 0.7,, }})", "", "not valid JSON"},
      {"truncated JSON", R"({"implement": {"length_m": 0.7, "mass_kg": 0.25)", "", "not valid JSON"},
      {"not an object", "[1, 2, 3]", "/", "expected a JSON object"},
      {"empty file", "", "", "empty"},
      {"binary file", std::string("\x7f" "ELF\0\0\x01", 7), "", "binary"},
      {"invalid UTF-8", with_implement("\"name\": \"\xff\xfe\""), "", "not valid JSON"},
      {"deep nesting", with_implement("\"name\": " + deep), "/name", "nesting deeper"},
  };
  for (const BadInput& c : cases) {
    INFO(c.what << ": " << c.content);
    const fs::path design = box.file("design.json", c.content);
    const fs::path output = box.path("out.json");
    const Run run = box.run("evaluate \"" + design.string() + "\" --format json --output \"" +
                            output.string() + "\"");
    INFO("stderr: " << run.err);
    CHECK(run.status == 2);
    CHECK(run.out.empty());
    CHECK(run.err.find(design.string() + ": " + c.pointer) != std::string::npos);
    CHECK(run.err.find(c.expected) != std::string::npos);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(output));
  }
}

TEST_CASE("A missing design file is bad input, not a crash") {
  const Sandbox box;
  const Run run = box.run("evaluate \"" + box.path("nowhere.json").string() + "\"");
  CHECK(run.status == 2);
  CHECK(run.err.find("cannot open") != std::string::npos);
}

TEST_CASE("Bad input never clobbers an existing output file, and no temporary is left") {
  const Sandbox box;
  const fs::path output = box.file("report.md", "previous report\n");
  const fs::path design = box.file("bad.json", with_implement(R"("frame": {"cor": -1})"));
  CHECK(box.run("evaluate \"" + design.string() + "\" --output \"" + output.string() + "\"").status ==
        2);
  CHECK(slurp(output) == "previous report\n");
  const fs::path good = box.file("good.json", with_implement(""));
  CHECK(box.run("evaluate \"" + good.string() + "\" --output \"" + output.string() + "\"").status == 0);
  CHECK(slurp(output).find("peak_wrist_force_N") != std::string::npos);
  for (const auto& entry : fs::directory_iterator(output.parent_path())) {
    CHECK(entry.path().filename().string().find(".tmp.") == std::string::npos);
  }
}

TEST_CASE("evaluate --format json carries every output the issue names") {
  const Sandbox box;
  const fs::path design = box.file("d.json", with_implement(""));
  const Run run = box.run("evaluate \"" + design.string() + "\" --format json");
  REQUIRE(run.status == 0);
  for (const char* key :
       {"\"mass_kg\"", "\"balance_from_butt_m\"", "\"I_cm_kg_m2\"", "\"swingweight_kg_cm2\"",
        "\"recoil_weight_kg_cm2\"", "\"effective_mass_kg\"", "\"apparent_cor\"",
        "\"peak_impact_force_N\"", "\"wrist_force_ratio\"", "\"peak_wrist_force_N\"",
        "\"cop_free_from_tip_m\"", "\"cop_hand_from_tip_m\"", "\"rotation_axis_free_from_butt_m\"",
        "\"rotation_axis_hand_from_butt_m\"", "\"system_com_from_butt_m\"", "\"system_I_cm_kg_m2\""}) {
    INFO(key);
    CHECK(run.out.find(key) != std::string::npos);
  }
}

TEST_CASE("An axis at infinity is null in JSON with the reason beside it") {
  const Sandbox box;
  // A uniform 0.7 m beam with no hand, struck at its centre.
  const fs::path design = box.file("c.json", R"({"implement": {"sections": [{"length_m": 0.7,
      "mass_kg": 0.3}]}, "hand": {"mass_kg": 0}, "forearm": {"equivalent_mass_kg": 0},
      "impact": {"from_butt_m": 0.35}})");
  const Run run = box.run("evaluate \"" + design.string() + "\" --format json");
  REQUIRE(run.status == 0);
  CHECK(run.out.find("\"rotation_axis_free_from_butt_m\": null") != std::string::npos);
  CHECK(run.out.find("at infinity") != std::string::npos);
  // Every null output carries its reason: no NaN slipped out as a bare null.
  const nlohmann::json j = nlohmann::json::parse(run.out);
  for (const auto& [name, value] : j["outputs"].items()) {
    INFO(name);
    CHECK((!value.is_null() || j["notes"].contains(name)));
  }
}

TEST_CASE("Usage errors exit 2 and --help, --version exit 0") {
  const Sandbox box;
  CHECK(box.run("").status == 2);
  CHECK(box.run("frobnicate").status == 2);
  CHECK(box.run("evaluate").status == 2);
  CHECK(box.run("figure 7").status == 2);
  CHECK(box.run("evaluate x.json --format xml").status == 2);
  const Run help = box.run("--help");
  CHECK(help.status == 0);
  CHECK(help.out.find("evaluate") != std::string::npos);
  CHECK(box.run("evaluate --help").status == 0);
  const Run version = box.run("--version");
  CHECK(version.status == 0);
  CHECK(version.out.find("sweetspot ") != std::string::npos);
}

}  // namespace

namespace {

TEST_CASE("optimize --format json carries the keys the issue names") {
  const Sandbox box;
  const Run run = box.run(std::string("optimize \"") + SWEETSPOT_SOURCE_DIR +
                          "/designs/studies/4-robust-lowest-worst-wrist-force.json\" --format json");
  REQUIRE(run.status == 0);
  const nlohmann::json j = nlohmann::json::parse(run.out);
  for (const char* key : {"best_design", "objective_value", "evaluations", "termination", "seconds"}) {
    INFO(key);
    CHECK(j.contains(key));
  }
  // The best design is a complete design file that evaluate accepts.
  const fs::path best = box.file("best.json", j["best_design"].dump());
  CHECK(box.run("evaluate \"" + best.string() + "\"").status == 0);
}

TEST_CASE("A bad study exits 2 naming the study file and its JSON path") {
  const Sandbox box;
  const std::string design = std::string(SWEETSPOT_SOURCE_DIR) + "/designs/table1/row1.json";
  struct Case {
    std::string study;
    const char* pointer;
  } cases[] = {
      {R"({"design": ")" + design + R"(", "variables": [{"path": "/implement/colour", "min": 0, "max": 1}],
          "objective": {"output": "peak_wrist_force_N"}})", "/variables/0/path"},
      {R"({"design": ")" + design + R"(", "variables": [{"path": "/frame/cor", "min": 0.8, "max": 0.6}],
          "objective": {"output": "peak_wrist_force_N"}})", "/variables/0/min"},
      {R"({"design": ")" + design + R"(", "variables": [{"path": "/frame/cor", "min": 0.6, "max": 0.8}],
          "objective": {"output": "comfort"}})", "/objective/output"},
      {R"({"design": ")" + design + R"(", "variables": [{"path": "/frame/cor", "min": 0.6, "max": 0.8}],
          "objective": {"output": "peak_wrist_force_N"}, "algorithm": "GN_GUESS"})", "/algorithm"},
      {R"({"design": ")" + design + R"(", "variables": [{"path": "/frame/cor", "min": 0.6, "max": 0.8}]})",
       "/objective"},
  };
  for (const Case& c : cases) {
    INFO(c.study);
    const fs::path study = box.file("study.json", c.study);
    const Run run = box.run("optimize \"" + study.string() + "\"");
    INFO(run.err);
    CHECK(run.status == 2);
    CHECK(run.err.find(study.string() + ": " + c.pointer) != std::string::npos);
  }
}

TEST_CASE("sweep streams one CSV row per grid point, first variable fastest") {
  const Sandbox box;
  const fs::path csv = box.path("sweep.csv");
  const Run run = box.run(std::string("sweep \"") + SWEETSPOT_SOURCE_DIR +
                          "/designs/studies/5b-sweep-wrist-force-forearm-mass.json\" --output \"" +
                          csv.string() + "\" --quiet");
  REQUIRE(run.status == 0);
  const std::string text = slurp(csv);
  // 81 impact points x 5 forearm masses, plus the header.
  CHECK(std::count(text.begin(), text.end(), '\n') == 81 * 5 + 1);
  CHECK(text.rfind("/impact/from_tip_m,/forearm/equivalent_mass_kg,peak_wrist_force_N,error\n", 0) == 0);
}

TEST_CASE("modes reports the beam's fundamental and refuses a design without stiffness") {
  const Sandbox box;
  const Run run = box.run(std::string("modes \"") + SWEETSPOT_SOURCE_DIR + "/designs/paper-beam.json\" --format json");
  REQUIRE(run.status == 0);
  const nlohmann::json j = nlohmann::json::parse(run.out);
  CHECK(j["free"][0]["frequency_Hz"].get<double>() == Approx(193.0).epsilon(1e-9));
  const Run bad = box.run(std::string("modes \"") + SWEETSPOT_SOURCE_DIR + "/designs/table1/row1.json\"");
  CHECK(bad.status == 2);
  CHECK(bad.err.find("/frame/EI_N_m2") != std::string::npos);
}

}  // namespace

namespace {

TEST_CASE("evaluate --batch streams rows in input order, a bad row is an error row and the exit status 1") {
  const Sandbox box;
  const fs::path catalogue = box.file("catalogue.csv",
                                      "name,implement.length_in,implement.mass_g,implement.balance_cm,"
                                      "implement.swingweight_kg_cm2,impact.from_butt_m\n"
                                      "\"A, tour\",27,305,32.5,320,0.52\n"
                                      "B,27,300,80,320,0.5\n"
                                      "C,27.5,265,35.5,305,0.53\n");
  const fs::path base = box.file("base.json", R"({"implement": {"length_m": 0.7, "mass_kg": 0.3,
      "balance_cm": 33, "swingweight_kg_cm2": 320}})");
  for (const char* threads : {"1", "2"}) {
    INFO("threads " << threads);
    const Run run = box.run("evaluate --batch \"" + catalogue.string() + "\" --base \"" + base.string() +
                            "\" --threads " + threads);
    CHECK(run.status == 1);
    std::istringstream rows(run.out);
    std::string header, a, b, c;
    std::getline(rows, header);
    std::getline(rows, a);
    std::getline(rows, b);
    std::getline(rows, c);
    CHECK(a.rfind("2,\"A, tour\",0.6858,0.305,", 0) == 0);
    CHECK(b.rfind("3,,", 0) == 0);
    CHECK(b.find("catalogue.csv:3: /implement/balance_cm") != std::string::npos);
    CHECK(c.rfind("4,C,", 0) == 0);
    CHECK(run.err.find("1 of 3 rows failed") != std::string::npos);
  }
}

TEST_CASE("evaluate --batch reads JSON Lines merged over the base") {
  const Sandbox box;
  const fs::path lines = box.file("designs.jsonl", R"({"name": "light", "implement": {"mass_kg": 0.25}}
{"name": "heavy", "implement": {"mass_kg": 0.40}}
)");
  const fs::path base = box.file("base.json", R"({"implement": {"length_m": 0.7, "mass_kg": 0.3,
      "head_to_handle_mass_ratio": 0.8}})");
  const Run run = box.run("evaluate --batch \"" + lines.string() + "\" --base \"" + base.string() +
                          "\" --format json");
  REQUIRE(run.status == 0);
  std::istringstream rows(run.out);
  std::string first, second;
  std::getline(rows, first);
  std::getline(rows, second);
  // Table I rows 1 and 2: F0 = 1117 and 1341 N.
  CHECK(nlohmann::json::parse(first)["outputs"]["peak_impact_force_N"].get<double>() == Approx(1117).margin(1));
  CHECK(nlohmann::json::parse(second)["outputs"]["peak_impact_force_N"].get<double>() == Approx(1341).margin(1));
}

}  // namespace

namespace {

TEST_CASE("response writes every impact, time and point, with zero dc velocity where the paper says") {
  const Sandbox box;
  const std::string beam = std::string(SWEETSPOT_SOURCE_DIR) + "/designs/paper-beam.json";
  // The paper's COP for the disk 2 cm from the end is 23.3 cm from the other end:
  // x = 0.72 - 0.2333 from the butt (Eq. 5 exactly: 0.36 + I/(M 0.34)).
  const double cop = 0.36 + 0.72 * 0.72 / 12 / 0.34;
  const Run run = box.run("response \"" + beam + "\" --at 0.02 --impacts " + std::to_string(cop) + " --until-ms 10");
  REQUIRE(run.status == 0);
  std::istringstream rows(run.out);
  std::string line;
  std::getline(rows, line);
  CHECK(line == "impact_from_butt_m,t_s,point_from_butt_m,v_dc_m_s,v_ac_m_s,v_m_s");
  int count = 0;
  double last_dc = 1.0;
  while (std::getline(rows, line)) {
    ++count;
    std::vector<double> cells;
    std::stringstream fields(line);
    std::string cell;
    while (std::getline(fields, cell, ',')) cells.push_back(std::stod(cell));
    last_dc = cells[3];
  }
  CHECK(count == 401);
  // std::to_string keeps 6 decimals of the impact point: a 1e-6 m miss moves v_dc by ~1e-6 of its scale.
  CHECK(std::abs(last_dc) < 1e-5);
  const Run bad = box.run(std::string("response \"") + SWEETSPOT_SOURCE_DIR + "/designs/table1/row1.json\"");
  CHECK(bad.status == 2);
  CHECK(bad.err.find("/frame/EI_N_m2") != std::string::npos);
}

TEST_CASE("evaluate asks for the response model when the COR is to be derived") {
  const Sandbox box;
  const fs::path design = box.file("d.json", R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "frame": {"cor_rigid": 0.85, "fundamental_free_Hz": 150}})");
  const Run rigid = box.run("evaluate \"" + design.string() + "\" --fidelity rigid");
  CHECK(rigid.status == 2);
  CHECK(rigid.err.find("/frame/cor_rigid") != std::string::npos);
  const Run run = box.run("evaluate \"" + design.string() + "\" --format json");
  REQUIRE(run.status == 0);
  const nlohmann::json j = nlohmann::json::parse(run.out);
  CHECK(j["fidelity"] == "response");
  for (const char* key : {"cor", "impact_duration_s", "vibration_energy_J"}) {
    INFO(key);
    CHECK(j["outputs"][key].is_number());
  }
  CHECK(j["inputs"]["frame/cor"]["provenance"].get<std::string>().find("derived") != std::string::npos);
}

TEST_CASE("modes accepts a design whose COR is to be derived, as evaluate and response do") {
  const Sandbox box;
  const fs::path design = box.file("d.json", R"({"implement": {"length_m": 0.7, "mass_kg": 0.25,
      "head_to_handle_mass_ratio": 0.8}, "frame": {"cor_rigid": 0.85, "fundamental_free_Hz": 150}})");
  for (const char* command : {"evaluate", "response", "modes"}) {
    INFO(command);
    const Run run = box.run(std::string(command) + " \"" + design.string() + "\"");
    CHECK(run.status == 0);
    CHECK(run.err.empty());
  }
  const Run modes = box.run("modes \"" + design.string() + "\" --format json");
  REQUIRE(modes.status == 0);
  CHECK(nlohmann::json::parse(modes.out)["free"][0]["frequency_Hz"].get<double>() == Approx(150.0).epsilon(1e-9));
}

}  // namespace

namespace {

TEST_CASE("An infeasible study writes its report and exits 2 naming /constraints") {
  const Sandbox box;
  const fs::path study = box.file("infeasible.json", std::string(R"({"design": ")") + SWEETSPOT_SOURCE_DIR +
                                                         R"(/designs/table1/row1.json",
      "variables": [{"path": "/implement/mass_kg", "min": 0.25, "max": 0.40}],
      "objective": {"output": "peak_wrist_force_N"},
      "constraints": [{"output": "swingweight_kg_cm2", "max": 100}]})");
  const fs::path report = box.path("report.md");
  const Run run = box.run("optimize \"" + study.string() + "\" --output \"" + report.string() + "\"");
  CHECK(run.status == 2);
  CHECK(run.err.find(study.string() + ": /constraints: no design") != std::string::npos);
  CHECK(slurp(report).find("No feasible design was found") != std::string::npos);
}

TEST_CASE("A design's own fidelity is used unless the command line says otherwise") {
  const Sandbox box;
  const fs::path design = box.file("d.json", std::string(R"({"fidelity": "rigid", "implement": {"sections":
      [{"length_m": 0.72, "mass_kg": 0.328}]}, "frame": {"fundamental_free_Hz": 193}})"));
  const Run rigid = box.run("evaluate \"" + design.string() + "\" --format json");
  REQUIRE(rigid.status == 0);
  CHECK(nlohmann::json::parse(rigid.out)["fidelity"] == "rigid");
  const Run modal = box.run("evaluate \"" + design.string() + "\" --format json --fidelity modal");
  REQUIRE(modal.status == 0);
  CHECK(nlohmann::json::parse(modal.out)["fidelity"] == "modal");
}

}  // namespace

namespace {

TEST_CASE("A usage error is one line on stderr, prefixed, exit 2") {
  const Sandbox box;
  for (const char* args : {"evaluate", "bogus", "evaluate x.json --threads 0", "response x.json --until-ms -5"}) {
    INFO(args);
    const Run run = box.run(args);
    CHECK(run.status == 2);
    CHECK(run.err.rfind("sweetspot: ", 0) == 0);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  }
}

TEST_CASE("Output that cannot be written exits 1, and streamed files are readable by all") {
  const Sandbox box;
  const std::string full = std::string("\"") + SWEETSPOT_CLI + "\" evaluate \"" + SWEETSPOT_SOURCE_DIR +
                           "/designs/table1/row1.json\" >/dev/full 2>/dev/null";
  const int raw = std::system(full.c_str());
  CHECK((WIFEXITED(raw) && WEXITSTATUS(raw) == 1));
  const fs::path csv = box.path("sweep.csv");
  REQUIRE(box.run(std::string("sweep \"") + SWEETSPOT_SOURCE_DIR +
                  "/designs/studies/5b-sweep-wrist-force-forearm-mass.json\" -q -o \"" + csv.string() + "\"")
              .status == 0);
  CHECK((fs::status(csv).permissions() & fs::perms::others_read) != fs::perms::none);
}

TEST_CASE("A study whose fidelity cannot give its outputs, or whose grid is absurd, exits 2") {
  const Sandbox box;
  const std::string design = std::string(SWEETSPOT_SOURCE_DIR) + "/designs/studies/table1-racquet-flexible.json";
  const fs::path rigid = box.file("rigid.json", R"({"design": ")" + design + R"(", "fidelity": "rigid",
      "variables": [{"path": "/implement/mass_kg", "min": 0.25, "max": 0.4}],
      "objective": {"output": "peak_wrist_force_N"},
      "constraints": [{"output": "fundamental_free_Hz", "min": 100}]})");
  const Run a = box.run("optimize \"" + rigid.string() + "\"");
  CHECK(a.status == 2);
  CHECK(a.err.find(rigid.string() + ": /fidelity") != std::string::npos);
  const fs::path huge = box.file("huge.json", R"({"design": ")" + design + R"(",
      "variables": [{"path": "/implement/mass_kg", "min": 0.25, "max": 0.4, "points": 1e10}],
      "outputs": ["peak_wrist_force_N"]})");
  const Run b = box.run("sweep \"" + huge.string() + "\"");
  CHECK(b.status == 2);
  CHECK(b.err.find(huge.string() + ": /variables/0/points") != std::string::npos);
}

TEST_CASE("evaluate --batch uses each design's own fidelity unless --fidelity is given") {
  const Sandbox box;
  const fs::path lines = box.file("d.jsonl", R"({"fidelity": "modal", "implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8}}
)");
  const Run own = box.run("evaluate --batch \"" + lines.string() + "\" --format json");
  CHECK(own.status == 1);  // modal without a stiffness: that row fails
  CHECK(own.out.find("/frame/EI_N_m2") != std::string::npos);
  CHECK(box.run("evaluate --batch \"" + lines.string() + "\" --fidelity rigid").status == 0);
}

TEST_CASE("report with no designs folder and response with an empty point exit 2 and write nothing") {
  const Sandbox box;
  const fs::path out = box.path("reports");
  const Run report = box.run("report --designs \"" + box.path("nowhere").string() + "\" --out \"" + out.string() + "\"");
  CHECK(report.status == 2);
  CHECK(report.err.find("not a folder of designs") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  // CLI11 would read "" as 0, the butt: refused instead.
  const Run response = box.run(std::string("response \"") + SWEETSPOT_SOURCE_DIR + "/designs/paper-beam.json\" --at \"\"");
  CHECK(response.status == 2);
  CHECK(response.err.find("--at: an empty point") != std::string::npos);
  CHECK(response.out.empty());
}

}  // namespace
