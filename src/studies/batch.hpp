#pragma once

// `sweetspot evaluate --batch FILE`: a catalogue of designs, one per line, in
// JSON Lines (each line a design object, merged over a base design) or CSV
// whose header names design fields by path ("implement.length_in"). Output is
// one row per input, in input order, streamed: memory stays bounded however
// long the file. A bad row becomes an error row naming its line and field;
// the others go on.

#include <cstddef>
#include <istream>
#include <optional>
#include <ostream>
#include <string>

#include "io/format.hpp"
#include "io/json_reader.hpp"

namespace sweetspot::io {

// Rows evaluated together (and split among the threads) before they are written.
inline constexpr std::size_t kBatchChunkRows = 4096;

struct BatchOptions {
  bool csv_input = false;         // else JSON Lines
  std::optional<Json> base;       // defaults for every row ("--base DESIGN.json")
  Format format = Format::kCsv;   // kCsv or kJson (JSON Lines out)
  int threads = 1;                // >= 1
  std::string fidelity;           // rigid, modal, response or auto; empty: each design's own
  double modal_tolerance = 1e-6;  // the hand-held modes' relative frequency error
  // CSV rows set on a design compiled once per shape of filled cells
  // (design_binding.hpp). Off, every row is written into a JSON document and
  // read again: the reference the tests compare the compiled path with.
  bool compiled = true;
};

struct BatchSummary {
  std::size_t rows = 0;
  std::size_t failed = 0;
};

// Reads `in` (named `source` in messages) row by row and writes `out`.
// Throws InputError only for a file it cannot read as a whole (a CSV header
// naming no field); everything else is per row.
BatchSummary run_batch(std::istream& in, const std::string& source, const BatchOptions& options,
                       std::ostream& out);

// Whether a catalogue is CSV (its name ends in ".csv"); else JSON Lines.
bool is_csv_catalogue(const std::string& path);

// "implement.point_masses.0.mass_g" -> "/implement/point_masses/0/mass_g".
std::string field_to_pointer(const std::string& field);

}  // namespace sweetspot::io
