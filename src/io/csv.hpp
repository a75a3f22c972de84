#pragma once

// The one CSV reader: a catalogue's lines read in bounded memory and checked
// as text, a record's lines joined while a quoted field is open, and a
// record split into its fields (RFC 4180). Rows are written by io/rows.hpp.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace sweetspot::io {

// The lines of an input, each read into a buffer that never grows past
// `max_line_bytes`: a longer line, a NUL byte, bytes that are not UTF-8 and
// a failed read are refused with the line they are on (InputError at
// "source:line", ReadError). A byte-order mark opening the input is skipped.
class LineReader {
 public:
  LineReader(std::istream& in, const std::string& source, std::size_t max_line_bytes)
      : in_(in), source_(source), max_line_bytes_(max_line_bytes), buffer_(1 << 16) {}

  std::size_t line_number() const { return line_; }
  // The bytes read from the input so far.
  std::uint64_t bytes_read() const { return bytes_read_; }

  // Hands `lines` back, to be read again in order by next().
  void unread(std::vector<std::string> lines);

  // The next line without its "\n" (or "\r\n"), appended to `text` after a
  // "\n" when `continued` (a CSV record going on inside quotes); false at the
  // end of the input.
  bool next(std::string& text, bool continued = false);

  // Throws InputError at "source:line".
  [[noreturn]] void refuse(std::size_t line, const std::string& detail) const;

 private:
  bool fill();

  std::istream& in_;
  const std::string& source_;
  std::size_t max_line_bytes_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
  std::size_t line_ = 0;
  std::uint64_t bytes_read_ = 0;
  std::deque<std::string> unread_;
  bool end_of_input_ = false;
};

// Reads the lines that continue `record` while a quoted field is open. A
// quote left open to the end of the input makes the record its first line
// alone (that row's error says the quote is not closed) and hands the lines
// after it back, to be read as rows of their own.
void complete_record(LineReader& reader, std::string& record);

// One CSV record split into its fields. The fields are views into the
// record, or into `unquoted` for a quoted field, so the record must outlive
// them; one CsvRecord is reused from row to row, allocating nothing once
// it has grown to the rows' size.
struct CsvRecord {
  std::vector<std::string_view> fields;  // the first `max_fields` fields
  std::size_t count = 0;                 // how many fields the record has
  std::string error;                     // why it is not RFC 4180 CSV, "" when it is
  std::string unquoted;                  // the quoted fields' text, quotes taken off
};

// Splits one CSV record (RFC 4180) into `out`: fields separated by commas; a
// field in double quotes may hold commas, line breaks and quotes written
// twice. A quote inside an unquoted field, or text after a closing quote, is
// an error.
void split_csv(std::string_view record, std::size_t max_fields, CsvRecord& out);

// Whether a CSV record has no cell at all: only commas, blanks and empty
// quoted fields (",,,," is the row a spreadsheet writes for an empty line).
bool blank_record(std::string_view record);

}  // namespace sweetspot::io
