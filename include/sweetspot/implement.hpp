#pragma once

#include <optional>
#include <vector>

#include "sweetspot/mass_properties.hpp"

namespace sweetspot {

// The model's range: larger values are refused rather than left to overflow
// (a bat is about 1 m and 1 kg; these leave every real implement far inside).
inline constexpr double kMaxLength_m = 100.0;
inline constexpr double kMaxMass_kg = 1e6;
// Bending stiffness: a solid steel bar 30 cm thick has about 1.4e8 N m^2.
inline constexpr double kMaxEI_N_m2 = 1e12;
// A profile's material: denser than osmium (22 600 kg/m^3) or stiffer than
// diamond (about 1.2e12 Pa) is refused.
inline constexpr double kMaxDensity_kg_m3 = 3e4;
inline constexpr double kMaxModulus_Pa = 2e12;

// A uniform slice of an implement. Sections are listed butt to tip.
struct Section {
  double length_m = 0.0;          // [m], > 0
  double mass_kg = 0.0;           // [kg], >= 0
  std::optional<double> EI_N_m2;  // bending stiffness [N m^2], > 0; only the modes need it
};

// The round cross-section of a slice cut from a profile (profile_sections()):
// its outer diameter at the slice's middle and its wall, 0 for a solid slice.
// Timoshenko's terms can then come from each slice's own section
// (CrossSection::Shape::kProfile).
struct RoundSlice {
  double diameter_m = 0.0;  // [m], > 0
  double wall_m = 0.0;      // [m], 0 (solid) or in (0, diameter / 2]
};

// Measured industry specifications of a frame: they fix its rigid-body
// properties but not its mass distribution.
struct IndustrySpecs {
  double length_m = 0.0;             // [m], > 0
  double mass_kg = 0.0;              // [kg], > 0
  double balance_from_butt_m = 0.0;  // [m], in (0, L)
  double swingweight_kg_m2 = 0.0;    // [kg m^2] about the axis 10 cm from the butt
};

// A station of a round implement's profile: its diameter at a distance from the butt.
struct ProfileStation {
  double from_butt_m = 0.0;  // [m]
  double diameter_m = 0.0;   // [m], > 0
};

// A round implement of one material (a wood bat, an aluminium or composite
// bat, a tool handle, a rod) by its profile: the diameter at stations butt to
// tip, a straight taper between them, solid or a shell of one wall
// thickness. The first station is the butt (0), the last the tip.
struct RoundProfile {
  std::vector<ProfileStation> stations;  // at least two, from_butt_m strictly increasing
  double density_kg_m3 = 0.0;            // > 0 (ash and maple about 650-700, aluminium 2700)
  double youngs_modulus_Pa = 0.0;        // > 0, along the grain (wood about 1e10-1.5e10)
  // [m], 0 for a solid implement, else in (0, half the smallest diameter]: a
  // shell whose inner diameter is d - 2 wall (half the diameter is solid there).
  double wall_m = 0.0;
};

// The longest slice profile_sections() cuts (a longer implement than 2 m is
// cut into 400 slices).
inline constexpr double kProfileSlice_m = 0.005;

// The profile as sections: each interval between stations cut into equal
// slices no longer than kProfileSlice_m. A slice's mass is the density times
// its frustum's volume, pi h (d1^2 + d1 d2 + d2^2) / 12 (exact), less its
// bore's of the inner diameters d - 2 wall for a shell; its bending stiffness
// E pi (d^4 - d_i^4) / 64 at its middle diameter (Euler-Bernoulli, a circle or
// a tube). A uniform profile is exact; a taper's centre of mass, inertia and
// stiffness are right to O((h / L)^2). Throws FieldError naming
// "profile/N/...", "density_kg_m3", "youngs_modulus_Pa" or "wall_m". Given
// `slices`, it receives each section's round cross-section, one per section.
std::vector<Section> profile_sections(const RoundProfile& profile,
                                      std::vector<RoundSlice>* slices = nullptr);

// The profile's diameter at `from_butt_m`, straight between its stations
// (validated by profile_sections()); 0 outside the implement [m].
double profile_diameter_m(const RoundProfile& profile, double from_butt_m);

// An implement (racquet, bat, beam) from butt (x = 0) to tip (x = L): a frame
// plus point masses. Immutable; every factory validates its arguments and throws
// std::invalid_argument naming the argument and its value.
class Implement {
 public:
  // Piecewise-uniform sections, butt to tip; a uniform beam is one section.
  static Implement from_sections(std::vector<Section> sections,
                                 std::vector<PointMass> point_masses = {});

  // Cross (2004) Table I racquet: two halves of equal length, each uniform,
  // head mass M1 and handle mass M2 with M1/M2 = head_to_handle_mass_ratio (> 0).
  static Implement paper_racquet(double length_m, double mass_kg, double head_to_handle_mass_ratio,
                                 std::vector<PointMass> point_masses = {});

  // Measured specs. The swingweight must be physically possible for a body of
  // that length: M (B - 0.1)^2 < SW <= M (B - 0.1)^2 + M B (L - B).
  static Implement from_specs(const IndustrySpecs& specs, std::vector<PointMass> point_masses = {});

  // A solid round implement by its profile (profile_sections()): a wood bat
  // given by its diameters, its wood's density and modulus.
  static Implement from_profile(const RoundProfile& profile,
                                std::vector<PointMass> point_masses = {});

  double length_m() const { return length_m_; }

  // Rigid-body properties of the frame alone (no point masses).
  const MassProperties& frame_mass_properties() const { return frame_; }
  // Rigid-body properties of frame plus point masses.
  const MassProperties& mass_properties() const { return total_; }

  // The mass distribution, butt to tip; empty when built from specs.
  const std::vector<Section>& sections() const { return sections_; }
  const std::vector<PointMass>& point_masses() const { return point_masses_; }
  bool has_mass_distribution() const { return !sections_.empty(); }
  // Each section's round cross-section where the implement was given by its
  // profile (one per section), else empty.
  const std::vector<RoundSlice>& round_slices() const { return round_slices_; }
  // The profile it was given by, if it was.
  const std::optional<RoundProfile>& profile() const { return profile_; }

 private:
  Implement() = default;
  double length_m_ = 0.0;
  std::vector<Section> sections_;
  std::vector<RoundSlice> round_slices_;
  std::optional<RoundProfile> profile_;
  std::vector<PointMass> point_masses_;
  MassProperties frame_;
  MassProperties total_;
};

// Mass properties of piecewise-uniform sections laid end to end from the butt.
// Throws std::invalid_argument for an empty list, a length <= 0 or a mass < 0.
MassProperties section_mass_properties(const std::vector<Section>& sections);

}  // namespace sweetspot
