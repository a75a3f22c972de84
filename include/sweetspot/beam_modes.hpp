#pragma once

// Transverse bending modes of a slender implement treated as a flexible beam:
// free (suspended on strings) or held in one hand. Positions are measured from
// the butt (x = 0) to the tip (x = L); sections are listed butt to tip.
//
// Free vibration of an Euler-Bernoulli beam, EI w'''' = mu omega^2 w, with
// piecewise-constant EI and mass per length mu = m_i / L_i, plus point masses.
// Two independent solvers:
//  * kExact: transfer matrices of the closed-form solution in each uniform
//    segment; the frequency equation is the determinant that makes moment and
//    shear vanish at the tip for a free butt. Euler-Bernoulli only.
//  * kFiniteElement: two-node cubic elements (Hermite for Euler-Bernoulli, the
//    shear-deformable "interdependent interpolation" element for Timoshenko),
//    consistent mass, with the two rigid-body modes deflated exactly.
// The hand-held beam (Cross 2004, Sec. IV) is finite-element only.
//
// Adjacent sections of equal mass per length and EI are one uniform stretch.
// Elements follow the sizing, not the sections: a run of sections each
// shorter than an element shares elements, which integrate their mass and
// point masses exactly and take their compliance in series (the exact static
// stiffness of piecewise EI), so 10 000 sections solve on a few dozen
// elements. There the error follows how much the properties vary inside an
// element rather than (beta h)^4 (see ModeOptions::rel_tol).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "sweetspot/implement.hpp"
#include "sweetspot/mass_properties.hpp"

namespace sweetspot {

// Limits of the solvers, published once for every caller.
// Flexible modes any solver reports (ModeOptions::modes, ResponseOptions::modes).
inline constexpr int kMaxModes = 50;
// Modes the exact solver gives: cosh(beta L) grows, and beyond the 6th mode
// the unscaled frequency determinant loses more than ~1e-8 of relative accuracy.
inline constexpr int kMaxExactModes = 6;
// Finite elements of an explicit mesh (ModeOptions::elements).
inline constexpr int kMaxElements = 4000;
// Finite elements a mesh chosen from rel_tol (ModeOptions::elements == 0) may
// have. The free beam's refinement assembles dense (2N)^2 matrices: at 1000
// elements ~100 MB (an estimate from the matrix size; the solve's time there
// has not been measured); a design whose sections' stiffness
// contrast asks for more (9494 elements, GBs and minutes) is refused
// (ModelRefusal naming "implement/sections"), not solved.
inline constexpr int kMaxAutoElements = 1000;
// The finite elements' relative tolerance on f1 (ModeOptions::rel_tol):
// below ~1e-8 the round-off of the assembled stiffness (cond ~ (L/h)^4) dominates.
inline constexpr double kMinRelTol = 1e-8;
inline constexpr double kMaxRelTol = 0.1;

// Shear coefficient kappa of a solid rectangular cross-section.
inline constexpr double kRectangularShearCoefficient = 5.0 / 6.0;

// Timoshenko data of one section: shear stiffness kappa G A and the radius of
// gyration r = sqrt(I / A) of the cross-section about the bending axis (rotary
// inertia per length is mu r^2).
struct TimoshenkoSection {
  double shear_stiffness_N = 0.0;     // kappa G A [N], > 0
  double radius_of_gyration_m = 0.0;  // r [m], >= 0
};

// A solid rectangle of `width_m` bending across its `thickness_m`:
// kappa = 5/6, A = width * thickness, r = thickness / sqrt(12).
// Throws std::invalid_argument for a non-positive argument.
TimoshenkoSection rectangular_timoshenko_section(double shear_modulus_Pa, double width_m,
                                                 double thickness_m);

// The cross-section a Timoshenko beam is made of, of Poisson's ratio
// `poisson_ratio` in [0, 0.5]:
//   rectangle      solid, `width_m` across, bending across its `thickness_m`;
//   circle         solid, of `diameter_m`;
//   hollow_circle  a tube of that outer diameter and `wall_m` (0 < wall <=
//                  diameter / 2; a wall of half the diameter is the circle);
//   ellipse        solid, of axes `width_m` across and `thickness_m` in the
//                  direction of bending;
//   box            a hollow rectangle of those outer sizes and one `wall_m`
//                  (0 < wall < min(width, thickness) / 2);
//   profile        no sizes of its own: each section of an implement given by
//                  its profile is the circle or tube of that section's
//                  RoundSlice (implement.hpp), so the section changes along a
//                  tapered bat (flexible_frame() reads it; the functions below
//                  refuse it, having no sizes).
struct CrossSection {
  enum class Shape { kRectangle, kCircle, kHollowCircle, kEllipse, kBox, kProfile };
  Shape shape = Shape::kRectangle;
  double width_m = 0.0;      // rectangle, ellipse, box: across the direction of bending
  double thickness_m = 0.0;  // rectangle, ellipse, box: in the direction of bending
  double diameter_m = 0.0;   // circle and tube: the outer diameter
  double wall_m = 0.0;       // tube and box
  double poisson_ratio = 0.0;
};

// A rectangle, an ellipse and a box are sized by a width and a thickness,
// a circle and a tube by an outer diameter; a tube and a box have a wall; a
// profile has no size of its own.
constexpr bool sized_by_width(CrossSection::Shape shape) {
  return shape == CrossSection::Shape::kRectangle || shape == CrossSection::Shape::kEllipse ||
         shape == CrossSection::Shape::kBox;
}
constexpr bool sized_by_diameter(CrossSection::Shape shape) {
  return shape == CrossSection::Shape::kCircle || shape == CrossSection::Shape::kHollowCircle;
}
constexpr bool has_wall(CrossSection::Shape shape) {
  return shape == CrossSection::Shape::kHollowCircle || shape == CrossSection::Shape::kBox;
}

// The shear coefficient kappa of a cross-section, Cowper (1966), "The shear
// coefficient in Timoshenko's beam theory", J. Appl. Mech. 33, 335, Table 1:
//   rectangle    10 (1 + nu) / (12 + 11 nu)            (5/6 at nu = 0)
//   circle        6 (1 + nu) / (7 + 6 nu)              (6/7 at nu = 0)
//   tube, m = r_inner / r_outer:
//     6 (1 + nu) (1 + m^2)^2 / ((7 + 6 nu) (1 + m^2)^2 + (20 + 12 nu) m^2),
//   the circle at m = 0 and the thin tube's 2 (1 + nu) / (4 + 3 nu) as m -> 1;
//   ellipse, m = thickness / width (the semi-axis in the direction of bending
//   over the one across):
//     12 (1 + nu) m^2 (3 m^2 + 1) / ((40 + 37 nu) m^4 + (16 + 10 nu) m^2 + nu),
//   the circle at m = 1; at nu = 0, 0.9 for a blade on edge (m -> inf) and 0.75
//   for a flat one (m -> 0), the closed forms of the shear flow's energy;
//   box, Cowper's thin-walled box on the wall's centre line, b = width - wall
//   across and h = thickness - wall deep, m = n = b / h (Cowper's
//   m = b t_flange / (h t_web) with one wall):
//     10 (1 + nu) (1 + 3 m)^2 / ((12 + 72 m + 150 m^2 + 90 m^3)
//       + nu (11 + 66 m + 135 m^2 + 90 m^3) + 10 n^2 ((3 + nu) m + 3 m^2)),
//   20 (1 + nu) / (48 + 39 nu) for a square tube. It is the thin wall's
//   expression: exact at nu = 0 as the wall thins (the shear flow's energy),
//   an estimate for a thick one (docs/model.md).
// Throws std::invalid_argument for a section no shape above describes.
double shear_coefficient(const CrossSection& section);

// The circle (a wall of 0) or the tube of a profile's slice, of Poisson's
// ratio `poisson_ratio`: what CrossSection::Shape::kProfile makes each section.
CrossSection round_cross_section(const RoundSlice& slice, double poisson_ratio);

// kappa G A and r = sqrt(I / A) of the section: A = w t and r = t / sqrt(12)
// for the rectangle, A = pi (R^2 - r_i^2) and r = sqrt(R^2 + r_i^2) / 2 for
// the circle (r_i = 0) and the tube, A = pi w t / 4 and r = t / 4 for the
// ellipse, and the box's outer rectangle less its bore for A and I.
// Throws std::invalid_argument as above.
TimoshenkoSection timoshenko_section(double shear_modulus_Pa, const CrossSection& section);

struct ModeOptions {
  enum class Method { kExact, kFiniteElement };
  enum class Theory { kEulerBernoulli, kTimoshenko };

  int modes = 3;          // flexible modes wanted (rigid-body modes never count), in [1, kMaxModes]
                          // ([1, kMaxExactModes] for kExact)
  double rel_tol = 1e-6;  // FE: target relative error of f1 when `elements` == 0, in [kMinRelTol,
                          // kMaxRelTol] (round-off of the assembled stiffness floors FE near 1e-8).
                          // Sections far shorter than an element and unlike each other
                          // are resolved only on average: a few times rel_tol.
                          // The exact solver always refines roots to ~1e-12.
  Method method = Method::kExact;
  Theory theory = Theory::kEulerBernoulli;  // kTimoshenko needs kFiniteElement
  int elements = 0;       // FE: total element count in [0, kMaxElements]; 0 = choose from rel_tol
  int shape_samples = 0;  // points in ModalResult's shape table (0 = none, else >= 2)
  // One entry per section when theory == kTimoshenko, ignored otherwise.
  std::vector<TimoshenkoSection> timoshenko;

  // hand_held_modes only: how the damped eigenproblem (s^2 M + s C + K) q = 0
  // is solved on the mesh. Both give the same modes to round-off.
  //  * kRefined: a dense state-space solve on a coarse mesh (~2.6 elements per
  //    requested mode; runs of short sections share its elements when one
  //    element each would be more than twice that) finds and orders the
  //    modes; each is then converged on
  //    the full mesh by Rayleigh-functional iteration with a banded
  //    factorisation of s^2 M + s C + K, O(n) per step. Falls back to
  //    kDenseStateSpace (saying so in ModalResult::message) when a coarse mode
  //    cannot be matched unambiguously.
  //  * kDenseStateSpace: every eigenvalue of the 2n x 2n state matrix, O(n^3).
  enum class DampedSolver { kRefined, kDenseStateSpace };
  DampedSolver damped_solver = DampedSolver::kRefined;

  // Empty if the options are consistent, otherwise the first problem found,
  // naming the field and its value.
  std::string validate() const;
};

// One piece of a mode shape on [start_m, end_m]. With xi = x - start_m and
// z = wavenumber_per_m * xi:
//   w(x) = w S(z) + w' xi T(z)/z + w'' xi^2 U(z)/z^2 + w''' xi^3 V(z)/z^3,
// where S, T, U, V = (cosh z +- cos z)/2, (sinh z +- sin z)/2 are Krylov's
// functions: the exact solution of w'''' = beta^4 w from its value and
// derivatives at the start. With wavenumber 0 it is the cubic Taylor polynomial
// (finite elements).
struct ShapePiece {
  double start_m = 0.0;
  double end_m = 0.0;
  double wavenumber_per_m = 0.0;        // beta >= 0
  std::array<double, 4> derivatives{};  // w, w', w'', w''' at start_m
};

struct Mode {
  // Damped natural frequency Im(s)/2pi [Hz]; equals the undamped one when free.
  double frequency_Hz = 0.0;
  // |s|/2pi [Hz].
  double undamped_frequency_Hz = 0.0;
  // -Re(s)/|s|, 0 for the free beam.
  double damping_ratio = 0.0;
  // Interior zeros of w(x), butt to tip [m], located on the analytic shape.
  std::vector<double> nodes_from_butt_m;
  // w(x) butt to tip, normalised to max |w| = 1 (sampled) with w(L) > 0.
  // For the hand-held beam: the complex shape turned to be as real as possible
  // (q_b^T M_b q_b real and positive over the beam's DOFs).
  std::vector<ShapePiece> shape;
  // Hand-held only: hand translation in the same normalisation.
  double hand_displacement = 0.0;  // [same units as w]
  // Hand-held only: |Im| / |Re| of the turned complex shape in the beam's
  // mass norm (0 = real mode).
  double complexity = 0.0;
  // Hand-held only: share of the mode's kinetic energy in the hand, in [0, 1]
  // (near 1 for the hand rocking on the grip, small for bending modes).
  double hand_energy_fraction = 0.0;
  // FE only: the eigenvector, DOFs (w_0, theta_0, w_1, theta_1, ...) at
  // BeamMatrices::node_positions_m, then (hand translation, hand rotation) when
  // hand held; mass-normalised (phi^T M phi = 1). Empty for the exact solver.
  std::vector<double> fe_dofs;
};

// Displacement of `mode` at `x_m` (same normalisation as Mode::shape).
// Throws std::invalid_argument if x_m is outside the beam.
double mode_shape_at(const Mode& mode, double x_m);

struct ModalResult {
  std::vector<Mode> modes;  // ascending frequency; fewer than asked if !complete
  ModeOptions::Method method = ModeOptions::Method::kExact;
  ModeOptions::Theory theory = ModeOptions::Theory::kEulerBernoulli;
  int elements_used = 0;  // FE only
  bool complete = true;   // false: fewer modes than asked, see message
  std::string message;
  // Plotting table (ModeOptions::shape_samples points, butt to tip):
  // shape_w[k][i] = w of modes[k] at shape_x_m[i].
  std::vector<double> shape_x_m;
  std::vector<std::vector<double>> shape_w;
};

// Free-free bending modes of piecewise-uniform sections plus point masses.
// The exact solver gives up to kMaxExactModes (cosh(beta L) conditioning) and is
// accurate to ~1e-12; FE to about options.rel_tol on f1, higher modes
// (beta_k / beta_1)^4 times worse. Rigid-body modes are never reported.
// Every section needs EI > 0 and length > 0, mass >= 0 (> 0 for FE); point
// masses >= 0 within [0, L]. Throws std::invalid_argument naming the offending
// argument (e.g. "sections[1].EI_N_m2") and its value, or for invalid options.
ModalResult free_modes(const std::vector<Section>& sections,
                       const std::vector<PointMass>& point_masses, const ModeOptions& options = {});

// A support of the beam, as the laboratory holds an implement: clamped over
// a stretch (a vice on the handle; a head clamped for the string-bed drop
// test), w = w' = 0 there, or pinned at a point (a bat on the standards'
// pivot 6 in from the knob), w = 0 there and free to turn.
struct BeamSupport {
  enum class Kind { kClamped, kPinned };
  Kind kind = Kind::kClamped;
  double from_m = 0.0;  // from the butt: the clamp's start, or the pivot
  double to_m = 0.0;    // the clamp's end (>= from_m; a point clamp when equal); ignored pinned
};

// Modes of the beam on its support by finite elements (options.method must be
// kFiniteElement): the DOFs the support fixes removed and, pinned, the rigid
// turn about the pivot deflated, so every mode reported is flexible. Nodes
// are the interior zeros of w outside a clamp (a pivot is one), none on a
// stretch beyond the clamp that moves less than a thousandth of the mode's
// largest displacement (a stub behind a vice, still to round-off). Throws
// std::invalid_argument as free_modes(), or for a support off the beam or a
// clamp ending before it starts.
ModalResult supported_modes(const std::vector<Section>& sections,
                            const std::vector<PointMass>& point_masses, const BeamSupport& support,
                            const ModeOptions& options);

// The hand as a rigid body (Cross 2004 Sec. IV: "gripped firmly by one hand"),
// joined to the handle over [grip_start_m, grip_start_m + grip_length_m] by a
// distributed transverse spring k and dashpot c acting on the relative
// displacement w(x) - u_h - phi_h (x - x_c), x_c the grip centre. The hand
// translates (u_h) and rotates (phi_h); the arm is not modelled.
struct HandCoupling {
  double mass_kg = 0.5;         // M_h [kg], > 0 (Cross 2004 Sec. V uses 0.5 kg)
  double grip_start_m = 0.02;   // [m] from the butt, >= 0
  double grip_length_m = 0.10;  // [m], > 0; default centre 0.07 m as in Cross 2004 Sec. V
  double stiffness_N_m2 = 0.0;  // k [N/m per m of grip], >= 0
  double damping_N_s_m2 = 0.0;  // c [N s/m per m of grip], >= 0
  // Rotary inertia about the grip centre [kg m^2], > 0; default M_h Lg^2 / 12
  // (the hand's mass spread evenly along the grip).
  std::optional<double> rotary_inertia_kg_m2;
};

// Grip stiffness and damping calibrated on Cross (2004)'s beam (0.72 m,
// 0.328 kg, uniform, EI from the free f1 = 193 Hz) held by a 0.5 kg hand over
// 0.02-0.12 m (centre 0.07 m, Sec. V). One measured number, the hand-held
// f1 = 171 Hz (Sec. III), fixes one parameter: k is set to a typical order for
// hand tissue (2e4 N/m in total over the 10 cm grip) and c is solved so the
// damped fundamental is 171 Hz. The result is "strongly damped" as observed:
// damping ratio 0.10, free-end node 16.9 cm from the tip (free: 16.1 cm), the
// handle-end node moved under the hand (10.8 cm from the butt).
inline constexpr double kCalibratedGripStiffness_N_m2 = 2.0e5;
inline constexpr double kCalibratedGripDamping_N_s_m2 = 1.30e3;

// The calibrated hand: 0.5 kg, grip 0.02-0.12 m, k and c as above.
HandCoupling calibrated_hand();

// How tightly a player holds the handle: the paper's hand above, or one of the
// three grips Savage measured on two strung racquets held by a player and hit
// by a ball (N. J. Savage, "Vibration absorption in the tennis grip and the
// effects on racquet dynamics", PhD thesis, RMIT University, 2006, Appendix 4,
// Tables 17-18: the fundamental free 183.75 / 162.5 Hz; held light 170.25 /
// 149, medium 165 / 146.25, tight 162.25 / 142.5 Hz; the half-power
// bandwidth over the peak, 2 zeta, light 0.125 / 0.121, medium 0.127 / 0.130,
// tight 0.150 / 0.156; five impacts each). Each grip's k and c are the least
// squares fit (each residual over its published standard deviation) of
// hand_held_modes() on two racquets of a typical strung racquet's specs (27
// in, 305 g, balance 32.5 cm, swingweight 320 kg cm^2; the thesis's own
// masses were not reached) with the measured free fundamentals, a 0.5 kg hand
// over 0.02-0.12 m: every fitted frequency and 2 zeta within one standard
// deviation (docs/model.md, "The grip"). Tighter is stiffer and more damped.
enum class GripTightness { kPaper, kLight, kMedium, kTight };
struct GripCoefficients {
  double stiffness_N_m2 = 0.0;  // k [N/m per m of grip]
  double damping_N_s_m2 = 0.0;  // c [N s/m per m of grip]
};
inline constexpr GripCoefficients kLightGrip{5.4e4, 3.05e3};
inline constexpr GripCoefficients kMediumGrip{5.6e5, 4.8e3};
inline constexpr GripCoefficients kTightGrip{2.1e6, 5.5e3};
constexpr GripCoefficients grip_coefficients(GripTightness grip) {
  switch (grip) {
    case GripTightness::kLight:
      return kLightGrip;
    case GripTightness::kMedium:
      return kMediumGrip;
    case GripTightness::kTight:
      return kTightGrip;
    case GripTightness::kPaper:
      break;
  }
  return {kCalibratedGripStiffness_N_m2, kCalibratedGripDamping_N_s_m2};
}

// Damped modes of the beam held in the hand: the first-order (state-space)
// complex eigenproblem of M q'' + C q' + K q = 0 with the rigid-body motion
// of beam plus hand deflated. Only oscillatory modes (Im s > 0) are reported,
// ascending in damped frequency; they include the hand rocking on the grip
// (Mode::hand_energy_fraction near 1), so the beam's fundamental is the first
// mode with a small hand share. Requires options.method == kFiniteElement.
// Throws std::invalid_argument as free_modes(), or for a grip outside the beam
// or a negative k or c.
ModalResult hand_held_modes(const std::vector<Section>& sections,
                            const std::vector<PointMass>& point_masses, const HandCoupling& hand,
                            const ModeOptions& options);

// A hand-held mode whose kinetic energy the hand carries at least this share
// of is the hand rocking on the grip; below it, a bending mode of the beam.
inline constexpr double kHandModeEnergyShare = 0.5;

// The beam's hand-held fundamental alone: the first of the lowest
// options.modes modes of hand_held_modes() in which the hand carries less than
// kHandModeEnergyShare of the kinetic energy, in result.modes (empty, with
// complete = false, when none of them is a beam mode). Faster: the coarse mesh
// tells which mode that is, so only it is refined and shaped. It is the mode
// hand_held_modes() reports, bit for bit, whenever that refines every mode;
// where another mode's refinement fails and hand_held_modes() falls back to the
// dense solve, the two agree to round-off. Throws as hand_held_modes().
ModalResult hand_held_beam_fundamental(const std::vector<Section>& sections,
                                       const std::vector<PointMass>& point_masses,
                                       const HandCoupling& hand, const ModeOptions& options);

// Copies of `sections` with every EI multiplied by one factor so that the free
// fundamental equals `f1_Hz`. For Euler-Bernoulli f is proportional to sqrt(EI),
// so this is closed form after one solve; for Timoshenko the factor is iterated
// (shear stiffness is held fixed). Every section must already have EI > 0.
// Throws std::invalid_argument for f1_Hz <= 0 or bad sections.
std::vector<Section> scale_EI_to_fundamental(const std::vector<Section>& sections,
                                             const std::vector<PointMass>& point_masses,
                                             double f1_Hz, const ModeOptions& options = {});

// The single EI [N m^2] which, given to every section, makes the free
// Euler-Bernoulli fundamental `f1_Hz` (any EI already in `sections` is ignored).
double uniform_EI_for_fundamental(const std::vector<Section>& sections,
                                  const std::vector<PointMass>& point_masses, double f1_Hz);

// Assembled finite-element matrices of the free beam (and hand, when given),
// dense, row-major, size x size. DOFs: (w_i, theta_i) at each node, then
// (u_h, phi_h) for the hand. The mesh is the one free_modes / hand_held_modes
// use for the same arguments.
struct BeamMatrices {
  std::vector<double> node_positions_m;
  int size = 0;
  std::vector<double> stiffness;  // K [N/m, N, N m]
  std::vector<double> mass;       // M [kg, kg m, kg m^2]
  std::vector<double> damping;    // C [N s/m, ...]; zero without a hand
};
BeamMatrices assemble_beam_matrices(const std::vector<Section>& sections,
                                    const std::vector<PointMass>& point_masses,
                                    const ModeOptions& options,
                                    const std::optional<HandCoupling>& hand = std::nullopt);

}  // namespace sweetspot
