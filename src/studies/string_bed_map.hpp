#pragma once

// The string bed in two dimensions (`sweetspot map`): the rigid model (and,
// with the frame's stiffness, the vibration the impact excites) evaluated on a
// grid over the head's ellipse. Plain data, so that a report can draw it.

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "sweetspot/design.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/head_geometry.hpp"

namespace sweetspot::studies {

struct StringBedMapOptions {
  int columns = 50;  // grid points along the long axis (x), in [2, 1000]
  int rows = 50;     // grid points across it (y), in [2, 1000]
  // kModal or kResponse: also the vibration energy each impact leaves in the
  // free frame's modes (needs the frame's stiffness); kCollision: the solved
  // collision at every point (needs the string tension and the stiffness, no
  // COR): its rebound, its peak force and the vibration it leaves; kRigid:
  // power and shock only.
  Fidelity fidelity = Fidelity::kRigid;
  // Threads the grid's columns are shared among (>= 1); the map is the same
  // whatever their number.
  int threads = 1;
  // Called on the calling thread now and then with the grid points done and
  // their total (for a progress line); may be empty.
  std::function<void(std::size_t, std::size_t)> progress;
};

// One grid point. Values are those of evaluate() at (x, y) with the design's
// other inputs, the duration re-derived at each point when it comes from the
// string tension.
struct StringBedMapPoint {
  double from_butt_m = 0.0;  // x [m]
  double off_axis_m = 0.0;   // y [m], > 0 towards 3 o'clock
  bool on_bed = false;       // inside the string bed's ellipse; the values below only then
  double effective_mass_kg = 0.0;
  double apparent_cor = 0.0;           // power
  double peak_wrist_force_N = 0.0;     // shock
  double peak_twist_torque_N_m = 0.0;  // F0 |y|
  // Feel (modal level): the energy left in the free frame's modes [J]; none
  // where it would exceed what the ball loses (the response model's limit,
  // where evaluate() refuses the design).
  std::optional<double> vibration_energy_J;
};

struct StringBedMap {
  HeadEllipse bed;
  int columns = 0, rows = 0;
  // Cell centres, x fastest: point (i, j) is points[j * columns + i], x_i
  // increasing, y_j increasing (y_j = -y_{rows-1-j} exactly).
  std::vector<StringBedMapPoint> points;
  double polar_inertia_kg_m2 = 0.0;
  bool polar_inertia_estimated = false;
  std::optional<double> cop_hand_from_butt_m;   // the hand-held COP (least shock), Eq. (13)
  std::optional<double> node_free_from_butt_m;  // the free fundamental's node (least vibration)
  Fidelity fidelity = Fidelity::kRigid;
};

// The map of `design` (validated; its polar inertia must be known: a
// twistweight or a head, and its head gives the ellipse: without a head, an
// ellipse of the default shape whose area is a 100 in^2 head). Throws
// std::invalid_argument naming the design's input at fault (the caller
// rethrows it at the file's key), or "--rows"/"--columns" for the grid.
StringBedMap string_bed_map(const Design& design, const StringBedMapOptions& options = {});

}  // namespace sweetspot::studies
