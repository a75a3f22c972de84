#pragma once

// The loop paths of the rigid model: what a sweep, a catalogue or a study
// evaluates many times over after validating a design once. Each gives, bit
// for bit, the numbers evaluate() (evaluate.hpp) gives for the same design;
// they differ from it only in what they skip (validation, allocation, the
// parts that do not depend on the impact point). The solved collision's loop
// path is DesignCollision (collision.hpp), the modes' ModeCache
// (mode_cache.hpp). Use evaluate() unless a profile says otherwise.

#include <span>

#include "sweetspot/design.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/mass_properties.hpp"
#include "sweetspot/rigid_impact.hpp"

namespace sweetspot {

// Only what rigid_outcome() answers of evaluate(design, Fidelity::kRigid), for
// a design validate() has accepted: effective_mass_kg, apparent_cor,
// rebound_speed_m_s, impulse_N_s, peak_impact_force_N, wrist_force_ratio and
// peak_wrist_force_N are written into `e`, bit for bit evaluate()'s, and its
// other fields are left as they are (a sweep that outputs only these). Returns
// false, `e` untouched, where only evaluate() answers as it would: a COR or a
// duration to derive (cor_rigid, a string tension), an impact off the long
// axis, a swing (solved at the speed the ball and the racquet meet), or a
// result that is not finite (evaluate() refuses it, saying why).
// For a validated design the rigid model's invariants (Fidelity) follow from
// Eqs. (15)-(17) once every number is finite, so this check is theirs.
bool evaluate_rigid_outcome(const Design& design, Evaluation& e);

// The rigid model without validation and with the design's cor and
// impact_duration_s as they stand (no tension, no cor_rigid), for callers that
// validated once and evaluate many impacts or variants in a loop. No allocation.
Evaluation evaluate_unchecked(const Design& design);

// The design as a RigidCase for rigid_outcomes(): validated like evaluate(),
// with the duration derived from a string tension. A COR to be derived
// (cor_rigid) needs the response model and throws std::invalid_argument.
RigidCase rigid_case(const Design& design);

// The shot of a design without a swing, as evaluate() reports it at
// e.impact_from_butt_m: the incoming speed the ball's, the racquet's speed
// the assumed groundstroke's there (e.swing, kTypicalGroundstroke) and the
// shot off it at e.apparent_cor.
void put_assumed_shot(const Design& design, Evaluation& e);

// The rigid model of one design at many impact points (a player's spread of
// hits, a sweep along the strings): what does not depend on the impact point
// is computed once. at() allocates nothing and does not check the impact
// point (keep it on the implement). The design's COR, duration and ball speed
// are used as given: a design with cor_rigid, a string tension or a swing
// (whose meeting speed moves with the impact point) is refused; ask
// impact_sweep_answers() first.
bool impact_sweep_answers(const Design& design);
class ImpactSweep {
 public:
  // Validates the design; throws std::invalid_argument like evaluate(), and
  // for a design impact_sweep_answers() turns away.
  explicit ImpactSweep(const Design& design);
  // At the design's distance off the axis (Design::impact_off_axis_m).
  Evaluation at(double impact_from_butt_m) const;
  // The same at a distance `off_axis_m` off the long axis, which needs the
  // polar inertia (Design::twistweight_kg_m2 or head): throws
  // std::invalid_argument naming "impact/off_axis_m" without it when y != 0.
  Evaluation at(double impact_from_butt_m, double off_axis_m) const;

 private:
  Design design_;
  MassProperties system_;
  Evaluation base_;
};

// ------------------------------------------------------------ column-wise
// Cross (2004) Table I racquets (Implement::paper_racquet, no point masses),
// each held in the hand and hit on the long axis, as one array per input:
// the rigid model of a million designs in the paper's parametrisation at the
// speed of rigid_outcomes(). The racquet's spans (length, mass, ratio) and
// the impact point's have one element per case; each setting (the hand, the
// forearm, the ball, the COR, the duration) one per case or one for every
// case. With every setting given once, they are checked once, not per case.
struct PaperRigidCases {
  std::span<const double> length_m, mass_kg, head_to_handle_mass_ratio;
  std::span<const double> hand_mass_kg, hand_center_from_butt_m, forearm_equivalent_mass_kg;
  std::span<const double> ball_mass_kg, ball_speed_m_s, cor, impact_duration_s;
  std::span<const double> impact_from_butt_m;
};

// For each case i, answered[i] = 1 and the outcomes, bit for bit those of
// evaluate(design, Fidelity::kRigid) for the design with these numbers
// (effective_mass_kg ... peak_wrist_force_N, and cop_hand_from_butt_m), where
// the case lies inside the ranges validate() accepts, its results are finite
// and they keep the rigid model's laws (invariants.hpp); else answered[i] = 0
// and its outcomes are unspecified: evaluate() says why, or answers a case
// at the edge of its range that this leaves to it. Throws
// std::invalid_argument naming the first span of another length (a setting's
// may also be 1). No allocation.
void paper_rigid_outcomes(const PaperRigidCases& cases, const RigidOutcomes& out,
                          std::span<unsigned char> answered);

}  // namespace sweetspot
