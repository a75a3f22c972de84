#include "sweetspot/head_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/check.hpp"
#include "sweetspot/errors.hpp"

namespace sweetspot {
namespace {

void check_head(const HeadShape& head) {
  detail::require_positive("headsize", head.area_m2, "m^2");
  // A head larger than a 100 m implement's square could not fit on it.
  detail::require_in_range("headsize", head.area_m2, 0.0, kMaxLength_m * kMaxLength_m, "m^2");
  detail::require_in_range("headsize aspect_ratio", head.aspect_ratio, 1.0, 10.0, "");
  detail::require_in_range("hoop_width_m", head.hoop_width_m, 0.0, kMaxLength_m, "m");
}

}  // namespace

HeadEllipse string_bed(const HeadShape& head, double length_m) {
  check_head(head);
  detail::require_positive("length_m", length_m, "m");
  const double c = std::sqrt(head.area_m2 / (std::numbers::pi * head.aspect_ratio));
  const double a = head.aspect_ratio * c;
  const double overall_m = 2.0 * a + 2.0 * head.hoop_width_m;
  if (!(overall_m <= length_m)) {
    // The largest area of this aspect whose length with its hoop is L:
    // a = L / 2 - w, area = pi a^2 / aspect.
    const double longest_a = 0.5 * length_m - head.hoop_width_m;
    std::optional<FieldError::Range> range;
    if (longest_a > 0.0) {
      range = FieldError::Range{0.0, head_area_m2(longest_a, head.aspect_ratio), true, head.area_m2,
                                "for the head of its aspect, with its hoop, to fit the "
                                "implement's length"};
    }
    throw FieldError("headsize",
                     "a head of " + detail::format_significant(head.area_m2) + " m^2 is " +
                         detail::format_significant(overall_m) +
                         " m long with its hoop, longer than the implement (" +
                         detail::format_number(length_m) + " m)",
                     range);
  }
  return HeadEllipse{length_m - head.hoop_width_m - a, a, c};
}

bool on_string_bed(const HeadEllipse& bed, double from_butt_m, double off_axis_m) {
  const double u = (from_butt_m - bed.center_from_butt_m) / bed.semi_length_m;
  const double v = off_axis_m / bed.semi_width_m;
  return u * u + v * v <= 1.0;
}

HeadEllipse hoop_outline(const HeadShape& head, double length_m) {
  HeadEllipse outline = string_bed(head, length_m);
  outline.semi_length_m += head.hoop_width_m;
  outline.semi_width_m += head.hoop_width_m;
  return outline;
}

double half_width_at(const HeadEllipse& ellipse, double from_butt_m) {
  const double u = (from_butt_m - ellipse.center_from_butt_m) / ellipse.semi_length_m;
  return std::abs(u) <= 1.0 ? ellipse.semi_width_m * std::sqrt(1.0 - u * u) : 0.0;
}

double head_area_m2(double semi_length_m, double aspect_ratio) {
  return std::numbers::pi * semi_length_m * semi_length_m / aspect_ratio;
}

FacePoint clock_position(const HeadShape& head, double length_m, double hours) {
  detail::require_in_range("clock", hours, 0.0, 12.0, "");
  const HeadEllipse bed = string_bed(head, length_m);
  const double A = bed.semi_length_m + 0.5 * head.hoop_width_m;
  const double C = bed.semi_width_m + 0.5 * head.hoop_width_m;
  const double theta = hours * (std::numbers::pi / 6.0);
  const double cos_t = std::cos(theta), sin_t = std::sin(theta);
  // Exact at the quarters, where cos or sin of a multiple of pi/2 is not exactly 0.
  const double hours_mod = std::fmod(hours, 12.0);
  if (hours_mod == 3.0) return FacePoint{bed.center_from_butt_m, C};
  if (hours_mod == 9.0) return FacePoint{bed.center_from_butt_m, -C};
  if (hours_mod == 6.0) return FacePoint{bed.center_from_butt_m - A, 0.0};
  if (hours_mod == 0.0) return FacePoint{bed.center_from_butt_m + A, 0.0};
  const double r = 1.0 / std::sqrt(cos_t * cos_t / (A * A) + sin_t * sin_t / (C * C));
  return FacePoint{bed.center_from_butt_m + r * cos_t, r * sin_t};
}

namespace {
// The handle of a racquet of this length: kHandleLength_m at 27 in, in
// proportion below.
double handle_length_m(double length_m) {
  return kHandleLength_m * std::min(1.0, length_m / kHandleRacquetLength_m);
}
}  // namespace

double grip_half_width_m() {
  return kLargestGripCircumference_m / (16.0 * std::sin(std::numbers::pi / 8.0));
}

std::optional<HeadShape> largest_legal_head(double length_m) {
  HeadShape head = kLargestLegalHead;
  const double room_m = length_m - handle_length_m(length_m);
  const double c = std::sqrt(head.area_m2 / (std::numbers::pi * head.aspect_ratio));
  if (2.0 * (head.aspect_ratio * c + head.hoop_width_m) <= room_m) return head;
  const double a = 0.5 * room_m - head.hoop_width_m;
  if (!(a > 0.0)) return std::nullopt;
  head.area_m2 = head_area_m2(a, head.aspect_ratio);
  return head;
}

double face_half_width_m(const HeadShape& head, double length_m, double from_butt_m) {
  const HeadEllipse outline = hoop_outline(head, length_m);
  const double A = outline.semi_length_m, C = outline.semi_width_m;
  const double xc = outline.center_from_butt_m;
  const double x = from_butt_m;
  if (!(x >= 0.0 && x <= length_m)) return 0.0;
  const double h = grip_half_width_m();
  // The handle, in proportion on a racquet shorter than 27 in; no head on it.
  const double handle_end = handle_length_m(length_m);
  if (x <= handle_end) return h;
  double half = half_width_at(outline, x);
  // The tangent from the handle's end (p, q) in the ellipse's units: the line
  // x cos t / A + y sin t / C = 1 through it has p cos t + q sin t = 1, so
  // t = phi -+ acos(1 / R), R = |(p, q)|, phi its angle; the upper tangent is
  // the smaller t. None when the handle's end is inside the hoop.
  const double p = (handle_end - xc) / A, q = h / C;
  if (const double R = std::hypot(p, q); R > 1.0 && x > handle_end) {
    const double t = std::atan2(q, p) - std::acos(1.0 / R);
    const double tangent_x = xc + A * std::cos(t), tangent_y = C * std::sin(t);
    if (x < tangent_x) {
      half = std::max(half, h + (tangent_y - h) * (x - handle_end) / (tangent_x - handle_end));
    }
  }
  return half;
}

double estimated_polar_inertia_kg_m2(const HeadShape& head, double length_m, double frame_mass_kg) {
  detail::require_positive("frame mass", frame_mass_kg, "kg");
  const HeadEllipse bed = string_bed(head, length_m);
  const double A = bed.semi_length_m + 0.5 * head.hoop_width_m;
  const double C = bed.semi_width_m + 0.5 * head.hoop_width_m;
  // Mean of y^2 along the hoop (x = A cos t, y = C sin t), weighted by arc
  // length; the midpoint rule converges spectrally for a periodic integrand.
  constexpr int kSteps = 256;
  double weighted = 0.0, total = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double t = 2.0 * std::numbers::pi * (i + 0.5) / kSteps;
    const double ds = std::hypot(A * std::sin(t), C * std::cos(t));
    const double y = C * std::sin(t);
    weighted += y * y * ds;
    total += ds;
  }
  const double mean_y2 = weighted / total;
  const double strings = std::min(kStringSetMass_kg, 0.1 * frame_mass_kg);
  const double c = bed.semi_width_m;
  // A uniform elliptical lamina: I about its long axis = m c^2 / 4.
  return kHoopMassShare * frame_mass_kg * mean_y2 + strings * c * c / 4.0;
}

double polar_inertia_with_point_masses(double frame_polar_inertia_kg_m2,
                                       const std::vector<PointMass>& point_masses) {
  double I = frame_polar_inertia_kg_m2;
  for (const PointMass& p : point_masses) I += p.mass_kg * p.off_axis_m * p.off_axis_m;
  return I;
}

}  // namespace sweetspot
