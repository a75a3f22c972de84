#pragma once

// A design as its file describes it, before anything is derived from it: each
// number in SI, in the form the file gave it (a balance in points head-light,
// an impact from the tip, the forearm's own mass). A study variable, a sweep
// axis or a batch column changes one of these numbers; derive() then rebuilds
// only what depends on it (the implement, the impact point from the tip, the
// equivalent forearm mass) with the reader's own arithmetic, so the design is
// bit for bit the one read_design() gives for the changed file.

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sweetspot/design.hpp"

namespace sweetspot::io {

// 1 point head-light = 1/8 inch from the middle of the length towards the butt.
inline constexpr double kPointHeadLight_m = 0.0254 / 8.0;

// The largest |points| head-light that keeps the balance inside (0, L).
double points_head_light_limit(double length_m);
// The balance point [m from the butt] of `points` head-light on a length L.
double balance_from_points_head_light(double length_m, double points);
// The string bed's radius [m] of a head of area `area_m2` (a circle).
double head_radius_from_area(double area_m2);
// Two head sizes given as the same quantity in two keys (implement.headsize_*
// and strings.head_size_*) agree when within this relative difference: the
// same number in in^2 and cm^2 converts with rounding.
inline constexpr double kSameHeadAreaRelTol = 1e-9;
bool same_head_area(double a_m2, double b_m2);

// A point mass as the file places it, in SI, before the geometry places it:
// on the axis from the butt or the tip (optionally off it), at clock positions
// on the hoop (one piece of mass_kg at each hour), or under the butt cap. A
// position relative to the geometry is resolved by place_point_masses() each
// time the implement is built, so it follows a length or a head that changes.
struct PointMassDescription {
  double mass_kg = 0.0;               // of each piece
  std::optional<double> from_butt_m;  // on (or off) the axis, from the butt
  std::optional<double> from_tip_m;   // on (or off) the axis, from the tip
  double off_axis_m = 0.0;            // with from_butt_m or from_tip_m
  std::vector<double> clock_hours;    // a piece at each hour on the hoop
  // A place on the handle by its word: under the butt cap ("handle", "butt":
  // kHandleWeightFromButt_m) or under the grip ("grip": kUnderGripFromButt_m),
  // from the butt, at the butt end of an implement shorter than it.
  std::optional<double> handle_from_butt_m;
};

// Why place_point_masses() refused an entry: its index in the file's list,
// the key (relative to the entry, "" for the entry) and what is wrong.
struct PointMassError : std::invalid_argument {
  PointMassError(std::size_t entry, std::string key, const std::string& detail)
      : std::invalid_argument(detail), entry(entry), key(std::move(key)) {}
  std::size_t entry;
  std::string key;
};

// The point masses the entries give on an implement of length `length_m`
// with `head` (a clock entry becomes one point mass per hour, in the entries'
// order). Throws PointMassError for an entry that the geometry cannot place
// (a mass outside [0, kMaxMass_kg], a place off the implement, a clock
// position without a head or off the hoop).
std::vector<PointMass> place_point_masses(const std::vector<PointMassDescription>& entries,
                                          double length_m, const std::optional<HeadShape>& head);

// How the implement was given, in SI, before the implement is built.
struct ImplementDescription {
  enum class Form { kHeadToHandleRatio, kSections, kSpecs, kProfile };
  Form form = Form::kHeadToHandleRatio;
  double length_m = 0.0;                   // kHeadToHandleRatio, kSpecs
  double mass_kg = 0.0;                    // kHeadToHandleRatio, kSpecs
  double head_to_handle_mass_ratio = 0.0;  // kHeadToHandleRatio
  bool balance_in_points = false;          // kSpecs: balance_pts_hl, else metres from the butt
  double balance = 0.0;                    // kSpecs: [m] from the butt, or points head-light
  double swingweight_kg_m2 = 0.0;          // kSpecs
  std::vector<Section> sections;           // kSections
  RoundProfile profile;                    // kProfile
  // The file's list, entry for entry: /implement/point_masses/N is entry N.
  std::vector<PointMassDescription> point_masses;
  std::optional<HeadShape> head;  // implement/headsize_*: places clock positions
};

// Where the ball hits: given from the tip or from the butt, or, when the file
// gives no impact, the default of its kind of design (default_impact()),
// resolved again whenever the geometry changes.
enum class ImpactPlace { kFromTip, kFromButt, kCentreOfStrings };

// The centre of the string bed of racquet_head() (design.hpp) [m from the tip]: 18.15 cm
// for 100 sq in with the default shape; half the length when the head would
// not fit.
double centre_of_strings_from_tip_m(const Design& design);

// Whether a design is a racquet with a head for the default impact: it gives
// a head (implement.headsize_*), a string bed (strings.tension_*) or a
// spec sheet's numbers (balance and swingweight, a racquet's head then the
// default 100 sq in). The paper's designs (head-to-handle ratio or sections,
// no head, no strings) are not.
bool has_racquet_head(const Design& design, ImplementDescription::Form form);

// The impact a design gets when its file gives none, the same in every
// command: a racquet with a head is hit at the centre of its strings, the
// paper's designs 5 cm from the tip (the paper's Table I).
inline constexpr double kPaperImpactFromTip_m = 0.05;
ImpactPlace default_impact(const Design& design, ImplementDescription::Form form);

struct DesignDescription {
  ImplementDescription implement;
  // The design as read. derive() overwrites its implement and the derived
  // numbers below; every other field is set directly.
  Design design;
  bool forearm_from_mass = false;  // forearm/mass_*: M_e = M_F / 3 (Eq. 7)
  double forearm_mass_kg = 0.0;
  ImpactPlace impact_place = ImpactPlace::kFromTip;
  double impact_m = kPaperImpactFromTip_m;  // from the tip or from the butt (not kCentreOfStrings)
  bool impact_given = true;                 // false: the default of default_impact()
  std::optional<double> head_area_m2;       // strings/head_size_*: sets the string bed's radius
  // The bed came from a stringer's ticket (a pattern, mains and crosses, a
  // material, a loss, a measurement): its tension and spacing, and the head
  // its pattern spans, are the reader's to derive, not a binding's to set.
  bool string_ticket = false;
};

// The implement the description gives. Throws std::invalid_argument (the
// implement's factories) or std::domain_error (a balance outside the length)
// where read_design() refuses it.
Implement build_implement(const ImplementDescription& description);

// The racquet's head as the description gives it: the implement's, else the
// string bed's size given alone (strings.head_size_*) with the default shape;
// one head, one size, so a lead's clock position is placed on it either way.
std::optional<HeadShape> racquet_head_of(const DesignDescription& description);

// The implement the whole description gives: build_implement() with the
// clock positions placed on racquet_head_of().
Implement build_implement(const DesignDescription& description);

// Recomputes description.design's derived numbers (the head, the equivalent
// forearm mass, the string bed's radius from strings.head_size_* or else the
// implement's head, the impact point from the butt) from the description and
// its implement as it stands, then validate()s the design.
// Throws where read_design() would refuse the same numbers (the message is
// not the reader's: re-read the file for that).
void derive(DesignDescription& description);

}  // namespace sweetspot::io
