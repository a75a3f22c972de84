// libFuzzer target: arbitrary bytes as a catalogue for `evaluate --batch`,
// through sweetspot::studies::run_batch on a stream, as CSV (a header naming design
// fields, then rows) or as JSON Lines (one design object per line), each row
// laid over a base design.
//
// The contract under test (docs/catalogues.md): a bad row becomes an
// error row and the rest go on; a file that cannot be read as a whole (its
// header) is refused with sweetspot::io::InputError naming the source. Any
// other exception escaping, a crash, a sanitizer report, a hang or unbounded
// memory is a bug. The output must hold one row per non-blank input line
// (plus the CSV header) and never a NaN.
//
// The first byte (after a byte-order mark) picks the format: '{' is JSON
// Lines, anything else CSV; the seeds in fuzz/seeds-batch/ are both.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>

#include "input_layer.hpp"

namespace {

// The base design every row is laid over (Cross 2004 Table I, top row, with a
// stiffness so that modal rows can be asked for).
constexpr std::string_view kBase = R"({
  "implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
  "frame": {"cor": 0.8},
  "strings": {"impact_duration_ms": 4},
  "hand": {"mass_kg": 0.5, "center_from_butt_m": 0.07},
  "forearm": {"equivalent_mass_kg": 0.5},
  "ball": {"mass_kg": 0.057, "speed_m_s": 50},
  "impact": {"from_tip_m": 0.05}
})";

// A CSV output row with a non-finite number: a field (outside quotes, after
// the line and name columns) that reads nan or inf. JSON Lines output writes
// NaN as null, which a reader cannot tell from "not applicable": CSV only.
bool holds_nan(const std::string& csv) {
  std::istringstream lines(csv);
  std::string line;
  while (std::getline(lines, line)) {
    std::string field;
    int column = 0;
    bool quoted = false;
    for (std::size_t i = 0; i <= line.size(); ++i) {
      const char c = i < line.size() ? line[i] : ',';
      if (c == '"') quoted = !quoted;
      if (quoted || c == '"') continue;
      if (c != ',') {
        field += c;
        continue;
      }
      if (column++ >= 2) {
        for (const char* bad : {"nan", "-nan", "inf", "-inf"}) {
          if (field == bad) return true;
        }
      }
      field.clear();
    }
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string source = "fuzz-batch";
  sweetspot::studies::BatchOptions options;
  std::string_view body = text;
  if (body.starts_with("\xEF\xBB\xBF")) body.remove_prefix(3);
  options.input = body.empty() || body.front() != '{'
                      ? sweetspot::studies::CatalogueFormat::kCsv
                      : sweetspot::studies::CatalogueFormat::kJsonLines;
  options.base = sweetspot::io::parse_json(kBase, "base.json");
  options.format = size % 2 == 0 ? sweetspot::io::Format::kCsv : sweetspot::io::Format::kJson;
  options.threads = 1;
  std::istringstream in(text);
  std::ostringstream out;
  try {
    const sweetspot::studies::BatchSummary summary =
        sweetspot::studies::run_batch(in, source, options, out);
    if (summary.failed > summary.rows) std::abort();
  } catch (const sweetspot::io::InputError& refused) {
    if (std::string_view(refused.what()).substr(0, source.size()) != source) std::abort();
    return 0;
  }
  if (options.format == sweetspot::io::Format::kCsv && holds_nan(out.str())) {
    std::fprintf(stderr, "batch_reader_fuzz: NaN or infinity in the output\n");
    std::abort();
  }
  return 0;
}
