#include "studies/string_ticket.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sweetspot/evaluate.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot::studies {
namespace {

using io::kPoundForce_N;

const StringBed& bed_of(const Design& design) {
  if (!design.strings) {
    throw std::invalid_argument(
        is_round(design)
            ? "strings: the design is given by its profile, a round implement (a bat, a rod), "
              "which has no string bed"
            : "strings: the design has no string bed: give strings.tension_lb (or a ticket: "
              "pattern, mains, crosses)");
  }
  return *design.strings;
}

// The ball's contact time on the bed at the design's impact point [s].
double dwell_of(const Design& design, const StringBed& bed) {
  const double M_eff =
      effective_mass(design.implement.mass_properties(), design.impact_from_butt_m,
                     design.impact_off_axis_m, polar_inertia_kg_m2(design).value_or(0.0));
  return tension_impact_duration(bed, design.ball.mass_kg, M_eff).duration_s;
}

}  // namespace

std::string_view to_string(BedQuantity quantity) {
  switch (quantity) {
    case BedQuantity::kStiffness:
      return "stiffness";
    case BedQuantity::kRing:
      return "ring";
    case BedQuantity::kDwell:
      return "dwell";
  }
  return "stiffness";
}

std::optional<BedQuantity> parse_bed_quantity(std::string_view name) {
  for (const BedQuantity q : {BedQuantity::kStiffness, BedQuantity::kRing, BedQuantity::kDwell})
    if (name == to_string(q)) return q;
  return std::nullopt;
}

std::string_view unit_of(BedQuantity quantity) {
  switch (quantity) {
    case BedQuantity::kStiffness:
      return "N/m";
    case BedQuantity::kRing:
      return "Hz";
    case BedQuantity::kDwell:
      return "s";
  }
  return "";
}

double BedReading::value(BedQuantity quantity) const {
  switch (quantity) {
    case BedQuantity::kStiffness:
      return stiffness_N_m;
    case BedQuantity::kRing:
      return ring_Hz;
    case BedQuantity::kDwell:
      return dwell_s;
  }
  return 0.0;
}

double BedReading::per_lb(BedQuantity quantity) const {
  switch (quantity) {
    case BedQuantity::kStiffness:
      return stiffness_per_lb;
    case BedQuantity::kRing:
      return ring_per_lb;
    case BedQuantity::kDwell:
      return dwell_per_lb;
  }
  return 0.0;
}

Design with_pull(const Design& design, double pull_tension_N,
                 std::optional<double> cross_pull_tension_N) {
  Design d = design;
  StringBed& bed = *d.strings;
  bed.tension_N = pull_tension_N * (1.0 - bed.tension_loss);
  if (cross_pull_tension_N) bed.cross_tension_ratio = *cross_pull_tension_N / pull_tension_N;
  return d;
}

BedReading read_bed(const Design& design) {
  const StringBed& bed = bed_of(design);
  BedReading r;
  r.bed_tension_N = bed.tension_N;
  r.tension_loss = bed.tension_loss;
  r.pull_tension_N = bed.pull_tension_N();
  r.cross_pull_tension_N = r.pull_tension_N * bed.cross_tension_ratio;
  r.stiffness_N_m = string_bed_stiffness(bed);
  r.ring_Hz = string_bed_ring_frequency(bed);
  r.dwell_s = dwell_of(design, bed);
  r.strings_mass_kg = string_bed_strings_mass(bed);
  // k grows as the tension, f as its square root (both exact); the dwell by
  // a central difference of half a pound either way (1 lb apart).
  const double pull_lb = r.pull_tension_N / kPoundForce_N;
  r.stiffness_per_lb = r.stiffness_N_m / pull_lb;
  r.ring_per_lb = 0.5 * r.ring_Hz / pull_lb;
  const double h = 0.5 * kPoundForce_N;
  r.dwell_per_lb = (dwell_of(design, *with_pull(design, r.pull_tension_N + h).strings) -
                    dwell_of(design, *with_pull(design, r.pull_tension_N - h).strings));
  return r;
}

TensionAnswer tension_for(const Design& design, BedQuantity quantity, double target) {
  const StringBed& bed = bed_of(design);
  if (!(std::isfinite(target) && target > 0.0)) {
    throw std::invalid_argument(std::string(to_string(quantity)) + ": the target must be > 0 " +
                                std::string(unit_of(quantity)));
  }
  TensionAnswer a;
  a.keep = quantity;
  a.target = target;
  std::optional<double> bed_tension;
  switch (quantity) {
    case BedQuantity::kStiffness:
      bed_tension = tension_for_stiffness(bed, target);
      break;
    case BedQuantity::kRing:
      bed_tension = tension_for_ring(bed, target);
      break;
    case BedQuantity::kDwell: {
      const double M_eff =
          effective_mass(design.implement.mass_properties(), design.impact_from_butt_m,
                         design.impact_off_axis_m, polar_inertia_kg_m2(design).value_or(0.0));
      bed_tension = tension_for_duration(bed, target, design.ball.mass_kg, M_eff);
      if (!bed_tension) bed_tension = kMaxTension_N * 2.0;  // shorter than the ball's own
      break;
    }
  }
  // Both families inside the verified range of tensions.
  const double highest = std::max(1.0, bed.cross_tension_ratio);
  const double lowest = std::min(1.0, bed.cross_tension_ratio);
  const double min_bed = kMinTension_N / lowest, max_bed = kMaxTension_N / highest;
  a.reachable = *bed_tension >= min_bed && *bed_tension <= max_bed;
  const double settled = std::clamp(*bed_tension, min_bed, max_bed);
  a.exact_pull_N = settled / (1.0 - bed.tension_loss);
  a.exact_cross_pull_N = a.exact_pull_N * bed.cross_tension_ratio;
  a.rounded_pull_lb =
      std::round(a.exact_pull_N / kPoundForce_N / kMachineStep_lb) * kMachineStep_lb;
  // A rounding that leaves the range stays at its end.
  const double lo_lb = min_bed / (1.0 - bed.tension_loss) / kPoundForce_N;
  const double hi_lb = max_bed / (1.0 - bed.tension_loss) / kPoundForce_N;
  if (a.rounded_pull_lb < lo_lb) a.rounded_pull_lb += kMachineStep_lb;
  if (a.rounded_pull_lb > hi_lb) a.rounded_pull_lb -= kMachineStep_lb;
  const double cross_lb = a.rounded_pull_lb * bed.cross_tension_ratio;
  a.rounded_cross_pull_lb = std::round(cross_lb / kMachineStep_lb) * kMachineStep_lb;
  // A cross rounded out of the range stays at its end.
  if (a.rounded_cross_pull_lb * kPoundForce_N * (1.0 - bed.tension_loss) < kMinTension_N)
    a.rounded_cross_pull_lb += kMachineStep_lb;
  if (a.rounded_cross_pull_lb * kPoundForce_N * (1.0 - bed.tension_loss) > kMaxTension_N)
    a.rounded_cross_pull_lb -= kMachineStep_lb;
  a.at_rounded = read_bed(with_pull(design, a.rounded_pull_lb * kPoundForce_N,
                                    a.rounded_cross_pull_lb * kPoundForce_N));
  return a;
}

}  // namespace sweetspot::studies
