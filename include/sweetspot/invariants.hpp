#pragma once

// What every evaluation guarantees (issue 20), and the refusal of one that
// does not: a number sweetspot prints obeys the laws the model is built on.
// The invariants of each fidelity are stated where the fidelity is documented
// (evaluate.hpp, collision.hpp); check_invariants() is the one place they are
// checked, at the end of every evaluate() and DesignCollision::at().

#include <stdexcept>
#include <string>

#include "sweetspot/errors.hpp"

namespace sweetspot {

struct CollisionResult;
struct Design;
struct Evaluation;

// The model cannot answer this design: an evaluation broke one of its
// invariants, or a solver could not reach the accuracy the model promises.
// `field` names the design input (a relative JSON pointer, "ball/contact/
// stiffness") that took the model outside its valid range, `value` its value
// in SI; what() is "field: detail", as every core error, so that the JSON layer
// points at the file's key. The command line exits 3 for it (an input outside
// its stated range is a FieldError from validate(), exit 2).
class ModelRefusal : public FieldError {
 public:
  // `reason`: what broke, without the input blamed for it (detail when empty),
  // so that a caller who knows better whom to blame can say so in its words.
  ModelRefusal(std::string field, double value, std::string detail, std::string reason = {});
  double value() const { return value_; }
  const std::string& reason() const { return reason_; }

 private:
  double value_;
  std::string reason_;
};

// Round-off allowed in the invariants, relative to the ball's incident kinetic
// energy (energies), momentum (impulse) or 1 (CORs): the ledger of the solved
// collision is an identity of each step and closes to ~1e-12 over thousands
// of steps; the Richardson-extrapolated run adds its step error (kMaxStepError).
inline constexpr double kInvariantRoundOff = 1e-9;
// The largest change of the solved collision's apparent COR between its runs
// at h and h/2 (CollisionResult::step_error: the run at h's own error, ~c h^2)
// for which the extrapolation is trusted. The calibrated racquet's is 1.4e-4,
// and its extrapolated answer is within ~1e-6 (tests/collision_test.cpp); an
// unresolved contact (a stiff ball before issue 20) changed it by O(1).
inline constexpr double kMaxStepError = 1e-2;

// The first invariant of `e`'s fidelity that `e` breaks, as a sentence with
// the numbers; empty when every one holds. `design` is what was evaluated.
std::string broken_invariant(const Evaluation& e, const Design& design);

// The same for a solved collision (collision.hpp) of a ball of `ball_mass_kg`
// on a frame of effective mass `effective_mass_kg` with a string bed of
// `string_bed_mass_kg` (0: none).
std::string broken_invariant(const CollisionResult& r, double ball_mass_kg,
                             double effective_mass_kg, double string_bed_mass_kg);

// The design input to name when the solved collision of `design` (its free
// fundamental `fundamental_free_Hz`) cannot answer: of those that set the
// collision's scales (the ball's stiffness, speed and mass, the tension, the
// string bed's mass, the frame's fundamental), the one furthest in ratio from
// the calibrated racquet the model was verified on (tour-100-strung.json).
struct Suspect {
  std::string field;  // relative JSON pointer, "ball/contact/stiffness"
  double value = 0.0;
};
Suspect collision_suspect(const Design& design, double fundamental_free_Hz);

// The input to name when the solved collision squeezes the ball past its
// radius: of those that set the squeeze, the one furthest in ratio from the
// calibrated racquet's in the direction that squeezes more (a faster, heavier
// ball; a smaller one; a softer law, its stiffness lower or its exponent
// higher; a tighter bed), the speed when none is (the law itself squeezes
// past the radius).
Suspect squeeze_suspect(const Design& design);

// Throws ModelRefusal when broken_invariant(e, design) is not empty, naming
// the input most likely to have taken the model out of its range.
void check_invariants(const Evaluation& e, const Design& design);

}  // namespace sweetspot
