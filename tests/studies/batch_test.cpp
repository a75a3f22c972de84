// Catalogues (evaluate --batch): a bad header is the file's error, reported
// once; a bad row is that row's error; the reader holds no more than its
// limits whatever the input, and a read failure is never the end of the file.
#include "studies/batch.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <utility>
#include <vector>

#include "io/design_reader.hpp"
#include "io/format.hpp"
#include "io/input_error.hpp"
#include "io/outputs.hpp"
#include "sweetspot/frame_specs.hpp"

namespace sweetspot::studies {
namespace {

constexpr const char* kBase =
    R"({"implement": {"length_m": 0.7, "mass_kg": 0.3, "head_to_handle_mass_ratio": 0.8}})";

struct Outcome {
  studies::BatchSummary summary;
  std::string out;
};

Outcome run_with(const std::string& text, studies::BatchOptions options) {
  std::istringstream in(text);
  std::ostringstream out;
  Outcome outcome;
  outcome.summary = studies::run_batch(in, "cat.csv", options, out);
  outcome.out = out.str();
  return outcome;
}

Outcome run(const std::string& text,
            studies::CatalogueFormat input = studies::CatalogueFormat::kAuto,
            io::Format format = io::Format::kJson) {
  studies::BatchOptions options;
  options.input = input;
  options.base = io::parse_json(kBase, "base.json");
  options.format = format;
  return run_with(text, options);
}

// The message of the InputError run() throws, or "(no error)".
std::string refusal(const std::string& text,
                    studies::CatalogueFormat input = studies::CatalogueFormat::kAuto) {
  try {
    run(text, input);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// The JSON Lines written for each row.
std::vector<io::Json> rows_of(const Outcome& outcome) {
  std::vector<io::Json> rows;
  std::istringstream lines(outcome.out);
  for (std::string line; std::getline(lines, line);) rows.push_back(io::Json::parse(line));
  return rows;
}

TEST_CASE(
    "A header giving one quantity in two units or forms is refused once, naming line 1 and both "
    "columns") {
  CHECK_THAT(
      refusal("name,implement.mass_kg,implement.mass_g\na,0.3,\nb,,300\n"),
      Catch::StartsWith(
          "cat.csv:1: column 3 \"implement.mass_g\": contradicts column 2 \"implement.mass_kg\""));
  CHECK_THAT(refusal("impact.from_butt_m,impact.from_tip_cm\n0.5,\n"),
             Catch::Contains("column 2 \"impact.from_tip_cm\": contradicts column 1"));
  CHECK_THAT(refusal("frame.cor,frame.cor_rigid\n0.8,\n"),
             Catch::Contains("column 2 \"frame.cor_rigid\": contradicts"));
  CHECK_THAT(refusal("strings.tension_lb,strings.impact_duration_ms\n55,\n"),
             Catch::Contains("column 2 \"strings.impact_duration_ms\": contradicts column 1"));
  // The same quantity of two different objects is no contradiction.
  CHECK(refusal("implement.mass_kg,hand.mass_g\n0.3,400\n") == "(no error)");
}

TEST_CASE("A repeated column, or one inside another, is refused once") {
  CHECK_THAT(refusal("implement.mass_kg,hand.mass_kg,implement.mass_kg\n0.3,0.4,0.35\n"),
             Catch::StartsWith("cat.csv:1: column 3 \"implement.mass_kg\": repeats column 1"));
  CHECK_THAT(refusal("name,name\na,b\n"), Catch::Contains("column 2 \"name\": repeats column 1"));
  CHECK_THAT(
      refusal("hand,hand.mass_kg\n1,0.4\n"),
      Catch::StartsWith("cat.csv:1: column 2 \"hand.mass_kg\": lies inside column 1 \"hand\""));
}

TEST_CASE("A column that is not a path of names is refused once, naming it") {
  for (const char* header :
       {"implement..mass_kg", "implement.mass_kg.", ".implement", "implement.mass kg",
        "implement/mass_kg", "implement.point_masses.01.mass_kg", "0.mass_kg",
        "implement.point_masses.123456.mass_kg", "implement.mass_\xC3\xA9"}) {
    INFO(header);
    CHECK_THAT(refusal(std::string("name,") + header + "\na,1\n"),
               Catch::StartsWith(std::string("cat.csv:1: column 2 ")));
  }
  CHECK_THAT(refusal("name,,implement.mass_kg\na,1,0.3\n"),
             Catch::Contains("column 2 \"\": an empty column name"));
  // Blanks around a name are not part of it.
  CHECK(refusal("name, implement.mass_kg \na,0.3\n") == "(no error)");
}

TEST_CASE("A field the design does not have is the header's error, reported once") {
  std::string catalogue = "name,implement.colour\n";
  for (int i = 0; i < 300; ++i) catalogue += "r" + std::to_string(i) + ",1\n";
  CHECK_THAT(refusal(catalogue),
             Catch::StartsWith("cat.csv:1: column 2 \"implement.colour\": unknown key"));
  // Inside a number of the base: a field there cannot be set.
  CHECK_THAT(refusal("implement.mass_kg.x\n1\n"),
             Catch::StartsWith(
                 "cat.csv:1: column 1 \"implement.mass_kg.x\": the base design holds a value"));
}

TEST_CASE("A byte-order mark opening a catalogue is not part of its first column") {
  const Outcome csv = run("\xEF\xBB\xBFname,implement.mass_kg\nlight,0.25\n");
  CHECK(csv.summary.rows == 1);
  CHECK(csv.summary.failed == 0);
  CHECK(rows_of(csv)[0]["name"] == "light");
  const Outcome lines =
      run("\xEF\xBB\xBF{\"name\": \"heavy\", \"implement\": {\"mass_kg\": 0.4}}\n");
  CHECK(lines.summary.failed == 0);
  CHECK(rows_of(lines)[0]["name"] == "heavy");
}

TEST_CASE(
    "CSV fields are RFC 4180: quoted commas, doubled quotes and line breaks, a row keeps its first "
    "line") {
  const Outcome out =
      run("name,implement.mass_kg\n\"A, \"\"tour\"\"\",0.25\n\"two\r\nlines\",\"0.3\"\nC,0.35\n");
  REQUIRE(out.summary.failed == 0);
  const std::vector<io::Json> rows = rows_of(out);
  REQUIRE(rows.size() == 3);
  CHECK(rows[0]["name"] == "A, \"tour\"");
  CHECK(rows[1]["name"] == "two\nlines");
  CHECK(rows[1]["line"] == 3);
  CHECK(rows[2]["line"] == 5);
  // Table I rows 1 and 2 share the mass 0.25 kg only with row 1.
  CHECK(rows[0]["outputs"]["peak_impact_force_N"].get<double>() == Approx(1117).margin(1));
}

TEST_CASE("A malformed or non-numeric cell is that row's error, quoting the value once") {
  const Outcome out =
      run("name,implement.mass_kg\nA,VS5\nB,\"VS5\"\nC,5\"\nD,\"0.3\"x\nE,nan\nF,0.3\n");
  const std::vector<io::Json> rows = rows_of(out);
  REQUIRE(rows.size() == 6);
  CHECK(out.summary.failed == 5);
  for (int i : {0, 1}) {
    const std::string error = rows[i]["error"];
    CHECK_THAT(error, Catch::EndsWith("/implement/mass_kg: expected a number, got 'VS5'"));
  }
  CHECK_THAT(rows[2]["error"].get<std::string>(),
             Catch::Contains("cat.csv:4: not CSV: field 2: a quote inside an unquoted field"));
  CHECK_THAT(rows[3]["error"].get<std::string>(),
             Catch::Contains("field 2: text after the closing quote"));
  CHECK_THAT(rows[4]["error"].get<std::string>(),
             Catch::Contains("expected a finite number, got 'nan'"));
  CHECK_FALSE(rows[5].contains("error"));
}

TEST_CASE(
    "In CSV output an error quotes a cell's value in single quotes, which CSV leaves as they are") {
  const Outcome out =
      run("name,implement.mass_kg\nA,VS5\n", studies::CatalogueFormat::kAuto, io::Format::kCsv);
  CHECK_THAT(out.out,
             Catch::EndsWith(",\"cat.csv:2: /implement/mass_kg: expected a number, got 'VS5'\"\n"));
  CHECK(out.out.find("\"\"") == std::string::npos);
}

TEST_CASE("A quote left open to the end of the file spoils its own row, not the rows after it") {
  const Outcome out = run("name,implement.mass_kg\n\"a,0.3\nb,0.31\nc,0.32\n",
                          studies::CatalogueFormat::kCsv, io::Format::kCsv);
  CHECK(out.summary.rows == 3);
  CHECK(out.summary.failed == 1);
  CHECK(out.out.find("cat.csv:2: not CSV: field 1: a quoted field is not closed") !=
        std::string::npos);
  CHECK(out.out.find("\n3,b,") != std::string::npos);  // each later line keeps its own number
  CHECK(out.out.find("\n4,c,") != std::string::npos);
}

TEST_CASE("More columns than the limit are refused, naming the limit") {
  std::string header = "name";
  for (std::size_t k = 1; k <= studies::kMaxBatchColumns; ++k) header += ",hand.mass_kg";
  CHECK_THAT(refusal(header + "\n"),
             Catch::StartsWith("cat.csv:1: 1001 columns, more than the limit of 1000"));
}

// A stream that never ends: `prefix`, then `pattern` forever.
class Endless : public std::streambuf {
 public:
  Endless(std::string prefix, const std::string& pattern) : prefix_(std::move(prefix)) {
    while (block_.size() < (1 << 16)) block_ += pattern;
    setg(prefix_.data(), prefix_.data(), prefix_.data() + prefix_.size());
  }

 protected:
  int_type underflow() override {
    setg(block_.data(), block_.data(), block_.data() + block_.size());
    return traits_type::to_int_type(block_[0]);
  }

 private:
  std::string prefix_;
  std::string block_;
};

// A stream that gives `text`, then fails as a disk would.
class Failing : public std::streambuf {
 public:
  explicit Failing(std::string text) : text_(std::move(text)) {
    setg(text_.data(), text_.data(), text_.data() + text_.size());
  }

 protected:
  int_type underflow() override { throw std::ios_base::failure("read error"); }

 private:
  std::string text_;
};

std::string refusal_of(std::streambuf& buffer) {
  studies::BatchOptions options;
  std::istream in(&buffer);
  std::ostringstream out;
  try {
    studies::run_batch(in, "endless", options, out);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

TEST_CASE("An endless line is refused at the line limit, binary input at its first NUL byte") {
  Endless letters("", "a");
  CHECK_THAT(refusal_of(letters),
             Catch::StartsWith("endless:1: a line longer than 1048576 bytes, the limit"));
  Endless zeros("", std::string(1, '\0'));
  CHECK_THAT(refusal_of(zeros), Catch::StartsWith("endless:1: a NUL byte"));
  // A quoted CSV field opened and never closed: one record, growing line by line.
  Endless open_field("name\n\"", "a\n");
  CHECK_THAT(refusal_of(open_field), Catch::Contains("a CSV record longer than 1048576 bytes"));
}

TEST_CASE("Bytes that are not UTF-8 text are refused with their line") {
  CHECK_THAT(refusal("name,implement.mass_kg\nA,0.3\n\xFF\xFE,0.3\n"),
             Catch::StartsWith("cat.csv:3: byte 1 is not UTF-8 text"));
}

TEST_CASE("A read error is an error, never the end of the input") {
  Failing failing("name,implement.mass_kg\nA,0.3\n");
  std::istream in(&failing);
  std::ostringstream out;
  studies::BatchOptions options;
  options.base = io::parse_json(kBase, "base.json");
  CHECK_THROWS_AS(studies::run_batch(in, "disk.csv", options, out), io::ReadError);
}

TEST_CASE("A catalogue's format follows its name, else its first line") {
  CHECK(studies::catalogue_format("a.csv") == studies::CatalogueFormat::kCsv);
  CHECK(studies::catalogue_format("a.jsonl") == studies::CatalogueFormat::kJsonLines);
  CHECK(studies::catalogue_format("-") == studies::CatalogueFormat::kAuto);
  const Outcome lines = run("\n{\"name\": \"x\", \"implement\": {\"mass_kg\": 0.4}}\n");
  CHECK(rows_of(lines)[0]["name"] == "x");
  CHECK(rows_of(lines)[0]["line"] == 2);
  const Outcome csv = run("\nname,implement.mass_kg\ny,0.4\n");
  CHECK(rows_of(csv)[0]["name"] == "y");
  CHECK(rows_of(csv)[0]["line"] == 3);
  // Told it is CSV, a line of JSON is a header naming no field.
  CHECK_THAT(refusal("{\"implement\": {}}\n", studies::CatalogueFormat::kCsv),
             Catch::StartsWith("cat.csv:1: "));
}

TEST_CASE("A row overriding the base with another form of a quantity replaces it") {
  // The base gives the duration; a row giving the tension derives it instead.
  studies::BatchOptions options;
  options.base = io::parse_json(
      R"({"implement": {"length_m": 0.7, "mass_kg": 0.3, "head_to_handle_mass_ratio": 0.8},
                                "strings": {"impact_duration_ms": 4}})",
      "base.json");
  options.format = io::Format::kJson;
  std::istringstream in("{\"strings\": {\"tension_lb\": 55}}\n");
  std::ostringstream out;
  const studies::BatchSummary summary = run_batch(in, "rows.jsonl", options, out);
  CHECK(summary.failed == 0);
  CHECK_THAT(out.str(), !Catch::Contains("error"));
}

// A retailer's table as it comes: its own column names, units and columns
// the design does not use (invented rows in the headers of a real retailer's lab table).
constexpr const char* kRetailerTable =
    "pcode,mfg,racquet,headsize,length,weight,balance,swingweight,flex,vibration\n"
    "A1,Acme,Club 100,100,27.0,300,32.5,318,66,150\n"
    "B2,Acme,Tour 97,97,27.0,335,31.5,330,62,142\n"
    "C3,Bolt,Lite 105,105,27.25,275,34.0,300,70,158\n";
const std::vector<std::pair<std::string, std::string>> kRetailerMap{
    {"racquet", "name"},
    {"headsize", "strings.head_size_in2"},
    {"length", "implement.length_in"},
    {"weight", "implement.mass_g"},
    {"balance", "implement.balance_cm"},
    {"swingweight", "implement.swingweight_kg_cm2"},
    {"flex", "frame.RA"}};
constexpr const char* kStrungBase =
    R"({"implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5, "swingweight_kg_cm2": 325},
        "strings": {"tension_lb": 52}, "impact": {"from_tip_cm": 17}})";

studies::BatchOptions mapped(io::Format format = io::Format::kJson) {
  studies::BatchOptions options;
  options.input = studies::CatalogueFormat::kCsv;
  options.base = io::parse_json(kStrungBase, "base.json");
  options.format = format;
  options.map = kRetailerMap;
  return options;
}

std::string refusal_with(const std::string& text, const studies::BatchOptions& options) {
  try {
    run_with(text, options);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST_CASE("A mapped catalogue gives what the same designs written as design files give") {
  const std::vector<io::Json> rows = rows_of(run_with(kRetailerTable, mapped()));
  REQUIRE(rows.size() == 3);
  // Row 2 by hand, as a design file: the map's targets name the units of the table.
  io::Json design = io::parse_json(kStrungBase, "b2.json");
  design["name"] = "Tour 97";
  design["implement"] = {
      {"length_in", 27.0}, {"mass_g", 335.0}, {"balance_cm", 31.5}, {"swingweight_kg_cm2", 330.0}};
  design["frame"] = {{"RA", 62.0}};
  design["strings"]["head_size_in2"] = 97.0;
  const io::DesignFile file = io::read_design(design, "cat.csv:3");
  const io::Json single = evaluation_json(file, evaluate_design_file(file, "", 1e-6));
  io::Json row = rows[1];
  CHECK(row["line"] == 3);
  CHECK(row["columns"] == io::Json({{"pcode", "B2"}, {"mfg", "Acme"}, {"vibration", "142"}}));
  // As complete as a single evaluate: fidelity, inputs, outputs, notes, and nothing else differs.
  row.erase("line");
  row.erase("columns");
  CHECK(row == single);
  // A tension and a stiffness (RA) with no COR: auto solves the collision.
  CHECK(row["fidelity"] == "collision");
  CHECK(row["inputs"]["frame/RA"]["value"] == 62.0);
  CHECK(row["inputs"]["strings/tension_N"]["given"] == io::Json({{"/strings/tension_lb", 52}}));
}

TEST_CASE("A swung racquet's rows are solved at the speed the ball and the racquet meet") {
  // The paper's racquet with a swing: rows that only move the impact and the
  // hand would suit the column-wise rigid path, which knows no swing; each row
  // must be what evaluate gives the same design file, at v_in + V.
  constexpr const char* kSwung =
      R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
          "frame": {"cor": 0.8}, "strings": {"impact_duration_ms": 4},
          "ball": {"speed_m_s": 20}, "swing": {"angular_speed_rad_s": 20, "pivot_beyond_butt_m": 0.6}})";
  studies::BatchOptions options;
  options.input = studies::CatalogueFormat::kCsv;
  options.base = io::parse_json(kSwung, "base.json");
  options.format = io::Format::kJson;
  const std::vector<io::Json> rows =
      rows_of(run_with("impact.from_tip_m,hand.mass_kg\n0.05,0.5\n0.2,0.4\n", options));
  REQUIRE(rows.size() == 2);
  const double from_tip[] = {0.05, 0.2}, hand[] = {0.5, 0.4};
  for (int i = 0; i < 2; ++i) {
    io::Json design = io::parse_json(kSwung, "row.json");
    design["impact"] = {{"from_tip_m", from_tip[i]}};
    design["hand"] = {{"mass_kg", hand[i]}};
    const io::DesignFile file = io::read_design(design, "row.json");
    const io::Json single = evaluation_json(file, evaluate_design_file(file, "", 1e-6));
    const io::Json& outputs = rows[i]["outputs"];
    CHECK(outputs["peak_wrist_force_N"] == single["outputs"]["peak_wrist_force_N"]);
    CHECK(outputs["impulse_N_s"] == single["outputs"]["impulse_N_s"]);
    // The impulse is m (1 + e_A) (v_in + V): the meeting speed, not the ball's 20 m/s.
    const double meeting = single["outputs"]["impulse_N_s"].get<double>() /
                           (0.057 * (1.0 + single["outputs"]["apparent_cor"].get<double>()));
    CHECK(meeting == Approx(20.0 + single["outputs"]["racquet_speed_m_s"].get<double>()));
  }
}

TEST_CASE("Unmapped columns pass through to CSV beside the outputs, as they were written") {
  const Outcome out = run_with(kRetailerTable, mapped(io::Format::kCsv));
  CHECK(out.summary.failed == 0);
  CHECK_THAT(out.out, Catch::StartsWith("line,name,pcode,mfg,vibration,length_m,"));
  CHECK(out.out.find("\n2,Club 100,A1,Acme,150,0.6858,") != std::string::npos);
  CHECK(out.out.find("\n4,Lite 105,C3,Bolt,158,") != std::string::npos);
}

TEST_CASE("A passed-through cell or a name a spreadsheet would read as a formula is neutralised") {
  studies::BatchOptions options;
  options.input = studies::CatalogueFormat::kCsv;
  options.base = io::parse_json(kBase, "base.json");
  options.format = io::Format::kCsv;
  options.map = {{"racquet", "name"}, {"weight", "implement.mass_g"}};
  const Outcome out = run_with(
      "code,racquet,weight,note\n"
      "=1+2,@SUM(A1),300,-0.5\n"
      "+cmd,-Club,310,\"two\nlines, \"\"quoted\"\"\"\n",
      options);
  CHECK(out.summary.failed == 0);
  CHECK_THAT(out.out, Catch::StartsWith("line,name,code,note,"));
  // The formulas quoted after a single quote; a number stays a number.
  CHECK(out.out.find("\n2,\"'@SUM(A1)\",\"'=1+2\",-0.5,") != std::string::npos);
  // A multi-line cell comes back as the same quoted multi-line cell.
  CHECK(out.out.find("\n3,\"'-Club\",\"'+cmd\",\"two\nlines, \"\"quoted\"\"\",") !=
        std::string::npos);
}

TEST_CASE("The blank last row a spreadsheet exports is skipped, not an error row") {
  for (const std::string blank : {",\n", ", ,\n", "\"\",\"\"\n", ",\r\n"}) {
    const Outcome out = run("name,implement.mass_g\nr1,300\n" + blank,
                            studies::CatalogueFormat::kCsv, io::Format::kCsv);
    CHECK(out.summary.rows == 1);
    CHECK(out.summary.failed == 0);
  }
  // A row with one cell is a row.
  CHECK(run("name,implement.mass_g\nr1,300\n,310\n", studies::CatalogueFormat::kCsv).summary.rows ==
        2);
}

TEST_CASE("A column passed through twice is refused once, naming both") {
  studies::BatchOptions options;
  options.input = studies::CatalogueFormat::kCsv;
  options.base = io::parse_json(kBase, "base.json");
  options.map = {{"weight", "implement.mass_kg"}};
  CHECK_THROWS_WITH(run_with("code,weight,code\nA,0.3,B\n", options),
                    "cat.csv:1: column 3 \"code\": repeats column 1, passed through too "
                    "(expected each column passed through named once)");
}

TEST_CASE("A reference.source column fills the design's reference, as a design file would") {
  const Outcome out =
      run("name,reference.source,reference.swingweight_kg_cm2\nr1,Spec sheet (2024),320\n",
          studies::CatalogueFormat::kCsv, io::Format::kCsv);
  CHECK(out.summary.failed == 0);
  // Its numbers are numbers, as in a file.
  const Outcome bad = run("name,reference.swingweight_kg_cm2\nr1,heavy\n",
                          studies::CatalogueFormat::kCsv, io::Format::kCsv);
  CHECK(bad.summary.failed == 1);
  CHECK(bad.out.find("/reference/swingweight_kg_cm2") != std::string::npos);
}

TEST_CASE("An inline map and a JSON map are the same map") {
  const auto inline_map = studies::parse_column_map(
      "racquet=name, headsize=strings.head_size_in2,length=implement.length_in,"
      "weight=implement.mass_g,balance=implement.balance_cm,"
      "swingweight=implement.swingweight_kg_cm2,flex=frame.RA",
      "--map");
  CHECK(inline_map == kRetailerMap);
  io::Json json = io::Json::object();
  for (const auto& [column, field] : kRetailerMap) json[column] = field;
  auto from_json = studies::column_map_from_json(json, "map.json");
  std::sort(from_json.begin(), from_json.end());
  auto expected = kRetailerMap;
  std::sort(expected.begin(), expected.end());
  CHECK(from_json == expected);
}

TEST_CASE("A bad map is refused once, naming the map, the column and what was expected") {
  CHECK_THROWS_WITH(
      studies::parse_column_map("weight=implement.mass_g,weight=implement.mass_kg", "--map"),
      "--map: column \"weight\": mapped twice (expected each column once)");
  CHECK_THROWS_WITH(studies::parse_column_map("weight", "--map"),
                    Catch::StartsWith("--map: item 1 \"weight\": expected COLUMN=design.field"));
  CHECK_THROWS_WITH(studies::parse_column_map("weight=implement.mass_g,", "--map"),
                    Catch::StartsWith("--map: item 2 \"\": expected COLUMN=design.field"));
  CHECK_THROWS_WITH(studies::parse_column_map("=implement.mass_g", "--map"),
                    Catch::Contains("expected a column name and a design field"));
  CHECK_THROWS_WITH(studies::column_map_from_json(io::Json::array(), "map.json"),
                    Catch::StartsWith("map.json: expected a JSON object"));
  CHECK_THROWS_WITH(studies::column_map_from_json(io::Json::object(), "map.json"),
                    Catch::StartsWith("map.json: expected a JSON object"));
  CHECK_THROWS_WITH(studies::column_map_from_json(io::Json{{"weight", 300}}, "map.json"),
                    "map.json: /weight: expected a design field as text, such as "
                    "\"implement.mass_g\", got 300");
  studies::BatchOptions options = mapped();
  options.map.emplace_back("wieght", "implement.mass_g");
  CHECK_THAT(refusal_with(kRetailerTable, options),
             Catch::StartsWith("--map: column \"wieght\": not in the header of cat.csv:1 "
                               "(expected one of \"pcode\", \"mfg\""));
  options = mapped();
  options.map.emplace_back("vibration", "frame.fundamental_free_Hz");
  CHECK_THAT(refusal_with(kRetailerTable, options),
             Catch::StartsWith("cat.csv:1: column 10 \"vibration\" (mapped to "
                               "\"frame.fundamental_free_Hz\"): contradicts column 9 \"flex\""));
  options = mapped();
  options.map.emplace_back("pcode", "implement.mass_kg");
  CHECK_THAT(refusal_with(kRetailerTable, options),
             Catch::Contains("contradicts column 1 \"pcode\" (mapped to \"implement.mass_kg\")"));
  options = mapped();
  options.map.emplace_back("mfg", "implement.mass g");
  CHECK_THAT(
      refusal_with(kRetailerTable, options),
      Catch::StartsWith("--map: column \"mfg\": the field \"implement.mass g\": a character"));
  options = mapped();
  options.map[3].second = "implement.weight_g";  // a field the design does not have
  CHECK_THAT(refusal_with(kRetailerTable, options),
             Catch::StartsWith("cat.csv:1: column 6 \"weight\" (mapped to "
                               "\"implement.weight_g\"): unknown key"));
  // A map is for CSV: a JSON Lines row names its fields itself.
  options = mapped();
  options.input = studies::CatalogueFormat::kJsonLines;
  CHECK_THAT(refusal_with("{\"name\": \"x\"}\n", options),
             Catch::StartsWith("--map: a column map is for a CSV catalogue"));
  // A column passed through may not take an output's own name in CSV.
  options = mapped(io::Format::kCsv);
  options.map = {{"racquet", "name"}};
  CHECK_THAT(refusal_with("racquet,error\nx,1\n", options),
             Catch::Contains("column 2 \"error\": passed through, it would repeat the output's"));
}

TEST_CASE("A cell of a mapped column that is not a number is its row's error, naming the column") {
  std::string table = kRetailerTable;
  table += "D4,Bolt,Unlisted,100,27.0,300,32.5,n/a,66,150\n";
  const Outcome out = run_with(table, mapped());
  CHECK(out.summary.failed == 1);
  const std::vector<io::Json> rows = rows_of(out);
  CHECK(rows[3]["error"] ==
        "cat.csv:5: /implement/swingweight_kg_cm2: column 'swingweight': expected a number, got "
        "'n/a'");
  CHECK(rows[3]["name"] == "Unlisted");
  CHECK(rows[3]["columns"]["pcode"] == "D4");
}

std::vector<double> sorted_values(const Outcome& out, const std::string& output) {
  std::vector<double> values;
  for (const io::Json& row : rows_of(out)) {
    if (row.contains("outputs")) values.push_back(row["outputs"][output].get<double>());
  }
  return values;
}

TEST_CASE("A failed JSON Lines row keeps its name, as a failed CSV row does") {
  const std::string jsonl =
      "{\"name\": \"good\", \"implement\": {\"mass_g\": 300}}\n"
      "{\"name\": \"bad mass\", \"implement\": {\"mass_g\": -5}}\n";
  const Outcome lines = run(jsonl, studies::CatalogueFormat::kJsonLines);
  const Outcome csv = run("name,implement.mass_g\ngood,300\nbad mass,-5\n");
  REQUIRE(lines.summary.failed == 1);
  REQUIRE(csv.summary.failed == 1);
  const auto failed_name = [](const Outcome& o) {
    for (const io::Json& row : rows_of(o))
      if (row.contains("error")) return row.value("name", std::string("(none)"));
    return std::string("(no failed row)");
  };
  CHECK(failed_name(lines) == "bad mass");
  CHECK(failed_name(csv) == "bad mass");
}

TEST_CASE("Sorted rows come in the output's order, failed rows last, --top keeps the first N") {
  std::string table = "name,implement.mass_g,impact.from_tip_cm\n";
  for (int i = 0; i < 60; ++i)
    table += "r" + std::to_string(i) + "," + std::to_string(250 + (i * 37) % 120) + "," +
             std::to_string(5 + (i * 13) % 25) + "\n";
  table += "bad,heavy,10\n";
  studies::BatchOptions options;
  options.base = io::parse_json(kBase, "base.json");
  options.format = io::Format::kJson;
  const Outcome plain = run_with(table, options);
  std::vector<double> expected = sorted_values(plain, "peak_wrist_force_N");
  std::sort(expected.begin(), expected.end());
  options.sort_output = "peak_wrist_force_N";
  const Outcome ascending = run_with(table, options);
  CHECK(ascending.summary.rows == 61);
  CHECK(ascending.summary.failed == 1);
  CHECK(sorted_values(ascending, "peak_wrist_force_N") == expected);
  CHECK(rows_of(ascending).back()["name"] == "bad");  // failed: last
  options.descending = true;
  const Outcome descending = run_with(table, options);
  std::reverse(expected.begin(), expected.end());
  CHECK(sorted_values(descending, "peak_wrist_force_N") == expected);
  CHECK(rows_of(descending).back()["name"] == "bad");
  options.top = 5;
  const Outcome top = run_with(table, options);
  CHECK(rows_of(top).size() == 5);
  CHECK(sorted_values(top, "peak_wrist_force_N") ==
        std::vector<double>(expected.begin(), expected.begin() + 5));
  CHECK(top.summary.rows == 61);  // every row was evaluated, and counted
}

TEST_CASE("The top N over more rows than a chunk are the first N of sorting them all") {
  std::string table = "name,implement.mass_g\n";
  const int rows = static_cast<int>(studies::kBatchChunkRows) * 2 + 77;
  for (int i = 0; i < rows; ++i)
    table += "r" + std::to_string(i) + "," + std::to_string(200 + (i * 7919) % 2000 * 0.1) + "\n";
  studies::BatchOptions options;
  options.base = io::parse_json(kBase, "base.json");
  options.format = io::Format::kCsv;
  options.sort_output = "swingweight_kg_cm2";
  options.threads = 2;
  const std::string all = run_with(table, options).out;
  options.top = 3;
  const std::string top = run_with(table, options).out;
  // The header and the first three rows of the full sort.
  std::size_t end = 0;
  for (int i = 0; i < 4; ++i) end = all.find('\n', end) + 1;
  CHECK(top == all.substr(0, end));
}

TEST_CASE("A row is written the same after any other rows, across chunks and threads") {
  // The rows of a chunk, their fields and each thread's evaluation are reused
  // from row to row: nothing of an earlier row (its name, the cells passed
  // through, its error, a long line) may show in a later one. The oracle is
  // the row alone in its catalogue, at the same line (blank lines before it).
  const std::string header = "pcode,mfg,racquet,weight,swingweight\n";
  const std::string long_name(3 * 4096, 'L');
  const auto row_text = [&](int i) -> std::string {
    const std::string n = std::to_string(i);
    // A row's kind hashed from its index: each chunk's slot holds another kind in the next.
    switch ((static_cast<std::uint32_t>(i) * 2654435761u) >> 29) {
      case 0:
        return "P" + n + ",\"Ac\"\"me, Inc\",\"Tour\n" + n + "\",301,320\n";
      case 1:
        return "P" + n + ",Acme," + long_name + n + ",302,321\n";
      case 2:
        return "P" + n + ",Bolt,,303,322\n";  // the base's name
      case 3:
        return "P" + n + ",Bolt,R" + n + ",heavy,323\n";  // not a number
      case 4:
        return "P" + n + ",Bolt,R" + n + ",304\n";  // too few fields
      case 5:
        return "P" + n + ",Bolt,R" + n + ",305,\n";  // the base's swingweight
      case 6:
        return "P" + n + ",Bolt,R" + n + ",-5,324\n";  // refused by the model
      default:
        return "P" + n + ",Acme,R" + n + "," + std::to_string(280 + i % 41) + "," +
               std::to_string(300 + i % 37) + "\n";
    }
  };
  std::string table = header;
  std::vector<std::pair<int, std::string>> rows;  // the line each row starts on, and its text
  int line = 2;
  const int count = static_cast<int>(studies::kBatchChunkRows) + 300;
  for (int i = 0; i < count; ++i) {
    const std::string text = row_text(i);
    rows.emplace_back(line, text);
    table += text;
    line += static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  }
  studies::BatchOptions options;
  options.input = studies::CatalogueFormat::kCsv;
  options.base = io::parse_json(
      R"({"name": "Base", "implement": {"length_in": 27, "mass_g": 318, "balance_cm": 32.5,
          "swingweight_kg_cm2": 325}})",
      "base.json");
  options.map = {{"racquet", "name"},
                 {"weight", "implement.mass_g"},
                 {"swingweight", "implement.swingweight_kg_cm2"}};
  options.format = io::Format::kCsv;
  const std::string all = run_with(table, options).out;
  // Each output row is one CSV record (a multi-line name stays one quoted
  // cell), starting with its input line's number.
  std::map<int, std::string> written;
  std::istringstream lines(all);
  std::string text;
  std::getline(lines, text);  // the header
  while (std::getline(lines, text)) {
    std::string more;
    while (std::count(text.begin(), text.end(), '"') % 2 == 1 && std::getline(lines, more))
      text += "\n" + more;
    written[std::stoi(text)] = text;
  }
  REQUIRE(written.size() == rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    // Rows of the first chunk now and then; of the second (in reused slots) often.
    if (i % (i < studies::kBatchChunkRows ? 97 : 5) != 0) continue;
    const auto& [at, row] = rows[i];
    INFO("row " << i << " at line " << at);
    const std::string alone = run_with(header + std::string(at - 2, '\n') + row, options).out;
    CHECK(alone.substr(alone.find('\n') + 1) == written.at(at) + "\n");
  }
  // Sorted, every row that failed (its error, the last column, not empty) comes
  // after every row that did not.
  studies::BatchOptions sorted = options;
  sorted.sort_output = "mass_kg";
  std::istringstream sorted_lines(run_with(table, sorted).out);
  std::getline(sorted_lines, text);
  std::size_t ok = 0, failed = 0, ok_after_failed = 0;
  while (std::getline(sorted_lines, text)) {
    std::string more;
    while (std::count(text.begin(), text.end(), '"') % 2 == 1 && std::getline(sorted_lines, more))
      text += "\n" + more;
    if (!text.ends_with(',')) {
      ++failed;
    } else {
      ++ok;
      if (failed > 0) ++ok_after_failed;
    }
  }
  CHECK(ok_after_failed == 0);
  CHECK(ok + failed == rows.size());
  CHECK(failed > 0);
  // The same rows on two threads, and read as JSON documents instead of compiled.
  options.threads = 2;
  CHECK(run_with(table, options).out == all);
  options.compiled = false;
  CHECK(run_with(table, options).out == all);
}

TEST_CASE("A tension column in lb or kg gives the tension in N it converts to") {
  studies::BatchOptions options;
  options.base = io::parse_json(kBase, "base.json");
  options.format = io::Format::kJson;
  // 50 lb is 222.41108076 N and 22.6796185 kgf.
  std::vector<io::Json> rows;
  for (const char* table : {"strings.tension_N\n222.41108076302\n", "strings.tension_lb\n50\n",
                            "strings.tension_kg\n22.6796185\n"}) {
    const Outcome out = run_with(table, options);
    REQUIRE(out.summary.failed == 0);
    rows.push_back(rows_of(out).at(0));
  }
  const double duration = rows[0]["outputs"]["impact_duration_s"];
  CHECK(rows[1]["outputs"]["impact_duration_s"].get<double>() == Approx(duration).epsilon(1e-9));
  CHECK(rows[2]["outputs"]["impact_duration_s"].get<double>() == Approx(duration).epsilon(1e-9));
  CHECK(rows[1]["inputs"]["strings/tension_N"]["given"] == io::Json({{"/strings/tension_lb", 50}}));
}

TEST_CASE(
    "The shipped catalogue, map and base of docs/catalogues.md evaluate every row but the one with "
    "n/a") {
  const std::string dir = std::string(SWEETSPOT_SOURCE_DIR) + "/designs/catalogues/";
  studies::BatchOptions options;
  options.input = studies::CatalogueFormat::kCsv;
  options.base = io::read_json_file(dir + "base-52lb.json");
  options.map = studies::column_map_from_json(io::read_json_file(dir + "retailer-map.json"), "map");
  options.format = io::Format::kJson;
  options.sort_output = "peak_wrist_force_N";
  std::ifstream in(dir + "spec-sheets.csv", std::ios::binary);
  std::ostringstream out;
  const studies::BatchSummary summary = run_batch(in, "spec-sheets.csv", options, out);
  CHECK(summary.rows == 6);
  CHECK(summary.failed == 1);
  const std::vector<io::Json> rows = rows_of(Outcome{summary, out.str()});
  REQUIRE(rows.size() == 6);
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    INFO(rows[i]["name"]);
    CHECK(rows[i]["fidelity"] == "modal");  // the RA column gives the frame's stiffness
    // Its frequency is the RA relation's for the row's RA and mass (no lead tape).
    const io::Json& outputs = rows[i]["outputs"];
    CHECK(outputs["fundamental_free_Hz"].get<double>() ==
          Approx(fundamental_free_Hz_from_RA(rows[i]["inputs"]["frame/RA"]["value"].get<double>(),
                                             outputs["mass_kg"].get<double>(),
                                             outputs["length_m"].get<double>()))
              .epsilon(1e-6));
    if (i > 0) {
      CHECK(outputs["peak_wrist_force_N"].get<double>() >=
            rows[i - 1]["outputs"]["peak_wrist_force_N"].get<double>());
    }
  }
  CHECK(rows.back()["columns"]["pcode"] == "BAD1");
  CHECK_THAT(rows.back()["error"].get<std::string>(), Catch::Contains("column 'swingweight'"));
}

TEST_CASE("A mapped catalogue with an RA column gives the same rows compiled as read as JSON") {
  const std::string dir = std::string(SWEETSPOT_SOURCE_DIR) + "/designs/catalogues/";
  const auto run_shipped = [&](bool compiled) {
    studies::BatchOptions options;
    options.input = studies::CatalogueFormat::kCsv;
    options.base = io::read_json_file(dir + "base-52lb.json");
    options.map =
        studies::column_map_from_json(io::read_json_file(dir + "retailer-map.json"), "map");
    options.format = io::Format::kCsv;
    options.compiled = compiled;
    std::ifstream in(dir + "spec-sheets.csv", std::ios::binary);
    std::ostringstream out;
    studies::run_batch(in, "spec-sheets.csv", options, out);
    return out.str();
  };
  CHECK(run_shipped(true) == run_shipped(false));
}

}  // namespace
}  // namespace sweetspot::studies
