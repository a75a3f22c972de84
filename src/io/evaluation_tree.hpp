#pragma once

// The tree of one evaluation that `sweetspot evaluate --format json` prints
// (evaluation_json()) and the Python module returns as a dict, written once
// through a node type, so that each builds its own tree directly:
//
//   struct Node {
//     void number(std::string_view key, double value);
//     void integer(std::string_view key, std::int64_t value);
//     void text(std::string_view key, std::string_view value);
//     void null(std::string_view key);
//     void numbers(std::string_view key, const std::vector<double>& values);
//     void json_number(std::string_view key, const Json& value);  // an int or a double
//     Node object(std::string_view key);  // a child object under `key`
//     List list(std::string_view key);    // a child list under `key`
//   };
//   struct List { Node object(); };        // a child object appended
//
// A child is filled before its parent's next child is made.

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "io/design_reader.hpp"
#include "io/format.hpp"
#include "io/outputs.hpp"
#include "sweetspot/evaluate.hpp"

namespace sweetspot::io {
namespace evaluation_tree_detail {

// Where the solved collision replaced an input by what it found: the COR
// (Eq. 16 inverted) and the impact duration (the contact time). Empty when
// it did not.
std::string_view solved_provenance(std::string_view name, const Evaluation& e);

// Why a cheaper model would have done (empty when nothing to say).
std::string fidelity_note(const Evaluation& e);

// An input the file gave in another unit ("strings/tension_N" given as
// {"/strings/tension_lb": 52}): its pointer and the number as given.
std::optional<std::pair<std::string, Json>> given_elsewhere(const DesignFile& file,
                                                            std::string_view name);

}  // namespace evaluation_tree_detail

// {"name", "fidelity", "inputs": {canonical name: {"value", "unit",
// "provenance"[, "given"]}}, "outputs": {...}, "notes": {output: why null},
// and "power_point", "collision", "vibration_modes" where the evaluation has them}.
template <class Node>
void write_evaluation(Node& root, const DesignFile& file, const Evaluation& e) {
  namespace detail = evaluation_tree_detail;
  const Design& d = file.design;
  root.text("name", file.name);
  root.text("fidelity", to_string(fidelity_of(e)));
  if (e.modal) {
    root.text("mass_distribution", e.modal->mass_distribution_fitted
                                       ? "fitted to the specs (quadratic density)"
                                       : "given");
  }
  {
    Node inputs = root.object("inputs");
    inputs.text("implement/form", file.implement_form);
    const auto input = [&](const char* name, double value, const char* unit) {
      Node entry = inputs.object(name);
      entry.number("value", value);
      entry.text("unit", unit);
      const std::string_view solved = detail::solved_provenance(name, e);
      const auto it = file.provenance.find(name);
      entry.text("provenance", !solved.empty()               ? solved
                               : it == file.provenance.end() ? std::string_view("given")
                                                             : std::string_view(it->second));
      if (const auto given = detail::given_elsewhere(file, name)) {
        Node as_given = entry.object("given");
        as_given.json_number(given->first, given->second);
      }
    };
    input("frame/cor", e.cor, "");
    input("strings/impact_duration_s", e.impact_duration_s, "s");
    if (d.cor_rigid) input("frame/cor_rigid", *d.cor_rigid, "");
    if (d.strings) input("strings/tension_N", d.strings->tension_N, "N");
    input("hand/mass_kg", d.hand.mass_kg, "kg");
    input("hand/center_from_butt_m", d.hand.center_from_butt_m, "m");
    input("forearm/equivalent_mass_kg", d.forearm_equivalent_mass_kg, "kg");
    input("ball/mass_kg", d.ball.mass_kg, "kg");
    input("ball/speed_m_s", d.ball.speed_m_s, "m/s");
    // What the solved collision's squeeze is held to (its radius).
    if (e.details && e.details->collision) input("ball/diameter_m", d.ball.diameter_m, "m");
    input("impact/from_butt_m", d.impact_from_butt_m, "m");
    if (d.stiffness.RA) input("frame/RA", *d.stiffness.RA, "");
  }
  const Evaluation::Details details = e.details.value_or(Evaluation::Details{});
  {
    Node outputs = root.object("outputs");
    for (const OutputSpec& output : output_specs()) {
      if (const std::optional<double> value = output.value(e)) {
        outputs.number(output.name, *value);
      } else {
        outputs.null(output.name);
      }
    }
    if (details.collision) {
      const CollisionResult& c = *details.collision;
      Node ledger = outputs.object("energy_ledger");
      ledger.number("ball_in_J", c.ball_in_J);
      ledger.number("ball_out_J", c.ball_out_J);
      ledger.number("implement_rigid_J", c.implement_rigid_J);
      ledger.number("vibration_J", c.vibration_J);
      ledger.number("ball_loss_J", c.ball_loss_J);
      ledger.number("strings_loss_J", c.strings_loss_J);
    }
  }
  {
    Node notes = root.object("notes");
    for (const OutputSpec& output : output_specs()) {
      if (!output.value(e)) notes.text(output.name, output.absent_because(e));
    }
    if (const std::string note = detail::fidelity_note(e); !note.empty())
      notes.text("fidelity", note);
  }
  // The power point: searched along the string bed for one design (evaluate),
  // so not an output of every row (studies::with_power_point()).
  if (e.power_point_from_butt_m && e.power_point_shot_speed_m_s) {
    const double v = *e.power_point_shot_speed_m_s;
    Node point = root.object("power_point");
    point.number("from_tip_m", e.length_m - *e.power_point_from_butt_m);
    point.number("shot_speed_m_s", v);
    point.number("shot_speed_km_h", v * kKmHPerMS);
    point.number("shot_speed_mph", v * kMphPerMS);
  }
  if (details.collision) {
    const CollisionResult& c = *details.collision;
    Node collision = root.object("collision");
    collision.integer("contacts", c.contacts);
    collision.number("peak_ball_compression_m", c.peak_ball_compression_m);
    collision.number("peak_string_deflection_m", c.peak_string_deflection_m);
    collision.number("string_bed_energy_J", c.string_bed_energy_J);
    collision.numbers("time_s", c.time_s);
    collision.numbers("force_N", c.force_N);
  }
  if (!details.vibration_modes.empty()) {
    auto modes = root.list("vibration_modes");
    for (const auto& [frequency, energy] : details.vibration_modes) {
      Node mode = modes.object();
      mode.number("frequency_Hz", frequency);
      mode.number("energy_J", energy);
    }
  }
}

}  // namespace sweetspot::io
