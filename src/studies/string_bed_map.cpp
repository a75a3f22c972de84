#include "studies/string_bed_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "io/parallel.hpp"
#include "sweetspot/collision.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/frame_modes.hpp"
#include "sweetspot/impact_response.hpp"
#include "sweetspot/invariants.hpp"
#include "sweetspot/kernels.hpp"
#include "sweetspot/rigid_impact.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot::studies {
namespace {

void check_grid(const char* name, int n) {
  if (!(n >= 2 && n <= 1000)) {
    throw std::invalid_argument(std::string(name) + ": expected a whole number in [2, 1000], got " +
                                std::to_string(n));
  }
}

// `error` again, with the grid point it was raised at: the map's refusal says
// where, as evaluate's says at the design's impact. A ModelRefusal stays one.
[[noreturn]] void rethrow_at_point(const FieldError& error, double from_tip_m,
                                   std::optional<double> off_axis_m) {
  std::string where =
      ", at the map's point " + fmt::format("{:.3g}", from_tip_m * 100.0) + " cm from the tip";
  if (off_axis_m) {
    where += *off_axis_m == 0.0
                 ? ", on the axis"
                 : ", " + fmt::format("{:.3g}", std::abs(*off_axis_m) * 100.0) +
                       " cm off the axis toward " + (*off_axis_m > 0.0 ? "3" : "9") + " o'clock";
  }
  if (const auto* refusal = dynamic_cast<const ModelRefusal*>(&error))
    throw ModelRefusal(refusal->field(), refusal->value(), refusal->detail() + where,
                       refusal->reason());
  throw FieldError(error.field(), error.detail() + where);
}

}  // namespace

StringBedMap string_bed_map(const Design& design, const StringBedMapOptions& options) {
  check_grid("--columns", options.columns);
  check_grid("--rows", options.rows);
  if (is_rig(design.support)) {
    // A rig holds the implement still: no wrist, no player, nothing to map.
    throw FieldError("support",
                     "a map is of a racquet in play (its wrist force and rebound "
                     "at each point); a rig (" +
                         std::string(to_string(design.support.kind)) +
                         ") has none: ask `sweetspot evaluate` about one point of it, "
                         "or give support free or hand");
  }
  if (design.cor_rigid) {
    throw std::invalid_argument(
        "frame/cor_rigid: a map uses the given COR (frame/cor); a COR derived at every point of "
        "the string bed is not supported");
  }
  // Validates the design and derives the duration at its own impact point.
  RigidCase base = rigid_case(design);
  if (is_round(design)) {
    throw std::invalid_argument(
        "implement: a map of the string bed needs a head, and an implement given by its "
        "profile (a bat) has none: ask `sweetspot evaluate` about a point of it");
  }
  const std::optional<double> polar = polar_inertia_kg_m2(design);
  if (!polar) {
    throw std::invalid_argument(
        "implement: a map of the string bed needs the head's size: give headsize_sq_in (or "
        "twistweight_kg_cm2, for the default 100 in^2 head)");
  }
  StringBedMap map;
  map.bed = string_bed(racquet_head(design), design.implement.length_m());
  map.columns = options.columns;
  map.rows = options.rows;
  map.polar_inertia_kg_m2 = *polar;
  map.polar_inertia_estimated = polar_inertia_estimated(design);
  map.fidelity = options.fidelity;
  const MassProperties system = hand_held_system(design);
  map.cop_hand_from_butt_m = hand_held_cop_from_butt(system);

  std::optional<ResponseModel> model;
  std::optional<DesignCollision> collision;
  if (options.fidelity == Fidelity::kCollision) {
    collision.emplace(design);  // throws for a design that cannot be solved
    map.node_free_from_butt_m = evaluate_modes(design).node_free_from_butt_m;
  } else if (options.fidelity != Fidelity::kRigid) {
    if (!has_stiffness(design)) {
      throw std::invalid_argument(
          "frame/EI_N_m2: the vibration map needs the frame's stiffness (frame EI_N_m2, RA or "
          "fundamental_free_Hz)");
    }
    map.node_free_from_butt_m = evaluate_modes(design).node_free_from_butt_m;
    model = response_model(design, ResponseOptions{});
  }

  const HeadEllipse& bed = map.bed;
  const double x0 = bed.center_from_butt_m - bed.semi_length_m;
  const double dx = 2.0 * bed.semi_length_m / options.columns;
  const double dy = 2.0 * bed.semi_width_m / options.rows;
  const MassProperties& body = design.implement.mass_properties();
  map.points.resize(static_cast<std::size_t>(options.columns) * options.rows);
  // One column of the grid, written into its own points: columns are
  // independent, so threads may take any of them.
  const auto column = [&](int i) {
    const double x = x0 + (i + 0.5) * dx;
    std::optional<double> at_y;  // the point being solved, for a refusal
    try {
      // A swung racquet meets the ball at v_in + V(x), as evaluate() solves it.
      std::optional<Meeting> meeting;
      if (design.swing) meeting = meeting_at(design, x);
      const double speed_m_s = meeting ? meeting->speed_m_s : design.ball.speed_m_s;
      // With a given duration the vibration per unit impulse depends on x only.
      std::optional<double> column_kappa;
      if (model && !design.strings)
        column_kappa = vibration_compliance(*model, x, base.impact_duration_s);
      for (int j = 0; j < options.rows; ++j) {
        // -c + k dy and c - k dy round alike: y_j = -y_{rows-1-j} exactly.
        // The middle row of an odd count is the axis itself.
        const double y = 2 * j + 1 == options.rows ? 0.0
                         : j < options.rows / 2    ? -bed.semi_width_m + (j + 0.5) * dy
                                                : bed.semi_width_m - (options.rows - j - 0.5) * dy;
        StringBedMapPoint& p = map.points[static_cast<std::size_t>(j) * options.columns + i];
        p.from_butt_m = x;
        p.off_axis_m = y;
        p.on_bed = on_string_bed(bed, x, y);
        if (!p.on_bed) continue;
        at_y = y;
        RigidCase c = base;
        c.ball_speed_m_s = speed_m_s;
        c.impact_from_butt_m = x;
        c.impact_twist_per_kg = impact_twist_per_kg(y, *polar);
        if (design.strings) {
          c.impact_duration_s = tension_impact_duration(*design.strings, design.ball.mass_kg,
                                                        effective_mass(body, x, y, *polar))
                                    .duration_s;
        }
        const RigidOutcome o = rigid_outcome(c, system);
        p.effective_mass_kg = o.effective_mass_kg;
        if (collision) {
          // The solved collision's rebound, force and vibration; the wrist
          // feels the rigid model's share of the solved peak force (Eq. 11),
          // as evaluate() at Fidelity::kCollision.
          CollisionResult r;
          try {
            r = collision->at_speed(x, y, speed_m_s);
          } catch (const ModelRefusal& refusal) {
            if (meeting) rethrow_at_meeting(refusal, design, *meeting);
            throw;
          }
          p.apparent_cor = r.apparent_cor;
          // Held in the hand, the impact moves implement and hand: M_eff is the
          // solved collision's (evaluate() at Fidelity::kCollision), not Eq. 17's.
          if (design.support.kind == Support::Kind::kHand)
            p.effective_mass_kg = 1.0 / collision->frame_at(x, y).inverse_effective_mass_per_kg;
          p.peak_wrist_force_N = peak_wrist_force(o.wrist_force_ratio, r.peak_force_N);
          p.peak_twist_torque_N_m = r.peak_force_N * std::abs(y);
          p.vibration_energy_J = r.vibration_J;
          continue;
        }
        p.apparent_cor = o.apparent_cor;
        p.peak_wrist_force_N = o.peak_wrist_force_N;
        p.peak_twist_torque_N_m = o.peak_impact_force_N * std::abs(y);
        if (model) {
          const double kappa =
              column_kappa ? *column_kappa : vibration_compliance(*model, x, c.impact_duration_s);
          const double energy_J = 0.5 * o.impulse_N_s * o.impulse_N_s * kappa;
          // The energy ledger of evaluate(): the frame cannot keep more than the
          // ball loses; past that the prescribed pulse does not hold (no value).
          const double v1 = speed_m_s;
          const double ball_loss_J =
              0.5 * design.ball.mass_kg * v1 * v1 * (1.0 - o.apparent_cor * o.apparent_cor);
          if (energy_J <= ball_loss_J * (1.0 + 1e-12)) p.vibration_energy_J = energy_J;
        }
      }
    } catch (const FieldError& error) {
      rethrow_at_point(error, design.implement.length_m() - x, at_y);
    }
  };
  const std::size_t total = map.points.size();
  const int threads = std::max(1, options.threads);
  // Columns in waves, a few per thread, so that the progress is told between
  // waves and the ellipse's short edge columns do not leave a thread idle long.
  const int wave = threads * 4;
  if (options.progress) options.progress(0, total);
  for (int first = 0; first < options.columns; first += wave) {
    const int count = std::min(wave, options.columns - first);
    io::for_blocks(static_cast<std::size_t>(count), threads,
                   [&](std::size_t, std::size_t from, std::size_t to) {
                     for (std::size_t k = from; k < to; ++k) column(first + static_cast<int>(k));
                   });
    if (options.progress)
      options.progress(static_cast<std::size_t>(first + count) * options.rows, total);
  }
  return map;
}

}  // namespace sweetspot::studies
