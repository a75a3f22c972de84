// The compiled path (a study variable, sweep axis or batch column bound once
// to a typed design) against its oracle, the JSON path (the number written
// into the document and the design read again): the same designs bit for bit,
// the same CSV bytes and the same error rows, on good and bad points alike.
#include "studies/design_binding.hpp"

#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/design_fields.hpp"
#include "io/design_reader.hpp"
#include "io/format.hpp"
#include "io/outputs.hpp"
#include "studies/batch.hpp"
#include "studies/optimization.hpp"
#include "studies/study.hpp"
#include "studies/sweep.hpp"

namespace sweetspot::studies {
namespace {

std::string studies() { return std::string(SWEETSPOT_SOURCE_DIR) + "/designs/studies/"; }

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Every number of the rigid model and the implement, compared bit for bit.
void check_same_design(const Design& a, const Design& b) {
  CHECK(same_bits(a.implement.length_m(), b.implement.length_m()));
  const MassProperties& p = a.implement.mass_properties();
  const MassProperties& q = b.implement.mass_properties();
  CHECK(same_bits(p.mass_kg, q.mass_kg));
  CHECK(same_bits(p.com_from_butt_m, q.com_from_butt_m));
  CHECK(same_bits(p.I_cm_kg_m2, q.I_cm_kg_m2));
  CHECK(a.implement.sections().size() == b.implement.sections().size());
  CHECK(a.implement.point_masses().size() == b.implement.point_masses().size());
  CHECK(same_bits(a.cor, b.cor));
  CHECK(same_bits(a.impact_duration_s, b.impact_duration_s));
  CHECK(same_bits(a.hand.mass_kg, b.hand.mass_kg));
  CHECK(same_bits(a.hand.center_from_butt_m, b.hand.center_from_butt_m));
  CHECK(same_bits(a.forearm_equivalent_mass_kg, b.forearm_equivalent_mass_kg));
  CHECK(same_bits(a.ball.mass_kg, b.ball.mass_kg));
  CHECK(same_bits(a.ball.speed_m_s, b.ball.speed_m_s));
  CHECK(same_bits(a.impact_from_butt_m, b.impact_from_butt_m));
  CHECK(same_bits(a.implement.frame_mass_properties().I_cm_kg_m2,
                  b.implement.frame_mass_properties().I_cm_kg_m2));
  const std::vector<PointMass>& pa = a.implement.point_masses();
  const std::vector<PointMass>& pb = b.implement.point_masses();
  for (std::size_t k = 0; k < pa.size() && k < pb.size(); ++k) {
    CHECK(same_bits(pa[k].from_butt_m, pb[k].from_butt_m));
    CHECK(same_bits(pa[k].mass_kg, pb[k].mass_kg));
    CHECK(same_bits(pa[k].off_axis_m, pb[k].off_axis_m));
  }
  CHECK(a.head.has_value() == b.head.has_value());
  if (a.head && b.head) {
    CHECK(same_bits(a.head->area_m2, b.head->area_m2));
    CHECK(same_bits(a.head->aspect_ratio, b.head->aspect_ratio));
    CHECK(same_bits(a.head->hoop_width_m, b.head->hoop_width_m));
  }
  CHECK(a.strings.has_value() == b.strings.has_value());
  if (a.strings && b.strings) {
    CHECK(same_bits(a.strings->tension_N, b.strings->tension_N));
    CHECK(same_bits(a.strings->head_radius_m, b.strings->head_radius_m));
  }
}

// A design of each implement form, and pointers with values (good and bad) for it.
struct Case {
  const char* design;
  std::vector<std::pair<const char*, std::vector<double>>> fields;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> list{
      {R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
          "strings": {"impact_duration_ms": 4}, "forearm": {"mass_kg": 1.5}, "impact": {"from_tip_cm": 5}})",
       {{"/implement/mass_kg", {0.3, -0.1, 0.0}},
        {"/implement/head_to_handle_mass_ratio", {1.2, -1.0}},
        {"/implement/length_m", {0.68, 0.03}},
        {"/strings/impact_duration_ms", {5.0, 0.0}},
        {"/forearm/mass_kg", {1.2, -3.0}},
        {"/impact/from_tip_cm", {12.0, -1.0, 90.0}}}},
      {R"({"implement": {"length_in": 27, "mass_g": 305, "balance_pts_hl": 4, "swingweight_kg_cm2": 320},
          "frame": {"cor": 0.8}, "ball": {"speed_mph": 100}, "impact": {"from_butt_mm": 500}})",
       {{"/implement/balance_pts_hl", {6.0, 200.0, -3.0}},
        {"/implement/swingweight_kg_cm2", {330.0, 1.0, 5000.0}},
        {"/implement/length_in", {27.5, 1.0}},
        {"/implement/mass_g", {290.0, -5.0}},
        {"/frame/cor", {0.6, 1.5}},
        {"/ball/speed_mph", {90.0, -10.0}},
        {"/impact/from_butt_mm", {450.0, 900.0}}}},
      {R"({"implement": {"length_cm": 68.5, "mass_kg": 0.31, "balance_cm": 32, "swingweight_kg_m2": 0.032},
          "hand": {"mass_g": 450, "center_from_butt_cm": 8}, "forearm": {"equivalent_mass_g": 400}})",
       {{"/implement/balance_cm", {33.0, 0.0, 80.0}},
        {"/implement/swingweight_kg_m2", {0.031, 0.2}},
        {"/hand/mass_g", {500.0, -1.0}},
        {"/hand/center_from_butt_cm", {7.0, 100.0}},
        {"/forearm/equivalent_mass_g", {300.0, -2.0}}}},
      {R"({"implement": {"sections": [{"length_m": 0.35, "mass_kg": 0.14, "EI_N_m2": 300},
                                      {"length_cm": 35, "mass_g": 110}],
                         "point_masses": [{"from_butt_m": 0.68, "mass_g": 6}]},
          "frame": {"EI_N_m2": 250}, "strings": {"tension_lb": 55, "head_size_in2": 98}})",
       {{"/implement/sections/0/length_m", {0.36, -0.1}},
        {"/implement/sections/1/mass_g", {120.0, -1.0}},
        {"/implement/sections/0/EI_N_m2", {280.0, -5.0}},
        {"/implement/point_masses/0/from_butt_m", {0.6, 0.9}},
        {"/implement/point_masses/0/mass_g", {8.0, -1.0}},
        {"/strings/tension_lb", {60.0, -1.0, 1e9}},
        {"/strings/head_size_in2", {100.0, 0.0, 1e5}},
        {"/frame/EI_N_m2", {260.0, -1.0}}}},
      // A racquet with a head and no impact (hit at the centre of its strings),
      // tape placed relative to the geometry: each follows a length or head
      // that changes, and list index N is the file's entry N.
      {R"({"implement": {"length_in": 27, "mass_g": 300, "balance_cm": 32.5, "swingweight_kg_cm2": 320,
                         "headsize_sq_in": 100, "point_masses": [{"clock": 12, "mass_g": 3},
                         {"clock": [3, 9], "mass_g": 2}, {"clock": "handle", "mass_g": 10},
                         {"from_tip_cm": 20, "off_axis_cm": 4, "mass_g": 2}]},
          "frame": {"RA": 66}, "strings": {"tension_lb": 52}})",
       {{"/implement/length_in", {29.0, 27.5, 10.0}},
        {"/implement/point_masses/0/mass_g", {20.0, -1.0}},
        {"/implement/point_masses/1/mass_g", {5.0, -1.0}},
        {"/implement/point_masses/2/mass_g", {20.0, 2e9}},
        {"/implement/point_masses/0/clock", {11.0, 13.0, -1.0}},
        {"/implement/point_masses/3/from_tip_cm", {30.0, 100.0}},
        {"/implement/point_masses/3/off_axis_cm", {-4.0, 200.0}},
        {"/implement/headsize_sq_in", {95.0, 110.0, 0.0, 1e5}},
        {"/implement/head_aspect_ratio", {1.2, 0.5}},
        {"/impact/from_tip_cm", {10.0, 100.0}}}},
      // The head given as the string bed's size alone (one head, one size):
      // the clock positions are placed on it and follow it.
      {R"({"implement": {"length_in": 27, "mass_g": 300, "balance_cm": 32.5, "swingweight_kg_cm2": 320,
                         "point_masses": [{"clock": 12, "mass_g": 3}, {"clock": [3, 9], "mass_g": 2}]},
          "frame": {"RA": 66}, "strings": {"tension_lb": 52, "head_size_in2": 100}})",
       {{"/strings/head_size_in2", {95.0, 110.0, 0.0, 1e5}},
        {"/implement/point_masses/0/clock", {11.0, 13.0}},
        {"/implement/point_masses/1/mass_g", {5.0, -1.0}},
        {"/implement/length_in", {29.0, 10.0}}}},
      // The paper's racquet with a head: the throat follows its length.
      {R"({"implement": {"length_m": 0.7, "mass_kg": 0.3, "head_to_handle_mass_ratio": 0.8,
                         "headsize_cm2": 600, "point_masses": [{"clock": "throat", "mass_g": 5}]}})",
       {{"/implement/length_m", {0.68, 0.75, 0.3}},
        {"/implement/headsize_cm2", {650.0, -1.0}},
        {"/implement/point_masses/0/mass_g", {10.0, -1.0}}}},
      // Sections with a head: tape at 10.5 and from the tip follows a section's length.
      {R"({"implement": {"sections": [{"length_m": 0.35, "mass_kg": 0.14}, {"length_m": 0.35, "mass_kg": 0.11}],
                         "headsize_sq_in": 100, "point_masses": [{"clock": 10.5, "mass_g": 4},
                         {"from_tip_cm": 10, "mass_g": 3}]}, "frame": {"EI_N_m2": 250}})",
       {{"/implement/sections/1/length_m", {0.4, 0.3, 0.01}},
        {"/implement/sections/0/mass_kg", {0.15, -1.0}},
        {"/implement/point_masses/1/from_tip_cm", {20.0, 90.0}}}},
  };
  return list;
}

TEST_CASE(
    "A bound field gives, bit for bit, the design read from the file with the value written "
    "there") {
  for (const Case& c : cases()) {
    const io::Json document = io::Json::parse(c.design);
    const io::DesignDescription description = io::describe_design(document, "design.json");
    for (const auto& [pointer, values] : c.fields) {
      INFO(c.design << "\n" << pointer);
      const std::vector<std::string> pointers{pointer};
      const auto compiled = studies::CompiledDesign::compile(description, pointers);
      REQUIRE(compiled);
      studies::BoundDesign bound(*compiled);
      for (const double value : values) {
        INFO("value " << value);
        io::Json changed = document;
        changed[io::Json::json_pointer(pointer)] = value;
        std::optional<io::DesignFile> read;
        try {
          read.emplace(io::read_design(changed, "design.json"));
        } catch (const std::exception&) {
        }
        const Design* design = bound.at(std::span<const double>(&value, 1));
        // The binding never accepts what the reader refuses (it may leave to
        // the reader what it accepts, never the other way round).
        if (!read) CHECK(design == nullptr);
        REQUIRE((design != nullptr) == read.has_value());
        if (design) check_same_design(*design, read->design);
      }
    }
  }
}

TEST_CASE("Fields no binding can set are not compiled") {
  const io::Json document = io::Json::parse(cases()[0].design);
  const io::DesignDescription description = io::describe_design(document, "design.json");
  for (const char* pointer :
       {"/name", "/reference/peak_wrist_force_N", "/implement/balance_cm",
        "/implement/sections/0/mass_kg", "/impact/from_butt_m", "/forearm/equivalent_mass_kg",
        "/strings/tension_N", "/frame/cor_rigid", "/hand", "/implement/mass_kg/x",
        "hand/mass_kg"}) {
    INFO(pointer);
    CHECK_FALSE(studies::bind_field(description, pointer));
  }
  CHECK(studies::bind_field(description, "/hand/mass_g")->scale.factor == 0.001);
  CHECK(studies::bind_field(description, "/impact/from_tip_in")->scale.factor == 0.0254);
  CHECK(studies::bind_field(description, "/implement/mass_g")->implement);
  CHECK_FALSE(studies::bind_field(description, "/hand/mass_g")->implement);
}

std::string sweep_csv(const studies::Study& study, studies::SweepOptions options) {
  std::ostringstream csv;
  studies::run_sweep(
      study, csv, [](std::size_t, std::size_t) {}, options);
  return csv.str();
}

TEST_CASE(
    "A compiled sweep writes the bytes of the sweep that reads every point, error rows included") {
  for (const Case& c : cases()) {
    for (std::size_t i = 0; i + 1 < c.fields.size(); ++i) {
      const auto& [first, a] = c.fields[i];
      const auto& [second, b] = c.fields[i + 1];
      io::Json text =
          io::Json::parse(R"({"outputs": ["peak_wrist_force_N", "mass_kg", "swingweight_kg_cm2",
                                  "impact_from_tip_m", "impact_duration_s", "rotation_axis_free_from_butt_m"]})");
      text["design"] = io::Json::parse(c.design);
      text["variables"] = io::Json::array(
          {io::Json{{"path", first}, {"values", a}}, io::Json{{"path", second}, {"values", b}}});
      INFO(text.dump());
      studies::Study study;
      try {
        study = studies::read_study(text, "sweep.json", studies());
      } catch (const std::exception& e) {
        continue;  // a start point the study refuses: nothing to sweep
      }
      REQUIRE(studies::compiled_for_variables(study));
      const std::string reference = sweep_csv(study, studies::SweepOptions{1, false, false});
      CHECK(sweep_csv(study, studies::SweepOptions{1, false, true}) == reference);
      CHECK(sweep_csv(study, studies::SweepOptions{2, true, true}) == reference);
    }
  }
}

TEST_CASE(
    "A rigid sweep of rigid_outcome()'s outputs alone writes what evaluating every point writes") {
  // The oracle is the sweep that reads every point from JSON and evaluates it
  // whole (evaluate()): each output evaluate_rigid_outcome() answers, alone
  // and all together, at good and bad points, on the axis and off it (where
  // the whole evaluation answers), bit for bit in the CSV.
  const auto names = studies::rigid_outcome_outputs();
  std::vector<io::Json> output_lists;
  for (const std::string_view name : names) {
    REQUIRE(io::find_output(name));
    output_lists.push_back(io::Json::array({std::string(name)}));
  }
  output_lists.push_back(io::Json::array());
  for (const std::string_view name : names) output_lists.back().push_back(std::string(name));
  const char* designs[] = {
      R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
          "frame": {"cor": 0.8}, "strings": {"impact_duration_ms": 4},
          "hand": {"mass_kg": 0.5, "center_from_butt_m": 0.07}, "forearm": {"equivalent_mass_kg": 0.5}})",
      R"({"implement": {"length_in": 27, "mass_g": 305, "balance_pts_hl": 4, "swingweight_kg_cm2": 320,
          "twistweight_kg_cm2": 14}, "frame": {"cor": 0.8}, "impact": {"from_tip_cm": 12, "off_axis_cm": 3},
          "hand": {"mass_g": 450, "center_from_butt_cm": 8}, "forearm": {"equivalent_mass_kg": 0.5}})"};
  std::size_t points = 0;
  for (const char* design : designs) {
    for (const io::Json& outputs : output_lists) {
      io::Json text = io::Json::object();
      text["design"] = io::Json::parse(design);
      text["outputs"] = outputs;
      text["fidelity"] = "rigid";
      text["variables"] =
          io::Json::parse(R"([{"path": "/hand/mass_kg", "values": [0.3, 0.0, -0.2, 0.45]},
          {"path": "/forearm/equivalent_mass_kg", "values": [0.5, 0.0, -1.0, 2.0]}])");
      INFO(text.dump());
      const studies::Study study = studies::read_study(text, "sweep.json", studies());
      REQUIRE(studies::compiled_for_variables(study));
      const std::string reference = sweep_csv(study, studies::SweepOptions{1, false, false, false});
      CHECK(reference.find("must be") != std::string::npos);  // bad points too
      CHECK(sweep_csv(study, studies::SweepOptions{1, true, true, true}) == reference);
      CHECK(sweep_csv(study, studies::SweepOptions{1, true, true, false}) == reference);
      points += 16;
    }
  }
  CHECK(points == 2 * 8 * 16);
}

TEST_CASE("Every point of a hand x forearm sweep is the point read from JSON, off the range too") {
  const studies::Study study =
      studies::read_study(io::Json::parse(R"({"design": "../table1/row1.json",
      "outputs": ["peak_wrist_force_N", "wrist_force_ratio", "cop_hand_from_tip_m"],
      "variables": [{"path": "/hand/mass_kg", "min": -0.2, "max": 0.6, "points": 17},
                    {"path": "/forearm/equivalent_mass_kg", "min": -0.1, "max": 1.0, "points": 12}]})"),
                          "sweep.json", studies());
  const std::string reference = sweep_csv(study, studies::SweepOptions{1, true, false});
  CHECK(reference.find("/hand/mass_kg: must be in") != std::string::npos);
  CHECK(reference.find("/forearm/equivalent_mass_kg: must be in") != std::string::npos);
  CHECK(sweep_csv(study, studies::SweepOptions{1, true, true}) == reference);
}

std::string batch_output(const std::string& csv, const studies::BatchOptions& options) {
  std::istringstream in(csv);
  std::ostringstream out;
  studies::run_batch(in, "catalogue.csv", options, out);
  return out.str();
}

TEST_CASE("A compiled batch writes the rows and error rows of the batch that reads every row") {
  const std::string catalogue =
      "name,implement.length_in,implement.mass_g,implement.balance_cm,implement.swingweight_kg_cm2,"
      "impact.from_tip_m\n"
      "a,27,305,32.5,320,0.1\n"
      ",27.5,290,33,310,0.12\n"
      "\"quoted, name\",27,300,31,330,\n"
      "bad mass,27,-5,32,320,0.1\n"
      "impossible swingweight,27,305,32.5,5000,0.1\n"
      "off the implement,27,305,32.5,320,2\n"
      "not a number,27,abc,32,320,0.1\n"
      "short row,27,305\n"
      "inf,27,inf,32,320,0.1\n"
      "balance outside,27,305,90,320,0.1\n"
      ",,,,,\n"
      "b,26.5,310,32,315,0.05\n";
  for (const char* base :
       {R"({"implement": {"length_in": 27, "mass_g": 305, "balance_cm": 32.5,
                               "swingweight_kg_cm2": 320}, "frame": {"cor": 0.8}})",
        R"({"name": "base", "implement": {"length_in": 27, "mass_g": 305, "balance_pts_hl": 4,
                               "swingweight_kg_cm2": 320}, "forearm": {"mass_kg": 1.2}})"}) {
    for (const io::Format format : {io::Format::kCsv, io::Format::kJson}) {
      INFO(base << (format == io::Format::kCsv ? " to CSV" : " to JSON"));
      studies::BatchOptions options;
      options.input = studies::CatalogueFormat::kCsv;
      options.base = io::Json::parse(base);
      options.format = format;
      options.compiled = false;
      const std::string reference = batch_output(catalogue, options);
      CHECK(reference.find("catalogue.csv:5") != std::string::npos);
      for (const int threads : {1, 2}) {
        options.compiled = true;
        options.threads = threads;
        CHECK(batch_output(catalogue, options) == reference);
      }
    }
  }
}

TEST_CASE("A column the base's implement form does not have is the header's error on either path") {
  // The columns describe specs; a base given by head/handle ratio has no such keys.
  const std::string catalogue = "name,implement.balance_cm\na,32\n";
  for (const bool compiled : {false, true}) {
    studies::BatchOptions options;
    options.input = studies::CatalogueFormat::kCsv;
    options.base = io::Json::parse(
        R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8}})");
    options.compiled = compiled;
    CHECK_THROWS_WITH(
        batch_output(catalogue, options),
        Catch::StartsWith("catalogue.csv:1: column 2 \"implement.balance_cm\": belongs to "
                          "another way of giving the implement than its "
                          "head_to_handle_mass_ratio"));
  }
}

TEST_CASE("A column no binding sets leaves its rows to the JSON path with the same output") {
  const std::string catalogue =
      "name,reference.peak_wrist_force_N,hand.mass_kg,frame.cor_rigid\n"
      "a,500,0.4,\n"
      "b,,0.45,\n"
      "c,,0.5,0.9\n";
  studies::BatchOptions options;
  options.input = studies::CatalogueFormat::kCsv;
  options.base = io::Json::parse(
      R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8}})");
  options.compiled = false;
  const std::string reference = batch_output(catalogue, options);
  options.compiled = true;
  CHECK(batch_output(catalogue, options) == reference);
}

TEST_CASE("An optimisation's compiled evaluations equal the JSON path's, at good and bad points") {
  for (const char* name :
       {"1-lowest-wrist-force-table1-ranges.json", "2-lowest-wrist-force-fixed-feel.json",
        "3a-cop-on-node-table1-racquet.json", "4-robust-lowest-worst-wrist-force.json"}) {
    INFO(name);
    studies::Study study = studies::load_study(studies() + name);
    REQUIRE(studies::compiled_for_variables(study));
    const optimizer::Problem compiled = make_problem(study);
    const std::shared_ptr<const CompiledDesign> kept = study.compiled;
    study.compiled.reset();
    const optimizer::Problem reference = make_problem(study);
    study.compiled = kept;
    const std::size_t n = compiled.start.size();
    for (const double t : {0.0, 0.3, 1.0, -0.5, 2.0}) {
      std::vector<double> x(n);
      for (std::size_t i = 0; i < n; ++i) {
        x[i] = compiled.lower[i] +
               (compiled.upper[i] - compiled.lower[i]) * (t + 0.1 * static_cast<double>(i));
      }
      INFO("t = " << t);
      double f1 = 0.0, f2 = 0.0;
      std::vector<double> c1(compiled.constraints.size()), c2(compiled.constraints.size());
      compiled.evaluate(x, f1, c1);
      reference.evaluate(x, f2, c2);
      CHECK(same_bits(f1, f2));
      for (std::size_t k = 0; k < c1.size(); ++k) CHECK(same_bits(c1[k], c2[k]));
    }
  }
}

TEST_CASE("The report's start and best outputs, kept from the search, are a fresh evaluation's") {
  // run_optimization takes them from the search's own evaluations (the
  // compiled design) instead of reading and evaluating the designs again:
  // every output must be what the JSON path gives, bit for bit.
  for (const char* name :
       {"1-lowest-wrist-force-table1-ranges.json", "2-lowest-wrist-force-fixed-feel.json",
        "3a-cop-on-node-table1-racquet.json", "4-robust-lowest-worst-wrist-force.json"}) {
    INFO(name);
    const studies::Study study = studies::load_study(studies() + name);
    const studies::OptimizationResult r = run_optimization(study);
    REQUIRE(r.start_outputs);
    REQUIRE(r.best_outputs);
    const Evaluation start = studies::evaluate_in(study, r.start),
                     best = evaluate_in(study, r.best);
    for (const io::OutputSpec& spec : io::output_specs()) {
      INFO(spec.name);
      const auto same = [&](const Evaluation& a, const Evaluation& b) {
        const std::optional<double> va = spec.value(a), vb = spec.value(b);
        return va.has_value() == vb.has_value() && (!va || same_bits(*va, *vb));
      };
      CHECK(same(*r.start_outputs, start));
      CHECK(same(*r.best_outputs, best));
    }
  }
}

}  // namespace
}  // namespace sweetspot::studies

namespace sweetspot::studies {
namespace {

// The outputs of evaluate --batch's first row, in CSV or JSON Lines.
std::string first_row_outputs(const std::string& csv, const char* base, io::Format format,
                              bool compiled) {
  studies::BatchOptions options;
  options.input = studies::CatalogueFormat::kCsv;
  options.base = io::Json::parse(base);
  options.format = format;
  options.compiled = compiled;
  const std::string out = batch_output(csv, options);
  if (format == io::Format::kJson) {
    const io::Json row = io::Json::parse(out.substr(0, out.find('\n')));
    return row.at("outputs").dump();
  }
  const std::size_t second = out.find('\n') + 1;
  const std::string line = out.substr(second, out.find('\n', second) - second);
  return line.substr(line.find(',', line.find(',') + 1));  // without line and name
}

}  // namespace

TEST_CASE(
    "Each index of the file's point-mass list means the same entry in every command, a clock "
    "pair one entry") {
  constexpr const char* kBase =
      R"({"name": "tape", "implement": {"length_in": 27, "mass_g": 300, "balance_cm": 32.5,
          "swingweight_kg_cm2": 320, "headsize_sq_in": 100,
          "point_masses": [{"clock": 12, "mass_g": 3}, {"clock": [3, 9], "mass_g": 2},
                           {"clock": "handle", "mass_g": 10}]},
          "frame": {"cor": 0.8}})";
  const io::Json base = io::Json::parse(kBase);
  const io::DesignDescription description = io::describe_design(base, "tape.json");
  const double frame_mass =
      io::read_design(base, "tape.json").design.implement.mass_properties().mass_kg;
  for (std::size_t n = 0; n < 3; ++n) {
    INFO("entry " << n);
    const std::string pointer = "/implement/point_masses/" + std::to_string(n) + "/mass_g";
    // The file with entry n at 20 g: the oracle.
    io::Json changed = base;
    changed[io::Json::json_pointer(pointer)] = 20.0;
    const io::DesignFile file = io::read_design(changed, "tape.json");
    // The entry's mass is each piece's: the pair adds 2 x 18 g, the others 17 g and 10 g.
    const double added[] = {0.017, 0.036, 0.010};
    CHECK(file.design.implement.mass_properties().mass_kg - frame_mass ==
          Approx(added[n]).epsilon(1e-12));
    // A study variable or sweep axis (the binding).
    const std::vector<std::string> pointers{pointer};
    const auto compiled = studies::CompiledDesign::compile(description, pointers);
    REQUIRE(compiled);
    studies::BoundDesign bound(*compiled);
    const double value = 20.0;
    const Design* design = bound.at(std::span<const double>(&value, 1));
    REQUIRE(design);
    check_same_design(*design, file.design);
    // Catalogue columns: the compiled CSV path, the JSON path, and JSON Lines.
    const std::string csv =
        "name,implement.point_masses." + std::to_string(n) + ".mass_g\nrow,20\n";
    const std::string reference = first_row_outputs(csv, kBase, io::Format::kCsv, false);
    CHECK(first_row_outputs(csv, kBase, io::Format::kCsv, true) == reference);
    const io::Json lines = io::Json::parse(first_row_outputs(csv, kBase, io::Format::kJson, true));
    const Evaluation e = evaluate(file.design, Fidelity::kRigid);
    for (const char* name : {"swingweight_kg_cm2", "mass_kg", "balance_from_butt_m"}) {
      const double value = *io::find_output(name)->value(e);
      CHECK(same_bits(lines.at(name).get<double>(), value));
      CHECK(reference.find("," + io::exact(value) + ",") != std::string::npos);
    }
  }
}

TEST_CASE(
    "Tape at 12 o'clock follows a swept length: the swingweight at 29 in is the file's at 29 in, "
    "bit for bit") {
  constexpr const char* kDesign =
      R"({"implement": {"length_in": 27, "mass_g": 300, "balance_cm": 32.5, "swingweight_kg_cm2": 320,
          "headsize_sq_in": 100, "point_masses": [{"clock": 12, "mass_g": 10}]},
          "frame": {"cor": 0.8}})";
  const io::Json document = io::Json::parse(kDesign);
  const std::vector<std::string> pointers{"/implement/length_in"};
  const auto compiled =
      studies::CompiledDesign::compile(io::describe_design(document, "d.json"), pointers);
  REQUIRE(compiled);
  studies::BoundDesign bound(*compiled);
  const double at27 = 27.0, at29 = 29.0;
  const double sw27 =
      evaluate(*bound.at(std::span<const double>(&at27, 1)), Fidelity::kRigid).swingweight_kg_m2;
  const Evaluation e29 = evaluate(*bound.at(std::span<const double>(&at29, 1)), Fidelity::kRigid);
  io::Json written = document;
  written["implement"]["length_in"] = 29;
  const Evaluation file29 = evaluate(io::read_design(written, "d.json").design, Fidelity::kRigid);
  CHECK(e29.swingweight_kg_m2 != sw27);
  CHECK(same_bits(e29.swingweight_kg_m2, file29.swingweight_kg_m2));
  CHECK(same_bits(e29.impact_from_butt_m, file29.impact_from_butt_m));  // the centre of the strings
  CHECK(same_bits(e29.peak_wrist_force_N, file29.peak_wrist_force_N));
}

}  // namespace sweetspot::studies

namespace sweetspot::studies {

TEST_CASE("The binding sets only fields of the design's field table, in the table's spellings") {
  std::size_t bound = 0;
  for (const Case& c : cases()) {
    const io::DesignDescription description =
        io::describe_design(io::Json::parse(c.design), "design.json");
    for (const io::DesignField& field : io::design_fields()) {
      std::string object(field.object);
      for (std::size_t at = object.find('N'); at != std::string::npos; at = object.find('N'))
        object.replace(at, 1, "0");
      for (const std::string& key : spellings_of(field)) {
        const std::string pointer = "/" + object + (object.empty() ? "" : "/") + key;
        if (studies::bind_field(description, pointer)) ++bound;
      }
      // A unit the table does not give is never bound.
      for (const char* odd : {"_oz", "_ft", "_kmh"}) {
        const std::string pointer =
            "/" + object + (object.empty() ? "" : "/") + std::string(field.stem) + odd;
        INFO(pointer);
        CHECK_FALSE(studies::bind_field(description, pointer));
        CHECK_FALSE(io::design_path_problem(pointer).empty());
      }
    }
  }
  CHECK(bound > 50);
}

}  // namespace sweetspot::studies

namespace sweetspot::studies {

TEST_CASE("Every number a binding sets is a field of the design's field table") {
  for (const auto& [object, stem] : bindable_fields()) {
    INFO(object << "/" << stem);
    CHECK_NOTHROW(io::si_key(object, stem));
  }
  // And the fields it leaves to the file: a name, a list, a law.
  CHECK_THROWS_AS(io::si_key("implement", "weight"), std::logic_error);
}

}  // namespace sweetspot::studies
