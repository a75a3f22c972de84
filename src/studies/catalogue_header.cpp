#include "studies/catalogue_header.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <map>

#include "io/csv.hpp"
#include "io/design_fields.hpp"
#include "io/input_error.hpp"
#include "io/json_reader.hpp"

namespace sweetspot::studies {
namespace {

constexpr std::string_view kBlank = " \t";

// The parts of a design a column may name directly when a map is given.
bool names_design_part(std::string_view field) {
  constexpr std::string_view kParts[] = {"implement", "frame", "strings", "hand",
                                         "forearm",   "ball",  "impact",  "reference"};
  const std::string_view part = field.substr(0, field.find('.'));
  return is_text_field(field) ||
         (part.size() < field.size() &&
          std::find(std::begin(kParts), std::end(kParts), part) != std::end(kParts));
}

// Why `field` cannot name a design field, "" when it can: dot-separated
// names of ASCII letters, digits and '_', an all-digit name an array index.
std::string field_problem(std::string_view field) {
  constexpr std::string_view kExample = " (expected a path of names such as implement.mass_g)";
  if (field.empty()) return "an empty column name" + std::string(kExample);
  std::size_t start = 0;
  for (int depth = 0;; ++depth) {
    const std::size_t dot = field.find('.', start);
    const std::string_view name =
        field.substr(start, dot == std::string_view::npos ? dot : dot - start);
    if (name.empty()) return "an empty name between dots" + std::string(kExample);
    if (name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") !=
        std::string_view::npos) {
      return "a character other than letters, digits, '_' and '.'" + std::string(kExample);
    }
    if (name.find_first_not_of("0123456789") == std::string_view::npos) {
      if (depth == 0)
        return "a path starts with a part of the design, not an index" + std::string(kExample);
      if (name.size() > 1 && name[0] == '0') return "an array index with a leading zero";
      if (name.size() > 5) return "an array index above 99999";
    }
    if (dot == std::string_view::npos) return "";
    start = dot + 1;
  }
}

}  // namespace

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(kBlank);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(kBlank) - first + 1);
}

// A cell or column name quoted for a message, shortened like brief().
std::string shown(std::string_view text) { return io::brief(io::valid_utf8(text)); }

bool is_text_field(std::string_view field) {
  // The stringer's words: a material, a pattern, a trade gauge ("16L"; a
  // gauge that is a number, 16, is read as one); a cross-section's shape; a
  // support by its name ("handle_clamped"; a pivot is support.pivot_from_butt_cm); a
  // ball's law by its name ("hysteretic"); a grip by its tightness ("tight").
  for (const std::string_view family : {"strings.", "strings.mains.", "strings.crosses."}) {
    if (!field.starts_with(family)) continue;
    const std::string_view stem = field.substr(family.size());
    if (stem == "material" || (family == "strings." && stem == "pattern")) return true;
  }
  return field == "name" || field == "description" || field == "fidelity" ||
         field == "reference.source" || field == "frame.cross_section.shape" ||
         field == "support" || field == "ball.contact.law" || field == "hand.grip";
}

bool takes_a_word(std::string_view field) {
  return field.ends_with(".clock") || field.ends_with(".gauge");
}

// The header, checked once: every column a design field (or, with a map,
// mapped onto one or passed through), none given twice, in two units or
// forms, or inside another; every column of the map in the header.
Header read_header(std::string_view line, const std::string& where, const ColumnMap& map,
                   const std::string& map_source) {
  io::CsvRecord record;
  io::split_csv(line, kMaxBatchColumns, record);
  if (!record.error.empty())
    throw io::InputError(where, "", "the header is not CSV: " + record.error);
  if (record.count > kMaxBatchColumns) {
    throw io::InputError(
        where, "",
        fmt::format("{} columns, more than the limit of {}", record.count, kMaxBatchColumns));
  }
  Header header;
  header.count = record.count;
  for (const std::string_view field : record.fields) header.names.emplace_back(trimmed(field));
  const bool mapped = !map.empty();
  std::map<std::string, std::string> target_of;  // column name -> design field
  for (const auto& [column, field] : map) {
    const auto first = std::find(header.names.begin(), header.names.end(), column);
    if (first == header.names.end()) {
      std::string columns;
      for (std::size_t k = 0; k < header.names.size() && k < 12; ++k)
        columns += (k ? ", " : "") + shown(header.names[k]);
      if (header.names.size() > 12) columns += ", ...";
      throw io::InputError(map_source, "",
                           fmt::format("column {}: not in the header of {} (expected one of {})",
                                       shown(column), where, columns));
    }
    if (std::find(first + 1, header.names.end(), column) != header.names.end()) {
      throw io::InputError(
          map_source, "",
          fmt::format("column {}: the header of {} has it twice (columns {} and {}), "
                      "expected a column name given once",
                      shown(column), where, first - header.names.begin() + 1,
                      std::find(first + 1, header.names.end(), column) - header.names.begin() + 1));
    }
    target_of.emplace(column, field);
  }
  for (std::size_t k = 0; k < header.names.size(); ++k) {
    const std::string& name = header.names[k];
    const auto target = target_of.find(name);
    if (mapped && target == target_of.end() && !names_design_part(name)) {
      for (const std::size_t other : header.passed) {
        if (header.names[other] == name) {
          throw io::InputError(where, "",
                               fmt::format("column {} {}: repeats column {}, passed through too "
                                           "(expected each column passed through named once)",
                                           k + 1, shown(name), other + 1));
        }
      }
      header.passed.push_back(k);
      continue;
    }
    const std::string& field = target == target_of.end() ? name : target->second;
    std::string label = fmt::format("column {} {}", k + 1, shown(name));
    if (target != target_of.end()) label += " (mapped to " + shown(field) + ")";
    if (const std::string problem = field_problem(field); !problem.empty()) {
      if (target != target_of.end()) {
        throw io::InputError(
            map_source, "",
            fmt::format("column {}: the field {}: {}", shown(name), shown(field), problem));
      }
      throw io::InputError(where, "", label + ": " + problem);
    }
    // A field no design has is the header's fault, refused once whatever the cells hold.
    if (const std::string unknown = io::design_path_problem(field_to_pointer(field));
        !unknown.empty())
      throw io::InputError(where, "", label + ": " + unknown);
    header.design.push_back(DesignColumn{k, field, std::move(label)});
  }
  check_fields_together(header.design, where);
  return header;
}

void check_fields_together(const std::vector<DesignColumn>& fields, const std::string& where) {
  std::map<std::string, std::size_t> column_of;  // pointer -> index in fields
  for (std::size_t j = 0; j < fields.size(); ++j) {
    const auto [same, inserted] = column_of.emplace(field_to_pointer(fields[j].field), j);
    if (!inserted) {
      throw io::InputError(where, "",
                           fmt::format("{}: repeats {} (each field may be given once)",
                                       fields[j].label, fields[same->second].label));
    }
  }
  for (const auto& [pointer, j] : column_of) {
    const std::string& label = fields[j].label;
    const std::size_t slash = pointer.rfind('/');
    const std::string parent = pointer.substr(0, slash);
    for (std::size_t at = parent.size(); at > 0; at = parent.rfind('/', at - 1)) {
      const auto outer = column_of.find(parent.substr(0, at));
      if (outer != column_of.end()) {
        throw io::InputError(where, "",
                             fmt::format("{}: lies inside {} (give the field or what it holds)",
                                         label, fields[outer->second].label));
      }
      if (at == 0) break;
    }
    for (const std::string& other : io::alternative_spellings(pointer.substr(slash + 1))) {
      const auto contradicted = column_of.find(parent + "/" + other);
      if (contradicted != column_of.end() && contradicted->second < j) {
        throw io::InputError(where, "",
                             fmt::format("{}: contradicts {}: give the quantity once, in one unit",
                                         label, fields[contradicted->second].label));
      }
    }
    // The same quantity in another object (the head's size as the implement's
    // and as the string bed's): one head, one size.
    for (const std::string& other : io::FieldOverride(pointer).elsewhere_pointers()) {
      const auto contradicted = column_of.find(other);
      if (contradicted != column_of.end() && contradicted->second < j) {
        throw io::InputError(
            where, "",
            fmt::format("{}: contradicts {}: one head, one size: give the quantity once", label,
                        fields[contradicted->second].label));
      }
    }
  }
}

std::string design_field_problem(std::string_view field) {
  if (std::string problem = field_problem(field); !problem.empty()) return problem;
  return io::design_path_problem(field_to_pointer(std::string(field)));
}

std::string field_to_pointer(const std::string& field) {
  std::string pointer = "/";
  for (const char c : field) pointer += c == '.' ? '/' : c;
  return pointer;
}

std::vector<std::pair<std::string, std::string>> parse_column_map(std::string_view text,
                                                                  const std::string& source) {
  std::vector<std::pair<std::string, std::string>> map;
  std::size_t start = 0;
  for (std::size_t item = 1;; ++item) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view entry = trimmed(text.substr(start, comma - start));
    const std::size_t equals = entry.find('=');
    if (equals == std::string_view::npos) {
      throw io::InputError(source, "",
                           fmt::format("item {} {}: expected COLUMN=design.field, such as "
                                       "weight=implement.mass_g",
                                       item, shown(entry)));
    }
    std::string column(trimmed(entry.substr(0, equals)));
    std::string field(trimmed(entry.substr(equals + 1)));
    if (column.empty() || field.empty()) {
      throw io::InputError(source, "",
                           fmt::format("item {} {}: expected a column name and a design field on "
                                       "either side of '=', such as weight=implement.mass_g",
                                       item, shown(entry)));
    }
    for (const auto& [other, _] : map) {
      if (other == column) {
        throw io::InputError(
            source, "",
            fmt::format("column {}: mapped twice (expected each column once)", shown(column)));
      }
    }
    map.emplace_back(std::move(column), std::move(field));
    if (comma == text.size()) return map;
    start = comma + 1;
  }
}

std::vector<std::pair<std::string, std::string>> column_map_from_json(const io::Json& json,
                                                                      const std::string& source) {
  if (!json.is_object() || json.empty()) {
    throw io::InputError(
        source, "",
        "expected a JSON object from the catalogue's column names to design fields, "
        "such as {\"weight\": \"implement.mass_g\"}, got " +
            io::brief(json));
  }
  std::vector<std::pair<std::string, std::string>> map;
  for (const auto& [column, field] : json.items()) {
    if (!field.is_string()) {
      throw io::InputError(
          source, (io::Json::json_pointer() / column).to_string(),
          "expected a design field as text, such as \"implement.mass_g\", got " + io::brief(field));
    }
    map.emplace_back(column, field.get<std::string>());
  }
  return map;
}

}  // namespace sweetspot::studies
