#include "io/rows.hpp"

#include <stdexcept>
#include <utility>

#include "io/json_reader.hpp"

namespace sweetspot::io {
namespace {

class CsvRows final : public RowWriter {
 public:
  void header(std::vector<std::string> names, std::string& out) override {
    for (std::size_t k = 0; k < names.size(); ++k) text(k, names[k], out);
    end_row(out);
  }
  void number(std::size_t column, std::optional<double> value, std::string& out) const override {
    char buffer[kMaxExactChars + 1];
    char* end = buffer;
    if (column > 0) *end++ = ',';
    if (value) end = write_exact(end, *value);
    out.append(buffer, static_cast<std::size_t>(end - buffer));
  }
  void text(std::size_t column, std::optional<std::string_view> value,
            std::string& out) const override {
    if (column > 0) out += ',';
    if (!value) return;
    if (csv_plain(*value)) {
      out += *value;
    } else {
      out += csv_field(*value);
    }
  }
  void end_row(std::string& out) const override { out += '\n'; }
};

class JsonLinesRows final : public RowWriter {
 public:
  void header(std::vector<std::string> names, std::string& /*out*/) override {
    keys_.clear();
    for (const std::string& name : names) keys_.push_back(dumped(Json(name)));
  }
  void number(std::size_t column, std::optional<double> value, std::string& out) const override {
    key(column, out);
    out += value ? dumped(Json(*value)) : std::string("null");
  }
  void text(std::size_t column, std::optional<std::string_view> value,
            std::string& out) const override {
    key(column, out);
    out += value ? dumped(Json(std::string(*value))) : std::string("null");
  }
  void end_row(std::string& out) const override { out += "}\n"; }

 private:
  // A JSON value as one line; text that is not UTF-8 has U+FFFD in its place.
  static std::string dumped(const Json& value) {
    return value.dump(-1, ' ', false, Json::error_handler_t::replace);
  }
  void key(std::size_t column, std::string& out) const {
    out += column == 0 ? '{' : ',';
    out += keys_.at(column);
    out += ':';
  }
  std::vector<std::string> keys_;  // each dumped as a JSON string
};

}  // namespace

std::unique_ptr<RowWriter> row_writer(Format format) {
  if (format == Format::kCsv) return std::make_unique<CsvRows>();
  if (format == Format::kJson) return std::make_unique<JsonLinesRows>();
  throw std::invalid_argument("row_writer: rows are written as CSV or JSON Lines");
}

}  // namespace sweetspot::io
