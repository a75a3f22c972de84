#pragma once

// Free finite-element modes: the dense symmetric solve, the coarse-to-fine
// refinement of large meshes, and the finite-element count that checks the
// exact solver. Internal to the beam-mode solvers.

#include <optional>
#include <string>
#include <utility>

#include "core/beam_modes/fe_mesh.hpp"

namespace sweetspot::beam_detail {

// Lowest flexible omega^2 eigenvalues and M-normalised eigenvectors.
std::pair<VectorXd, MatrixXd> free_spectrum(const Mesh& mesh);

// The lowest flexible omega^2 (eigenvalues only, as free_spectrum).
double lowest_free_omega2(const Mesh& mesh);

// The mode of FE eigenvector q; also returns the factor between its shape and q.
std::pair<Mode, double> fe_mode(const Mesh& mesh, const VectorXd& q, double omega);

// How many flexible modes a finite-element mesh finds below the highest of
// `found` beyond those found (0 when none were missed, or when the beam has a
// massless section the elements cannot take), and how many elements give
// the `wanted`-th mode to rel_tol (the usual sizing looks at f1 only, which
// here may be a near-rigid hinge mode).
struct RootCount {
  int missed = 0;
  int elements = 0;
};
RootCount missed_roots(const Segmentation& seg, const ModalResult& found, int wanted,
                       double rel_tol);

// The free modes by finite elements (options.method is kFiniteElement).
ModalResult fe_free_modes(const Segmentation& seg, const ModeOptions& options);

}  // namespace sweetspot::beam_detail
