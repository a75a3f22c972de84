#pragma once

// `sweetspot evaluate --batch FILE`: a catalogue of designs, one per line, in
// JSON Lines (each line a design object, merged over a base design) or CSV
// whose header names design fields by path ("implement.length_in"). Output is
// one row per input, in input order, streamed: memory stays bounded however
// long the file. A bad row becomes an error row naming its line and field;
// the others go on. A bad file (a header that names no field, or names one
// twice or in two units; a line past the limits; bytes that are not UTF-8
// text) is refused as a whole, once.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/format.hpp"
#include "io/json_reader.hpp"
#include "studies/catalogue_header.hpp"

namespace sweetspot::studies {

// Rows evaluated together (and split among the threads) before they are
// written, and the most text they may hold together.
inline constexpr std::size_t kBatchChunkRows = 4096;
inline constexpr std::size_t kBatchChunkBytes = std::size_t{16} << 20;

// Limits on a catalogue (docs/catalogues.md, "Input limits"): a line (a CSV record, which
// may span lines inside quotes) of at most 1 MiB; at most kMaxBatchColumns CSV columns
// (catalogue_header.hpp).
inline constexpr std::size_t kMaxBatchLineBytes = std::size_t{1} << 20;

enum class CatalogueFormat {
  kAuto,  // CSV unless the first line that is not blank starts with '{'
  kCsv,
  kJsonLines,
};

struct BatchOptions {
  CatalogueFormat input = CatalogueFormat::kAuto;
  std::optional<io::Json> base;          // defaults for every row ("--base DESIGN.json")
  io::Format format = io::Format::kCsv;  // kCsv or kJson (JSON Lines out)
  int threads = 1;                       // >= 1
  std::string fidelity;                  // rigid, modal, response or auto; empty: each design's own
  double modal_tolerance = 1e-6;         // the hand-held modes' relative frequency error
  // CSV rows set on a design compiled once per shape of filled cells
  // (design_binding.hpp). Off, every row is written into a JSON document and
  // read again: the reference the tests compare the compiled path with.
  bool compiled = true;
  // A catalogue as it comes (CSV only): its column names mapped onto design
  // fields ("weight" -> "implement.mass_g"; the field's suffix is the unit of
  // the column's values), in the order given. With a map, a column neither
  // mapped nor naming a design field itself (a path under implement, frame,
  // strings, hand, forearm, ball or impact; name, description, fidelity) is
  // passed through to the output as it is.
  ColumnMap map;
  std::string map_source = "--map";  // how messages name the map
  // Rows ordered by this output (a name of outputs.hpp), ascending, or
  // descending with `descending`; rows without it (failed, or null) last, in
  // input order. Empty: input order, streamed. Sorting keeps each row's key and
  // place in memory (32 bytes; with `top`, only the best `top`) and its text
  // in an unlinked temporary file under $TMPDIR (or /tmp).
  std::string sort_output;
  bool descending = false;
  std::size_t top = 0;  // with sort_output: only the first `top` rows (0: all)
  // Called on the calling thread after each chunk of rows with the rows read
  // and the bytes of the input read so far (for a progress line); may be empty.
  std::function<void(std::size_t, std::uint64_t)> progress;
};

struct BatchSummary {
  std::size_t rows = 0;
  std::size_t failed = 0;
};

// Reads `in` (named `source` in messages) row by row and writes `out`.
// Throws InputError for a file it cannot take as a whole (a bad CSV header,
// a line past the limits, binary or non-UTF-8 bytes), naming the line;
// ReadError when the input cannot be read to its end. Everything else is per
// row.
BatchSummary run_batch(std::istream& in, const std::string& source, const BatchOptions& options,
                       std::ostream& out);

// The format a catalogue's name gives: ".csv" CSV; ".jsonl", ".ndjson",
// ".json" JSON Lines; anything else (standard input, "-") kAuto.
CatalogueFormat catalogue_format(const std::string& path);

}  // namespace sweetspot::studies
