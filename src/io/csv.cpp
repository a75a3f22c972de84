#include "io/csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "io/input_error.hpp"
#include "io/json_reader.hpp"

namespace sweetspot::io {
namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

// Whether `text` is all ASCII, which is valid UTF-8: most catalogues' lines,
// told in one pass (which the compiler vectorises) before the byte-by-byte
// UTF-8 check.
bool is_ascii(std::string_view text) {
  unsigned char any = 0;
  for (const char c : text) any |= static_cast<unsigned char>(c);
  return any < 0x80;
}

// Where a CSV record stands after some of its text: whether a line break
// there is inside a quoted field (a quote opens one only at a field's start).
class CsvScan {
 public:
  bool inside_quotes() const { return state_ == State::kQuoted; }
  void read(std::string_view text) {
    for (const char c : text) {
      switch (state_) {
        case State::kFieldStart:
          state_ = c == '"' ? State::kQuoted : c == ',' ? State::kFieldStart : State::kUnquoted;
          break;
        case State::kUnquoted:
          if (c == ',') state_ = State::kFieldStart;
          break;
        case State::kQuoted:
          if (c == '"') state_ = State::kQuote;
          break;
        case State::kQuote:
          state_ = c == '"' ? State::kQuoted : c == ',' ? State::kFieldStart : State::kUnquoted;
          break;
      }
    }
  }

 private:
  enum class State {
    kFieldStart,
    kUnquoted,
    kQuoted,
    kQuote
  };  // kQuote: a quote inside a quoted field
  State state_ = State::kFieldStart;
};

}  // namespace

void LineReader::unread(std::vector<std::string> lines) {
  for (auto line = lines.rbegin(); line != lines.rend(); ++line)
    unread_.push_front(std::move(*line));
  line_ -= lines.size();
}

bool LineReader::next(std::string& text, bool continued) {
  if (!continued) text.clear();
  if (!unread_.empty()) {  // a line handed back, already checked
    if (continued) text += '\n';
    text += unread_.front();
    unread_.pop_front();
    ++line_;
    return true;
  }
  const std::size_t start = text.size() + (continued ? 1 : 0);
  if (continued) text += '\n';
  bool any = false;
  for (;;) {
    if (begin_ == end_ && !fill()) break;
    any = true;
    const char* from = buffer_.data() + begin_;
    const auto* newline = static_cast<const char*>(std::memchr(from, '\n', end_ - begin_));
    const std::size_t take = newline ? static_cast<std::size_t>(newline - from) : end_ - begin_;
    if (text.size() + take > max_line_bytes_) {
      refuse(line_ + 1,
             continued ? fmt::format("a CSV record longer than {} bytes, the limit (is a quoted "
                                     "field left open?)",
                                     max_line_bytes_)
                       : fmt::format("a line longer than {} bytes, the limit", max_line_bytes_));
    }
    if (std::memchr(from, '\0', take))
      refuse(line_ + 1, "a NUL byte: the file is binary, expected text");
    text.append(from, take);
    begin_ += take;
    if (newline) {
      ++begin_;
      break;
    }
  }
  if (!any) {
    if (continued) text.pop_back();
    return false;
  }
  ++line_;
  if (text.size() > start && text.back() == '\r') text.pop_back();
  if (line_ == 1 && std::string_view(text).starts_with(kByteOrderMark))
    text.erase(0, kByteOrderMark.size());
  const std::string_view added = std::string_view(text).substr(start);
  const std::size_t bad = is_ascii(added) ? std::string_view::npos : invalid_utf8_at(added);
  if (bad != std::string_view::npos) {
    refuse(line_, fmt::format("byte {} is not UTF-8 text (expected a UTF-8 CSV or JSON Lines file)",
                              bad + 1));
  }
  return true;
}

void LineReader::refuse(std::size_t line, const std::string& detail) const {
  throw InputError(fmt::format("{}:{}", source_, line), "", detail);
}

bool LineReader::fill() {
  if (end_of_input_) return false;
  errno = 0;
  in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  const int error = errno;
  if (in_.bad()) {
    throw ReadError(source_, fmt::format("cannot read line {}{}{}", line_ + 1, error ? ": " : "",
                                         error ? std::strerror(error) : ""));
  }
  begin_ = 0;
  end_ = static_cast<std::size_t>(in_.gcount());
  bytes_read_ += end_;
  if (end_ == 0) end_of_input_ = true;
  return end_ > 0;
}

// Reads the lines that continue `record` while a quoted field is open. A
// quote left open to the end of the input makes the record its first line
// alone (that row's error says the quote is not closed) and hands the lines
// after it back, to be read as rows of their own.
void complete_record(LineReader& reader, std::string& record) {
  if (record.find('"') == std::string::npos) return;  // no quote, no quoted field left open
  CsvScan scan;
  scan.read(record);
  const std::size_t first_line_end = record.size();
  while (scan.inside_quotes()) {
    const std::size_t from = record.size();
    if (!reader.next(record, true)) {
      std::vector<std::string> rest;
      for (std::size_t at = first_line_end; at < record.size();) {
        const std::size_t end = std::min(record.find('\n', at + 1), record.size());
        rest.emplace_back(record, at + 1, end - at - 1);
        at = end;
      }
      record.resize(first_line_end);
      reader.unread(std::move(rest));
      return;
    }
    scan.read(std::string_view(record).substr(from));
  }
}

// Splits one CSV record (RFC 4180) into `out`: fields separated by commas; a
// field in double quotes may hold commas, line breaks and quotes written
// twice. A quote inside an unquoted field, or text after a closing quote, is
// an error.
void split_csv(std::string_view record, std::size_t max_fields, CsvRecord& out) {
  out.fields.clear();
  out.count = 0;
  out.error.clear();
  out.unquoted.clear();
  // Never longer than the record: the views into it stay valid as it grows.
  out.unquoted.reserve(record.size());
  const bool quotes = record.find('"') != std::string_view::npos;  // most records have none
  std::size_t i = 0;
  for (;;) {
    const std::size_t number = out.count + 1;
    std::string_view field;
    if (i < record.size() && record[i] == '"') {
      const std::size_t start = out.unquoted.size();
      for (++i;; ++i) {
        if (i == record.size()) {
          out.error = fmt::format("field {}: a quoted field is not closed", number);
          return;
        }
        if (record[i] != '"') {
          out.unquoted += record[i];
        } else if (i + 1 < record.size() && record[i + 1] == '"') {
          out.unquoted += '"';
          ++i;
        } else {
          ++i;
          break;
        }
      }
      if (i < record.size() && record[i] != ',') {
        out.error = fmt::format(
            "field {}: text after the closing quote (quote the whole field, "
            "writing a quote inside it twice)",
            number);
        return;
      }
      field = std::string_view(out.unquoted).substr(start);
    } else {
      const std::size_t end = std::min(record.find(',', i), record.size());
      field = record.substr(i, end - i);
      if (quotes && field.find('"') != std::string_view::npos) {
        out.error = fmt::format(
            "field {}: a quote inside an unquoted field (quote the whole field, "
            "writing a quote inside it twice)",
            number);
        return;
      }
      i = end;
    }
    if (out.count++ < max_fields) out.fields.push_back(field);
    if (i == record.size()) return;
    ++i;  // the comma
  }
}

// Whether a CSV record has no cell at all: only commas, blanks and empty
// quoted fields (",,,," is the row a spreadsheet writes for an empty line).
bool blank_record(std::string_view record) {
  for (std::size_t at = 0; at < record.size(); ++at) {
    const char c = record[at];
    if (c == ',' || c == ' ' || c == '\t') continue;
    if (c == '"' && at + 1 < record.size() && record[at + 1] == '"' &&
        (at + 2 == record.size() || record[at + 2] == ',')) {
      ++at;
      continue;
    }
    return false;
  }
  return true;
}

}  // namespace sweetspot::io
