#pragma once

// Design files: JSON in SI units with the unit in the key name, industry units
// accepted by suffix (mass_g, length_in, balance_cm, balance_pts_hl,
// swingweight_kg_cm2, impact_duration_ms). The format is documented in
// docs/design-files.md and schema/design.schema.json.

#include <map>
#include <string>
#include <string_view>

#include "io/design_description.hpp"
#include "io/json_reader.hpp"
#include "sweetspot/design.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::io {

struct DesignFile {
  std::string source;  // the file, or the study that holds it inline
  std::string name;    // "name", or the source when absent
  Design design;
  // How the implement was described: "head_to_handle_mass_ratio", "sections" or "specs".
  std::string implement_form;
  // For each input (canonical SI name, e.g. "hand/mass_kg"): "given" or "default".
  std::map<std::string, std::string> provenance;
  // Published values to compare with ("reference": {"source": ..., output: value}).
  Json reference;
  // Where each input came from in the file (canonical SI name -> JSON pointer).
  KeyMap keys;
  // "fidelity": rigid, modal, response or auto (the command line's --fidelity wins).
  std::string fidelity = "auto";
};

// The physics core's complaint about this design (its message starts with the
// canonical name, "hand/grip_length_m: ...") as an InputError at the JSON
// pointer the file used.
[[noreturn]] void rethrow_in(const DesignFile& design, const std::invalid_argument& error);

// Reads a design from a parsed document. Throws InputError naming `source`,
// the JSON pointer, the value and what was expected.
DesignFile read_design(const Json& document, const std::string& source);

// read_design() without the provenance and the key map (empty in the
// result), for sweeps and batches that read a design per point; the design
// and every error are the same (an error is found again with the key map).
DesignFile read_design_lean(const Json& document, const std::string& source);

// read_design_lean() that keeps the numbers as the file gives them, before
// anything is derived (a study's variables and a batch's columns are bound to
// it once). Throws like read_design().
DesignDescription describe_design(const Json& document, const std::string& source);

// Reads a design file.
DesignFile load_design(const std::string& path);

// Evaluates a design file at the fidelity `fidelity` names ("rigid", "modal",
// "response" or "auto"; empty: the file's own "fidelity"), the hand-held
// modes to `rel_tol`. The core's complaints come back as InputError at the
// JSON pointer the file used (rethrow_in).
Evaluation evaluate_design_file(const DesignFile& file, std::string_view fidelity, double rel_tol);

// Refuses a rig (support head_clamped, handle_clamped, a pivot or a rigid
// surface: is_rig()) for `what`, a player's question, as InputError at
// /support naming the file (require_player(), evaluate.hpp).
void require_player_file(const DesignFile& file, std::string_view what);

// The design as a complete design file in SI units (what `evaluate` accepts).
Json design_to_json(const DesignFile& design);

}  // namespace sweetspot::io
