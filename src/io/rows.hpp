#pragma once

// A table written row by row as CSV or as JSON Lines, for every writer of
// rows (a sweep's grid, a catalogue's CSV): each output is written in its own
// format once, never written in one and parsed back into another.
//
// After header(), the writer holds no state, so threads may format rows into
// their own buffers at once. The cells of a row are given in the header's
// order, each with its column.

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/format.hpp"

namespace sweetspot::io {

class RowWriter {
 public:
  virtual ~RowWriter() = default;

  // The columns. CSV writes their names as the first line; JSON Lines keeps
  // them as each row's keys and writes nothing.
  virtual void header(std::vector<std::string> names, std::string& out) = 0;

  // Cell `column` of a row: a number (exact(): the shortest text that reads
  // back as it), text, or nothing (CSV: an empty cell; JSON: null).
  virtual void number(std::size_t column, std::optional<double> value, std::string& out) const = 0;
  virtual void text(std::size_t column, std::optional<std::string_view> value,
                    std::string& out) const = 0;
  // Ends the row (after its last cell).
  virtual void end_row(std::string& out) const = 0;
};

// CSV (RFC 4180, csv_field()'s quoting and neutralising) or JSON Lines (one
// object a row, numbers as JSON numbers, keys in the header's order).
// Throws std::invalid_argument for another format.
std::unique_ptr<RowWriter> row_writer(Format format);

}  // namespace sweetspot::io
