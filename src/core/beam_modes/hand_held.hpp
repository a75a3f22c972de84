#pragma once

// The damped modes of the beam held in the hand: the dense state-space
// solve, the coarse modal one, and the coarse-to-fine refinement on the
// banded pencil. Internal to the beam-mode solvers.

#include <optional>
#include <string>
#include <vector>

#include "core/beam_modes/banded_pencil.hpp"

namespace sweetspot::beam_detail {

struct DampedSpectrum {
  std::vector<DampedPair> pairs;  // Im s > 0, ascending Im s
  int overdamped = 0;             // real roots (not reported)
};

// A root is real (overdamped) when |Im s| <= kRealRootTol |s|.
inline constexpr double kRealRootTol = 1e-9;

// The oscillatory roots among every eigenvalue of a state matrix: the
// `drift` roots nearest 0 (drift_roots: the structure says how many) are
// set aside, then the roots with Im s > 0 are returned ascending in Im s, at
// most `wanted`, and the real ones counted. No cut-off in |s|: the low modes
// of a fine mesh are many orders below its highest frequency, and a cut-off
// relative to that (as once used) threw the fundamental away. The one place
// both the dense and the coarse modal solve choose their modes.
struct OscillatoryRoots {
  std::vector<int> order;  // indices into the eigenvalues
  int overdamped = 0;      // real roots
};
OscillatoryRoots select_oscillatory(const VectorXcd& eigenvalues, int drift, int wanted);

// The lowest `wanted` oscillatory modes from every eigenvalue of the dense
// state matrix: O(n^3), the reference.
DampedSpectrum dense_damped_spectrum(const Mesh& mesh, const Assembled& a, const HandCoupling& hand,
                                     int wanted);

// The lowest `wanted` oscillatory modes in the basis of the lowest `basis`
// undamped flexible modes (grip springs included): a 2 basis x 2 basis state
// matrix. Estimates only (modal truncation), refined on the full mesh.
DampedSpectrum modal_damped_spectrum(const Mesh& mesh, const Assembled& a, const HandCoupling& hand,
                                     int wanted, int basis);

// The reported mode of a damped eigenpair: the complex shape turned to be as
// real as possible, its real part mass-normalised.
Mode damped_mode(const Mesh& mesh, const Assembled& a, Complex s, VectorXcd q);

// The hand's share of the kinetic energy in the mode damped_mode() reports
// for the eigenvector q (Mode::hand_energy_fraction), without its shape.
double damped_hand_share(const Assembled& a, const VectorXcd& q);

// The lowest options.modes modes on `mesh` located on a coarse mesh and
// refined; empty with a reason in `why` when a mode cannot be matched. With
// `beam_fundamental_only`, only the first of them whose coarse estimate the
// hand carries less than kHandModeEnergyShare of is refined (all are when a
// coarse share lies within kShareMargin of that line): the pair is the one
// the full refinement gives, bit for bit.
std::optional<DampedSpectrum> refined_damped_spectrum(const Mesh& mesh, const Assembled& a,
                                                      const HandCoupling& hand,
                                                      const ModeOptions& options,
                                                      const Mesh& coarse, std::string* why,
                                                      bool beam_fundamental_only = false);

// sweetspot::hand_held_beam_fundamental() of a beam whose free fundamental
// (Euler-Bernoulli, exact) is known, `free_omega1_rad_s`: the mesh is sized
// from it (element_counts) instead of a coarse estimate, the same mesh.
ModalResult hand_held_beam_fundamental(const std::vector<Section>& sections,
                                       const std::vector<PointMass>& point_masses,
                                       const HandCoupling& hand, const ModeOptions& options,
                                       double free_omega1_rad_s);

}  // namespace sweetspot::beam_detail
