#pragma once

// What-ifs without a new file: `--set impact.off_axis_cm=3` on the command
// line sets one field of a design as a catalogue's column would (the same
// dotted names, any unit spelling the design file accepts), and the design is
// then read and checked exactly as a file that held the value would be.

#include <string>
#include <vector>

#include "io/design_reader.hpp"
#include "io/json_reader.hpp"

namespace sweetspot::studies {

struct Setting {
  std::string field;    // "impact.off_axis_cm"
  std::string pointer;  // "/impact/off_axis_cm"
  io::Json value;       // 3
  std::string text;     // "impact.off_axis_cm=3", as given
};

// The items of repeated `--set FIELD=VALUE` options: each FIELD a design
// field (checked as a catalogue's header is: none twice, in two units or
// forms, or inside another), each VALUE a finite number, a text for the
// fields that hold text (name, description, fidelity), or a JSON value (a
// list of point masses). Throws InputError naming "--set" and the item.
std::vector<Setting> parse_settings(const std::vector<std::string>& items);

// `document` with every setting written over it, the other spellings of the
// same quantity removed beside each (io::override_field).
// `file` names the design in a refusal ("racquet.json --set: ..."), for a
// command that reads several.
void apply_settings(io::Json& document, const std::vector<Setting>& settings,
                    const std::string& file = "");

// The design file at `path` with `settings` applied. With settings, its
// source (in every message) is "PATH --set ITEM ..." and its name the
// file's name followed by the items in brackets, unless a setting names it.
io::DesignFile load_design(const std::string& path, const std::vector<Setting>& settings);

// load_design() of a document already read from `file` (its input_name()).
io::DesignFile read_design(io::Json document, const std::string& file,
                           const std::vector<Setting>& settings);

}  // namespace sweetspot::studies
