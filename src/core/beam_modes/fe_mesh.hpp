#pragma once

// Finite elements of the beam: the two-node cubic element (Hermite or
// Timoshenko), the mesh over the segments and the assembled matrices.
// Internal to the beam-mode solvers.

#include <Eigen/Dense>
#include <complex>
#include <optional>
#include <utility>
#include <vector>

#include "core/beam_modes/segmentation.hpp"

namespace sweetspot::beam_detail {

using Complex = std::complex<double>;
using Eigen::Matrix4d;
using Eigen::MatrixXd;
using Eigen::Vector4d;
using Eigen::VectorXcd;
using Eigen::VectorXd;

// (beta h)^4 / kHermiteErrorConstant (fitted on the uniform free-free beam).
inline constexpr double kHermiteErrorConstant = 1440.0;
// Elements are sized for this fraction of the requested tolerance (safety).
inline constexpr double kToleranceSafety = 0.5;
// Elements per requested mode for the coarse mesh that locates the hand-held
// modes: beta h <= 2 at the highest requested bending mode, 2^4 / 1440 =
// 1 % in frequency, far inside the gaps between modes.
inline constexpr double kCoarseBetaH = 2.0;

// Integral of xi^n over [s, e].
inline double moment_over(int n, double s, double e) {
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
    c << 1, 0, 0, 0,             //
        0, 1, 0, 6 * g,          //
        1, h, h * h, h * h * h,  //
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
    const bool one_EI = std::all_of(pieces.begin(), pieces.end(), [&](const ElementPiece& p) {
      return p.EI == pieces.front().EI;
    });
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
      for (int j = 0; j < 4; ++j)
        ga(i, j) = s == 0.0 && e == h ? moment(i + j) : moment_over(i + j, s, e);
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
      const double I0 = moment(0), I1 = moment(1), I2 = moment(2), I3 = moment(3), I4 = moment(4);
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

struct Assembled {
  MatrixXd K, M, C;
  int beam_dofs = 0;
};

// The mesh of `counts` elements per segment (counts_for), tiny elements
// merged, but never across a node at one of `keep_nodes` (a support's ends).
Mesh build_mesh(const Segmentation& seg, const std::vector<int>& counts, const ModeOptions& options,
                const std::vector<double>& keep_nodes = {});

// K, M and C (grip dashpots) of the mesh, dense; the hand's two DOFs last.
Assembled assemble(const Mesh& mesh, const HandCoupling* hand);

// A hand joined by neither spring nor dashpot moves on its own: its
// translation and rotation are rigid-body motions too.
bool hand_detached(const HandCoupling* hand);

// Roots s = 0 of the damped problem that no deflation removes: a grip with a
// dashpot but no spring lets the hand drift from the beam (one root per hand
// DOF). They are simple, so round-off moves them by ~eps |A| only.
int drift_roots(const HandCoupling& hand);

// Basis of the M-orthogonal complement of the rigid-body motions (translation
// and rotation of beam and hand together, or of each alone when the hand is
// detached): K and C vanish on the rigid motions, so q = Q b decouples them
// exactly and the reduced problem has no zero modes.
MatrixXd flexible_basis(const Mesh& mesh, const Assembled& a, const HandCoupling* hand);

// Q^T K Q and Q^T M Q for that basis, found by applying its Householder
// reflections (one per rigid motion) to both sides of K and M: O(n^2) each,
// where forming Q and multiplying is O(n^3). Equal to the products to
// round-off, not bit for bit.
struct FlexibleMatrices {
  MatrixXd K, M;
};
FlexibleMatrices flexible_matrices(const Mesh& mesh, const Assembled& a, const HandCoupling* hand);

// Up to this many segments every one has at least one element (a few
// dozen dense DOFs at most); beyond, runs of short segments share elements.
inline constexpr std::size_t kMaxFollowedSegments = 64;

// Elements per segment for `per_phase_weight` elements per unit phase: a
// segment asking for at least one element gets ceil of what it asks. Above
// kMaxFollowedSegments segments (Euler-Bernoulli), a run
// of consecutive segments each asking for less shares elements, each closed
// once the run has asked for one (count 0: the segment joins the element
// that the next segment with count 1 closes). So elements follow the sizing,
// not the sections: 10 000 short sections make a few dozen elements, where
// one element each made a dense problem of 20 000 DOFs.
// `share_short`: runs of short segments share elements whatever their number.
std::vector<int> counts_for(const Segmentation& seg, double per_phase_weight,
                            bool share_short = false);

double total_phase_weight(const Segmentation& seg);

// Elements per segment: explicit total, or sized so the f1 error is about
// rel_tol from the h^4 convergence of the cubic element, (beta h)^4 / 1440,
// with beta from a coarse first estimate of f1.
// `free_omega1`, when known (the exact free fundamental of the same beam
// [rad/s]), takes the place of the coarse estimate wherever every estimate
// within kKnownFundamentalBand of it gives the same counts: the estimate, two
// elements per radian, lies within ~1e-4 of the exact value (h^4 error
// (beta h)^4 / 1440 <= 5e-5 at beta h <= 0.5), so the counts, and the mesh, are
// the ones it gives.
inline constexpr double kKnownFundamentalBand = 1e-3;
std::vector<int> element_counts(const Segmentation& seg, const ModeOptions& options,
                                std::optional<double> free_omega1 = std::nullopt);

int total_elements(const std::vector<int>& counts);

// The coarse mesh on which the lowest `modes` are located before refinement:
// kCoarseBetaH radians of phase per element at mode modes + 1/2.
// With `share_short` (the hand-held modes), a mesh that one element per
// segment would make more than kCoarseFollowedShare times the sizing lets runs
// of short segments share elements (counts_for), so the coarse solve stays
// coarse on a frame of many sections.
inline constexpr double kCoarseFollowedShare = 2.0;
Mesh coarse_mesh(const Segmentation& seg, const ModeOptions& options, bool share_short = false);

// Coarse DOFs carried to the nodes of `fine` through the coarse elements'
// interpolation (w and theta of the cubic), hand DOFs as they are.
VectorXcd interpolate_dofs(const Mesh& coarse, const VectorXcd& q, const Mesh& fine, int fine_size);

}  // namespace sweetspot::beam_detail
