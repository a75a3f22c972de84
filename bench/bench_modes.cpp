// Speed against accuracy of the modal solvers on the optimizer's study racquet:
// two sections of 0.35 m (handle 0.139 kg, head 0.111 kg: head/handle 0.8,
// 0.25 kg in all), one EI for a free Euler-Bernoulli f1 of 150 Hz, 6 g at
// 0.68 m; the hand-held rows use calibrated_hand() (grip 0.02-0.12 m).
//
// Returns CSV, one row per method and resolution:
//   method, resolution, elements, median_us, f1_Hz, f1_rel_error, node_m,
//   node_abs_error_m, order, reference
// f1 is the fundamental (hand held: the first mode with hand_energy_fraction
// < 0.5, damped frequency) and node_m its node nearest the tip. Errors are
// against `reference`: the exact transfer-matrix solver for free
// Euler-Bernoulli, the finest mesh of the same method otherwise. `order` is
// log2 of the f1 error ratio to the previous row (mesh doubled); it reads ~4
// while discretisation dominates and drops to noise at the round-off floor.
// median_us: median wall time of one call over repeated calls (one thread).
//
// `budget_ms` is the time spent per row (the median of as many calls as fit).
#include <fmt/printf.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "bench/bench.hpp"
#include "sweetspot/beam_modes.hpp"

namespace {

using namespace sweetspot;

struct Fundamental {
  double f_Hz = NAN;
  double node_m = NAN;
  int elements = 0;
};

std::vector<Section> study_racquet() {
  const double length = 0.70, mass = 0.25, handle = mass / 1.8;
  std::vector<Section> s{{length / 2, handle, 1.0}, {length / 2, mass - handle, 1.0}};
  return s;
}

const std::vector<PointMass> kTape{{0.68, 0.006}};

Fundamental fundamental_of(const ModalResult& r, bool hand_held) {
  for (const Mode& m : r.modes) {
    if (hand_held && m.hand_energy_fraction >= 0.5) continue;
    Fundamental f;
    f.f_Hz = m.frequency_Hz;
    f.node_m = m.nodes_from_butt_m.empty() ? NAN : m.nodes_from_butt_m.back();
    f.elements = r.elements_used;
    return f;
  }
  return {};
}

// Median wall time [us] of `solve` over as many calls as fit in budget_ms
// (at least 3, at most 1001), and its last result.
std::pair<double, Fundamental> time_it(const std::function<Fundamental()>& solve,
                                       double budget_ms) {
  std::vector<double> us;
  Fundamental last;
  double spent = 0.0;
  while (us.size() < 3 || (spent < budget_ms * 1e3 && us.size() < 1001)) {
    const auto t0 = std::chrono::steady_clock::now();
    last = solve();
    const double t =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
    us.push_back(t);
    spent += t;
  }
  return {sweetspot::bench::median(us), last};
}

struct Row {
  std::string method, resolution;
  double us = 0.0;
  Fundamental f;
};

void print(std::string& out, const std::vector<Row>& rows, const Fundamental& ref,
           const std::string& ref_name) {
  double previous_error = NAN;
  for (const Row& r : rows) {
    const double error = std::abs(r.f.f_Hz / ref.f_Hz - 1.0);
    const double node_error = std::abs(r.f.node_m - ref.node_m);
    const double order = std::log2(previous_error / error);
    out += fmt::sprintf(
        "%s,%s,%d,%.2f,%.12f,%.3e,%.9f,%.3e,%s,%s\n", r.method.c_str(), r.resolution.c_str(),
        r.f.elements, r.us, r.f.f_Hz, error, r.f.node_m, node_error,
        std::isfinite(order) ? std::to_string(order).substr(0, 5).c_str() : "", ref_name.c_str());
    previous_error = error;
  }
}

}  // namespace

namespace sweetspot::bench {

std::string speed_vs_error_modes_csv(double budget_ms) {
  std::string out;
  std::vector<Section> racquet = study_racquet();
  const double EI = uniform_EI_for_fundamental(racquet, kTape, 150.0);
  for (Section& s : racquet) s.EI_N_m2 = EI;
  const HandCoupling hand = calibrated_hand();

  out +=
      "method,resolution,elements,median_us,f1_Hz,f1_rel_error,node_m,node_abs_error_m,"
      "order,reference\n";

  // Free Euler-Bernoulli: exact against itself, FE against exact.
  ModeOptions exact;
  exact.modes = 1;
  auto solve_exact = [&] { return fundamental_of(free_modes(racquet, kTape, exact), false); };
  const auto [exact_us, exact_f] = time_it(solve_exact, budget_ms);
  print(out, {{"exact", "roots to 1e-13", exact_us, exact_f}}, exact_f, "exact");

  ModeOptions fe;
  fe.modes = 1;
  fe.method = ModeOptions::Method::kFiniteElement;
  auto fe_rows = [&](const std::string& name, ModeOptions o, const std::vector<int>& meshes,
                     bool hand_held) {
    std::vector<Row> rows;
    for (int n : meshes) {
      o.elements = n;
      const bool big = n > 256 || (hand_held && n > 64 &&
                                   o.damped_solver == ModeOptions::DampedSolver::kDenseStateSpace);
      auto solve = [&] {
        return fundamental_of(
            hand_held ? hand_held_modes(racquet, kTape, hand, o) : free_modes(racquet, kTape, o),
            hand_held);
      };
      const auto [us, f] = time_it(solve, big ? 0.0 : budget_ms);
      rows.push_back({name, "elements=" + std::to_string(n), us, f});
    }
    return rows;
  };
  const std::vector<int> meshes{4, 8, 16, 32, 64, 128, 256, 512};
  print(out, fe_rows("fe-eb", fe, meshes, false), exact_f, "exact");

  ModeOptions timoshenko = fe;
  timoshenko.theory = ModeOptions::Theory::kTimoshenko;
  timoshenko.timoshenko.assign(2, rectangular_timoshenko_section(1e9, 0.02, 0.025));
  {
    ModeOptions finest = timoshenko;
    finest.elements = 1024;
    const Fundamental ref = fundamental_of(free_modes(racquet, kTape, finest), false);
    print(out, fe_rows("fe-timoshenko", timoshenko, {4, 8, 16, 32, 64, 128, 256}, false), ref,
          "fe-timoshenko elements=1024");
  }

  // Hand held: modes = 3 as frame_modes asks (the hand's rocking mode comes first).
  ModeOptions held = fe;
  held.modes = 3;
  ModeOptions finest = held;
  finest.elements = 256;
  const Fundamental held_ref = fundamental_of(hand_held_modes(racquet, kTape, hand, finest), true);
  const std::string held_ref_name = "hand-held-refined elements=256";
  ModeOptions dense = held;
  dense.damped_solver = ModeOptions::DampedSolver::kDenseStateSpace;
  print(out, fe_rows("hand-held-dense", dense, {4, 8, 16, 32, 64, 128}, true), held_ref,
        held_ref_name);
  print(out, fe_rows("hand-held-refined", held, meshes, true), held_ref, held_ref_name);

  // What the optimizer calls: elements chosen from rel_tol.
  for (auto solver :
       {ModeOptions::DampedSolver::kDenseStateSpace, ModeOptions::DampedSolver::kRefined}) {
    std::vector<Row> rows;
    for (double tol : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
      ModeOptions o = held;
      o.damped_solver = solver;
      o.rel_tol = tol;
      auto solve = [&] { return fundamental_of(hand_held_modes(racquet, kTape, hand, o), true); };
      const bool dense_and_fine =
          solver == ModeOptions::DampedSolver::kDenseStateSpace && tol < 1e-6;
      const auto [us, f] = time_it(solve, dense_and_fine ? 0.0 : budget_ms);
      char res[32];
      std::snprintf(res, sizeof res, "rel_tol=%.0e", tol);
      rows.push_back({solver == ModeOptions::DampedSolver::kRefined ? "hand-held-refined-tol"
                                                                    : "hand-held-dense-tol",
                      res, us, f});
    }
    print(out, rows, held_ref, held_ref_name);
  }
  return out;
}

}  // namespace sweetspot::bench
