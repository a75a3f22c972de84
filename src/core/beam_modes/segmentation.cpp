#include "core/beam_modes/segmentation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/check.hpp"
#include "sweetspot/errors.hpp"

namespace sweetspot::beam_detail {

using detail::format_number;

[[noreturn]] void fail(const std::string& name, const std::string& expected, double value) {
  throw FieldError(name, "must be " + expected + ", got " + format_number(value));
}

double validated_length(const std::vector<Section>& sections, bool need_mass) {
  if (sections.empty()) throw FieldError("sections", "must not be empty");
  double length = 0.0;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const Section& s = sections[i];
    detail::require_positive(detail::Element{"sections", i, "length_m"}, s.length_m, "m");
    if (need_mass) {
      detail::require_positive(detail::Element{"sections", i, "mass_kg"}, s.mass_kg, "kg");
    } else {
      detail::require_at_least(detail::Element{"sections", i, "mass_kg"}, s.mass_kg, 0.0, "kg");
    }
    if (!s.EI_N_m2) {
      throw FieldError(detail::indexed("sections", i, "EI_N_m2"),
                       "must be given for the bending modes, got none");
    }
    detail::require_positive(detail::Element{"sections", i, "EI_N_m2"}, *s.EI_N_m2, "N m^2");
    length += s.length_m;
  }
  return length;
}

void validate_options(const ModeOptions& options, std::size_t section_count) {
  const std::string why = options.validate();
  if (!why.empty()) throw std::invalid_argument("options." + why);
  if (options.theory == ModeOptions::Theory::kTimoshenko &&
      options.timoshenko.size() != section_count) {
    fail("options.timoshenko.size()",
         "the number of sections (" + std::to_string(section_count) + ")",
         static_cast<double>(options.timoshenko.size()));
  }
}

void validate_hand(const HandCoupling& hand, double length_m) {
  detail::require_positive("hand.mass_kg", hand.mass_kg, "kg");
  detail::require_in_range("hand.grip_start_m", hand.grip_start_m, 0.0, length_m, "m");
  detail::require_in_range("hand.grip_length_m", hand.grip_length_m, 0.0,
                           length_m - hand.grip_start_m, "m");
  detail::require_positive("hand.grip_length_m", hand.grip_length_m, "m");
  detail::require_at_least("hand.stiffness_N_m2", hand.stiffness_N_m2, 0.0, "N/m^2");
  detail::require_at_least("hand.damping_N_s_m2", hand.damping_N_s_m2, 0.0, "N s/m^2");
  if (hand.rotary_inertia_kg_m2) {
    detail::require_positive("hand.rotary_inertia_kg_m2", *hand.rotary_inertia_kg_m2, "kg m^2");
  }
}

double phase_weight(double mu_kg_m, double EI_N_m2, double length_m) {
  return std::pow(mu_kg_m / EI_N_m2, 0.25) * length_m;
}

// True when sections i and i + 1 are one uniform stretch: the same mass per
// length, EI and (Timoshenko) cross-section. Their boundary is then no
// breakpoint, so a design given as many equal sections costs what one costs.
bool same_properties(const std::vector<Section>& sections,
                     const std::vector<TimoshenkoSection>& timoshenko, std::size_t i) {
  const Section& a = sections[i];
  const Section& b = sections[i + 1];
  if (a.mass_kg / a.length_m != b.mass_kg / b.length_m || *a.EI_N_m2 != *b.EI_N_m2) return false;
  return timoshenko.empty() ||
         (timoshenko[i].shear_stiffness_N == timoshenko[i + 1].shear_stiffness_N &&
          timoshenko[i].radius_of_gyration_m == timoshenko[i + 1].radius_of_gyration_m);
}

Segmentation segment(const std::vector<Section>& sections,
                     const std::vector<PointMass>& point_masses, std::vector<double> extra_breaks,
                     const std::vector<TimoshenkoSection>& timoshenko) {
  Segmentation out;
  out.groupable = timoshenko.empty();
  std::vector<double> section_ends;
  double x = 0.0;
  for (const Section& s : sections) section_ends.push_back(x += s.length_m);
  out.length_m = x;
  const double eps = 1e-12 * x;

  std::vector<double> breaks{0.0};
  for (std::size_t i = 0; i + 1 < sections.size(); ++i) {
    if (!same_properties(sections, timoshenko, i)) breaks.push_back(section_ends[i]);
  }
  breaks.push_back(x);
  for (const PointMass& p : point_masses) breaks.push_back(p.from_butt_m);
  breaks.insert(breaks.end(), extra_breaks.begin(), extra_breaks.end());
  std::sort(breaks.begin(), breaks.end());
  std::vector<double> unique;
  for (double b : breaks) {
    if (unique.empty() || b - unique.back() > eps) unique.push_back(b);
  }
  unique.back() = out.length_m;

  std::size_t section = 0;
  for (std::size_t i = 0; i + 1 < unique.size(); ++i) {
    const double mid = 0.5 * (unique[i] + unique[i + 1]);
    while (section + 1 < sections.size() && mid > section_ends[section]) ++section;
    const Section& s = sections[section];
    Segment seg;
    seg.start_m = unique[i];
    seg.length_m = unique[i + 1] - unique[i];
    seg.mu_kg_m = s.mass_kg / s.length_m;
    seg.EI_N_m2 = *s.EI_N_m2;
    seg.section = section;
    out.segments.push_back(seg);
  }
  for (const PointMass& p : point_masses) {
    if (p.from_butt_m >= out.length_m - eps) {
      out.tip_mass_kg += p.mass_kg;
      continue;
    }
    auto it = std::min_element(
        out.segments.begin(), out.segments.end(), [&](const Segment& a, const Segment& b) {
          return std::abs(a.start_m - p.from_butt_m) < std::abs(b.start_m - p.from_butt_m);
        });
    it->mass_at_start_kg += p.mass_kg;
  }
  return out;
}

const std::vector<TimoshenkoSection>& timoshenko_of(const ModeOptions& options) {
  static const std::vector<TimoshenkoSection> kNone;
  return options.theory == ModeOptions::Theory::kTimoshenko ? options.timoshenko : kNone;
}

Segmentation hand_segmentation(const std::vector<Section>& sections,
                               const std::vector<PointMass>& point_masses, const HandCoupling& hand,
                               const ModeOptions& options) {
  return segment(sections, point_masses,
                 {hand.grip_start_m, hand.grip_start_m + hand.grip_length_m},
                 timoshenko_of(options));
}

}  // namespace sweetspot::beam_detail
