#include "core/beam_modes/transfer_matrix.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/beam_modes/free_fe.hpp"
#include "core/beam_modes/shapes.hpp"
#include "core/check.hpp"
#include "sweetspot/roots.hpp"

namespace sweetspot::beam_detail {
namespace {

using detail::format_number;

// The exact solver refines each root to this relative tolerance (in beta L).
constexpr double kExactRootRelTol = 1e-13;
// Bracketing step in total phase lambda = sum beta_i l_i. Roots of a uniform
// free-free beam are pi apart; 1/16 of that leaves room for non-uniform beams.
constexpr double kScanStep = kPi / 16.0;
// Start of the scan. The frequency function is normalised by omega^4, so the
// double rigid-body root at omega = 0 is divided out and any small start works.
constexpr double kScanStart = 1e-3;

// Transfer matrices for the dimensionless state (w, theta L, M L^2/EI0,
// V L^3/EI0), with M = EI w'' and V = EI w''' (V jumps by m omega^2 w at a
// point mass). In a uniform segment of length l, EI = r EI0, P = mu omega^2
// L^4 / EI, a = l/L, z = P^(1/4) a:
//   [ S          a T1        a^2 U2/r   a^3 V3/r ]
//   [ P a^3 V3   S           a T1/r     a^2 U2/r ]
//   [ r P a^2 U2 r P a^3 V3  S          a T1     ]
//   [ r P a T1   r P a^2 U2  P a^3 V3   S        ]
// with S, T1, U2, V3 from krylov(z); every entry is finite at omega = 0.
class TransferModel {
 public:
  explicit TransferModel(const Segmentation& seg) : seg_(seg) {
    L_ = seg.length_m;
    for (const Segment& s : seg.segments) EI0_ = std::max(EI0_, s.EI_N_m2);
    double mass = seg.tip_mass_kg;
    for (const Segment& s : seg.segments) {
      mass += s.mu_kg_m * s.length_m + s.mass_at_start_kg;
      phase_per_root_omega_ += phase_weight(s.mu_kg_m, s.EI_N_m2, s.length_m);
    }
    mu_bar_ = mass / L_;
    if (phase_per_root_omega_ == 0.0) phase_per_root_omega_ = phase_weight(mu_bar_, EI0_, L_);
    // What matrix() needs of each segment that does not depend on omega.
    for (const Segment& s : seg.segments) {
      Fixed f;
      f.r = s.EI_N_m2 / EI0_;
      f.a = s.length_m / L_;
      f.a2 = f.a * f.a;
      f.a3 = f.a2 * f.a;
      fixed_.push_back(f);
    }
  }

  // omega [rad/s] for a total phase lambda = sum beta_i l_i.
  double omega(double lambda) const {
    const double r = lambda / phase_per_root_omega_;
    return r * r;
  }

  // The two free-butt states (unit displacement, unit slope) carried through
  // every segment and point mass to the tip.
  std::pair<std::array<double, 4>, std::array<double, 4>> tip_states(double omega) const {
    using State = std::array<double, 4>;
    State s1{1, 0, 0, 0}, s2{0, 1, 0, 0};
    const double w2 = omega * omega;
    for (std::size_t i = 0; i < seg_.segments.size(); ++i) {
      const Segment& s = seg_.segments[i];
      const double jump = s.mass_at_start_kg * w2 * L_ * L_ * L_ / EI0_;
      s1[3] += jump * s1[0];
      s2[3] += jump * s2[0];
      double m[4][4];
      matrix(s, fixed_[i], w2, m);
      s1 = apply(m, s1);
      s2 = apply(m, s2);
    }
    const double jump = seg_.tip_mass_kg * w2 * L_ * L_ * L_ / EI0_;
    s1[3] += jump * s1[0];
    s2[3] += jump * s2[0];
    return {s1, s2};
  }

  // Frequency function: det of the tip (moment, shear) block over the two
  // free-butt states, divided by (mu_bar omega^2 L^4 / EI0)^2 so that the
  // double root at omega = 0 is removed.
  double frequency_function(double omega) const {
    const auto [s1, s2] = tip_states(omega);
    const double det = s1[2] * s2[3] - s2[2] * s1[3];
    const double w2 = omega * omega;
    const double scale = mu_bar_ * w2 * L_ * L_ * L_ * L_ / EI0_;
    return det / (scale * scale);
  }

  // The exact shape at a root omega of the frequency function.
  std::vector<ShapePiece> shape(double omega) const {
    using State = std::array<double, 4>;
    const double w2 = omega * omega;
    // Null vector of the tip block from the row of larger norm.
    const auto [s1, s2] = tip_states(omega);
    double c1, c2;
    if (std::hypot(s1[2], s2[2]) >= std::hypot(s1[3], s2[3])) {
      c1 = s2[2];
      c2 = -s1[2];
    } else {
      c1 = s2[3];
      c2 = -s1[3];
    }
    State s{c1, c2, 0, 0};
    std::vector<ShapePiece> pieces;
    for (std::size_t i = 0; i < seg_.segments.size(); ++i) {
      const Segment& seg = seg_.segments[i];
      s[3] += seg.mass_at_start_kg * w2 * L_ * L_ * L_ / EI0_ * s[0];
      const double r = seg.EI_N_m2 / EI0_;
      ShapePiece p;
      p.start_m = seg.start_m;
      p.end_m = seg.start_m + seg.length_m;
      p.wavenumber_per_m = std::pow(seg.mu_kg_m * w2 / seg.EI_N_m2, 0.25);
      p.derivatives = {s[0], s[1] / L_, s[2] / (r * L_ * L_), s[3] / (r * L_ * L_ * L_)};
      pieces.push_back(p);
      double m[4][4];
      matrix(seg, fixed_[i], w2, m);
      s = apply(m, s);
    }
    return pieces;
  }

 private:
  // The segment's numbers that do not depend on omega.
  struct Fixed {
    double r = 1.0, a = 0.0, a2 = 0.0, a3 = 0.0;
  };

  void matrix(const Segment& s, const Fixed& f, double w2, double m[4][4]) const {
    const double r = f.r;
    const double P = s.mu_kg_m * w2 * L_ * L_ * L_ * L_ / s.EI_N_m2;
    const double a = f.a;
    const double a2 = f.a2, a3 = f.a3;
    const Krylov k = krylov(std::sqrt(std::sqrt(P)) * a);
    const double T = a * k.t1, U = a2 * k.u2, V = a3 * k.v3;
    if (r == 1.0) {
      // The stiffest segment (every one on a frame of one EI): the entries
      // below without their factors of 1, the same numbers.
      m[0][0] = k.s;
      m[0][1] = T;
      m[0][2] = U;
      m[0][3] = V;
      m[1][0] = P * V;
      m[1][1] = k.s;
      m[1][2] = T;
      m[1][3] = U;
      m[2][0] = P * U;
      m[2][1] = P * V;
      m[2][2] = k.s;
      m[2][3] = T;
      m[3][0] = P * T;
      m[3][1] = P * U;
      m[3][2] = P * V;
      m[3][3] = k.s;
      return;
    }
    m[0][0] = k.s;
    m[0][1] = T;
    m[0][2] = U / r;
    m[0][3] = V / r;
    m[1][0] = P * V;
    m[1][1] = k.s;
    m[1][2] = T / r;
    m[1][3] = U / r;
    m[2][0] = r * P * U;
    m[2][1] = r * P * V;
    m[2][2] = k.s;
    m[2][3] = T;
    m[3][0] = r * P * T;
    m[3][1] = r * P * U;
    m[3][2] = P * V;
    m[3][3] = k.s;
  }

  static std::array<double, 4> apply(const double m[4][4], const std::array<double, 4>& s) {
    std::array<double, 4> out{};
    for (int i = 0; i < 4; ++i) {
      out[i] = m[i][0] * s[0] + m[i][1] * s[1] + m[i][2] * s[2] + m[i][3] * s[3];
    }
    return out;
  }

  const Segmentation& seg_;
  std::vector<Fixed> fixed_;
  double L_ = 0.0;
  double EI0_ = 0.0;
  double mu_bar_ = 0.0;
  double phase_per_root_omega_ = 0.0;
};

// Roots of a free-free beam are about pi apart in total phase (pi / 16 per
// scan step); consecutive roots found further apart than this may hide a
// skipped pair, which the count below then checks.
constexpr double kSuspectRootGap = 1.5 * kPi;

}  // namespace

ModalResult exact_free_modes(const Segmentation& seg, const ModeOptions& options) {
  ModalResult result;
  result.method = ModeOptions::Method::kExact;
  result.theory = ModeOptions::Theory::kEulerBernoulli;
  const TransferModel model(seg);
  auto f = [&](double lambda) { return model.frequency_function(model.omega(lambda)); };

  const double lambda_max = kPi * (2.0 * options.modes + 6.0);
  double a = kScanStart;
  double fa = f(a);
  double last_lambda = 0.0;
  bool wide_gap = false;
  while (static_cast<int>(result.modes.size()) < options.modes && a < lambda_max) {
    const double b = a + kScanStep;
    const double fb = f(b);
    if (fa == 0.0 || (fa < 0.0) != (fb < 0.0)) {
      const double lambda = brent_root(f, a, b, fa, fb, kExactRootRelTol * b);
      if (!result.modes.empty() && lambda - last_lambda > kSuspectRootGap) wide_gap = true;
      last_lambda = lambda;
      const double omega = model.omega(lambda);
      Mode mode;
      mode.frequency_Hz = mode.undamped_frequency_Hz = omega / (2.0 * kPi);
      mode.shape = model.shape(omega);
      normalise_and_find_nodes(mode);
      result.modes.push_back(std::move(mode));
    }
    a = b;
    fa = fb;
  }
  if (wide_gap) {
    // Two roots inside one scan step change no sign and are skipped. Finite
    // elements never count fewer modes below a frequency than there are
    // (their frequencies are upper bounds), so more of them below the highest
    // root found means roots were missed: the finite elements answer instead.
    const RootCount count = missed_roots(seg, result, options.modes, options.rel_tol);
    if (count.missed > 0) {
      ModeOptions fe_options = options;
      fe_options.method = ModeOptions::Method::kFiniteElement;
      fe_options.elements = count.elements;
      ModalResult fe = fe_free_modes(seg, fe_options);
      fe.message = "the exact scan missed " + std::to_string(count.missed) +
                   " nearly repeated root(s) below " +
                   format_number(result.modes.back().frequency_Hz) + " Hz; " + fe.message;
      return fe;
    }
  }
  if (static_cast<int>(result.modes.size()) < options.modes) {
    result.complete = false;
    result.message = "found " + std::to_string(result.modes.size()) + " of " +
                     std::to_string(options.modes) +
                     " modes below beta L = " + format_number(lambda_max);
  } else {
    result.message = "exact transfer-matrix solution";
  }
  return result;
}

}  // namespace sweetspot::beam_detail
