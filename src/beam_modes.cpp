#include "sweetspot/beam_modes.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "check.hpp"
#include "sweetspot/roots.hpp"

namespace sweetspot {
namespace {

using detail::format_number;

constexpr double kPi = 3.14159265358979323846;

// The exact solver refines each root to this relative tolerance (in beta L).
constexpr double kExactRootRelTol = 1e-13;
// Bracketing step in total phase lambda = sum beta_i l_i. Roots of a uniform
// free-free beam are pi apart; 1/16 of that leaves room for non-uniform beams.
constexpr double kScanStep = kPi / 16.0;
// Start of the scan. The frequency function is normalised by omega^4, so the
// double rigid-body root at omega = 0 is divided out and any small start works.
constexpr double kScanStart = 1e-3;
// cosh(beta L) grows; beyond the 6th mode the unscaled determinant loses more
// than ~1e-8 of relative accuracy, so the exact solver stops there.
constexpr int kMaxExactModes = 6;
constexpr int kMaxModes = 50;
constexpr int kMaxElements = 4000;
// Nodes of a mode shape are located to this absolute tolerance [m].
constexpr double kNodeTol_m = 1e-13;
// Relative f1 error of the consistent Hermite element sized to beta h:
// (beta h)^4 / kHermiteErrorConstant (fitted on the uniform free-free beam).
constexpr double kHermiteErrorConstant = 1440.0;
// Elements are sized for this fraction of the requested tolerance (safety).
constexpr double kToleranceSafety = 0.5;

[[noreturn]] void fail(const std::string& name, const std::string& expected, double value) {
  throw std::invalid_argument(name + ": must be " + expected + ", got " + format_number(value));
}


// ---------------------------------------------------------------- validation

double validated_length(const std::vector<Section>& sections, bool need_mass) {
  if (sections.empty()) throw std::invalid_argument("sections: must not be empty");
  double length = 0.0;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const Section& s = sections[i];
    detail::require_positive(detail::indexed("sections", i, "length_m"), s.length_m, "m");
    if (need_mass) {
      detail::require_positive(detail::indexed("sections", i, "mass_kg"), s.mass_kg, "kg");
    } else {
      detail::require_at_least(detail::indexed("sections", i, "mass_kg"), s.mass_kg, 0.0, "kg");
    }
    if (!s.EI_N_m2) {
      throw std::invalid_argument(detail::indexed("sections", i, "EI_N_m2") +
                                  ": must be given for the bending modes, got none");
    }
    detail::require_positive(detail::indexed("sections", i, "EI_N_m2"), *s.EI_N_m2, "N m^2");
    length += s.length_m;
  }
  return length;
}

void validate_options(const ModeOptions& options, std::size_t section_count) {
  const std::string why = options.validate();
  if (!why.empty()) throw std::invalid_argument("options." + why);
  if (options.theory == ModeOptions::Theory::kTimoshenko &&
      options.timoshenko.size() != section_count) {
    fail("options.timoshenko.size()", "the number of sections (" +
                                          std::to_string(section_count) + ")",
         static_cast<double>(options.timoshenko.size()));
  }
}

// ------------------------------------------------------- piecewise segments

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
double phase_weight(double mu_kg_m, double EI_N_m2, double length_m) {
  return std::pow(mu_kg_m / EI_N_m2, 0.25) * length_m;
}

// True when sections i and i + 1 are one uniform stretch: the same mass per
// length, EI and (Timoshenko) cross-section. Their boundary is then no
// breakpoint, so a design given as many equal sections costs what one costs.
bool same_properties(const std::vector<Section>& sections, const std::vector<TimoshenkoSection>& timoshenko,
                     std::size_t i) {
  const Section& a = sections[i];
  const Section& b = sections[i + 1];
  if (a.mass_kg / a.length_m != b.mass_kg / b.length_m || *a.EI_N_m2 != *b.EI_N_m2) return false;
  return timoshenko.empty() || (timoshenko[i].shear_stiffness_N == timoshenko[i + 1].shear_stiffness_N &&
                                timoshenko[i].radius_of_gyration_m == timoshenko[i + 1].radius_of_gyration_m);
}

// `timoshenko`: one entry per section when the theory is Timoshenko, else empty.
Segmentation segment(const std::vector<Section>& sections,
                     const std::vector<PointMass>& point_masses,
                     std::vector<double> extra_breaks = {},
                     const std::vector<TimoshenkoSection>& timoshenko = {}) {
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
    auto it = std::min_element(out.segments.begin(), out.segments.end(),
                               [&](const Segment& a, const Segment& b) {
                                 return std::abs(a.start_m - p.from_butt_m) <
                                        std::abs(b.start_m - p.from_butt_m);
                               });
    it->mass_at_start_kg += p.mass_kg;
  }
  return out;
}

// ------------------------------------------------------ Krylov functions

// S(z), T(z)/z, U(z)/z^2, V(z)/z^3 with S, U = (cosh z +- cos z)/2 and
// T, V = (sinh z +- sin z)/2: finite at z = 0 (1, 1, 1/2, 1/6).
struct Krylov {
  double s, t1, u2, v3;
};

Krylov krylov(double z) {
  if (z < 1.5) {
    // Taylor series in q = z^4; the terms after q^6 are below 1e-19 here.
    const double q = z * z * z * z;
    auto series = [q](const double* c) {
      double sum = c[6];
      for (int k = 5; k >= 0; --k) sum = sum * q + c[k];
      return sum;
    };
    static const auto kCoefficients = [] {
      // kCoefficients[j][k] = 1/(4k + j)!, j = 0..3 for S, T1, U2, V3.
      std::array<std::array<double, 7>, 4> c{};
      for (int j = 0; j < 4; ++j) {
        for (int k = 0; k < 7; ++k) {
          double factorial = 1.0;
          for (int n = 2; n <= 4 * k + j; ++n) factorial *= n;
          c[j][k] = 1.0 / factorial;
        }
      }
      return c;
    }();
    const double* kS = kCoefficients[0].data();
    const double* kT = kCoefficients[1].data();
    const double* kU = kCoefficients[2].data();
    const double* kV = kCoefficients[3].data();
    return {series(kS), series(kT), series(kU), series(kV)};
  }
  const double e = std::exp(z);
  const double ch = 0.5 * (e + 1.0 / e);
  const double sh = 0.5 * (e - 1.0 / e);
  const double c = std::cos(z);
  const double s = std::sin(z);
  const double z2 = z * z;
  return {0.5 * (ch + c), 0.5 * (sh + s) / z, 0.5 * (ch - c) / z2, 0.5 * (sh - s) / (z2 * z)};
}

// w at xi from a piece's start values (see ShapePiece).
double evaluate_piece(const ShapePiece& p, double xi) {
  const Krylov k = krylov(p.wavenumber_per_m * xi);
  const auto& d = p.derivatives;
  return d[0] * k.s + xi * (d[1] * k.t1 + xi * (d[2] * k.u2 + xi * d[3] * k.v3));
}

// ----------------------------------------------- mode shape post-processing

// Scales `mode.shape` to max |w| = 1 (sampled) with w(L) > 0 and locates its
// interior zeros on the analytic pieces. Returns the factor applied.
double normalise_and_find_nodes(Mode& mode) {
  struct Sample {
    std::size_t piece;
    double xi, w;
  };
  std::vector<Sample> samples;
  double w_max = 0.0;
  for (std::size_t i = 0; i < mode.shape.size(); ++i) {
    const ShapePiece& p = mode.shape[i];
    const double length = p.end_m - p.start_m;
    const int intervals =
        std::max(2, static_cast<int>(std::ceil(p.wavenumber_per_m * length / (kPi / 8.0))));
    for (int j = 0; j <= intervals; ++j) {
      const double xi = length * j / intervals;
      const double w = evaluate_piece(p, xi);
      samples.push_back({i, xi, w});
      w_max = std::max(w_max, std::abs(w));
    }
  }
  const double w_tip = samples.back().w;
  double scale = 1.0 / w_max;
  if (w_tip < 0.0) scale = -scale;
  for (ShapePiece& p : mode.shape) {
    for (double& d : p.derivatives) d *= scale;
  }
  mode.nodes_from_butt_m.clear();
  const double x_end = mode.shape.back().end_m;
  auto add_node = [&](double x) {
    if (x <= 0.0 || x >= x_end) return;
    if (!mode.nodes_from_butt_m.empty() && x - mode.nodes_from_butt_m.back() < 1e-9) return;
    mode.nodes_from_butt_m.push_back(x);
  };
  for (std::size_t k = 0; k + 1 < samples.size(); ++k) {
    const Sample& a = samples[k];
    const Sample& b = samples[k + 1];
    const ShapePiece& p = mode.shape[a.piece];
    if (a.w == 0.0) add_node(p.start_m + a.xi);
    if (a.piece != b.piece) continue;  // the same point, end of one piece and start of next
    if ((a.w < 0.0 && b.w > 0.0) || (a.w > 0.0 && b.w < 0.0)) {
      const double xi =
          brent_root([&](double t) { return evaluate_piece(p, t); }, a.xi, b.xi, a.w * scale,
                     b.w * scale, kNodeTol_m);
      add_node(p.start_m + xi);
    }
  }
  return scale;
}

void fill_shape_table(ModalResult& result, double length_m, int samples) {
  if (samples <= 0) return;
  result.shape_x_m.resize(samples);
  for (int i = 0; i < samples; ++i) result.shape_x_m[i] = length_m * i / (samples - 1);
  for (const Mode& m : result.modes) {
    std::vector<double> w(samples);
    for (int i = 0; i < samples; ++i) w[i] = mode_shape_at(m, result.shape_x_m[i]);
    result.shape_w.push_back(std::move(w));
  }
}

// ------------------------------------------------------------ exact solver

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
    for (const Segment& s : seg_.segments) {
      const double jump = s.mass_at_start_kg * w2 * L_ * L_ * L_ / EI0_;
      s1[3] += jump * s1[0];
      s2[3] += jump * s2[0];
      double m[4][4];
      matrix(s, w2, m);
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
    for (const Segment& seg : seg_.segments) {
      s[3] += seg.mass_at_start_kg * w2 * L_ * L_ * L_ / EI0_ * s[0];
      const double r = seg.EI_N_m2 / EI0_;
      ShapePiece p;
      p.start_m = seg.start_m;
      p.end_m = seg.start_m + seg.length_m;
      p.wavenumber_per_m = std::pow(seg.mu_kg_m * w2 / seg.EI_N_m2, 0.25);
      p.derivatives = {s[0], s[1] / L_, s[2] / (r * L_ * L_), s[3] / (r * L_ * L_ * L_)};
      pieces.push_back(p);
      double m[4][4];
      matrix(seg, w2, m);
      s = apply(m, s);
    }
    return pieces;
  }

 private:
  void matrix(const Segment& s, double w2, double m[4][4]) const {
    const double r = s.EI_N_m2 / EI0_;
    const double P = s.mu_kg_m * w2 * L_ * L_ * L_ * L_ / s.EI_N_m2;
    const double a = s.length_m / L_;
    const double a2 = a * a, a3 = a2 * a;
    const Krylov k = krylov(std::sqrt(std::sqrt(P)) * a);
    const double T = a * k.t1, U = a2 * k.u2, V = a3 * k.v3;
    m[0][0] = k.s;       m[0][1] = T;         m[0][2] = U / r;     m[0][3] = V / r;
    m[1][0] = P * V;     m[1][1] = k.s;       m[1][2] = T / r;     m[1][3] = U / r;
    m[2][0] = r * P * U; m[2][1] = r * P * V; m[2][2] = k.s;       m[2][3] = T;
    m[3][0] = r * P * T; m[3][1] = r * P * U; m[3][2] = P * V;     m[3][3] = k.s;
  }

  static std::array<double, 4> apply(const double m[4][4], const std::array<double, 4>& s) {
    std::array<double, 4> out{};
    for (int i = 0; i < 4; ++i) {
      out[i] = m[i][0] * s[0] + m[i][1] * s[1] + m[i][2] * s[2] + m[i][3] * s[3];
    }
    return out;
  }

  const Segmentation& seg_;
  double L_ = 0.0;
  double EI0_ = 0.0;
  double mu_bar_ = 0.0;
  double phase_per_root_omega_ = 0.0;
};

// Roots of a free-free beam are about pi apart in total phase (pi / 16 per
// scan step); consecutive roots found further apart than this may hide a
// skipped pair, which the count below then checks.
constexpr double kSuspectRootGap = 1.5 * kPi;

// How many flexible modes a finite-element mesh finds below the highest of
// `found` beyond those found (0 when none were missed, or when the beam has a
// massless section the elements cannot take), and how many elements give
// the `wanted`-th mode to rel_tol (the usual sizing looks at f1 only, which
// here may be a near-rigid hinge mode).
struct RootCount {
  int missed = 0;
  int elements = 0;
};
RootCount missed_roots(const Segmentation& seg, const ModalResult& found, int wanted, double rel_tol);
ModalResult fe_free_modes(const Segmentation& seg, const ModeOptions& options);

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
                   " nearly repeated root(s) below " + format_number(result.modes.back().frequency_Hz) +
                   " Hz; " + fe.message;
      return fe;
    }
  }
  if (static_cast<int>(result.modes.size()) < options.modes) {
    result.complete = false;
    result.message = "found " + std::to_string(result.modes.size()) + " of " +
                     std::to_string(options.modes) + " modes below beta L = " +
                     format_number(lambda_max);
  } else {
    result.message = "exact transfer-matrix solution";
  }
  return result;
}

// ------------------------------------------------------------ finite elements

using Eigen::Matrix4d;
using Eigen::MatrixXd;
using Eigen::Vector4d;
using Eigen::VectorXd;

// Integral of xi^n over [s, e].
double moment_over(int n, double s, double e) {
  double ps = s, pe = e;
  for (int i = 0; i < n; ++i) {
    ps *= s;
    pe *= e;
  }
  return (pe - ps) / (n + 1);
}

// A uniform stretch of an Euler-Bernoulli element, [s, e] in element
// coordinates (an element merged over a breakpoint has several).
struct ElementPiece {
  double s = 0.0, e = 0.0, EI = 0.0, mu = 0.0;
  std::size_t section = 0;  // of the beam, for messages
};

// One two-node element on [x0, x0 + h]. With g = EI/(kappa G A) (0 for
// Euler-Bernoulli) the static solution of the Timoshenko beam is
//   w = a0 + a1 xi + a2 xi^2 + a3 xi^3,  theta = w' + 6 g a3,
// shear strain w' - theta = -6 g a3, and the nodal DOFs (w1, theta1, w2,
// theta2) = C a. g = 0 gives the Hermite cubic element, which may span
// several uniform pieces and carry point masses inside (merge_tiny_elements).
struct Element {
  double x0 = 0.0, h = 0.0;
  double EI = 0.0, mu = 0.0, rotary = 0.0, g = 0.0;  // rotary = mu r^2; EI, mu of the first piece
  std::vector<ElementPiece> pieces;                  // covering [0, h]
  std::vector<std::pair<double, double>> masses;     // point masses inside: xi, kg
  Matrix4d c_inv;                                    // a = c_inv * DOFs

  Element(double x0_, double h_, double EI_, double mu_, double rotary_, double g_)
      : x0(x0_), h(h_), EI(EI_), mu(mu_), rotary(rotary_), g(g_), pieces{{0.0, h_, EI_, mu_}} {
    Matrix4d c;
    c << 1, 0, 0, 0,                              //
        0, 1, 0, 6 * g,                           //
        1, h, h * h, h * h * h,                   //
        0, 1, 2 * h, 3 * h * h + 6 * g;
    c_inv = c.inverse();
  }

  // Integral of xi^n over the element.
  double moment(int n) const {
    double power = h;
    for (int i = 0; i < n; ++i) power *= h;
    return power / (n + 1);
  }

  Matrix4d stiffness() const {
    // Bending EI theta'^2 with theta' = 2 a2 + 6 a3 xi, plus shear
    // kappa G A (6 g a3)^2 = 36 EI g a3^2.
    Matrix4d ka = Matrix4d::Zero();
    if (pieces.size() == 1) {
      ka(2, 2) = 4 * h;
      ka(2, 3) = ka(3, 2) = 6 * h * h;
      ka(3, 3) = 12 * h * h * h + 36 * g * h;
      return c_inv.transpose() * (EI * ka) * c_inv;
    }
    const bool one_EI = std::all_of(pieces.begin(), pieces.end(),
                                    [&](const ElementPiece& p) { return p.EI == pieces.front().EI; });
    if (!one_EI && g == 0.0) return flexibility_stiffness();
    for (const ElementPiece& p : pieces) {
      ka(2, 2) += 4 * p.EI * moment_over(0, p.s, p.e);
      ka(2, 3) += 12 * p.EI * moment_over(1, p.s, p.e);
      ka(3, 3) += 36 * p.EI * moment_over(2, p.s, p.e);
    }
    ka(3, 2) = ka(2, 3);
    return c_inv.transpose() * ka * c_inv;
  }

  // The exact static stiffness of an Euler-Bernoulli element whose EI varies
  // piecewise: the inverse of its flexibility as a cantilever from node 1,
  //   F = int_0^h [(h - x)^2, h - x; h - x, 1] / EI(x) dx,
  // for the end shear and moment, carried to the four DOFs by the
  // deformation (w2 - w1 - theta1 h, theta2 - theta1). Equal to the Hermite
  // stiffness for one EI; across a stiffness change it gives the compliance
  // of the stretches in series, which a cubic's curvature cannot.
  Matrix4d flexibility_stiffness() const {
    Eigen::Matrix2d f = Eigen::Matrix2d::Zero();
    for (const ElementPiece& p : pieces) {
      const double a = h - p.s, b = h - p.e;  // h - x at the ends of the piece
      f(0, 0) += (a * a * a - b * b * b) / (3.0 * p.EI);
      f(0, 1) += (a * a - b * b) / (2.0 * p.EI);
      f(1, 1) += (p.e - p.s) / p.EI;
    }
    f(1, 0) = f(0, 1);
    Eigen::Matrix<double, 2, 4> t;
    t << -1, -h, 1, 0,  //
        0, -1, 0, 1;
    return t.transpose() * f.inverse() * t;
  }

  // Integral of N_w^T N_w over [s, e] (the whole element by default), the
  // pattern of mass, grip springs and dashpots.
  Matrix4d gram() const { return gram(0.0, h); }
  Matrix4d gram(double s, double e) const {
    Matrix4d ga;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) ga(i, j) = s == 0.0 && e == h ? moment(i + j) : moment_over(i + j, s, e);
    return c_inv.transpose() * ga * c_inv;
  }

  Matrix4d mass() const {
    Matrix4d m;
    if (pieces.size() == 1) {
      m = mu * gram();
    } else {
      Matrix4d ga = Matrix4d::Zero();
      for (const ElementPiece& p : pieces) {
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) ga(i, j) += p.mu * moment_over(i + j, p.s, p.e);
      }
      m = c_inv.transpose() * ga * c_inv;
    }
    for (const auto& [xi, kg] : masses) {
      // A point mass where it is: kg N_w(xi)^T N_w(xi).
      const Vector4d n = c_inv.transpose() * Vector4d(1.0, xi, xi * xi, xi * xi * xi);
      m += kg * n * n.transpose();
    }
    if (rotary > 0.0) {
      // theta = (0, 1, 2 xi, 3 xi^2 + 6 g) . a
      const double I0 = moment(0), I1 = moment(1), I2 = moment(2), I3 = moment(3),
                   I4 = moment(4);
      Matrix4d ta = Matrix4d::Zero();
      ta(1, 1) = I0;
      ta(1, 2) = ta(2, 1) = 2 * I1;
      ta(1, 3) = ta(3, 1) = 3 * I2 + 6 * g * I0;
      ta(2, 2) = 4 * I2;
      ta(2, 3) = ta(3, 2) = 6 * I3 + 12 * g * I1;
      ta(3, 3) = 9 * I4 + 36 * g * I2 + 36 * g * g * I0;
      m += rotary * c_inv.transpose() * ta * c_inv;
    }
    return m;
  }

  // Integral of N_w^T (xi + x0 - xc)^p over [s, e], for p = 0, 1.
  Vector4d load(int p, double xc, double s, double e) const {
    const bool whole = s == 0.0 && e == h;
    const auto mom = [&](int n) { return whole ? moment(n) : moment_over(n, s, e); };
    Vector4d la;
    for (int i = 0; i < 4; ++i) la(i) = p == 0 ? mom(i) : mom(i + 1) + (x0 - xc) * mom(i);
    return c_inv.transpose() * la;
  }

  // Shape piece from nodal DOFs: derivatives of the cubic at x0.
  ShapePiece piece(const Vector4d& dofs) const {
    const Vector4d a = c_inv * dofs;
    ShapePiece p;
    p.start_m = x0;
    p.end_m = x0 + h;
    p.derivatives = {a(0), a(1), 2 * a(2), 6 * a(3)};
    return p;
  }
};

struct Mesh {
  std::vector<Element> elements;
  std::vector<double> nodes_m;
  std::vector<double> nodal_mass_kg;  // point masses lumped at the nodes
  double length_m = 0.0;
};

// An element far shorter than the mesh's sizing asks for (a sliver of a
// section, a point mass a hair from a section boundary) makes K
// ill-conditioned by (h_neighbour / h)^3: at 1e-6 m beside 1 cm elements the
// frequencies came out wrong by a factor of 2. Elements are sized to equal
// phase (mu/EI)^(1/4) h, so one whose phase is below kMergeRatio of its
// neighbour's is merged into a neighbour, which then integrates both uniform
// pieces exactly and carries the node's point mass where it is
// (Element::pieces, masses). Round-off then stays below about
// 1e4 eps / kMergeRatio^3 ~ 2e-9.
constexpr double kMergeRatio = 0.1;
// One cubic cannot bend differently on either side of a stiffness jump: a
// merged element spanning EI_min..EI_max misstates the frame's compliance by
// about (EI_max / EI_min - 1) h_short / L. Merges that would exceed this are
// refused (the exact solver, free modes only, has no such limit).
constexpr double kMergeTolerance = 1e-9;

double phase(const Element& e) {
  double sum = 0.0;
  for (const ElementPiece& p : e.pieces) sum += phase_weight(p.mu, p.EI, p.e - p.s);
  return sum;
}

double merge_error(const Element& a, const Element& b, double length_m) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const Element* e : {&a, &b}) {
    for (const ElementPiece& p : e->pieces) {
      lo = std::min(lo, p.EI);
      hi = std::max(hi, p.EI);
    }
  }
  return (hi / lo - 1.0) * std::min(a.h, b.h) / length_m;
}

void merge_tiny_elements(Mesh& mesh) {
  std::vector<double> phases;  // of each element, kept in step with the merges
  for (const Element& e : mesh.elements) phases.push_back(phase(e));
  while (mesh.elements.size() > 1) {
    std::size_t tiny = 0;
    double worst = kMergeRatio;
    for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
      double neighbour = 0.0;
      if (e > 0) neighbour = std::max(neighbour, phases[e - 1]);
      if (e + 1 < mesh.elements.size()) neighbour = std::max(neighbour, phases[e + 1]);
      const double ratio = phases[e] / neighbour;
      if (ratio < worst) {
        worst = ratio;
        tiny = e;
      }
    }
    if (!(worst < kMergeRatio)) return;
    // Into the neighbour that misstates the stiffness least, else the longer in phase.
    const std::size_t last = mesh.elements.size() - 1;
    const double error_left =
        tiny > 0 ? merge_error(mesh.elements[tiny - 1], mesh.elements[tiny], mesh.length_m)
                 : std::numeric_limits<double>::infinity();
    const double error_right =
        tiny < last ? merge_error(mesh.elements[tiny], mesh.elements[tiny + 1], mesh.length_m)
                    : std::numeric_limits<double>::infinity();
    if (std::min(error_left, error_right) > kMergeTolerance) {
      const ElementPiece& p = mesh.elements[tiny].pieces.front();
      throw std::invalid_argument(
          detail::indexed("sections", p.section, "length_m") + ": a stretch of " +
          detail::format_number(mesh.elements[tiny].h) + " m at " +
          detail::format_number(mesh.elements[tiny].x0) + " m from the butt, with EI " +
          detail::format_number(p.EI) +
          " N m^2 unlike its neighbours', is too short for finite elements to resolve (the hand-held "
          "modes always use them); lengthen it or give it its neighbours' EI");
    }
    const bool into_left =
        error_left < error_right ||
        (error_left == error_right && tiny > 0 && phases[tiny - 1] >= phases[tiny + 1]);
    const std::size_t left = into_left ? tiny - 1 : tiny;
    const Element& a = mesh.elements[left];
    const Element& b = mesh.elements[left + 1];
    Element merged(a.x0, a.h + b.h, a.EI, a.mu, 0.0, 0.0);
    merged.pieces = a.pieces;
    merged.masses = a.masses;
    for (const ElementPiece& p : b.pieces) merged.pieces.push_back({p.s + a.h, p.e + a.h, p.EI, p.mu, p.section});
    merged.pieces.back().e = merged.h;
    if (mesh.nodal_mass_kg[left + 1] > 0.0) merged.masses.emplace_back(a.h, mesh.nodal_mass_kg[left + 1]);
    for (const auto& [xi, kg] : b.masses) merged.masses.emplace_back(xi + a.h, kg);
    phases[left] += phases[left + 1];
    phases.erase(phases.begin() + static_cast<std::ptrdiff_t>(left) + 1);
    mesh.elements[left] = std::move(merged);
    mesh.elements.erase(mesh.elements.begin() + static_cast<std::ptrdiff_t>(left) + 1);
    mesh.nodes_m.erase(mesh.nodes_m.begin() + static_cast<std::ptrdiff_t>(left) + 1);
    mesh.nodal_mass_kg.erase(mesh.nodal_mass_kg.begin() + static_cast<std::ptrdiff_t>(left) + 1);
  }
}

Mesh build_mesh(const Segmentation& seg, const std::vector<int>& counts,
                const ModeOptions& options) {
  Mesh mesh;
  mesh.length_m = seg.length_m;
  mesh.nodes_m.push_back(0.0);
  mesh.nodal_mass_kg.push_back(0.0);
  const bool timoshenko = options.theory == ModeOptions::Theory::kTimoshenko;
  std::size_t group = 0;  // first segment of the open group (counts 0 ... 0 1)
  for (std::size_t i = 0; i < seg.segments.size(); ++i) {
    const Segment& s = seg.segments[i];
    if (counts[i] == 0 || (i > group && counts[i - 1] == 0)) {
      // Part of a group: one element over segments group..i once counts[i] == 1.
      if (i == group) mesh.nodal_mass_kg.back() += s.mass_at_start_kg;
      if (counts[i] == 0) continue;
      const Segment& first = seg.segments[group];
      Element element(first.start_m, s.start_m + s.length_m - first.start_m, first.EI_N_m2, first.mu_kg_m, 0.0, 0.0);
      element.pieces.clear();
      for (std::size_t j = group; j <= i; ++j) {
        const Segment& p = seg.segments[j];
        element.pieces.push_back({p.start_m - first.start_m, p.start_m + p.length_m - first.start_m, p.EI_N_m2,
                                  p.mu_kg_m, p.section});
        if (j > group && p.mass_at_start_kg > 0.0) element.masses.emplace_back(p.start_m - first.start_m, p.mass_at_start_kg);
      }
      element.pieces.back().e = element.h;
      mesh.elements.push_back(std::move(element));
      mesh.nodes_m.push_back(s.start_m + s.length_m);
      mesh.nodal_mass_kg.push_back(0.0);
      group = i + 1;
      continue;
    }
    group = i + 1;
    mesh.nodal_mass_kg.back() += s.mass_at_start_kg;
    double g = 0.0, rotary = 0.0;
    if (timoshenko) {
      const TimoshenkoSection& t = options.timoshenko[s.section];
      g = s.EI_N_m2 / t.shear_stiffness_N;
      rotary = s.mu_kg_m * t.radius_of_gyration_m * t.radius_of_gyration_m;
    }
    const double h = s.length_m / counts[i];
    for (int e = 0; e < counts[i]; ++e) {
      mesh.elements.emplace_back(s.start_m + e * h, h, s.EI_N_m2, s.mu_kg_m, rotary, g);
      mesh.elements.back().pieces.front().section = s.section;
      mesh.nodes_m.push_back(e + 1 == counts[i] ? s.start_m + s.length_m : s.start_m + (e + 1) * h);
      mesh.nodal_mass_kg.push_back(0.0);
    }
  }
  mesh.nodal_mass_kg.back() += seg.tip_mass_kg;
  if (!timoshenko) merge_tiny_elements(mesh);
  return mesh;
}

struct Assembled {
  MatrixXd K, M, C;
  int beam_dofs = 0;
};

Assembled assemble(const Mesh& mesh, const HandCoupling* hand) {
  const int beam_dofs = 2 * static_cast<int>(mesh.nodes_m.size());
  const int n = beam_dofs + (hand ? 2 : 0);
  Assembled out;
  out.beam_dofs = beam_dofs;
  out.K = MatrixXd::Zero(n, n);
  out.M = MatrixXd::Zero(n, n);
  out.C = MatrixXd::Zero(n, n);
  double grip_start = 0, grip_end = 0, xc = 0;
  if (hand) {
    grip_start = hand->grip_start_m;
    grip_end = hand->grip_start_m + hand->grip_length_m;
    xc = 0.5 * (grip_start + grip_end);
  }
  const double eps = 1e-12 * mesh.length_m;
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const Element& el = mesh.elements[e];
    const int i0 = 2 * static_cast<int>(e);
    out.K.block<4, 4>(i0, i0) += el.stiffness();
    out.M.block<4, 4>(i0, i0) += el.mass();
    // The part of the element under the grip, [s, e] in element coordinates
    // (the whole element or none, unless merge_tiny_elements joined across a grip end).
    const double s = std::max(0.0, grip_start - el.x0), e_end = std::min(el.h, grip_end - el.x0);
    const bool whole = s <= eps && e_end >= el.h - eps;
    if (hand && (whole || e_end - s > eps)) {
      const double lo = whole ? 0.0 : s, hi = whole ? el.h : e_end;
      // 1/2 int k (w - u - phi (x - xc))^2 dx, and the same with c for the dashpots.
      const Matrix4d gram = el.gram(lo, hi);
      const Vector4d l0 = el.load(0, xc, lo, hi), l1 = el.load(1, xc, lo, hi);
      const double r0 = hi - lo;
      const double r1 = r0 * (el.x0 + 0.5 * (lo + hi) - xc);
      const double d0 = el.x0 + lo - xc, d1 = d0 + r0;
      const double r2 = (d1 * d1 * d1 - d0 * d0 * d0) / 3.0;
      const int u = beam_dofs, phi = beam_dofs + 1;
      auto add = [&](MatrixXd& A, double k) {
        A.block<4, 4>(i0, i0) += k * gram;
        A.block<4, 1>(i0, u) -= k * l0;
        A.block<1, 4>(u, i0) -= k * l0.transpose();
        A.block<4, 1>(i0, phi) -= k * l1;
        A.block<1, 4>(phi, i0) -= k * l1.transpose();
        A(u, u) += k * r0;
        A(u, phi) += k * r1;
        A(phi, u) += k * r1;
        A(phi, phi) += k * r2;
      };
      add(out.K, hand->stiffness_N_m2);
      add(out.C, hand->damping_N_s_m2);
    }
  }
  for (std::size_t i = 0; i < mesh.nodes_m.size(); ++i) out.M(2 * i, 2 * i) += mesh.nodal_mass_kg[i];
  if (hand) {
    out.M(beam_dofs, beam_dofs) = hand->mass_kg;
    out.M(beam_dofs + 1, beam_dofs + 1) =
        hand->rotary_inertia_kg_m2.value_or(hand->mass_kg * hand->grip_length_m *
                                            hand->grip_length_m / 12.0);
  }
  return out;
}

// A hand joined by neither spring nor dashpot moves on its own: its
// translation and rotation are rigid-body motions too.
bool hand_detached(const HandCoupling* hand) {
  return hand && hand->stiffness_N_m2 == 0.0 && hand->damping_N_s_m2 == 0.0;
}

// Roots s = 0 of the damped problem that no deflation removes: a grip with a
// dashpot but no spring lets the hand drift from the beam (one root per hand
// DOF). They are simple, so round-off moves them by ~eps |A| only.
int drift_roots(const HandCoupling& hand) {
  return hand.stiffness_N_m2 == 0.0 && hand.damping_N_s_m2 > 0.0 ? 2 : 0;
}

// Basis of the M-orthogonal complement of the rigid-body motions (translation
// and rotation of beam and hand together, or of each alone when the hand is
// detached): K and C vanish on the rigid motions, so q = Q b decouples them
// exactly and the reduced problem has no zero modes.
MatrixXd flexible_basis(const Mesh& mesh, const Assembled& a, const HandCoupling* hand) {
  const int n = static_cast<int>(a.M.rows());
  const bool detached = hand_detached(hand);
  MatrixXd R = MatrixXd::Zero(n, detached ? 4 : 2);
  for (std::size_t i = 0; i < mesh.nodes_m.size(); ++i) {
    R(2 * i, 0) = 1.0;
    R(2 * i, 1) = mesh.nodes_m[i];
    R(2 * i + 1, 1) = 1.0;
  }
  if (hand) {
    const int u = detached ? 2 : 0, phi = detached ? 3 : 1;
    R(a.beam_dofs, u) = 1.0;
    if (!detached) R(a.beam_dofs, phi) = hand->grip_start_m + 0.5 * hand->grip_length_m;
    R(a.beam_dofs + 1, phi) = 1.0;
  }
  const Eigen::HouseholderQR<MatrixXd> qr(a.M * R);
  const MatrixXd Q = qr.householderQ() * MatrixXd::Identity(n, n);
  return Q.rightCols(n - R.cols());
}

// Elements per segment for `per_phase_weight` elements per unit phase: a
// segment asking for at least one element gets ceil of what it asks; a run
// of consecutive segments each asking for less shares elements, each closed
// once the run has asked for one (count 0: the segment joins the element
// that the next segment with count 1 closes). So elements follow the sizing,
// not the sections: 10 000 short sections make a few dozen elements, where
// one element each made a dense problem of 20 000 DOFs.
std::vector<int> counts_for(const Segmentation& seg, double per_phase_weight) {
  std::vector<int> counts;
  counts.reserve(seg.segments.size());
  double open = 0.0;  // elements asked for by the open run, < 1
  std::size_t last_close = std::string::npos;  // the run's last closed element
  // Ends a run: a remainder asking for under half an element joins the run's
  // previous element rather than make a sliver.
  auto close_run = [&] {
    if (!counts.empty() && counts.back() == 0) {
      if (open < 0.5 && last_close != std::string::npos) counts[last_close] = 0;
      counts.back() = 1;
    }
    open = 0.0;
    last_close = std::string::npos;
  };
  for (const Segment& s : seg.segments) {
    const double asked = per_phase_weight * phase_weight(s.mu_kg_m, s.EI_N_m2, s.length_m);
    if (!seg.groupable || asked >= 1.0 - 1e-9) {
      close_run();
      counts.push_back(std::max(1, static_cast<int>(std::ceil(asked - 1e-9))));
      continue;
    }
    open += asked;
    counts.push_back(open >= 1.0 - 1e-9 ? 1 : 0);
    if (counts.back() == 1) {
      open = 0.0;
      last_close = counts.size() - 1;
    }
  }
  close_run();
  return counts;
}

double total_phase_weight(const Segmentation& seg) {
  double sum = 0.0;
  for (const Segment& s : seg.segments) sum += phase_weight(s.mu_kg_m, s.EI_N_m2, s.length_m);
  return sum;
}

// Lowest flexible omega^2 eigenvalues and M-normalised eigenvectors.
std::pair<VectorXd, MatrixXd> free_spectrum(const Mesh& mesh) {
  const Assembled a = assemble(mesh, nullptr);
  const MatrixXd Q = flexible_basis(mesh, a, nullptr);
  const MatrixXd Kr = Q.transpose() * a.K * Q;
  const MatrixXd Mr = Q.transpose() * a.M * Q;
  // Kr is positive definite once the rigid-body modes are gone, so solve the
  // inverted pencil Mr b = (1/omega^2) Kr b: its largest eigenvalues, the low
  // modes, come out with relative (not ~cond(K) times worse) accuracy.
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> es(Mr, Kr);
  const int m = static_cast<int>(Kr.rows());
  VectorXd omega2(m);
  MatrixXd vectors(a.M.rows(), m);
  for (int k = 0; k < m; ++k) {
    const int j = m - 1 - k;
    omega2(k) = 1.0 / es.eigenvalues()(j);
    const VectorXd b = es.eigenvectors().col(j);
    vectors.col(k) = Q * (b / std::sqrt(b.dot(Mr * b)));
  }
  return {omega2, vectors};
}

// The lowest flexible omega^2 (eigenvalues only, as free_spectrum).
double lowest_free_omega2(const Mesh& mesh) {
  const Assembled a = assemble(mesh, nullptr);
  const MatrixXd Q = flexible_basis(mesh, a, nullptr);
  const MatrixXd Kr = Q.transpose() * a.K * Q;
  const MatrixXd Mr = Q.transpose() * a.M * Q;
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> es(Mr, Kr, Eigen::EigenvaluesOnly);
  return 1.0 / es.eigenvalues().maxCoeff();
}

// Elements per segment: explicit total, or sized so the f1 error is about
// rel_tol from the h^4 convergence of the cubic element, (beta h)^4 / 1440,
// with beta from a coarse first estimate of f1.
std::vector<int> element_counts(const Segmentation& seg, const ModeOptions& options) {
  const double weight = total_phase_weight(seg);
  if (options.elements > 0) return counts_for(seg, options.elements / weight);
  // Coarse estimate: ~2 elements per radian of phase at the first mode.
  ModeOptions coarse = options;
  const std::vector<int> coarse_counts = counts_for(seg, 2.0 * 4.73 / weight);
  const Mesh mesh = build_mesh(seg, coarse_counts, coarse);
  const double omega1 = std::sqrt(std::max(lowest_free_omega2(mesh), 0.0));
  const double beta_h =
      std::pow(kHermiteErrorConstant * kToleranceSafety * options.rel_tol, 0.25);
  std::vector<int> counts = counts_for(seg, std::sqrt(omega1) / beta_h);
  int total = 0;
  for (int c : counts) total += c;
  if (total < options.modes + 2) counts = counts_for(seg, (options.modes + 2) / weight);
  return counts;
}

int total_elements(const std::vector<int>& counts) {
  int total = 0;
  for (int c : counts) total += c;
  return total;
}

// The mode of FE eigenvector q; also returns the factor between its shape and q.
std::pair<Mode, double> fe_mode(const Mesh& mesh, const VectorXd& q, double omega) {
  Mode mode;
  mode.frequency_Hz = mode.undamped_frequency_Hz = omega / (2.0 * kPi);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    mode.shape.push_back(mesh.elements[e].piece(q.segment<4>(2 * e)));
  }
  const double scale = normalise_and_find_nodes(mode);
  mode.fe_dofs.assign(q.data(), q.data() + q.size());
  if (scale < 0.0) {
    for (double& v : mode.fe_dofs) v = -v;
  }
  return {std::move(mode), scale};
}

RootCount missed_roots(const Segmentation& seg, const ModalResult& found, int wanted, double rel_tol) {
  for (const Segment& s : seg.segments) {
    if (!(s.mu_kg_m > 0.0)) return {};
  }
  const double omega_top = 2.0 * kPi * found.modes.back().frequency_Hz;
  // About 3 elements per radian of phase at the top root: its FE frequency
  // within ~1e-4 of the exact one, lower modes closer still.
  const std::vector<int> counts = counts_for(seg, 3.0 * std::sqrt(omega_top));
  if (total_elements(counts) > kMaxElements) return {};
  const Mesh mesh = build_mesh(seg, counts, ModeOptions{});
  const VectorXd omega2 = free_spectrum(mesh).first;
  const double below = omega_top * omega_top * (1.0 - 1e-6);
  int count = 0;
  for (int k = 0; k < omega2.size(); ++k) count += omega2(k) < below ? 1 : 0;
  const int k_wanted = std::max(0, std::min(wanted, static_cast<int>(omega2.size())) - 1);
  const double omega_wanted = std::sqrt(std::max(omega2(k_wanted), 0.0));
  const double beta_h = std::pow(kHermiteErrorConstant * kToleranceSafety * rel_tol, 0.25);
  return {std::max(0, count - (static_cast<int>(found.modes.size()) - 1)),
          std::min(kMaxElements, total_elements(counts_for(seg, std::sqrt(omega_wanted) / beta_h)))};
}

// Above this many elements the free beam's modes are not solved densely
// (O(N^3): 2000 elements took 3 minutes) but located on a coarse mesh and
// each refined on the full one with the banded solver of the hand-held modes.
constexpr int kDenseFreeElements = 256;

// The lowest options.modes free flexible omega^2 and M-normalised
// eigenvectors on `mesh`, found on `coarse` and refined; empty with a
// reason in `why` when a mode cannot be matched.
std::optional<std::pair<VectorXd, MatrixXd>> refined_free_spectrum(const Mesh& mesh, const ModeOptions& options,
                                                                   const Mesh& coarse, std::string* why);
Mesh coarse_mesh(const Segmentation& seg, const ModeOptions& options);

ModalResult fe_free_modes(const Segmentation& seg, const ModeOptions& options) {
  ModalResult result;
  result.method = ModeOptions::Method::kFiniteElement;
  result.theory = options.theory;
  const std::vector<int> counts = element_counts(seg, options);
  const Mesh mesh = build_mesh(seg, counts, options);
  result.elements_used = static_cast<int>(mesh.elements.size());  // after merge_tiny_elements
  result.message = "finite elements: " + std::to_string(result.elements_used) + " elements";
  std::optional<std::pair<VectorXd, MatrixXd>> spectrum;
  if (result.elements_used > kDenseFreeElements) {
    const Mesh coarse = coarse_mesh(seg, options);
    std::string why;
    spectrum = refined_free_spectrum(mesh, options, coarse, &why);
    result.message += spectrum ? ", each mode refined from a " + std::to_string(coarse.elements.size()) +
                                     "-element solve"
                               : ", dense (refinement skipped: " + why + ")";
  }
  if (!spectrum) spectrum = free_spectrum(mesh);
  const auto& [omega2, vectors] = *spectrum;
  const int available = static_cast<int>(omega2.size());
  for (int k = 0; k < std::min(options.modes, available); ++k) {
    result.modes.push_back(
        fe_mode(mesh, vectors.col(k), std::sqrt(std::max(omega2(k), 0.0))).first);
  }
  result.complete = static_cast<int>(result.modes.size()) == options.modes;
  return result;
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

// The Timoshenko data segment() compares sections by (empty for Euler-Bernoulli).
const std::vector<TimoshenkoSection>& timoshenko_of(const ModeOptions& options) {
  static const std::vector<TimoshenkoSection> kNone;
  return options.theory == ModeOptions::Theory::kTimoshenko ? options.timoshenko : kNone;
}

Segmentation hand_segmentation(const std::vector<Section>& sections,
                               const std::vector<PointMass>& point_masses,
                               const HandCoupling& hand, const ModeOptions& options) {
  return segment(sections, point_masses,
                 {hand.grip_start_m, hand.grip_start_m + hand.grip_length_m}, timoshenko_of(options));
}

// ------------------------------------------------------ damped eigenproblem

using Complex = std::complex<double>;
using Eigen::VectorXcd;

// Elements per requested mode for the coarse mesh that locates the hand-held
// modes: beta h <= 2 at the highest requested bending mode, 2^4 / 1440 =
// 1 % in frequency, far inside the gaps between modes.
constexpr double kCoarseBetaH = 2.0;
// The coarse damped problem is solved in the basis of this many undamped
// modes more than requested.
constexpr int kExtraBasisModes = 4;
// Rayleigh-functional iteration: at most this many steps per mode ...
constexpr int kMaxRefineSteps = 12;
// ... and a mode is accepted when its backward error (relative to the norms
// of K, C and M) is below kRefineAccept. It stops at round-off: a backward
// error below kRefineDone or one that no longer falls by kRefineStall.
constexpr double kRefineAccept = 1e-11;
constexpr double kRefineDone = 1e-14;
constexpr double kRefineStall = 0.1;
// A refined mode must lie nearer its coarse estimate than this fraction of
// the distance to the nearest other coarse mode, or the match is ambiguous.
constexpr double kMatchFraction = 0.25;

// An eigenpair of (s^2 M + s C + K) q = 0, q over every DOF of the mesh.
struct DampedPair {
  Complex s;
  VectorXcd q;
};

struct DampedSpectrum {
  std::vector<DampedPair> pairs;  // Im s > 0, ascending Im s
  int overdamped = 0;             // real roots (not reported)
};

// A root is real (overdamped) when |Im s| <= kRealRootTol |s|.
constexpr double kRealRootTol = 1e-9;

// The oscillatory roots among every eigenvalue of a state matrix: the
// `drift` roots nearest 0 (drift_roots: the structure says how many) are
// set aside, then the roots with Im s > 0 are returned ascending in Im s, at
// most `wanted`, and the real ones counted. No cut-off in |s|: the low modes
// of a fine mesh are many orders below its highest frequency, and a cut-off
// relative to that (as once used) threw the fundamental away.
struct OscillatoryRoots {
  std::vector<int> order;
  int overdamped = 0;
};
OscillatoryRoots select_oscillatory(const VectorXcd& eigenvalues, int drift, int wanted) {
  const int n = static_cast<int>(eigenvalues.size());
  std::vector<int> by_size(n);
  for (int j = 0; j < n; ++j) by_size[j] = j;
  std::sort(by_size.begin(), by_size.end(),
            [&](int i, int j) { return std::abs(eigenvalues(i)) < std::abs(eigenvalues(j)); });
  OscillatoryRoots out;
  for (int k = std::min(drift, n); k < n; ++k) {
    const int j = by_size[k];
    const Complex s = eigenvalues(j);
    if (s.imag() > kRealRootTol * std::abs(s)) out.order.push_back(j);
    if (std::abs(s.imag()) <= kRealRootTol * std::abs(s)) ++out.overdamped;
  }
  std::sort(out.order.begin(), out.order.end(),
            [&](int i, int j) { return eigenvalues(i).imag() < eigenvalues(j).imag(); });
  if (static_cast<int>(out.order.size()) > wanted) out.order.resize(wanted);
  return out;
}

// The lowest `wanted` oscillatory modes from every eigenvalue of the dense
// state matrix: O(n^3), the reference.
DampedSpectrum dense_damped_spectrum(const Mesh& mesh, const Assembled& a, const HandCoupling& hand,
                                     int wanted) {
  const MatrixXd Q = flexible_basis(mesh, a, &hand);
  const MatrixXd Kr = Q.transpose() * a.K * Q;
  const MatrixXd Cr = Q.transpose() * a.C * Q;
  const MatrixXd Mr = Q.transpose() * a.M * Q;
  const int m = static_cast<int>(Mr.rows());

  // y = L^T b with Mr = L L^T: y'' + Ct y' + Kt y = 0, then the state space
  // x = (y, y'), x' = A x, A = [0 I; -Kt -Ct].
  const Eigen::LLT<MatrixXd> llt(Mr);
  const MatrixXd Kt = llt.matrixL().solve(MatrixXd(llt.matrixL().solve(Kr)).transpose());
  const MatrixXd Ct = llt.matrixL().solve(MatrixXd(llt.matrixL().solve(Cr)).transpose());
  // Balance: x = (sigma y, y') with sigma ~ the highest natural frequency
  // makes both off-diagonal blocks O(sigma) instead of O(1) and O(sigma^2),
  // so the low eigenvalues keep relative accuracy.
  const double sigma = std::sqrt(std::max(Kt.diagonal().maxCoeff(), 1e-300));
  MatrixXd A = MatrixXd::Zero(2 * m, 2 * m);
  A.topRightCorner(m, m) = sigma * MatrixXd::Identity(m, m);
  A.bottomLeftCorner(m, m) = -Kt / sigma;
  A.bottomRightCorner(m, m) = -Ct;
  const Eigen::EigenSolver<MatrixXd> es(A, true);

  DampedSpectrum out;
  const OscillatoryRoots roots = select_oscillatory(es.eigenvalues(), drift_roots(hand), wanted);
  out.overdamped = roots.overdamped;
  for (int j : roots.order) {
    const VectorXcd y = es.eigenvectors().col(j).head(m) / sigma;
    const VectorXd b_re = llt.matrixU().solve(y.real());
    const VectorXd b_im = llt.matrixU().solve(y.imag());
    VectorXcd q = (Q * b_re).cast<Complex>() + Complex(0, 1) * (Q * b_im).cast<Complex>();
    out.pairs.push_back({es.eigenvalues()(j), std::move(q)});
  }
  return out;
}

// The lowest `wanted` oscillatory modes in the basis of the lowest `basis`
// undamped flexible modes (grip springs included): a 2 basis x 2 basis state
// matrix. Estimates only (modal truncation), refined on the full mesh.
DampedSpectrum modal_damped_spectrum(const Mesh& mesh, const Assembled& a, const HandCoupling& hand,
                                     int wanted, int basis) {
  const MatrixXd Q = flexible_basis(mesh, a, &hand);
  const MatrixXd Kr = Q.transpose() * a.K * Q;
  const MatrixXd Mr = Q.transpose() * a.M * Q;
  // Inverted pencil as in free_spectrum: the low modes keep relative accuracy.
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> es(Mr, Kr);
  const int n = static_cast<int>(Kr.rows());
  const int r = std::min(basis, n);
  MatrixXd phi(n, r);
  VectorXd omega2(r);
  for (int k = 0; k < r; ++k) {
    const int j = n - 1 - k;
    omega2(k) = 1.0 / es.eigenvalues()(j);
    const VectorXd b = es.eigenvectors().col(j);
    phi.col(k) = b / std::sqrt(b.dot(Mr * b));
  }
  const MatrixXd QPhi = Q * phi;
  const MatrixXd Cm = QPhi.transpose() * a.C * QPhi;
  const double sigma = std::sqrt(std::max(omega2(r - 1), 1e-300));
  MatrixXd A = MatrixXd::Zero(2 * r, 2 * r);
  A.topRightCorner(r, r) = sigma * MatrixXd::Identity(r, r);
  A.bottomLeftCorner(r, r).diagonal() = -omega2 / sigma;
  A.bottomRightCorner(r, r) = -Cm;
  const Eigen::EigenSolver<MatrixXd> ses(A, true);
  DampedSpectrum out;
  const OscillatoryRoots roots = select_oscillatory(ses.eigenvalues(), drift_roots(hand), wanted);
  out.overdamped = roots.overdamped;
  for (int j : roots.order) {
    const VectorXcd y = ses.eigenvectors().col(j).head(r);
    out.pairs.push_back({ses.eigenvalues()(j), QPhi.cast<Complex>() * y});
  }
  return out;
}

// The reported mode of a damped eigenpair: the complex shape turned to be as
// real as possible, its real part mass-normalised.
Mode damped_mode(const Mesh& mesh, const Assembled& a, Complex s, VectorXcd q) {
  // Turn the shape to be as real as possible: maximise the beam's kinetic
  // energy norm of Re(e^{i a} q), i.e. make q_b^T M_b q_b real and positive.
  // Mass-weighted rather than a sum over nodes, so the angle (and the nodes
  // of the turned shape) converge with the mesh at the element's rate.
  const int nb = a.beam_dofs;
  const auto Mb = a.M.topLeftCorner(nb, nb);
  const Complex sum_sq = (q.head(nb).transpose() * (Mb.cast<Complex>() * q.head(nb)))(0);
  q *= std::exp(Complex(0, -0.5 * std::arg(sum_sq)));
  const VectorXd q_re = q.head(nb).real(), q_im = q.head(nb).imag();
  const double re2 = q_re.dot(Mb * q_re), im2 = q_im.dot(Mb * q_im);
  VectorXd re = q.real();
  re /= std::sqrt(re.dot(a.M * re));
  auto [mode, scale] = fe_mode(mesh, re, std::abs(s));
  mode.frequency_Hz = s.imag() / (2.0 * kPi);
  mode.damping_ratio = -s.real() / std::abs(s);
  mode.complexity = std::sqrt(im2 / re2);
  mode.hand_displacement = scale * re(a.beam_dofs);
  const int u = a.beam_dofs;
  mode.hand_energy_fraction =
      a.M(u, u) * re(u) * re(u) + a.M(u + 1, u + 1) * re(u + 1) * re(u + 1);
  return mode;
}

// T(s) = s^2 M + s C + K of a hand-held mesh, stored by structure: the beam
// DOFs are banded (half-bandwidth 3, one element joins two nodes) and the two
// hand DOFs, last, couple only to the grip. With T = [A B; B^T D] (complex
// symmetric), A gets a banded LU with partial pivoting and the hand a 2 x 2
// Schur complement: O(n) per factorisation and solve.
class QuadraticPencil {
 public:
  static constexpr int kBand = 3;
  static constexpr int kLd = 3 * kBand + 1;  // LU rows per column (fill-in kBand above)

  explicit QuadraticPencil(const Assembled& a) : n_(a.beam_dofs) {
    const MatrixXd* src[3] = {&a.K, &a.C, &a.M};
    for (int m = 0; m < 3; ++m) {
      band_[m].assign(static_cast<std::size_t>(n_) * (2 * kBand + 1), 0.0);
      for (int j = 0; j < n_; ++j) {
        for (int i = std::max(0, j - kBand); i <= std::min(n_ - 1, j + kBand); ++i) {
          band_[m][j * (2 * kBand + 1) + (i - j + kBand)] = (*src[m])(i, j);
        }
      }
      border_[m] = src[m]->block(0, n_, n_, 2);
      corner_[m] = src[m]->block(n_, n_, 2, 2);
    }
  }

  // Infinity norm of K (m = 0), C (1) or M (2).
  double norm(int m) const {
    VectorXd rows = VectorXd::Zero(n_ + 2);
    for (int j = 0; j < n_; ++j) {
      for (int i = std::max(0, j - kBand); i <= std::min(n_ - 1, j + kBand); ++i) {
        rows(i) += std::abs(band_[m][j * (2 * kBand + 1) + (i - j + kBand)]);
      }
    }
    rows.head(n_) += border_[m].cwiseAbs().rowwise().sum();
    rows.tail(2) += border_[m].cwiseAbs().colwise().sum().transpose() +
                    corner_[m].cwiseAbs().rowwise().sum();
    return rows.maxCoeff();
  }

  // (c0 K + c1 C + c2 M) q.
  VectorXcd apply(Complex c0, Complex c1, Complex c2, const VectorXcd& q) const {
    VectorXcd out = VectorXcd::Zero(n_ + 2);
    const Complex c[3] = {c0, c1, c2};
    for (int m = 0; m < 3; ++m) {
      if (c[m] == 0.0) continue;
      for (int j = 0; j < n_; ++j) {
        const Complex cq = c[m] * q(j);
        for (int i = std::max(0, j - kBand); i <= std::min(n_ - 1, j + kBand); ++i) {
          out(i) += band_[m][j * (2 * kBand + 1) + (i - j + kBand)] * cq;
        }
      }
      out.head(n_) += c[m] * (border_[m].cast<Complex>() * q.tail(2));
      out.tail(2) += c[m] * (border_[m].transpose().cast<Complex>() * q.head(n_) +
                             corner_[m].cast<Complex>() * q.tail(2));
    }
    return out;
  }

  // Factorises T(s); false when a pivot vanishes (s is an eigenvalue of A or T).
  bool factorize(Complex s) {
    const Complex c[3] = {1.0, s, s * s};
    lu_.assign(static_cast<std::size_t>(n_) * kLd, 0.0);
    pivots_.assign(n_, 0);
    inverse_pivots_.assign(n_, 0.0);
    for (int j = 0; j < n_; ++j) {
      for (int i = std::max(0, j - kBand); i <= std::min(n_ - 1, j + kBand); ++i) {
        Complex v = 0.0;
        for (int m = 0; m < 3; ++m) v += c[m] * band_[m][j * (2 * kBand + 1) + (i - j + kBand)];
        at(i, j) = v;
      }
    }
    for (int k = 0; k < n_; ++k) {
      const int last_row = std::min(n_ - 1, k + kBand);
      const int last_col = std::min(n_ - 1, k + 2 * kBand);
      int p = k;
      // |Re| + |Im| as in LAPACK: no hypot in the inner loop.
      auto size = [](Complex z) { return std::abs(z.real()) + std::abs(z.imag()); };
      for (int i = k + 1; i <= last_row; ++i) {
        if (size(at(i, k)) > size(at(p, k))) p = i;
      }
      pivots_[k] = p;
      if (at(p, k) == 0.0) return false;
      if (p != k) {
        for (int j = k; j <= last_col; ++j) std::swap(at(k, j), at(p, j));
      }
      const Complex inv = 1.0 / at(k, k);
      inverse_pivots_[k] = inv;
      for (int i = k + 1; i <= last_row; ++i) {
        const Complex l = at(i, k) * inv;
        at(i, k) = l;
        if (l == 0.0) continue;
        for (int j = k + 1; j <= last_col; ++j) at(i, j) -= l * at(k, j);
      }
    }
    border_s_ = Eigen::MatrixX2cd(n_, 2);
    Eigen::Matrix2cd corner = Eigen::Matrix2cd::Zero();
    border_s_.setZero();
    for (int m = 0; m < 3; ++m) {
      border_s_ += c[m] * border_[m].cast<Complex>();
      corner += c[m] * corner_[m].cast<Complex>();
    }
    solved_border_ = border_s_;
    for (int col = 0; col < 2; ++col) {
      VectorXcd v = solved_border_.col(col);
      band_solve(v);
      solved_border_.col(col) = v;
    }
    schur_ = corner - border_s_.transpose() * solved_border_;
    const Complex det = schur_.determinant();
    if (det == 0.0) return false;
    schur_inverse_ = schur_.inverse();
    return true;
  }

  // x with T(s) x = r for the last factorised s.
  VectorXcd solve(const VectorXcd& r) const {
    VectorXcd xb = r.head(n_);
    band_solve(xb);
    const Eigen::Vector2cd xh = schur_inverse_ * (r.tail(2) - border_s_.transpose() * xb);
    VectorXcd x(n_ + 2);
    x.head(n_) = xb - solved_border_ * xh;
    x.tail(2) = xh;
    return x;
  }

 private:
  Complex& at(int i, int j) { return lu_[j * kLd + (i - j + 2 * kBand)]; }
  const Complex& at(int i, int j) const { return lu_[j * kLd + (i - j + 2 * kBand)]; }

  void band_solve(VectorXcd& b) const {
    for (int k = 0; k < n_; ++k) {
      if (pivots_[k] != k) std::swap(b(k), b(pivots_[k]));
      for (int i = k + 1; i <= std::min(n_ - 1, k + kBand); ++i) b(i) -= at(i, k) * b(k);
    }
    for (int k = n_ - 1; k >= 0; --k) {
      Complex sum = b(k);
      for (int j = k + 1; j <= std::min(n_ - 1, k + 2 * kBand); ++j) sum -= at(k, j) * b(j);
      b(k) = sum * inverse_pivots_[k];
    }
  }

  int n_ = 0;
  std::vector<double> band_[3];  // K, C, M of the beam DOFs, column-major band
  Eigen::MatrixX2d border_[3];   // beam-hand coupling
  Eigen::Matrix2d corner_[3];    // hand-hand
  std::vector<Complex> lu_;
  std::vector<int> pivots_;
  std::vector<Complex> inverse_pivots_;
  Eigen::MatrixX2cd border_s_, solved_border_;
  Eigen::Matrix2cd schur_, schur_inverse_;
};

// Converges an estimate (s, q) to an eigenpair of T(s) q = 0 by
// Rayleigh-functional iteration: s <- the root of q^T T(s) q = 0 nearest s,
// q <- T(s)^-1 T'(s) q. T is complex symmetric, so q is its own left
// eigenvector and the iteration converges cubically. Empty if it does not
// reach kRefineAccept.
std::optional<DampedPair> refine_damped_pair(QuadraticPencil& t, Complex s, VectorXcd q) {
  auto form = [](const VectorXcd& u, const VectorXcd& v) { return (u.transpose() * v)(0); };
  const double norm_K = t.norm(0), norm_C = t.norm(1), norm_M = t.norm(2);
  q /= q.norm();
  double error = std::numeric_limits<double>::infinity();
  for (int step = 0; step <= kMaxRefineSteps; ++step) {
    const VectorXcd Kq = t.apply(1.0, 0.0, 0.0, q);
    const VectorXcd Cq = t.apply(0.0, 1.0, 0.0, q);
    const VectorXcd Mq = t.apply(0.0, 0.0, 1.0, q);
    const Complex a2 = form(q, Mq), a1 = form(q, Cq), a0 = form(q, Kq);
    const Complex root = std::sqrt(a1 * a1 - 4.0 * a2 * a0);
    const Complex s1 = (-a1 + root) / (2.0 * a2), s2 = (-a1 - root) / (2.0 * a2);
    const Complex next = std::abs(s1 - s) <= std::abs(s2 - s) ? s1 : s2;
    // Backward error of (s, q): the relative change of K, C, M that makes it exact.
    const double next_error = (Kq + next * Cq + next * next * Mq).norm() /
                              (norm_K + std::abs(next) * norm_C + std::norm(next) * norm_M);
    const bool stalled = step > 0 && !(next_error < kRefineStall * error);
    if (!stalled) s = next;
    error = std::min(error, next_error);
    if (error < kRefineDone || stalled || step == kMaxRefineSteps) break;
    if (!t.factorize(s)) break;  // s is an eigenvalue to working precision
    const VectorXcd x = t.solve(2.0 * s * Mq + Cq);
    const double norm = x.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) return std::nullopt;
    q = x / norm;
  }
  if (!(error < kRefineAccept)) return std::nullopt;
  return DampedPair{s, std::move(q)};
}

// Coarse DOFs carried to the nodes of `fine` through the coarse elements'
// interpolation (w and theta of the cubic), hand DOFs as they are.
VectorXcd interpolate_dofs(const Mesh& coarse, const VectorXcd& q, const Mesh& fine,
                           int fine_size) {
  VectorXcd out = VectorXcd::Zero(fine_size);
  const int coarse_beam = 2 * static_cast<int>(coarse.nodes_m.size());
  const int fine_beam = 2 * static_cast<int>(fine.nodes_m.size());
  std::size_t e = 0;
  for (std::size_t i = 0; i < fine.nodes_m.size(); ++i) {
    const double x = fine.nodes_m[i];
    while (e + 1 < coarse.elements.size() && x > coarse.elements[e].x0 + coarse.elements[e].h) ++e;
    const Element& el = coarse.elements[e];
    const Eigen::Vector4cd c = el.c_inv.cast<Complex>() * q.segment<4>(2 * e);
    const double xi = std::clamp(x - el.x0, 0.0, el.h);
    out(2 * i) = c(0) + xi * (c(1) + xi * (c(2) + xi * c(3)));
    out(2 * i + 1) = c(1) + xi * (2.0 * c(2) + xi * 3.0 * c(3)) + 6.0 * el.g * c(3);
  }
  out.tail(fine_size - fine_beam) = q.tail(q.size() - coarse_beam);
  return out;
}

// The coarse mesh on which the lowest `modes` are located before refinement:
// kCoarseBetaH radians of phase per element at mode modes + 1/2.
Mesh coarse_mesh(const Segmentation& seg, const ModeOptions& options) {
  return build_mesh(seg, counts_for(seg, (options.modes + 0.5) * kPi / (kCoarseBetaH * total_phase_weight(seg))),
                    options);
}

// Each of the first `count` coarse estimates (s, q on `coarse`; `guesses`
// ascending, one more than wanted so the last is matched unambiguously)
// refined on `mesh`. Each must stay within kMatchFraction of the distance to
// its nearest neighbour (or its conjugate root); else empty with a reason.
std::optional<std::vector<DampedPair>> refine_estimates(QuadraticPencil& pencil, const Mesh& coarse,
                                                        const Mesh& mesh, int size,
                                                        const std::vector<DampedPair>& guesses, int count,
                                                        std::string* why) {
  std::vector<DampedPair> out;
  for (int k = 0; k < count; ++k) {
    const Complex s0 = guesses[k].s;
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < guesses.size(); ++j) {
      if (static_cast<int>(j) != k) gap = std::min(gap, std::abs(guesses[j].s - s0));
    }
    // The conjugate root is a neighbour too (and the overdamped real axis between).
    gap = std::min(gap, 2.0 * s0.imag());
    std::optional<DampedPair> pair =
        refine_damped_pair(pencil, s0, interpolate_dofs(coarse, guesses[k].q, mesh, size));
    if (!pair) {
      *why = "mode " + std::to_string(k + 1) + " did not converge";
      return std::nullopt;
    }
    if (!(std::abs(pair->s - s0) < kMatchFraction * gap)) {
      *why = "mode " + std::to_string(k + 1) + " moved too far from its coarse estimate";
      return std::nullopt;
    }
    out.push_back(std::move(*pair));
  }
  return out;
}

// The lowest `wanted` modes on `mesh` located on a coarse mesh and refined;
// empty with a reason in `why` when a mode cannot be matched.
std::optional<DampedSpectrum> refined_damped_spectrum(const Mesh& mesh, const Assembled& a,
                                                      const HandCoupling& hand, const ModeOptions& options,
                                                      const Mesh& coarse, std::string* why) {
  const Assembled ca = assemble(coarse, &hand);
  const DampedSpectrum guess =
      modal_damped_spectrum(coarse, ca, hand, options.modes + 1, options.modes + kExtraBasisModes);
  if (static_cast<int>(guess.pairs.size()) <= options.modes) {
    *why = "coarse mesh has too few oscillatory modes";
    return std::nullopt;
  }
  QuadraticPencil pencil(a);
  auto pairs = refine_estimates(pencil, coarse, mesh, static_cast<int>(a.M.rows()), guess.pairs, options.modes, why);
  if (!pairs) return std::nullopt;
  return DampedSpectrum{std::move(*pairs), guess.overdamped};
}

std::optional<std::pair<VectorXd, MatrixXd>> refined_free_spectrum(const Mesh& mesh, const ModeOptions& options,
                                                                   const Mesh& coarse, std::string* why) {
  const auto [coarse_omega2, coarse_vectors] = free_spectrum(coarse);
  if (coarse_omega2.size() <= options.modes) {
    *why = "coarse mesh has too few modes";
    return std::nullopt;
  }
  // The beam's K and M with two unit masses on no spring in the hand's place:
  // the banded pencil needs them, and they stay decoupled (their part of
  // every vector is zero).
  const Assembled beam = assemble(mesh, nullptr);
  const int n = beam.beam_dofs;
  Assembled a;
  a.beam_dofs = n;
  a.K = MatrixXd::Zero(n + 2, n + 2);
  a.C = MatrixXd::Zero(n + 2, n + 2);
  a.M = MatrixXd::Zero(n + 2, n + 2);
  a.K.topLeftCorner(n, n) = beam.K;
  a.M.topLeftCorner(n, n) = beam.M;
  a.M(n, n) = a.M(n + 1, n + 1) = 1.0;
  // Undamped coarse modes as damped estimates: s = i omega.
  const int coarse_n = static_cast<int>(coarse_vectors.rows());
  std::vector<DampedPair> guesses;
  for (int k = 0; k <= options.modes; ++k) {
    VectorXcd q0 = VectorXcd::Zero(coarse_n + 2);
    q0.head(coarse_n) = coarse_vectors.col(k).cast<Complex>();
    guesses.push_back({Complex(0.0, std::sqrt(std::max(coarse_omega2(k), 0.0))), std::move(q0)});
  }
  QuadraticPencil pencil(a);
  const auto pairs = refine_estimates(pencil, coarse, mesh, n + 2, guesses, options.modes, why);
  if (!pairs) return std::nullopt;
  VectorXd omega2(options.modes);
  MatrixXd vectors(n, options.modes);
  for (int k = 0; k < options.modes; ++k) {
    // Undamped: the eigenvector is real up to one complex factor.
    const VectorXcd q = (*pairs)[k].q.head(n);
    Eigen::Index largest = 0;
    q.cwiseAbs().maxCoeff(&largest);
    const VectorXd real = (q * (std::abs(q(largest)) / q(largest))).real();
    omega2(k) = std::norm((*pairs)[k].s);
    vectors.col(k) = real / std::sqrt(real.dot(beam.M * real));
  }
  return std::pair{omega2, vectors};
}

}  // namespace

// ======================================================================= API

TimoshenkoSection rectangular_timoshenko_section(double shear_modulus_Pa, double width_m,
                                                 double thickness_m) {
  detail::require_positive("shear_modulus_Pa", shear_modulus_Pa, "Pa");
  detail::require_positive("width_m", width_m, "m");
  detail::require_positive("thickness_m", thickness_m, "m");
  return {kRectangularShearCoefficient * shear_modulus_Pa * width_m * thickness_m,
          thickness_m / std::sqrt(12.0)};
}

std::string ModeOptions::validate() const {
  auto bad = [](const std::string& name, const std::string& expected, double value) {
    return name + ": must be " + expected + ", got " + format_number(value);
  };
  const int max_modes = method == Method::kExact ? kMaxExactModes : kMaxModes;
  if (modes < 1 || modes > max_modes) {
    return bad("modes", "in [1, " + std::to_string(max_modes) + "]", modes);
  }
  // Below ~1e-8 the round-off of the assembled stiffness (cond ~ (L/h)^4) dominates.
  if (!(rel_tol >= 1e-8 && rel_tol <= 0.1)) return bad("rel_tol", "in [1e-8, 0.1]", rel_tol);
  if (elements < 0 || elements > kMaxElements) {
    return bad("elements", "in [0, " + std::to_string(kMaxElements) + "]", elements);
  }
  if (shape_samples < 0 || shape_samples == 1) {
    return bad("shape_samples", "0 or >= 2", shape_samples);
  }
  if (theory == Theory::kTimoshenko) {
    if (method != Method::kFiniteElement) {
      return "theory: Timoshenko needs method kFiniteElement, got kExact";
    }
    for (std::size_t i = 0; i < timoshenko.size(); ++i) {
      const TimoshenkoSection& t = timoshenko[i];
      if (!(t.shear_stiffness_N > 0.0 && std::isfinite(t.shear_stiffness_N))) {
        return bad(detail::indexed("timoshenko", i, "shear_stiffness_N"), "> 0 N", t.shear_stiffness_N);
      }
      if (!(t.radius_of_gyration_m >= 0.0 && std::isfinite(t.radius_of_gyration_m))) {
        return bad(detail::indexed("timoshenko", i, "radius_of_gyration_m"), ">= 0 m",
                   t.radius_of_gyration_m);
      }
    }
  }
  return {};
}

double mode_shape_at(const Mode& mode, double x_m) {
  if (mode.shape.empty()) throw std::invalid_argument("mode: has no shape");
  const double length = mode.shape.back().end_m;
  const double eps = 1e-12 * length;
  if (!(x_m >= -eps && x_m <= length + eps)) fail("x_m", "in [0, " + format_number(length) + "] m", x_m);
  auto it = std::upper_bound(mode.shape.begin(), mode.shape.end(), x_m,
                             [](double x, const ShapePiece& p) { return x < p.end_m; });
  if (it == mode.shape.end()) --it;
  return evaluate_piece(*it, std::clamp(x_m - it->start_m, 0.0, it->end_m - it->start_m));
}

ModalResult free_modes(const std::vector<Section>& sections,
                       const std::vector<PointMass>& point_masses, const ModeOptions& options) {
  const bool fe = options.method == ModeOptions::Method::kFiniteElement;
  const double length = validated_length(sections, fe);
  detail::validate_point_masses(point_masses, length);
  validate_options(options, sections.size());
  const Segmentation seg = segment(sections, point_masses, {}, timoshenko_of(options));
  ModalResult result = fe ? fe_free_modes(seg, options) : exact_free_modes(seg, options);
  fill_shape_table(result, length, options.shape_samples);
  return result;
}

BeamMatrices assemble_beam_matrices(const std::vector<Section>& sections,
                                    const std::vector<PointMass>& point_masses,
                                    const ModeOptions& options,
                                    const std::optional<HandCoupling>& hand) {
  const double length = validated_length(sections, true);
  detail::validate_point_masses(point_masses, length);
  validate_options(options, sections.size());
  if (hand) validate_hand(*hand, length);
  const Segmentation seg =
      hand ? hand_segmentation(sections, point_masses, *hand, options)
           : segment(sections, point_masses, {}, timoshenko_of(options));
  const Mesh mesh = build_mesh(seg, element_counts(seg, options), options);
  const Assembled a = assemble(mesh, hand ? &*hand : nullptr);
  BeamMatrices out;
  out.node_positions_m = mesh.nodes_m;
  out.size = static_cast<int>(a.K.rows());
  auto row_major = [](const MatrixXd& m) {
    std::vector<double> v(m.size());
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        v.data(), m.rows(), m.cols()) = m;
    return v;
  };
  out.stiffness = row_major(a.K);
  out.mass = row_major(a.M);
  out.damping = row_major(a.C);
  return out;
}

ModalResult hand_held_modes(const std::vector<Section>& sections,
                            const std::vector<PointMass>& point_masses, const HandCoupling& hand,
                            const ModeOptions& options) {
  const double length = validated_length(sections, true);
  detail::validate_point_masses(point_masses, length);
  validate_options(options, sections.size());
  if (options.method != ModeOptions::Method::kFiniteElement) {
    throw std::invalid_argument("options.method: the hand-held beam needs kFiniteElement, got kExact");
  }
  validate_hand(hand, length);

  ModalResult result;
  result.method = ModeOptions::Method::kFiniteElement;
  result.theory = options.theory;
  const Segmentation seg = hand_segmentation(sections, point_masses, hand, options);
  const std::vector<int> counts = element_counts(seg, options);
  const Mesh mesh = build_mesh(seg, counts, options);
  result.elements_used = static_cast<int>(mesh.elements.size());  // after merge_tiny_elements
  const Assembled a = assemble(mesh, &hand);

  std::optional<DampedSpectrum> spectrum;
  std::string how;
  if (options.damped_solver == ModeOptions::DampedSolver::kRefined) {
    const Mesh coarse = coarse_mesh(seg, options);
    std::string why = "mesh no finer than the coarse one";
    if (coarse.elements.size() < mesh.elements.size()) {
      spectrum = refined_damped_spectrum(mesh, a, hand, options, coarse, &why);
    }
    how = spectrum ? "quadratic eigenproblem refined from a " + std::to_string(coarse.elements.size()) +
                         "-element state-space solve"
                   : "dense state-space eigenproblem (refinement skipped: " + why + ")";
  } else {
    how = "dense state-space eigenproblem";
  }
  if (!spectrum) spectrum = dense_damped_spectrum(mesh, a, hand, options.modes);
  for (const DampedPair& pair : spectrum->pairs) {
    result.modes.push_back(damped_mode(mesh, a, pair.s, pair.q));
  }
  result.complete = static_cast<int>(result.modes.size()) == options.modes;
  result.message = "finite elements: " + std::to_string(result.elements_used) + " elements, " +
                   how + "; " + std::to_string(spectrum->overdamped) +
                   " overdamped (real) roots not reported";
  fill_shape_table(result, length, options.shape_samples);
  return result;
}

HandCoupling calibrated_hand() {
  HandCoupling hand;
  hand.stiffness_N_m2 = kCalibratedGripStiffness_N_m2;
  hand.damping_N_s_m2 = kCalibratedGripDamping_N_s_m2;
  return hand;
}

std::vector<Section> scale_EI_to_fundamental(const std::vector<Section>& sections,
                                             const std::vector<PointMass>& point_masses,
                                             double f1_Hz, const ModeOptions& options) {
  detail::require_positive("f1_Hz", f1_Hz, "Hz");
  ModeOptions one = options;
  one.modes = 1;
  one.shape_samples = 0;
  std::vector<Section> scaled = sections;
  // Euler-Bernoulli: f ~ sqrt(EI) exactly, one step. Timoshenko: the shear
  // stiffness does not scale, so repeat the step until f1 matches.
  const int steps = options.theory == ModeOptions::Theory::kTimoshenko ? 30 : 1;
  for (int i = 0; i < steps; ++i) {
    const ModalResult r = free_modes(scaled, point_masses, one);
    if (r.modes.empty()) throw std::invalid_argument("sections: no flexible mode found");
    const double ratio = f1_Hz / r.modes[0].frequency_Hz;
    for (Section& s : scaled) s.EI_N_m2 = *s.EI_N_m2 * ratio * ratio;
    if (std::abs(ratio - 1.0) < 1e-13) break;
  }
  return scaled;
}

double uniform_EI_for_fundamental(const std::vector<Section>& sections,
                                  const std::vector<PointMass>& point_masses, double f1_Hz) {
  detail::require_positive("f1_Hz", f1_Hz, "Hz");
  std::vector<Section> unit = sections;
  for (Section& s : unit) s.EI_N_m2 = 1.0;
  ModeOptions one;
  one.modes = 1;
  const ModalResult r = free_modes(unit, point_masses, one);
  if (r.modes.empty()) throw std::invalid_argument("sections: no flexible mode found");
  const double ratio = f1_Hz / r.modes[0].frequency_Hz;
  return ratio * ratio;
}

}  // namespace sweetspot
