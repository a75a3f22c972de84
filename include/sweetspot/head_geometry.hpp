#pragma once

// The head of a racquet seen from the front: the string bed as an ellipse, the
// hoop (the frame around it) where lead tape goes, clock positions on it, and
// an estimate of the implement's polar inertia (its twistweight) from the
// head's size when it was not measured.
//
// Coordinates: x along the long axis from the butt (as everywhere), y across
// the face, off the long axis, positive towards 3 o'clock (the right-hand side
// of the face seen with the tip up). 12 o'clock is the tip.

#include <optional>

#include "sweetspot/implement.hpp"

namespace sweetspot {

// The default shape of a head. The industry "head size" is the strung area,
// pi/4 times the strung length times the strung width; a modern 100 in^2 head
// is about 13.5 in long and 10 in wide, so the strung length is 1.35 times the
// width (ITF rules allow at most 15.5 in by 11.5 in, aspect 1.35 as well).
inline constexpr double kDefaultHeadAspectRatio = 1.35;
// The hoop's width in the plane of the face (the frame's tube with its
// grommets, 13-18 mm on graphite frames): lead tape sits on its centre line,
// and the string bed ends this far below the tip.
inline constexpr double kDefaultHoopWidth_m = 0.015;
// Lead "in the handle" goes under the butt cap, this far from the butt (a
// clock "handle" or "butt" in a design file and in `tune`'s places).
inline constexpr double kHandleWeightFromButt_m = 0.02;
// The handle below the throat: 7 in (18 cm) long on a 27 in racquet (in
// proportion on a shorter one, a junior's), and at most as wide as the
// corners of the largest grip, an octagon of 4 3/4 in (12.07 cm) around (grip
// sizes run from 4 to 4 3/4 in), whose circumradius is its perimeter / (16
// sin(pi/8)), 1.97 cm.
inline constexpr double kHandleLength_m = 0.18;
inline constexpr double kHandleRacquetLength_m = 27 * 0.0254;
inline constexpr double kLargestGripCircumference_m = 4.75 * 0.0254;
// Lead "under the grip" is wrapped along the handle; taken as one point at
// the middle of the handle, 9 cm from the butt (a clock "grip"):
// a stated assumption of place (a grip's lead spread over its length differs
// by its own inertia about its middle, under 0.3 kg cm^2 for 10 g over 18 cm).
inline constexpr double kUnderGripFromButt_m = kHandleLength_m / 2.0;

// The estimate of the polar inertia from the head (estimated_polar_inertia_kg_m2):
// the hoop carries half the frame's mass, on its centre line, and a set of
// strings (17 g) is spread evenly over the string bed. The half comes from a
// mass budget of a 320 g strung frame: a graphite tube of nearly uniform mass per
// length, 96 cm of it in the hoop against 34 cm in the two shafts and 19 cm in
// the handle, plus grip, butt cap, strings and grommets.
inline constexpr double kHoopMassShare = 0.5;
inline constexpr double kStringSetMass_kg = 0.017;
// Its error against 263 strung racquets measured by a retailer's lab (head size,
// strung mass and twistweight side by side): mean +3.7 %, standard deviation
// 6.6 %, 81 % of racquets within +-10 %, 90 % within -7.6 % and +14.5 %, the
// extremes -15 % and +23 %. Taraborrelli et al., Sports Eng. 22:1-9 (2019)
// report -11 % to +12 % for their geometric model on 416 rackets and up to 25 %
// with 30 g added: an estimate, not a measurement.

// The head a racquet is given when nothing sizes it: 100 sq in, the inch
// 0.0254 m exactly.
inline constexpr double kDefaultHeadArea_m2 = 100.0 * 0.0254 * 0.0254;

// The head's shape: its strung area and the ratio of strung length to width.
struct HeadShape {
  double area_m2 = kDefaultHeadArea_m2;           // strung area [m^2], > 0
  double aspect_ratio = kDefaultHeadAspectRatio;  // strung length / strung width, >= 1
  double hoop_width_m = kDefaultHoopWidth_m;      // [m], >= 0
};

// The string bed as an ellipse on the implement of length L: its far end
// hoop_width_m below the tip, semi-axes a (along x) and c (across), pi a c = area.
struct HeadEllipse {
  double center_from_butt_m = 0.0;  // [m]
  double semi_length_m = 0.0;       // a [m]
  double semi_width_m = 0.0;        // c [m]
};

// The string bed of `head` on an implement of length `length_m`. Throws
// std::invalid_argument naming "headsize" when the area is not > 0 or the
// aspect ratio not in [1, 10], and when the head (with its hoop) would be longer
// than the implement.
HeadEllipse string_bed(const HeadShape& head, double length_m);

// Whether (x, y) lies on the string bed (inside or on the ellipse).
bool on_string_bed(const HeadEllipse& bed, double from_butt_m, double off_axis_m);

// The head to the hoop's outer edge: string_bed() widened by the hoop's
// width on every side (semi-axes a + w and c + w).
HeadEllipse hoop_outline(const HeadShape& head, double length_m);

// The ellipse's half-width at `from_butt_m`, c sqrt(1 - u^2) with u the
// distance from its centre over a; 0 beyond its ends [m].
double half_width_at(const HeadEllipse& ellipse, double from_butt_m);

// The strung area of a head whose strung semi-length is a: pi a c with
// c = a / aspect [m^2] (the inverse of string_bed()'s semi-axes).
double head_area_m2(double semi_length_m, double aspect_ratio);

// A point of the implement in the plane of the face.
struct FacePoint {
  double from_butt_m = 0.0;  // x [m]
  double off_axis_m = 0.0;   // y [m], positive towards 3 o'clock
};

// A clock position on the hoop's centre line (the ellipse of semi-axes a + w/2
// and c + w/2, w the hoop width): the point where the ray from the head's centre
// at clock angle theta = 30 deg per hour (clockwise from 12, the tip) meets it,
// r = 1 / sqrt(cos^2 theta / A^2 + sin^2 theta / C^2). 3 and 9 o'clock are at
// y = +C and -C, 12 at the tip, 6 at the throat. `hours` in [0, 12] (0 is 12);
// throws std::invalid_argument naming "clock" otherwise.
FacePoint clock_position(const HeadShape& head, double length_m, double hours);

// The largest head the ITF's rules allow (Rules of Tennis, Rule 4): a strung
// surface at most 15.5 in (39.4 cm) long and 11.5 in (29.2 cm) wide in a frame
// at most 12.5 in (31.7 cm) wide, so a hoop of (12.5 - 11.5) / 2 in. The
// outline where lead can sit on a racquet whose head is not given.
inline constexpr HeadShape kLargestLegalHead{
    .area_m2 = 0.25 * 3.14159265358979323846 * 15.5 * 11.5 * 0.0254 * 0.0254,
    .aspect_ratio = 15.5 / 11.5,
    .hoop_width_m = 0.5 * 0.0254};

// The largest grip's half-width across its corners [m], 1.97 cm.
double grip_half_width_m();

// The largest head an implement of `length_m` can have when its head is not
// given: kLargestLegalHead, or, on one too short to hold it beyond its
// handle (a junior's racquet, a paddle), the largest of its aspect and hoop
// that ends at the handle; std::nullopt when none does (under about 3.4 cm).
std::optional<HeadShape> largest_legal_head(double length_m);

// The racquet's half-width in the plane of the face `from_butt_m` from the
// butt: where lead can sit off its axis. Its outline is the handle
// (kHandleLength_m on a 27 in racquet, in proportion on a shorter one, as
// wide as the largest grip's corners; no head reaches over it), the throat
// as the straight lines from the handle's end tangent to the hoop's outer
// edge (the ellipse of semi-axes a + w and c + w: the hull of the handle's
// end and the hoop, which contains the throat's arms), and the hoop's outer
// edge; 0 outside the implement. An upper bound of a real racquet's
// outline, not its shape.
double face_half_width_m(const HeadShape& head, double length_m, double from_butt_m);

// The polar inertia about the long axis of a frame of mass `frame_mass_kg`
// with this head, estimated (see kHoopMassShare):
//   I = kHoopMassShare M <y^2>_hoop + m_strings c^2 / 4,
// <y^2>_hoop the mean of y^2 along the hoop's centre line [kg m^2]. Error: see
// kHoopMassShare. Throws std::invalid_argument for a mass <= 0.
double estimated_polar_inertia_kg_m2(const HeadShape& head, double length_m, double frame_mass_kg);

// The polar inertia of frame plus point masses about the long axis:
// I_frame + sum m y^2 [kg m^2] (each point mass's own size neglected).
double polar_inertia_with_point_masses(double frame_polar_inertia_kg_m2,
                                       const std::vector<PointMass>& point_masses);

}  // namespace sweetspot
