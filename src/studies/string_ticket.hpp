#pragma once

// What a stringer reads off a string bed, and the tension that gives a bed
// the stiffness, the ring or the dwell of another (docs/model.md, "The
// stringer's bed"): the analysis behind `sweetspot string`.

#include <optional>
#include <string_view>

#include "io/json_reader.hpp"
#include "sweetspot/design.hpp"

namespace sweetspot::studies {

// The quantity a customer keeps when the frame or the string changes.
enum class BedQuantity { kStiffness, kRing, kDwell };

std::string_view to_string(BedQuantity quantity);  // "stiffness", "ring", "dwell"
std::optional<BedQuantity> parse_bed_quantity(std::string_view name);
std::string_view unit_of(BedQuantity quantity);  // "N/m", "Hz", "s"

// A string bed as a stringer reads it. The tensions are the machine's pull
// and the bed's (the pull less the design's tension_loss); stiffness and ring
// are the membrane's (string_bed.hpp), the dwell the contact time the ball
// and the bed give as two springs at the design's impact point (Eq. 17's
// M_eff), the model the tension's duration comes from.
struct BedReading {
  double pull_tension_N = 0.0;        // mains
  double cross_pull_tension_N = 0.0;  // crosses
  double bed_tension_N = 0.0;         // mains, in the bed
  double tension_loss = 0.0;
  double stiffness_N_m = 0.0;
  double ring_Hz = 0.0;
  double dwell_s = 0.0;
  double strings_mass_kg = 0.0;  // the strings inside the head
  // What one pound more on the machine changes (mains and crosses alike
  // scaled, the crosses in proportion), per lb of the mains' pull.
  double stiffness_per_lb = 0.0;
  double ring_per_lb = 0.0;
  double dwell_per_lb = 0.0;

  double value(BedQuantity quantity) const;
  double per_lb(BedQuantity quantity) const;
};

// The bed of `design` (which must have one: throws std::invalid_argument
// naming "strings" otherwise).
BedReading read_bed(const Design& design);

// The design with the mains' pull `pull_tension_N` (the crosses in
// proportion, or at `cross_pull_tension_N` when given).
Design with_pull(const Design& design, double pull_tension_N,
                 std::optional<double> cross_pull_tension_N = std::nullopt);

// The pull on the design's machine that gives its bed `target` of `quantity`,
// exact (the crosses in the ticket's proportion) and rounded as a stringer
// sets a machine (mains and crosses each to 0.5 lb), with the bed at the
// rounded pulls. `reachable` is false when no tension in
// [kMinTension_N, kMaxTension_N] gives the target (a dwell shorter than the
// ball's own, a stiffness beyond the strongest string's): then the nearest
// end is reported.
struct TensionAnswer {
  BedQuantity keep = BedQuantity::kStiffness;
  double target = 0.0;
  bool reachable = true;
  double exact_pull_N = 0.0;
  double exact_cross_pull_N = 0.0;
  double rounded_pull_lb = 0.0;
  double rounded_cross_pull_lb = 0.0;
  BedReading at_rounded;
};

TensionAnswer tension_for(const Design& design, BedQuantity quantity, double target);

// The machine's step: a stringer sets the tension to half a pound.
inline constexpr double kMachineStep_lb = 0.5;

}  // namespace sweetspot::studies
