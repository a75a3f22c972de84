// Table I, top row, through the installed library: prints F0 and F_w.
#include <cstdio>
#include <sweetspot/evaluate.hpp>

int main() {
  const sweetspot::Design design{sweetspot::Implement::paper_racquet(0.70, 0.25, 0.8)};
  const sweetspot::Evaluation e = sweetspot::evaluate(design);
  std::printf("F0 = %.0f N, F_w = %.0f N\n", e.peak_impact_force_N, e.peak_wrist_force_N);
  return 0;
}
