#include "design_generator.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <utility>

#include "sweetspot/ball_contact.hpp"

namespace sweetspot::property {
namespace {

// The extremes an open or unbounded end is drawn at: accepted, and far past
// anything real.
constexpr double kTiny = 1e-300;
constexpr double kHuge = 1e300;

// Unit spellings and their factors to SI, as the key table of docs/design-files.md
// gives them. A factor that is a power of ten (`decimal` its exponent) moves the
// decimal point of the number as written: 282 g is the double nearest 0.282 kg
// (docs/design-files.md), which is not always 282 * 0.001.
struct Unit {
  const char* suffix;
  double to_si;
  int decimal = 0;
};
const std::vector<Unit> kLength{
    {"_m", 1.0}, {"_cm", 0.01, -2}, {"_mm", 0.001, -3}, {"_in", 0.0254}};
const std::vector<Unit> kMass{{"_kg", 1.0}, {"_g", 0.001, -3}};
const std::vector<Unit> kTime{{"_s", 1.0}, {"_ms", 0.001, -3}};
const std::vector<Unit> kSpeed{{"_m_s", 1.0}, {"_km_h", 1.0 / 3.6}, {"_mph", 0.44704}};
const std::vector<Unit> kInertia{{"_kg_m2", 1.0}, {"_kg_cm2", 1e-4, -4}};
const std::vector<Unit> kForce{{"_N", 1.0}, {"_lb", 4.4482216152605}, {"_kg", 9.80665}};

// The accepted ranges (SI). A range's corners are its closed bounds, or
// kTiny / kHuge at an open or unbounded end.
// implement.hpp: lengths in (0, kMaxLength_m = 100], masses in [0, kMaxMass_kg = 1e6].
const Range kLengthRange{1e-3, 100.0, true, kTiny, 100.0, 0.6, 0.75};
const Range kBatLengthRange{1e-3, 100.0, true, kTiny, 100.0, 0.5, 1.1};
const Range kImplementMass{1e-5, 1e6, true, kTiny, 1e6, 0.2, 0.4};
// Implement::paper_racquet: the ratio M1/M2 > 0, unbounded.
const Range kHeadToHandle{1e-4, 1e4, true, kTiny, kHuge, 0.7, 1.3};
// Section: mass >= 0 (0 allowed), length > 0.
const Range kSectionMass{1e-6, 1e6, true, 0.0, 1e6, 0.03, 0.2};
// EI in (0, kMaxEI_N_m2 = 1e12].
const Range kEI{1e-3, 1e12, true, kTiny, 1e12, 50.0, 1000.0};
// frame.fundamental_free_Hz > 0, unbounded.
const Range kFundamental{1e-2, 1e6, true, kTiny, kHuge, 100.0, 250.0};
// frame_specs.hpp: RA in [kMinRA, kMaxRA] = [50, 80].
const Range kRA{50.0, 80.0, false, 50.0, 80.0, 55.0, 75.0};
// cross_section: G in (0, 1e13] Pa, width, thickness and diameter in (0, 100] m.
const Range kShearModulus{1e3, 1e13, true, kTiny, 1e13, 1e9, 3e10};
const Range kSectionSize{1e-5, 100.0, true, kTiny, 100.0, 0.008, 0.03};
// frame.cor, frame.cor_rigid in [0, 1].
const Range kCor{0.0, 1.0, false, 0.0, 1.0, 0.7, 0.95};
// strings.impact_duration in [kMinDuration_s, kMaxDuration_s] = [1e-9, 10] s.
const Range kDuration{1e-9, 10.0, true, 1e-9, 10.0, 0.003, 0.006};
// StringBed::validate(): tension, spacing, contact radius > 0 and finite; the
// head (from head_size) larger than the contact.
const Range kTension{1e-6, 1e9, true, kTiny, kHuge, 150.0, 300.0};
const Range kSpacing{1e-6, 10.0, true, kTiny, kHuge, 0.012, 0.02};
const Range kHeadSizeSqIn{1e-3, 1e6, true, kTiny, kHuge, 85.0, 115.0};
const Range kContactRadius{1e-6, 10.0, true, kTiny, kHuge, 0.02, 0.04};
// strings.bed_mass in [1e-9, 1e6] kg, bed_damping_ratio in [0, 1).
const Range kBedMass{1e-9, 1e6, true, 1e-9, 1e6, 0.001, 0.008};
const Range kBedDamping{0.0, 0.9999999999999999, false, 0.0, 0.9999999999999999, 0.0, 0.05};
// design.hpp Hand: mass in [0, 1e6] kg, grip length > 0, stiffness in
// [0, 1e12] N/m^2, damping in [0, 1e8] N s/m^2.
const Range kHandMass{1e-6, 1e6, true, 0.0, 1e6, 0.3, 0.6};
const Range kGripStiffness{1e-3, 1e12, true, 0.0, 1e12, 1e5, 4e5};
const Range kGripDamping{1e-3, 1e8, true, 0.0, 1e8, 500.0, 3000.0};
// forearm equivalent mass in [0, kMaxForearmMass_kg = 1e12] kg (M_F = 3 M_e).
const Range kForearm{1e-6, 1e12, true, 0.0, 1e12, 0.3, 1.0};
// ball: mass in (0, 1e6] kg, speed in (0, kMaxSpeed_m_s = 1e4] m/s.
const Range kBallMass{1e-6, 1e6, true, kTiny, 1e6, 0.05, 0.16};
const Range kBallSpeed{1e-6, 1e4, true, kTiny, 1e4, 5.0, 60.0};
// ball: diameter in (0, kMaxLength_m = 100] m.
const Range kBallDiameter{1e-4, 100.0, true, kTiny, 100.0, 0.06, 0.075};
// swing.hpp: angular speed in (0, kMaxAngularSpeed_rad_s = 100] rad/s, pivot
// in [0, kMaxPivotBeyondButt_m = 3] m beyond the butt, the speed at the impact
// in (0, kMaxSpeed_m_s = 1e4] m/s.
const Range kAngularSpeed{1e-3, 100.0, true, kTiny, 100.0, 5.0, 40.0};
const Range kPivot{0.0, 3.0, false, 0.0, 3.0, 0.2, 1.0};
const Range kSwingSpeed{1e-3, 1e4, true, kTiny, 1e4, 5.0, 40.0};
// BallContactLaw::validate(): k in (0, 1e15], n in [1, 3], b in [0, 1e12], p in [0, 3].
const Range kContactStiffness{1.0, 1e15, true, kTiny, 1e15, 1e5, 1e6};
const Range kContactExponent{1.0, 3.0, false, 1.0, 3.0, 1.2, 1.8};
const Range kContactDamping{1e-3, 1e12, true, 0.0, 1e12, 10.0, 300.0};
const Range kContactDampingExponent{0.0, 3.0, false, 0.0, 3.0, 0.3, 1.5};
// implement twistweight in (0, kMaxMass_kg kMaxLength_m^2 = 1e10] kg m^2.
const Range kTwistweight{1e-8, 1e10, true, kTiny, 1e10, 1e-3, 2e-3};
// head_geometry.hpp: aspect in [1, 10], hoop width in [0, 1] m (the reader).
const Range kAspect{1.0, 10.0, false, 1.0, 10.0, 1.2, 1.5};
const Range kHoopWidth{1e-5, 1.0, true, 0.0, 1.0, 0.012, 0.018};
// A point mass: mass in [0, 1e6] kg.
const Range kPointMass{1e-6, 1e6, true, 0.0, 1e6, 0.002, 0.02};
// Fractions of a range that depends on another input ([0, 1]).
const Range kFraction{0.0, 1.0, false, 0.0, 1.0, 0.0, 1.0};

// The double nearest `given` x 10^decimal, `given` read as the shortest
// decimal that reads back as it (the digits a JSON file holds for it).
double move_decimal_point(double given, int decimal) {
  if (decimal == 0 || given == 0.0 || !std::isfinite(given)) return given;
  char text[64];
  const auto written = std::to_chars(text, text + 40, given, std::chars_format::scientific);
  std::string digits(text, written.ptr);
  const std::size_t e = digits.find('e');
  const int exponent = std::stoi(digits.substr(e + 1)) + decimal;
  digits = digits.substr(0, e) + "e" + std::to_string(exponent);
  return std::strtod(digits.c_str(), nullptr);  // an underflow: the nearest, 0 or subnormal
}

// A number given in unit `u`, in SI.
double to_si(double given, const Unit& u) {
  return u.decimal != 0 ? move_decimal_point(given, u.decimal) : given * u.to_si;
}

class Drawer {
 public:
  Drawer(Rng& rng, const Style& style) : rng_(rng), style_(style) {}
  Rng& rng() { return rng_; }

  double operator()(const Range& r) {
    if (rng_.chance(style_.corner)) {
      // A corner: the accepted bound (or the extreme past an open end), or
      // the whole range's interior end.
      const bool high = rng_.chance(0.5);
      if (rng_.chance(0.5)) return high ? r.corner_hi : r.corner_lo;
      return high ? r.hi : r.lo;
    }
    if (rng_.chance(style_.typical)) {
      return r.log ? rng_.log_uniform(r.typical_lo, r.typical_hi)
                   : rng_.uniform(r.typical_lo, r.typical_hi);
    }
    return r.log ? rng_.log_uniform(r.lo, r.hi) : rng_.uniform(r.lo, r.hi);
  }
  // A value in [lo, hi] of a range that depends on other inputs: its ends
  // as corners, else uniform, or typical in [typical_lo, typical_hi].
  double within(double lo, double hi, double typical_lo, double typical_hi) {
    if (rng_.chance(style_.corner)) return rng_.chance(0.5) ? lo : hi;
    if (rng_.chance(style_.typical))
      return std::clamp(rng_.uniform(typical_lo, typical_hi), lo, hi);
    return rng_.uniform(lo, hi);
  }
  bool chance(double p) { return rng_.chance(p); }

 private:
  Rng& rng_;
  Style style_;
};

// Writes the SI value `si` under `base` in a unit drawn from `units`; returns
// the value the file now says, in SI (what the reader converts it to).
double put(Rng& rng, Json& object, const std::string& base, const std::vector<Unit>& units,
           double si) {
  const Unit& u = rng.pick(units);
  const double given = si / u.to_si;
  object[base + u.suffix] = given;
  return to_si(given, u);
}

// The implement in one of its three forms.
void draw_implement(Drawer& draw, Json& implement, bool bat, double& length_m) {
  Rng& rng = draw.rng();
  const int form = rng.integer(0, 2);
  const Range& length_range = bat ? kBatLengthRange : kLengthRange;
  if (form == 0) {
    length_m = put(rng, implement, "length", kLength, draw(length_range));
    put(rng, implement, "mass", kMass, draw(kImplementMass));
    implement["head_to_handle_mass_ratio"] = draw(kHeadToHandle);
  } else if (form == 1) {
    const int n = draw.chance(0.1) ? rng.pick(std::vector<int>{1, 24}) : rng.integer(1, 6);
    Json sections = Json::array();
    double x = 0.0;
    const bool own_ei = draw.chance(0.25);
    for (int i = 0; i < n; ++i) {
      Json section;
      // Each within its share of the range, so that the total is inside it.
      Range each = length_range;
      each.hi /= n;
      each.corner_hi /= n;
      each.typical_lo /= n;
      each.typical_hi /= n;
      x += put(rng, section, "length", kLength, draw(each));
      Range mass = kSectionMass;
      mass.hi /= n;
      mass.corner_hi /= n;
      mass.typical_lo = 0.25 / n;
      mass.typical_hi = 0.35 / n;
      put(rng, section, "mass", kMass, draw(mass));
      if (own_ei && draw.chance(0.8)) section["EI_N_m2"] = draw(kEI);
      sections.push_back(section);
    }
    implement["sections"] = sections;
    length_m = x;
  } else {
    const double L = put(rng, implement, "length", kLength, draw(length_range));
    const double M = put(rng, implement, "mass", kMass, draw(kImplementMass));
    length_m = L;
    // Balance inside (0, L), in one of its three spellings.
    double B = L * draw.within(0.0, 1.0, 0.44, 0.52);
    const int spelling = rng.integer(0, 2);
    if (spelling == 0) {
      implement["balance_from_butt_m"] = B;
    } else if (spelling == 1) {
      implement["balance_cm"] = B / 0.01;
    } else {
      // 1 pt head-light = 1/8 in from the middle towards the butt.
      implement["balance_pts_hl"] = (0.5 * L - B) / (0.0254 / 8.0);
    }
    // The swingweight a body of this length, mass and balance can have:
    // M (B - 0.1)^2 < SW <= M (B - 0.1)^2 + M B (L - B).
    const double sw_min = M * (B - 0.1) * (B - 0.1);
    const double sw_max = sw_min + M * B * (L - B);
    const double t =
        draw.chance(0.5) ? draw.within(0.0, 1.0, 0.35, 0.65) : rng.log_uniform(1e-12, 1.0);
    put(rng, implement, "swingweight", kInertia, sw_min + t * (sw_max - sw_min));
  }
}

// The head (headsize, aspect, hoop), mostly fitted to the length: the string
// bed and its hoop no longer than the implement.
void draw_head(Drawer& draw, Json& implement, double L) {
  Rng& rng = draw.rng();
  double aspect = kDefaultHeadAspectRatio, hoop = kDefaultHoopWidth_m;
  if (draw.chance(0.4)) aspect = implement["head_aspect_ratio"] = draw(kAspect);
  if (draw.chance(0.3)) hoop = put(rng, implement, "hoop_width", kLength, draw(kHoopWidth));
  // The largest strung area that fits: 2 a + 2 hoop <= L (the hoop on both
  // ends, head_geometry.cpp) with pi a c = area, a = aspect c.
  const double a_max = std::max(0.0, 0.5 * L - hoop);
  const double area_max = std::numbers::pi * a_max * a_max / aspect;
  double area = 0.0;
  if (draw.chance(0.9) && area_max > 0.0) {
    area = area_max * (draw.chance(0.1) ? 1.0 : rng.log_uniform(1e-6, 1.0));
    const double typical = rng.uniform(85.0, 115.0) * 0.0254 * 0.0254;
    if (typical <= area_max && draw.chance(0.5)) area = typical;
  } else {
    area = draw(kHeadSizeSqIn) * 0.0254 * 0.0254;  // anywhere, fitting or not
  }
  if (rng.chance(0.5))
    implement["headsize_sq_in"] = area / (0.0254 * 0.0254);
  else
    implement["headsize_cm2"] = area / 1e-4;
}

// Point masses on the axis, off it, at clock positions (one or a list, the
// throat) or in the handle.
void draw_point_masses(Drawer& draw, Json& implement, double L, bool head) {
  Rng& rng = draw.rng();
  const int n = rng.integer(1, 4);
  Json list = Json::array();
  for (int i = 0; i < n; ++i) {
    Json p;
    put(rng, p, "mass", kMass, draw(kPointMass));
    const int where = rng.integer(0, head ? 5 : 2);
    if (where == 0 || where == 1) {
      put(rng, p, where == 0 ? "from_butt" : "from_tip", kLength,
          L * draw.within(0.0, 1.0, 0.0, 1.0));
      if (draw.chance(0.3)) put(rng, p, "off_axis", kLength, L * draw.within(-1.0, 1.0, -0.1, 0.1));
    } else if (where == 2) {
      static const char* const kHandleWords[] = {"handle", "butt", "grip"};
      p["clock"] = kHandleWords[rng.integer(0, 2)];
    } else if (where == 3) {
      p["clock"] = rng.chance(0.5) ? static_cast<double>(rng.integer(0, 12))
                                   : draw.within(0.0, 12.0, 0.0, 12.0);
    } else if (where == 4) {
      Json clock = Json::array();
      if (rng.chance(0.2)) {
        clock = "3/9";  // the pair as tune --places writes it
      } else if (rng.chance(0.6)) {
        clock = Json::array({3, 9});
      } else {
        const int count = rng.integer(1, 12);
        for (int k = 0; k < count; ++k) clock.push_back(rng.integer(0, 12));
      }
      p["clock"] = clock;
    } else {
      p["clock"] = "throat";
    }
    list.push_back(p);
  }
  implement["point_masses"] = list;
}

}  // namespace

DrawnDesign draw_design(Rng& rng, const std::string& fidelity, double typical_share) {
  static const std::vector<Style> kStyles{
      {"typical", 0.0, 0.9}, {"whole range", 0.05, 0.3}, {"corners", 0.5, 0.2}};
  // The rest split 5 : 2 between the whole range and the corners.
  const double which = rng.unit();
  const double whole = typical_share + (1.0 - typical_share) * 5.0 / 7.0;
  const Style& style = which < typical_share ? kStyles[0] : which < whole ? kStyles[1] : kStyles[2];
  Drawer draw(rng, style);
  DrawnDesign d;
  d.fidelity = fidelity;
  d.style = style.name;
  double L = 0.0;
  const bool modes = fidelity != "rigid";
  const bool collision = fidelity == "collision" || (fidelity == "auto" && rng.chance(0.4));
  const bool response = fidelity == "response";

  Json doc = Json::object();
  doc["name"] = "drawn";
  Json implement = Json::object();
  draw_implement(draw, implement, rng.chance(0.2), L);
  const bool head = draw.chance(0.5);
  if (head) draw_head(draw, implement, L);
  if (draw.chance(0.45)) draw_point_masses(draw, implement, L, head);
  const bool twistweight = draw.chance(0.2);
  if (twistweight) put(rng, implement, "twistweight", kInertia, draw(kTwistweight));
  doc["implement"] = implement;

  // The frame: a COR (or cor_rigid, or none), a stiffness, a cross-section.
  Json frame = Json::object();
  const double cor_kind = rng.unit();
  if (cor_kind < (response ? 0.5 : 0.03)) {
    frame["cor_rigid"] = draw(kCor);
  } else if (cor_kind < (collision ? 0.08 : 0.75)) {
    frame["cor"] = draw(kCor);
  }
  if (draw.chance(modes ? 0.9 : 0.3)) {
    const double kind = rng.unit();
    if (kind < 0.45) {
      frame["EI_N_m2"] = draw(kEI);
    } else if (kind < 0.88) {
      frame["fundamental_free_Hz"] = draw(kFundamental);
    } else {
      frame["RA"] = draw(kRA);
    }
    if (draw.chance(0.12)) {
      Json section;
      section["shear_modulus_Pa"] = draw(kShearModulus);
      // A rectangle (the default, or named), an ellipse or a box (its wall
      // under half the smaller side), a circle or a tube (its wall up to half
      // the diameter), of a Poisson's ratio in [0, 0.5] or none.
      const double shape = rng.unit();
      if (shape < 0.5) {
        if (shape < 0.3) {
          if (draw.chance(0.3)) section["shape"] = "rectangle";
        } else {
          section["shape"] = shape < 0.4 ? "ellipse" : "box";
        }
        const double width = put(rng, section, "width", kLength, draw(kSectionSize));
        const double thickness = put(rng, section, "thickness", kLength, draw(kSectionSize));
        if (section.value("shape", "") == "box") {
          put(rng, section, "wall", kLength,
              0.5 * std::min(width, thickness) * (0.01 + 0.98 * rng.unit()));
        }
      } else {
        const double diameter = put(rng, section, "diameter", kLength, draw(kSectionSize));
        if (shape < 0.75) {
          section["shape"] = "circle";
        } else {
          section["shape"] = "hollow_circle";
          put(rng, section, "wall", kLength, 0.5 * diameter * (0.01 + 0.98 * rng.unit()));
        }
      }
      if (draw.chance(0.5)) section["poisson_ratio"] = 0.5 * rng.unit();
      frame["cross_section"] = section;
    }
  }
  if (!frame.empty()) doc["frame"] = frame;

  // The strings: a duration, or a tension with its bed, and the solved collision's bed.
  Json strings = Json::object();
  const double string_kind = rng.unit();
  if (string_kind < (collision ? 0.93 : 0.45)) {
    put(rng, strings, "tension", kForce, draw(kTension));
    if (draw.chance(0.35)) put(rng, strings, "string_spacing", kLength, draw(kSpacing));
    if (draw.chance(0.35)) {
      if (rng.chance(0.5))
        strings["head_size_in2"] = draw(kHeadSizeSqIn);
      else
        strings["head_size_cm2"] = draw(kHeadSizeSqIn) * 6.4516;
    }
    if (draw.chance(0.3)) put(rng, strings, "contact_radius", kLength, draw(kContactRadius));
  } else if (string_kind < 0.8) {
    put(rng, strings, "impact_duration", kTime, draw(kDuration));
  }
  if (draw.chance(0.25)) put(rng, strings, "bed_mass", kMass, draw(kBedMass));
  if (draw.chance(0.25)) strings["bed_damping_ratio"] = draw(kBedDamping);
  if (!strings.empty()) doc["strings"] = strings;

  Json hand = Json::object();
  if (draw.chance(0.35)) put(rng, hand, "mass", kMass, draw(kHandMass));
  if (draw.chance(0.3))
    put(rng, hand, "center_from_butt", kLength, L * draw.within(0.0, 1.0, 0.07, 0.15));
  if (draw.chance(0.25)) {
    const Range grip{1e-6, L, true, kTiny, L, std::min(0.08, L), std::min(0.12, L)};
    put(rng, hand, "grip_length", kLength, draw(grip));
  }
  if (draw.chance(0.15)) {
    // A grip by its tightness, which sets its stiffness and damping.
    hand["grip"] = rng.pick(std::vector<std::string>{"paper", "light", "medium", "tight"});
  } else {
    if (draw.chance(0.25)) hand["grip_stiffness_N_m2"] = draw(kGripStiffness);
    if (draw.chance(0.25)) hand["grip_damping_N_s_m2"] = draw(kGripDamping);
  }
  if (!hand.empty()) doc["hand"] = hand;

  if (draw.chance(0.35)) {
    Json forearm = Json::object();
    if (rng.chance(0.5))
      put(rng, forearm, "equivalent_mass", kMass, draw(kForearm));
    else
      put(rng, forearm, "mass", kMass, 3.0 * draw(kForearm));
    doc["forearm"] = forearm;
  }

  Json ball = Json::object();
  if (draw.chance(0.4)) put(rng, ball, "mass", kMass, draw(kBallMass));
  if (draw.chance(0.6)) put(rng, ball, "speed", kSpeed, draw(kBallSpeed));
  if (draw.chance(0.2)) put(rng, ball, "diameter", kLength, draw(kBallDiameter));
  if (draw.chance(collision ? 0.45 : 0.2)) {
    Json contact = Json::object();
    if (rng.chance(0.3)) {
      contact["law"] = rng.chance(0.5) ? "hysteretic" : "two_mass";  // by name, no coefficients
    } else {
      if (draw.chance(0.7)) contact["stiffness"] = draw(kContactStiffness);
      if (draw.chance(0.6)) contact["exponent"] = draw(kContactExponent);
      if (draw.chance(0.6)) contact["damping"] = draw(kContactDamping);
      if (draw.chance(0.6)) contact["damping_exponent"] = draw(kContactDampingExponent);
    }
    ball["contact"] = contact;
  }
  // A ball by its COR on a rigid surface, [0, 1): each law reaches part of it.
  if (draw.chance(collision ? 0.15 : 0.05)) ball["cor_on_rigid_surface"] = 0.95 * rng.unit();
  if (!ball.empty()) doc["ball"] = ball;

  // What holds the implement (design.hpp Support): a player's or a rig's.
  if (draw.chance(collision ? 0.2 : 0.08)) {
    static const char* const kSupports[] = {"free", "hand", "head_clamped", "handle_clamped",
                                            "rigid_surface"};
    if (rng.chance(0.2)) {
      doc["support"] = Json{{"pivot_from_butt_m", L * rng.unit()}};
    } else {
      doc["support"] = kSupports[static_cast<std::size_t>(rng.unit() * 4.999)];
    }
  }

  // A swing (swing.hpp), the ball's speed above then the incoming one (0 allowed).
  if (draw.chance(0.15)) {
    Json swing = Json::object();
    if (rng.chance(0.5))
      swing["angular_speed_rad_s"] = draw(kAngularSpeed);
    else
      put(rng, swing, "speed_at_impact", kSpeed, draw(kSwingSpeed));
    put(rng, swing, "pivot_beyond_butt", kLength, draw(kPivot));
    doc["swing"] = swing;
  }

  Json impact = Json::object();
  const double impact_kind = rng.unit();
  if (impact_kind < 0.7) {
    const double from_tip = L * draw.within(0.0, 1.0, 0.0, 0.4);
    if (impact_kind < 0.45)
      put(rng, impact, "from_tip", kLength, from_tip);
    else
      put(rng, impact, "from_butt", kLength, L - from_tip);
  }
  if (draw.chance(head || twistweight ? 0.35 : 0.03))
    put(rng, impact, "off_axis", kLength, L * draw.within(-1.0, 1.0, -0.15, 0.15));
  if (!impact.empty()) doc["impact"] = impact;
  d.document = doc;
  return d;
}

namespace {

// A quantity in SI: the first of its spellings the object gives.
std::optional<double> si(const Json& object, const std::string& base,
                         const std::vector<Unit>& units) {
  if (!object.is_object()) return std::nullopt;
  for (const Unit& u : units) {
    const auto it = object.find(base + u.suffix);
    if (it != object.end() && it->is_number()) return to_si(it->get<double>(), u);
  }
  return std::nullopt;
}

std::optional<double> number(const Json& object, const std::string& key) {
  if (!object.is_object()) return std::nullopt;
  const auto it = object.find(key);
  if (it == object.end() || !it->is_number()) return std::nullopt;
  return it->get<double>();
}

const Json& part(const Json& document, const char* name) {
  static const Json kEmpty = Json::object();
  const auto it = document.find(name);
  return it == document.end() ? kEmpty : *it;
}

// Mass, first moment and inertia about the butt of uniform pieces laid along the axis.
struct MassSum {
  double mass = 0.0, moment = 0.0, inertia_butt = 0.0;
  void add(double m, double x, double own_inertia) {
    mass += m;
    moment += m * x;
    inertia_butt += own_inertia + m * x * x;
  }
};

}  // namespace

std::optional<Truth> read_truth(const Json& document) {
  if (!document.is_object()) return std::nullopt;
  const auto found = document.find("implement");
  if (found == document.end() || !found->is_object()) return std::nullopt;
  const Json& implement = *found;
  Truth t;
  MassSum frame;
  if (const auto sections = implement.find("sections"); sections != implement.end()) {
    if (!sections->is_array() || sections->empty()) return std::nullopt;
    double x = 0.0;
    for (const Json& s : *sections) {
      const auto l = si(s, "length", kLength);
      const auto m = si(s, "mass", kMass);
      if (!l || !m) return std::nullopt;
      frame.add(*m, x + 0.5 * *l, *m * *l * *l / 12.0);
      x += *l;
    }
    t.length_m = x;
    t.frame_mass_kg = frame.mass;
    t.frame_com_m = frame.mass > 0.0 ? frame.moment / frame.mass : 0.0;
    t.frame_I_cm_kg_m2 = frame.inertia_butt - frame.mass * t.frame_com_m * t.frame_com_m;
    t.frame_I_scale_kg_m2 = frame.inertia_butt;
  } else {
    const auto L = si(implement, "length", kLength);
    const auto M = si(implement, "mass", kMass);
    if (!L || !M) return std::nullopt;
    t.length_m = *L;
    t.frame_mass_kg = *M;
    if (const auto ratio = number(implement, "head_to_handle_mass_ratio")) {
      // Two uniform halves, head mass M1 = M r / (1 + r) towards the tip.
      const double handle = *M / (1.0 + *ratio), head = *M * *ratio / (1.0 + *ratio);
      const double half = 0.5 * *L;
      frame.add(handle, 0.25 * *L, handle * half * half / 12.0);
      frame.add(head, 0.75 * *L, head * half * half / 12.0);
      t.frame_com_m = frame.moment / frame.mass;
      t.frame_I_cm_kg_m2 = frame.inertia_butt - frame.mass * t.frame_com_m * t.frame_com_m;
      t.frame_I_scale_kg_m2 = frame.inertia_butt;
    } else {
      std::optional<double> B = number(implement, "balance_from_butt_m");
      if (const auto cm = number(implement, "balance_cm")) B = move_decimal_point(*cm, -2);
      if (const auto points = number(implement, "balance_pts_hl"))
        B = 0.5 * *L - *points * (0.0254 / 8.0);
      const auto sw = si(implement, "swingweight", kInertia);
      if (!B || !sw) return std::nullopt;
      // SW = I_cm + M (B - 0.1)^2 about the axis 10 cm from the butt.
      t.frame_com_m = *B;
      t.frame_I_cm_kg_m2 = *sw - *M * (*B - 0.1) * (*B - 0.1);
      t.frame_I_scale_kg_m2 = *sw;
    }
  }
  const double L = t.length_m;

  const auto sq_in = number(implement, "headsize_sq_in");
  const auto cm2 = number(implement, "headsize_cm2");
  if (sq_in || cm2) {
    HeadShape head;
    head.area_m2 = sq_in ? *sq_in * (0.0254 * 0.0254) : move_decimal_point(*cm2, -4);
    head.aspect_ratio = number(implement, "head_aspect_ratio").value_or(kDefaultHeadAspectRatio);
    head.hoop_width_m = si(implement, "hoop_width", kLength).value_or(kDefaultHoopWidth_m);
    t.head = head;
  }
  t.twistweight_kg_m2 = si(implement, "twistweight", kInertia);

  if (const auto list = implement.find("point_masses"); list != implement.end()) {
    if (!list->is_array()) return std::nullopt;
    for (const Json& p : *list) {
      const auto m = si(p, "mass", kMass);
      if (!m) return std::nullopt;
      const auto clock = p.find("clock");
      if (clock == p.end()) {
        const auto from_butt = si(p, "from_butt", kLength);
        const auto from_tip = si(p, "from_tip", kLength);
        if (!from_butt && !from_tip) return std::nullopt;
        t.point_masses.push_back(
            {from_butt ? *from_butt : L - *from_tip, *m, si(p, "off_axis", kLength).value_or(0.0)});
        continue;
      }
      const bool joined = clock->is_string() && clock->get<std::string>() == "3/9";
      if (clock->is_string() && clock->get<std::string>() != "throat" && !joined) {
        // Under the butt cap ("handle", "butt") or the grip ("grip"): head_geometry.hpp.
        const double x =
            clock->get<std::string>() == "grip" ? kUnderGripFromButt_m : kHandleWeightFromButt_m;
        t.point_masses.push_back({std::min(x, L), *m, 0.0});
        continue;
      }
      std::vector<double> hours;
      if (clock->is_number()) hours.push_back(clock->get<double>());
      if (clock->is_string() && clock->get<std::string>() == "throat") hours.push_back(6.0);
      if (joined) hours = {3.0, 9.0};
      if (clock->is_array()) {
        for (const Json& h : *clock) {
          if (!h.is_number()) return std::nullopt;
          hours.push_back(h.get<double>());
        }
      }
      if (hours.empty() || !t.head) return std::nullopt;
      for (const double h : hours) {
        try {
          const FacePoint f = clock_position(*t.head, L, h);
          t.point_masses.push_back({f.from_butt_m, *m, f.off_axis_m});
        } catch (const std::invalid_argument&) {
          return std::nullopt;
        }
      }
    }
  }

  const Json& ball = part(document, "ball");
  t.ball_mass_kg = si(ball, "mass", kMass).value_or(0.057);
  t.ball_speed_m_s = si(ball, "speed", kSpeed).value_or(50.0);
  t.ball_diameter_m = si(ball, "diameter", kLength).value_or(sweetspot::kTennisBallDiameter_m);
  const Json& swing = part(document, "swing");
  t.swing_angular_speed_rad_s = number(swing, "angular_speed_rad_s");
  t.swing_speed_at_impact_m_s = si(swing, "speed_at_impact", kSpeed);
  t.swing_pivot_beyond_butt_m = si(swing, "pivot_beyond_butt", kLength).value_or(0.0);
  const Json& contact = part(ball, "contact");
  t.ball_stiffness = number(contact, "stiffness").value_or(sweetspot::kTennisBallLaw.stiffness);
  t.ball_exponent = number(contact, "exponent").value_or(sweetspot::kTennisBallLaw.exponent);
  t.ball_hysteretic =
      contact.is_object() && contact.contains("law") && contact["law"] == "hysteretic";
  t.ball_two_mass = contact.is_object() && contact.contains("law") && contact["law"] == "two_mass";
  const Json& impact = part(document, "impact");
  if (const auto from_tip = si(impact, "from_tip", kLength)) t.impact_from_butt_m = L - *from_tip;
  if (const auto from_butt = si(impact, "from_butt", kLength)) t.impact_from_butt_m = *from_butt;
  t.impact_off_axis_m = si(impact, "off_axis", kLength).value_or(0.0);
  return t;
}

}  // namespace sweetspot::property
