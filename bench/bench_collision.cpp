// `sweetspot bench collision`: one solved collision of the typical racquet,
// its time against its error.

#include <fmt/format.h>
#include <time.h>

#include <cmath>
#include <vector>

#include "bench/bench.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "sweetspot/collision.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/mode_cache.hpp"

namespace sweetspot::bench {
namespace {

// This thread's CPU time [us]: on a machine shared with other work, the time
// the solve itself takes on its core, not the time it waits for one.
double thread_cpu_us() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e6 * static_cast<double>(t.tv_sec) + 1e-3 * static_cast<double>(t.tv_nsec);
}

// Median CPU time of one call of `run` [us], over `repeats` batches of `calls`.
template <class F>
double median_us(int repeats, int calls, F&& run) {
  std::vector<double> us;
  for (int i = 0; i < repeats; ++i) {
    const double start = thread_cpu_us();
    for (int c = 0; c < calls; ++c) run();
    us.push_back((thread_cpu_us() - start) / calls);
  }
  return median(us);
}

}  // namespace

void bench_collision(const BenchOptions& options, std::ostream& log) {
  // designs/racquets/tour-100.json with a 250 N string bed, hit 16 cm from the tip.
  Design d{Implement::from_specs({27.0 * 0.0254, 0.305, 0.325, 0.0320})};
  d.stiffness.fundamental_free_Hz = 155.0;
  d.impact_from_butt_m = d.implement.length_m() - 0.16;
  d.strings = StringBed{};
  d.cor_given = false;
  ResponseOptions ro;
  ro.modes = 6;
  const ResponseModel model = response_model(d, ro);
  const FrameAtImpact frame = frame_at_impact(model, d.impact_from_butt_m);
  const StringBedDynamics bed = string_bed_dynamics(*d.strings);
  auto solve = [&](int steps, bool extrapolate) {
    CollisionOptions o;
    o.steps_per_contact = steps;
    o.extrapolate = extrapolate;
    return collide(frame, bed, d.ball.mass_kg, d.ball_contact, d.ball.speed_m_s, o);
  };
  std::string md =
      "# The solved collision: speed against error\n\nMeasured by `sweetspot bench "
      "collision` on " +
      machine_description() + ". Median of " + std::to_string(options.repeats) +
      " runs on one core.\n\nThe typical racquet (designs/racquets/tour-100.json, "
      "free, 6 modes to 3 kHz), strung at 250 N, hit 16 cm from the tip at 50 m/s "
      "by the calibrated tennis ball. Error: against the same solve at a tenth of "
      "the step (extrapolated likewise), and against a 100 000-step unextrapolated "
      "reference.\n\n"
      "| steps per contact | extrapolated | steps taken | time (us) | e_A | error vs "
      "a tenth of the step | error vs reference | contact time error (s) |\n"
      "|---:|---|---:|---:|---:|---:|---:|---:|\n";
  std::string csv =
      "steps_per_contact,extrapolated,steps,median_us,apparent_cor,error_tenth,error_reference\n";
  const CollisionResult reference = solve(100000, false);
  double default_us = 0.0, default_error = 0.0;
  for (const bool extrapolate : {false, true}) {
    for (const int steps : {16, 32, 64, 128, 256, 512}) {
      const CollisionResult r = solve(steps, extrapolate);
      const CollisionResult tenth = solve(10 * steps, extrapolate);
      const double us = median_us(options.repeats, 200, [&] { solve(steps, extrapolate); });
      const double error_tenth = r.apparent_cor - tenth.apparent_cor;
      const double error_ref = r.apparent_cor - reference.apparent_cor;
      md += fmt::format("| {} | {} | {} | {:.1f} | {:.7f} | {:.1e} | {:.1e} | {:.1e} |\n", steps,
                        extrapolate ? "yes" : "no", r.steps, us, r.apparent_cor, error_tenth,
                        error_ref, r.contact_time_s - reference.contact_time_s);
      csv +=
          fmt::format("{},{},{},{},{},{},{}\n", steps, extrapolate ? 1 : 0, r.steps, io::exact(us),
                      io::exact(r.apparent_cor), io::exact(error_tenth), io::exact(error_ref));
      if (extrapolate && steps == CollisionOptions{}.steps_per_contact) {
        default_us = us;
        default_error = error_tenth;
      }
    }
  }
  const double modes_us = median_us(options.repeats, 5, [&] { response_model(d, ro); });
  const double evaluate_us =
      median_us(options.repeats, 5, [&] { evaluate(d, Fidelity::kCollision); });
  // A catalogue row or a study point that changes only the impact: the
  // frame's modes kept by a ModeCache (as the studies keep them per thread).
  ModeCache cache;
  Design moved = d;
  int row = 0;
  const double row_us = median_us(options.repeats, 50, [&] {
    moved.impact_from_butt_m = d.impact_from_butt_m - 0.001 * (row++ % 20);
    evaluate(moved, Fidelity::kCollision, {.rel_tol = 1e-6, .modes = &cache});
  });
  md += fmt::format(
      "\nThe default (64 steps per contact, extrapolated): {:.1f} us after the modes are known, "
      "error {:.1e} in the COR against a tenth of the step. The free modes take {:.0f} us; "
      "`evaluate` at fidelity collision (the free modes, the collision, the rigid model and the "
      "hand-held modes for the modal outputs) {:.0f} us; the same for a catalogue row or a study "
      "point that changes only the impact (the frame's modes kept, mode_cache.hpp) {:.0f} us."
      "\n\nTargets (issues 12 and 22): 1e-6 in the COR in at most 50 us after the modes are "
      "known ({}); at most 100 us in all, modes included ({}); a row that changes only the "
      "impact at most 100 us ({}).\n",
      default_us, default_error, modes_us, evaluate_us, row_us,
      default_us <= 50.0 && std::abs(default_error) <= 1e-6 ? "met" : "NOT met",
      evaluate_us <= 100.0 ? "met" : "NOT met", row_us <= 100.0 ? "met" : "NOT met");
  io::write_file_atomically(options.out_dir + "/speed-vs-error-collision.md", md);
  io::write_file_atomically(options.out_dir + "/speed-vs-error-collision.csv", csv);
  log << fmt::format("collision: {:.1f} us, error {:.1e}; wrote {}/speed-vs-error-collision.md\n",
                     default_us, default_error, options.out_dir);
}

}  // namespace sweetspot::bench
