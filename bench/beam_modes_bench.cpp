// Cost of one modal solve for a two-section racquet (stiff head, softer
// handle, lead tape), per method and tolerance. The target is f1 to 1e-6 and
// the node nearest the tip to 0.1 mm in <= 10 us with the exact solver.
#include <benchmark/benchmark.h>

#include <cmath>

#include "sweetspot/beam_modes.hpp"

namespace {

using sweetspot::ModeOptions;

const std::vector<sweetspot::Section> kRacquet{{0.34, 0.15, 180.0}, {0.345, 0.17, 95.0}};
const std::vector<sweetspot::PointMass> kTape{{0.50, 0.012}};

void BM_ExactFundamentalAndNodes(benchmark::State& state) {
  ModeOptions o;
  o.modes = static_cast<int>(state.range(0));
  for (auto _ : state) {
    auto r = sweetspot::free_modes(kRacquet, {}, o);
    benchmark::DoNotOptimize(r.modes.back().nodes_from_butt_m.back());
  }
}
BENCHMARK(BM_ExactFundamentalAndNodes)->Arg(1)->Arg(3)->Arg(5)->Unit(benchmark::kMicrosecond);

void BM_ExactWithPointMass(benchmark::State& state) {
  ModeOptions o;
  o.modes = 1;
  for (auto _ : state) {
    auto r = sweetspot::free_modes(kRacquet, kTape, o);
    benchmark::DoNotOptimize(r.modes[0].nodes_from_butt_m.back());
  }
}
BENCHMARK(BM_ExactWithPointMass)->Unit(benchmark::kMicrosecond);

void BM_FiniteElement(benchmark::State& state) {
  ModeOptions o;
  o.modes = 3;
  o.method = ModeOptions::Method::kFiniteElement;
  o.rel_tol = std::pow(10.0, -static_cast<double>(state.range(0)));
  int elements = 0;
  for (auto _ : state) {
    auto r = sweetspot::free_modes(kRacquet, kTape, o);
    elements = r.elements_used;
    benchmark::DoNotOptimize(r.modes[0].frequency_Hz);
  }
  state.counters["elements"] = elements;
}
BENCHMARK(BM_FiniteElement)->DenseRange(3, 8, 1)->Unit(benchmark::kMicrosecond);

void BM_Timoshenko(benchmark::State& state) {
  ModeOptions o;
  o.modes = 3;
  o.method = ModeOptions::Method::kFiniteElement;
  o.theory = ModeOptions::Theory::kTimoshenko;
  o.timoshenko.assign(2, sweetspot::rectangular_timoshenko_section(1e9, 0.02, 0.025));
  for (auto _ : state) {
    auto r = sweetspot::free_modes(kRacquet, kTape, o);
    benchmark::DoNotOptimize(r.modes[0].frequency_Hz);
  }
}
BENCHMARK(BM_Timoshenko)->Unit(benchmark::kMicrosecond);

void BM_HandHeld(benchmark::State& state) {
  ModeOptions o;
  o.modes = 3;
  o.method = ModeOptions::Method::kFiniteElement;
  o.rel_tol = std::pow(10.0, -static_cast<double>(state.range(0)));
  int elements = 0;
  for (auto _ : state) {
    auto r = sweetspot::hand_held_modes(kRacquet, kTape, sweetspot::calibrated_hand(), o);
    elements = r.elements_used;
    benchmark::DoNotOptimize(r.modes[0].frequency_Hz);
  }
  state.counters["elements"] = elements;
}
BENCHMARK(BM_HandHeld)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMicrosecond);

// The O(n^3) reference the refined solver replaces.
void BM_HandHeldDenseStateSpace(benchmark::State& state) {
  ModeOptions o;
  o.modes = 3;
  o.method = ModeOptions::Method::kFiniteElement;
  o.damped_solver = ModeOptions::DampedSolver::kDenseStateSpace;
  o.rel_tol = std::pow(10.0, -static_cast<double>(state.range(0)));
  int elements = 0;
  for (auto _ : state) {
    auto r = sweetspot::hand_held_modes(kRacquet, kTape, sweetspot::calibrated_hand(), o);
    elements = r.elements_used;
    benchmark::DoNotOptimize(r.modes[0].frequency_Hz);
  }
  state.counters["elements"] = elements;
}
BENCHMARK(BM_HandHeldDenseStateSpace)->Arg(4)->Arg(6)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
