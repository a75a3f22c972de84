#pragma once

// A design: an implement, the player holding it and the ball that hits it.
// Defaults are the conditions of Cross (2004) Table I, top row.

#include <optional>
#include <string_view>

#include "sweetspot/ball_contact.hpp"
#include "sweetspot/beam_modes.hpp"
#include "sweetspot/head_geometry.hpp"
#include "sweetspot/implement.hpp"
#include "sweetspot/string_bed.hpp"
#include "sweetspot/swing.hpp"

namespace sweetspot {

// The rest of the model's range (see kMaxLength_m): a forearm may stand for a
// wall (the fixed-pivot limit), a ball may not outrun a rifle bullet, and an
// impact lasts between a microsecond and ten seconds.
inline constexpr double kMaxForearmMass_kg = 1e12;
inline constexpr double kMaxSpeed_m_s = 1e4;
// A ball slower than 1 mm/s does not strike: its energy, ~1e-8 J, is below the
// round-off of everything it is compared with (issue 20: 1e-300 mph made the
// vibration share 0/0), and the solved contact would outlast max_time_s.
inline constexpr double kMinSpeed_m_s = 1e-3;
// The lightest ball (0.1 g, a twentieth of a table-tennis ball's 2.7 g) and
// the lightest implement (1 g) the model was verified for: below them the
// energies and the effective mass reach the round-off of the numbers they are
// compared with (issue 20: a 1e-300 kg ball on a 1e-300 kg racquet broke the
// rigid-body bound on the apparent COR by round-off alone).
inline constexpr double kMinBallMass_kg = 1e-4;
inline constexpr double kMinImplementMass_kg = 1e-3;
// The smallest ball, 0.1 mm across, as the lightest is 0.1 g: the range the
// model is held to (no ball law was verified on one), not a measured limit.
inline constexpr double kMinBallDiameter_m = 1e-4;
// A grip a million times stiffer (and its dashpot a hundred thousand times
// stronger) than the calibrated hand: past these the hand is rigid for every
// mode the model resolves.
inline constexpr double kMaxGripStiffness_N_m2 = 1e12;
inline constexpr double kMaxGripDamping_N_s_m2 = 1e8;
// A cross-section's size; its shear modulus (steel: 8e10 Pa).
inline constexpr double kMaxShearModulus_Pa = 1e13;
// Poisson's ratio of an isotropic solid's cross-section: [0, 0.5] (0.5 incompressible).
inline constexpr double kMaxPoissonRatio = 0.5;
inline constexpr double kMinDuration_s = 1e-9;
inline constexpr double kMaxDuration_s = 10.0;

// The ranges over which the solved collision (collision.hpp) was verified
// (issue 20: tests/collision_test.cpp "... every term >= 0 ..." sweeps each to
// its ends; an input beyond them is refused by validate(), exit status 2).
// The string tension: 20-1000 N (4.5-225 lb). Stringers use 90-330 N; below
// 20 N the calibrated ball at 50 m/s pushes the bed deeper than the head's
// radius (the membrane's small slopes fail), above 1000 N a string breaks
// (a 1.3 mm polyester string's strength is ~700-900 N).
inline constexpr double kMinTension_N = 20.0;
inline constexpr double kMaxTension_N = 1000.0;
// The string bed's moving mass: 1-20 g. A full set of strings weighs 15-20 g
// (kStringSetMass_kg), the part that moves with the ball less; the COR of the
// solved collision is Eq. (16) inverted with M_eff, which leaves the bed's
// mass out, right only while it is small against M_eff.
inline constexpr double kMinStringBedMass_kg = 0.001;
inline constexpr double kMaxStringBedMass_kg = 0.020;
// An impact off the long axis lands on the head: inside the hoop's outer edge
// (the string bed's ellipse widened by the hoop, head_geometry.hpp) when the
// head is given, else within the widest head the ITF allows, 11.5 in (29.2 cm)
// across. A measured twistweight cannot exceed the frame's mass all at that
// half-width, M c^2 (c the hoop's outer half-width, or this), nor be below
// kMinTwistweight_kg_m2 (a 20 g rod of 1 cm radius: the strings alone give more).
inline constexpr double kMaxHeadHalfWidth_m = 0.146;
inline constexpr double kMinTwistweight_kg_m2 = 1e-6;

// The hand, a point mass on the handle (Cross 2004: 0.07 m from the butt).
// For the vibration modes it grips the handle over `grip_length_m` centred on
// `center_from_butt_m` through a distributed spring and dashpot (beam_modes.hpp).
struct Hand {
  double mass_kg = 0.5;                                        // [kg], >= 0 (0: a free implement)
  double center_from_butt_m = 0.07;                            // [m], in [0, L]
  double grip_length_m = 0.10;                                 // [m], > 0, the grip inside [0, L]
  double grip_stiffness_N_m2 = kCalibratedGripStiffness_N_m2;  // [N/m per m], >= 0
  double grip_damping_N_s_m2 = kCalibratedGripDamping_N_s_m2;  // [N s/m per m], >= 0
};

// How stiff the frame is in bending: EI per section (Section::EI_N_m2), one EI
// for every section without its own, or the measured free fundamental from
// which one scale factor for every EI is solved. Only the modes need it.
struct FrameStiffness {
  std::optional<double> EI_N_m2;              // [N m^2], > 0
  std::optional<double> fundamental_free_Hz;  // [Hz], > 0
  // The spec sheet's stiffness rating RA, in [kMinRA, kMaxRA]: the free
  // fundamental of the frame without its point masses (lead tape added after
  // the rating) is derived from it and the frame's mass (frame_specs.hpp),
  // and one scale for every EI solved from that; point masses then lower it.
  std::optional<double> RA;
  // Timoshenko theory (shear and rotary inertia) when given: every section
  // of this shear modulus and cross-section (a rectangle, a circle or a tube,
  // its shear coefficient Cowper's for the shape).
  std::optional<double> shear_modulus_Pa;
  CrossSection cross_section;  // its sizes > 0 with shear_modulus_Pa
};

struct Ball {
  double mass_kg = 0.057;  // [kg], > 0 (a tennis ball)
  double speed_m_s =
      50.0;  // incident speed relative to the impact point [m/s], in [kMinSpeed_m_s, kMaxSpeed_m_s]
  // The ball's COR on a rigid surface at the drop test's speed, in [0, 1):
  // the contact law's loss is set to match it (with_rigid_surface_cor(),
  // collision.hpp) where the collision is solved; none, the law as given.
  std::optional<double> cor_on_rigid_surface = std::nullopt;
  // [m], in [kMinBallDiameter_m, kMaxLength_m]: a solved collision that squeezes the ball by
  // more than its radius (its centre past what it hits) is refused.
  double diameter_m = kTennisBallDiameter_m;
};

// What holds the implement when the ball hits it (docs/model.md, "Supports").
// A player: kFree (the default, the paper's racquet: the hand a point mass
// for Eqs. 8-14, the solved collision on the free frame, Cross 2004 Sec. VI)
// or kHand (the same, the solved collision on the frame held by the hand's
// grip, hand_held_response_model()). A laboratory's rig, which only the
// solved collision answers and where nothing of the player applies:
//  * kHeadClamped: the head held rigid, the ball on the strings of an
//    immovable frame (the string-bed drop test);
//  * kHandleClamped: the handle in a vice over the hand's grip, w = w' = 0
//    there (Brody's clamped-handle measurements);
//  * kPivot: free to turn about a pivot pivot_from_butt_m from the butt
//    (the bat standards' pivot 6 in from the knob);
//  * kRigidSurface: no implement, the ball onto a rigid plate (its own COR,
//    contact time, compression and force history).
struct Support {
  enum class Kind { kFree, kHand, kHeadClamped, kHandleClamped, kPivot, kRigidSurface };
  Kind kind = Kind::kFree;
  double pivot_from_butt_m = 0.0;  // kPivot: [m], in [0, L]
};

// True for a laboratory's rig (no player).
inline bool is_rig(const Support& support) { return support.kind >= Support::Kind::kHeadClamped; }

// The design file's name of a support: "free", "hand", "head_clamped",
// "handle_clamped", "pivot" (written {"pivot_from_butt_m": ...}), "rigid_surface".
std::string_view to_string(Support::Kind kind);

struct Design {
  Implement implement;
  double cor = 0.8;                  // frame COR e at the impact point, in [0, 1]
  double impact_duration_s = 0.004;  // T [s], > 0
  Hand hand{};
  double forearm_equivalent_mass_kg = 0.5;  // M_e = M_F / 3 at the wrist [kg], >= 0
  Ball ball{};
  double impact_from_butt_m = 0.65;  // [m], in [0, L]
  FrameStiffness stiffness{};        // for the modes only
  // When given, the COR is derived (impact response): the COR the ball and
  // strings would have on a rigid frame, in [0, 1].
  std::optional<double> cor_rigid{};
  // When given, the impact duration is derived from the string tension.
  std::optional<StringBed> strings{};
  // The solved collision (Fidelity::kCollision, collision.hpp): the ball's
  // contact law and the string bed's moving mass [kg] (> 0) and damping ratio
  // (in [0, 1)), in [kMinStringBedMass_kg, kMaxStringBedMass_kg]. Defaults: the calibrated
  // tennis ball, 4 g and 0.008.
  BallContactLaw ball_contact = kTennisBallLaw;
  double string_bed_mass_kg = kStringBedMass_kg;
  double string_bed_damping_ratio = kStringBedDampingRatio;
  // False when a design file leaves the frame's COR to its default: with a
  // string tension and the frame's stiffness, "auto" then solves the collision.
  bool cor_given = true;
  // The second dimension (head_geometry.hpp): the impact's distance off the
  // long axis, y [m] (either sign, |y| <= L); the measured polar inertia of the
  // implement without its point masses (its twistweight) [kg m^2], > 0; the
  // head, from which the polar inertia is estimated when not measured.
  double impact_off_axis_m = 0.0;
  std::optional<double> twistweight_kg_m2{};
  std::optional<HeadShape> head{};
  // The racquet swung at the ball (swing.hpp). When given, ball.speed_m_s is
  // the incoming ball's speed over the ground and the collision is solved in
  // the frame moving with the impact point, at the relative speed v_in + V;
  // when absent, the impact is the laboratory's (the racquet at rest) and the
  // shot speed is the one kTypicalGroundstroke would give.
  std::optional<Swing> swing{};
  Support support{};  // free unless a rig is given
};

// The polar inertia of the implement about its long axis [kg m^2]: the
// measured twistweight, else the estimate from the head, plus m y^2 for every
// point mass; std::nullopt when neither twistweight nor head is given.
std::optional<double> polar_inertia_kg_m2(const Design& design);

// True for a round implement: one given by its profile (a bat, a rod), which
// has no head and no string bed (validate() refuses either on it).
bool is_round(const Design& design);

// Whether the polar inertia is the head's estimate rather than measured.
bool polar_inertia_estimated(const Design& design);

// The head whose string bed a racquet is hit on: the implement's head when
// given (a string bed's size given alone is the head's); else the default
// shape with the string bed's area (pi R^2 of strings.head_radius_m); else the
// default shape of kDefaultHeadArea_m2. The centre of the strings, the check
// that a strung impact lands on them and the map's grid all take this one.
HeadShape racquet_head(const Design& design);

// Throws std::invalid_argument if any value is out of range. The message
// starts with the value's JSON pointer relative to a design file
// ("hand/mass_kg: must be >= 0 kg, got -0.5 kg").
void validate(const Design& design);

// The implement plus the hand rigidly attached: M, h and I_cm of Cross (2004) Eqs. (8)-(14).
MassProperties hand_held_system(const Design& design);

}  // namespace sweetspot
