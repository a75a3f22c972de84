#include "studies/design_settings.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "io/input_error.hpp"
#include "studies/catalogue_header.hpp"

namespace sweetspot::studies {
namespace {

constexpr std::string_view kSource = "--set";

io::Json setting_value(const std::string& field, std::string_view text, const std::string& label) {
  if (is_text_field(field)) return std::string(text);
  const std::string_view cell = trimmed(text);
  double number = 0.0;
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), number);
  if (!cell.empty() && error == std::errc() && end == cell.data() + cell.size()) {
    if (!std::isfinite(number))
      throw io::InputError(std::string(kSource), "", label + ": expected a finite number");
    // As JSON where the text is JSON (99 stays a whole number, quoted as the file's would be).
    const io::Json json = io::Json::parse(cell, nullptr, false);
    return json.is_number() ? json : io::Json(number);
  }
  io::Json value = io::Json::parse(cell, nullptr, false);
  // A trade gauge that is not a number ("16L"); a lead's clock by its word
  // ("throat", "handle"), as the design file's (a JSON string, quoted, too).
  if (value.is_discarded() && takes_a_word(field) && !cell.empty()) return std::string(cell);
  if (value.is_string() && field.ends_with(".clock")) return value;
  if (value.is_discarded() || value.is_string() || value.is_null()) {
    throw io::InputError(std::string(kSource), "",
                         fmt::format("{}: expected a number (or a JSON list or object), got {}",
                                     label, shown(text)));
  }
  return value;
}

}  // namespace

std::vector<Setting> parse_settings(const std::vector<std::string>& items) {
  std::vector<Setting> settings;
  std::vector<DesignColumn> fields;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const std::string_view item = items[k];
    const std::size_t equals = item.find('=');
    if (equals == std::string_view::npos) {
      throw io::InputError(
          std::string(kSource), "",
          fmt::format("{}: expected FIELD=VALUE, such as impact.off_axis_cm=3", shown(item)));
    }
    std::string field(trimmed(item.substr(0, equals)));
    const std::string label = shown(field);
    if (const std::string problem = design_field_problem(field); !problem.empty())
      throw io::InputError(std::string(kSource), "", label + ": " + problem);
    io::Json value = setting_value(field, item.substr(equals + 1), label);
    fields.push_back(DesignColumn{k, field, label});
    settings.push_back(Setting{field, field_to_pointer(field), std::move(value), items[k]});
  }
  check_fields_together(fields, std::string(kSource));
  return settings;
}

void apply_settings(io::Json& document, const std::vector<Setting>& settings,
                    const std::string& file) {
  const std::string source =
      file.empty() ? std::string(kSource) : file + " " + std::string(kSource);
  for (const Setting& setting : settings) {
    try {
      io::override_field(document, setting.pointer, setting.value);
    } catch (const io::PathError& e) {
      throw io::InputError(source, e.pointer(),
                           fmt::format("{}: {}", shown(setting.text), e.detail()));
    } catch (const io::Json::exception&) {
      throw io::InputError(source, setting.pointer,
                           fmt::format("{}: the design holds a value on its path that is not an "
                                       "object",
                                       shown(setting.text)));
    }
  }
}

io::DesignFile load_design(const std::string& path, const std::vector<Setting>& settings) {
  if (settings.empty()) return io::load_design(path);
  return read_design(io::read_json_file(path), io::input_name(path), settings);
}

io::DesignFile read_design(io::Json document, const std::string& file,
                           const std::vector<Setting>& settings) {
  if (settings.empty()) return io::read_design(document, file);
  std::string items;
  for (const Setting& setting : settings) items += (items.empty() ? "" : ", ") + setting.text;
  bool named = false;
  for (const Setting& setting : settings) named = named || setting.field == "name";
  apply_settings(document, settings, file);
  std::string source = file;
  for (const Setting& setting : settings) source += " --set " + setting.text;
  io::DesignFile design = io::read_design(document, source);
  if (!named) {
    const auto name = document.find("name");
    design.name = fmt::format("{} ({})", name == document.end() ? file : design.name, items);
  }
  return design;
}

}  // namespace sweetspot::studies
