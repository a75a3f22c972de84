#pragma once

// Validation of sections and options, and the division of the beam into
// uniform segments between breakpoints. Internal to the beam-mode solvers.

#include <cstddef>
#include <string>
#include <vector>

#include "sweetspot/beam_modes.hpp"

namespace sweetspot::beam_detail {

// Throws std::invalid_argument "<name>: must be <expected>, got <value>".
[[noreturn]] void fail(const std::string& name, const std::string& expected, double value);

// The implement's length; throws std::invalid_argument naming the first bad
// section (mass > 0 required when `need_mass`).
double validated_length(const std::vector<Section>& sections, bool need_mass);
void validate_options(const ModeOptions& options, std::size_t section_count);
void validate_hand(const HandCoupling& hand, double length_m);

// A uniform piece of the beam between consecutive breakpoints (section
// boundaries, point masses, grip ends).
struct Segment {
  double start_m = 0.0;
  double length_m = 0.0;
  double mu_kg_m = 0.0;
  double EI_N_m2 = 0.0;
  std::size_t section = 0;
  double mass_at_start_kg = 0.0;  // point masses at start_m
};

struct Segmentation {
  std::vector<Segment> segments;
  double tip_mass_kg = 0.0;
  double length_m = 0.0;
  // Finite elements may span several segments shorter than an element
  // (Euler-Bernoulli only: a Timoshenko element has one shear stiffness).
  bool groupable = true;
};

// The bending phase beta l of a uniform stretch per root omega:
// (mu / EI)^(1/4) l, so that beta l = sqrt(omega) times it. Meshes are sized
// to equal phase per element.
double phase_weight(double mu_kg_m, double EI_N_m2, double length_m);

// The beam's segments: breakpoints at section boundaries where the properties
// change, point masses and `extra_breaks`. `timoshenko`: one entry per
// section when the theory is Timoshenko, else empty.
Segmentation segment(const std::vector<Section>& sections,
                     const std::vector<PointMass>& point_masses,
                     std::vector<double> extra_breaks = {},
                     const std::vector<TimoshenkoSection>& timoshenko = {});

// The Timoshenko data segment() compares sections by (empty for Euler-Bernoulli).
const std::vector<TimoshenkoSection>& timoshenko_of(const ModeOptions& options);

// Segments with breakpoints at the grip's ends too.
Segmentation hand_segmentation(const std::vector<Section>& sections,
                               const std::vector<PointMass>& point_masses, const HandCoupling& hand,
                               const ModeOptions& options);

}  // namespace sweetspot::beam_detail
