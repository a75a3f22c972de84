#pragma once

// Random design files over the whole accepted range of every input, for the
// property tests (design_space_test.cpp). The ranges are those the code
// accepts today (include/sweetspot/design.hpp, implement.hpp, ball_contact.hpp,
// string_bed.hpp, head_geometry.hpp, frame_specs.hpp and the validate()
// functions; src/io/design_reader.cpp; docs/design-files.md's key table). Each input is
// drawn from one of three places: its accepted range's ends (the corners:
// the bound itself when it is closed, an extreme value next to it when it is
// open or unbounded), the whole range (log-uniform where it spans decades),
// or where real implements lie. The generator also records, in SI, what the
// test needs to check the answer independently of the code: the ball, the
// implement's mass distribution, the head and the impact.

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/json_reader.hpp"
#include "sweetspot/head_geometry.hpp"

namespace sweetspot::property {

using io::Json;

// splitmix64: a tiny generator whose stream is the same on every platform
// (the standard library's distributions are not).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  bool chance(double p) { return unit() < p; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  double log_uniform(double lo, double hi) {
    return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * unit());
  }
  int integer(int lo, int hi) {  // [lo, hi]
    return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  template <class T>
  const T& pick(const std::vector<T>& items) {
    return items[next() % items.size()];
  }

 private:
  std::uint64_t state_;
};

// One input's accepted range and where it is drawn from.
struct Range {
  double lo = 0.0, hi = 0.0;  // the whole range's interior draw
  bool log = false;           // log-uniform in [lo, hi]
  double corner_lo = 0.0;     // the accepted range's ends (see above)
  double corner_hi = 0.0;
  double typical_lo = 0.0, typical_hi = 0.0;  // real implements (log-uniform when log)
};

// How a design's inputs are drawn: the chance of a corner and of a typical value
// for each input (else the whole range).
struct Style {
  const char* name = "";
  double corner = 0.0;
  double typical = 0.0;
};

// A drawn design file and the fidelity it is to be evaluated at.
struct DrawnDesign {
  Json document;
  std::string fidelity;  // the level asked: rigid, modal, response, collision or auto
  std::string style;     // how its inputs were drawn: typical, whole range, corners
};

// What the test reads from a design file itself, in SI, to check an answer
// independently of the code: the ball, the implement's mass distribution
// (with its point masses placed), the polar inertia's parts and the impact.
struct PlacedMass {
  double from_butt_m = 0.0;
  double mass_kg = 0.0;
  double off_axis_m = 0.0;
};

struct Truth {
  double length_m = 0.0;
  // The frame without point masses: its mass, centre of mass and inertia about it.
  double frame_mass_kg = 0.0, frame_com_m = 0.0, frame_I_cm_kg_m2 = 0.0;
  // The sum of the |terms| that make frame_I_cm_kg_m2: I_cm's condition.
  double frame_I_scale_kg_m2 = 0.0;
  std::vector<PlacedMass> point_masses;
  std::optional<HeadShape> head;
  std::optional<double> twistweight_kg_m2;
  double ball_mass_kg = 0.057, ball_speed_m_s = 50.0;
  double ball_diameter_m = 0.067;
  // A swing (swing.hpp): the racquet's speed at the impact, given or omega (pivot + x).
  std::optional<double> swing_angular_speed_rad_s, swing_speed_at_impact_m_s;
  double swing_pivot_beyond_butt_m = 0.0;
  // The speed ball and strings meet at, for an impact `from_butt_m` from the butt: the
  // collision off a swinging racquet is the one onto a racquet at rest at this speed.
  double meeting_speed_m_s(double from_butt_m) const {
    if (swing_speed_at_impact_m_s) return ball_speed_m_s + *swing_speed_at_impact_m_s;
    if (swing_angular_speed_rad_s)
      return ball_speed_m_s +
             *swing_angular_speed_rad_s * (swing_pivot_beyond_butt_m + from_butt_m);
    return ball_speed_m_s;
  }
  // The ball's elastic law k x^n (ball.contact; absent: the calibrated tennis ball's).
  double ball_stiffness = 0.0, ball_exponent = 0.0;
  // ball.contact.law "hysteretic": its loading work (backbones of ball_contact.hpp) instead.
  bool ball_hysteretic = false;
  // ball.contact.law "two_mass": its compression is its centre's, which no
  // one law's stored energy bounds (its internal spring holds some too).
  bool ball_two_mass = false;
  std::optional<double> impact_from_butt_m;  // absent: the code's default
  double impact_off_axis_m = 0.0;
};

// The design file read by the test's own rules (the key table of docs/design-files.md);
// std::nullopt when it is not a design the test can read (the code must then refuse it).
std::optional<Truth> read_truth(const Json& document);

// The five names a fidelity is asked by.
inline const std::vector<std::string> kFidelities{"rigid", "modal", "response", "collision",
                                                  "auto"};

// A design file drawn for `fidelity` (the generator leans towards what that
// level needs: a stiffness for the modes, a tension and no COR for the
// collision, cor_rigid for the response). `typical_share` of the designs
// draw their inputs mostly where real implements lie; of the rest, 5 in 7
// over the whole ranges (some at their corners) and 2 in 7 mostly at the corners.
DrawnDesign draw_design(Rng& rng, const std::string& fidelity, double typical_share = 0.3);

}  // namespace sweetspot::property
