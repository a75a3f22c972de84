#include "bench/bench.hpp"

#include <fmt/format.h>
#include <sys/utsname.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/design_reader.hpp"
#include "io/format.hpp"
#include "io/input_error.hpp"
#include "io/json_reader.hpp"
#include "io/plot.hpp"
#include "reports/html_report.hpp"
#include "reports/optimization_report.hpp"
#include "studies/design_binding.hpp"
#include "studies/design_page.hpp"
#include "studies/optimization.hpp"
#include "studies/string_bed_map.hpp"
#include "studies/study.hpp"
#include "studies/sweep.hpp"
#include "sweetspot/beam_modes.hpp"
#include "sweetspot/evaluate.hpp"
#include "sweetspot/kernels.hpp"
#include "sweetspot/string_bed.hpp"

namespace sweetspot::bench {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

template <class F>
double median_seconds(int repeats, F&& run) {
  std::vector<double> seconds;
  for (int i = 0; i < repeats; ++i) {
    const auto start = Clock::now();
    run();
    seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  return median(seconds);
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown CPU";
}

// Which algorithms make sense for a study: constraint-taking ones only when
// it has constraints; derivative-based ones only when it is smooth.
std::vector<std::string> algorithms_for(const studies::Study& study,
                                        const optimizer::Problem& problem) {
  std::vector<std::string> list{"auto"};
  const bool constrained = !study.constraints.empty();
  const bool equality =
      std::any_of(study.constraints.begin(), study.constraints.end(),
                  [](const studies::StudyConstraint& c) { return c.equals.has_value(); });
  if (problem.smooth) list.push_back("LD_SLSQP");
  if (problem.smooth && !equality) list.push_back("LD_MMA");
  list.push_back("LN_COBYLA");
  if (!constrained) list.insert(list.end(), {"LN_BOBYQA", "GN_DIRECT_L"});
  list.push_back("GN_ISRES");
  return list;
}

// The targets of the issue on compiled designs, each against its peer: the
// same work done the obvious way in NumPy/SciPy.
struct StudyFigures {
  double study1_ms, study1_json_ms, study3a_ms, study3a_json_ms, study3a_threads_ms;
};
// The free beam's fundamental by finite elements, in-process.
struct FreeFeFigures {
  double us = 0.0;
  double f1_Hz = 0.0;
};

// Cross (2004)'s beam (0.72 m, 0.328 kg, uniform, EI for a free f1 of 193 Hz)
// on kFreeFeElements Hermite elements: one free_modes() call for the lowest
// mode, as the peer free_fe_eigh.py does it with scipy.linalg.eigh.
FreeFeFigures bench_free_fe(const BenchOptions& options) {
  std::vector<Section> beam{{0.72, 0.328, 1.0}};
  beam[0].EI_N_m2 = uniform_EI_for_fundamental(beam, {}, 193.0);
  ModeOptions o;
  o.method = ModeOptions::Method::kFiniteElement;
  o.elements = kFreeFeElements;
  o.modes = 1;
  constexpr int kCalls = 50;
  FreeFeFigures figures;
  const double seconds = median_seconds(options.repeats, [&] {
    for (int i = 0; i < kCalls; ++i)
      figures.f1_Hz = free_modes(beam, {}, o).modes.at(0).frequency_Hz;
  });
  figures.us = seconds / kCalls * 1e6;
  return figures;
}
std::string targets_section(const ThroughputReport& cli, const PeerFigures& peers,
                            const StudyFigures& studies, double arrays_ns, double cases_ns,
                            const FreeFeFigures& free_fe) {
  const bool have_peers = peers.skipped.empty();
  const auto ratio = [&](double ours, double theirs) {
    return have_peers && ours > 0.0 ? fmt::format("{:.1f}x", theirs / ours) : std::string("-");
  };
  const auto met = [](bool ok) { return ok ? "met" : "NOT met"; };
  std::string md = fmt::format(
      "\n## Designs compiled once: the targets, against NumPy/SciPy\n\n"
      "Every study variable, sweep axis and batch column is bound once to the typed design (its "
      "unit factor and "
      "a setter); each point sets numbers and re-derives only what depends on them. The peers are "
      "`bench/peers/*.py`, the same work written the obvious way in NumPy/SciPy, run with the "
      "system's Python "
      "(whole process for the sweep and the batch, as sweetspot is timed; in-process for the "
      "optimisation and "
      "the rigid model). `faster` is the peer's time over sweetspot's.\n\n{}"
      "| workload | sweetspot | read from JSON (before) | NumPy/SciPy | faster | target | |\n"
      "|---|---:|---:|---:|---:|---|---|\n",
      have_peers ? "" : fmt::format("Peers not run: {}.\n\n", peers.skipped));
  const double sweep_s = cli.every_point_sweep_1_thread_s;
  if (sweep_s > 0.0) {
    md += fmt::format(
        "| sweep, 1000 hand x 1000 forearm masses, one core, whole process (s) | {:.3f} | | {} | "
        "{} | "
        "<= 0.5 s and >= 5x NumPy | {} |\n",
        sweep_s, have_peers ? fmt::format("{:.3f}", peers.every_point_sweep_s) : "-",
        ratio(sweep_s, peers.every_point_sweep_s),
        met(sweep_s <= 0.5 && (!have_peers || peers.every_point_sweep_s >= 5.0 * sweep_s)));
  }
  if (cli.batch_1_thread_s > 0.0) {
    md += fmt::format(
        "| `evaluate --batch`, 100 000 racquets by specs (CSV), one core, whole process (s) | "
        "{:.3f} | | "
        "{} | {} | <= 0.3 s | {} |\n",
        cli.batch_1_thread_s, have_peers ? fmt::format("{:.3f}", peers.batch_s) : "-",
        ratio(cli.batch_1_thread_s, peers.batch_s), met(cli.batch_1_thread_s <= 0.3));
  }
  md += fmt::format(
      "| study 1 (`auto`), one optimisation in-process (ms) | {:.3f} | {:.3f} | {} | {} | <= 0.5 "
      "ms | {} |\n",
      studies.study1_ms, studies.study1_json_ms,
      have_peers
          ? fmt::format("{:.3f} (SLSQP, {} evaluations)", peers.study1_ms, peers.study1_evaluations)
          : "-",
      ratio(studies.study1_ms, peers.study1_ms), met(studies.study1_ms <= 0.5));
  md += fmt::format(
      "| study 3a (`auto`, modal model in the loop) in-process, one thread (ms) | {:.2f} ({:.2f} "
      "on {} threads) | {:.2f} | no peer | | "
      "<= 5 ms | {} |\n",
      studies.study3a_ms, studies.study3a_threads_ms, std::thread::hardware_concurrency(),
      studies.study3a_json_ms, met(studies.study3a_ms <= 5.0));
  md += fmt::format(
      "| rigid model on distinct designs, one core (million per second) | {:.1f} (arrays) | {:.1f} "
      "(`RigidCase`s) | {} | {} | >= 150 | {} |\n",
      1e3 / arrays_ns, 1e3 / cases_ns,
      have_peers ? fmt::format("{:.1f}", 1e3 / peers.rigid_ns) : "-",
      ratio(arrays_ns, peers.rigid_ns), met(1e3 / arrays_ns >= 150.0));
  md += fmt::format(
      "| free finite-element modes, {} elements, the fundamental in-process (us) | {:.1f} | | {} | "
      "{} | no slower than SciPy's `eigh` | {} |\n",
      kFreeFeElements, free_fe.us,
      have_peers ? fmt::format("{:.1f} (`eigh`, lowest flexible mode only)", peers.free_fe_us)
                 : "-",
      ratio(free_fe.us, peers.free_fe_us), met(!have_peers || free_fe.us <= peers.free_fe_us));
  if (have_peers) {
    md += fmt::format(
        "\nThe free finite-element row is at equal accuracy: the same mesh, f1 = {:.9f} Hz here "
        "and {:.9f} Hz from SciPy (the exact 193 Hz to {:.1e}).\n",
        free_fe.f1_Hz, peers.free_fe_f1_Hz, std::abs(free_fe.f1_Hz / 193.0 - 1.0));
  }
  md +=
      "\nStudy 3a spends its time in the modal solvers (the hand-held modes at every evaluation), "
      "not in "
      "reading the design; its peer would be a beam eigen-solver written in SciPy, which is not "
      "written.\n";
  return md;
}

}  // namespace

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string machine_description() {
  utsname u{};
  uname(&u);
  return fmt::format("{} ({} cores visible), Linux {}; {} {}, flags: {}", cpu_model(),
                     std::max(1u, std::thread::hardware_concurrency()), u.release,
#if defined(__clang__)
                     "clang++", __clang_version__,
#else
                     "g++", __VERSION__,
#endif
                     SWEETSPOT_CXX_FLAGS);
}

std::string bench_maps(const BenchOptions& options, std::ostream& log) {
  // A 27 in, 320 g racquet with a 100 in^2 head, Table I's player and ball.
  Design racquet{Implement::paper_racquet(0.6858, 0.320, 1.0)};
  racquet.head = HeadShape{100 * 0.0254 * 0.0254};
  racquet.impact_from_butt_m = 0.6858 - 0.16;
  Design tension = racquet;
  tension.strings = StringBed{};
  Design flexible = racquet;
  flexible.stiffness.fundamental_free_Hz = 150.0;
  Design strung = flexible;  // a tension, a stiffness and no COR: the solved collision
  strung.strings = StringBed{};
  strung.cor_given = false;
  std::string md =
      "\n## String-bed maps\n\n`sweetspot map`'s grid evaluation (`string_bed_map()`), 50 x 50 "
      "points over a 100 in^2 head (about 1960 on the string bed), median of the library call. "
      "Target (issue 14): well under 100 ms at the rigid level, under 1 s at the modal level; the "
      "solved collision at every point (a strung design with a stiffness and no COR) has no "
      "target.\n\n"
      "| map | median (ms) | per point on the bed (us) |\n|---|---:|---:|\n";
  for (const auto& [name, design, fidelity] :
       {std::tuple{"rigid, given duration", &racquet, Fidelity::kRigid},
        std::tuple{"rigid, duration from the string tension", &tension, Fidelity::kRigid},
        std::tuple{"modal (vibration energy; modes solved once)", &flexible, Fidelity::kModal},
        std::tuple{"collision (one solved collision per point)", &strung, Fidelity::kCollision}}) {
    studies::StringBedMapOptions grid;
    grid.columns = 50;
    grid.rows = 50;
    grid.fidelity = fidelity;
    std::size_t on_bed = 0;
    const double seconds = median_seconds(options.repeats, [&, design = design] {
      const studies::StringBedMap map = string_bed_map(*design, grid);
      on_bed = 0;
      for (const studies::StringBedMapPoint& p : map.points) on_bed += p.on_bed ? 1 : 0;
    });
    md += fmt::format("| {} | {:.2f} | {:.2f} |\n", name, seconds * 1e3,
                      seconds * 1e6 / static_cast<double>(on_bed));
    log << fmt::format("map 50 x 50, {}: {:.2f} ms\n", name, seconds * 1e3);
  }
  // The page a coach opens: every table, the drawings and the curves, and
  // the three maps drawn by gnuplot as inline SVG (one gnuplot run per plot).
  const fs::path page_design = fs::path(options.designs_dir) / "racquets" / "tour-100.json";
  if (fs::exists(page_design)) {
    const io::DesignFile file = io::load_design(page_design.string());
    const io::Json document = io::read_json_file(page_design.string());
    std::string page;
    const double seconds = median_seconds(options.repeats, [&] {
      page = reports::design_html_report(file, document, studies::design_page(file));
    });
    std::size_t figures = 0;
    for (std::size_t at = page.find("<svg"); at != std::string::npos;
         at = page.find("<svg", at + 1))
      ++figures;
    md += fmt::format(
        "\nThe HTML page of `designs/racquets/tour-100.json` (`sweetspot report DESIGN --html`, "
        "in-process: every number, and {} inline SVG figures, the plots and maps drawn by "
        "gnuplot): {:.0f} ms, {:.0f} kB.\n",
        figures, seconds * 1e3, static_cast<double>(page.size()) / 1024.0);
    log << fmt::format("HTML page of tour-100: {:.0f} ms\n", seconds * 1e3);
  }
  return md;
}

void require_bench_speed_inputs(const BenchOptions& options) {
  const fs::path studies = fs::path(options.designs_dir) / "studies";
  if (!fs::is_directory(studies)) {
    throw io::InputError(studies.string(), "",
                         "not a folder of studies (bench speed times every study in "
                         "DESIGNS/studies; give the designs folder with --designs)");
  }
}

void bench_speed(const BenchOptions& options, std::ostream& log) {
  // The inputs first: a wrong folder fails at once, not after the timings.
  require_bench_speed_inputs(options);
  // Rigid evaluations through the library, one core, no allocation: distinct
  // designs (mass, balance, hand, impact all vary) as RigidCases, 4096 at a
  // time (360 kB of cases and 230 kB of outcomes: the working set of a chunk).
  constexpr int kCases = 4096;
  std::vector<RigidCase> cases;
  for (int i = 0; i < kCases; ++i) {
    Design d{Implement::paper_racquet(0.68 + 0.001 * (i % 7), 0.25 + 0.001 * (i % 97),
                                      0.8 + 0.01 * (i % 41))};
    d.hand.mass_kg = 0.3 + 0.05 * (i % 5);
    d.impact_from_butt_m = 0.30 + 0.003 * (i % 113);
    cases.push_back(rigid_case(d));
  }
  std::vector<RigidOutcome> outcomes(kCases);
  constexpr int kPasses = 2000;  // 8.2 million cases per run
  double sink = 0.0;
  const double cases_seconds = median_seconds(options.repeats, [&] {
    for (int pass = 0; pass < kPasses; ++pass) {
      rigid_outcomes(cases, outcomes);
      sink += outcomes[pass % kCases].peak_wrist_force_N;
    }
  });
  const double cases_ns = cases_seconds / (double(kPasses) * kCases) * 1e9;
  // The same cases laid out as arrays (RigidCases): the vectorised loop.
  std::vector<std::vector<double>> in(11, std::vector<double>(kCases));
  std::vector<std::vector<double>> out(7, std::vector<double>(kCases));
  for (int i = 0; i < kCases; ++i) {
    const RigidCase& c = cases[i];
    const double fields[11] = {
        c.body.mass_kg, c.body.com_from_butt_m,       c.body.I_cm_kg_m2,   c.hand.from_butt_m,
        c.hand.mass_kg, c.forearm_equivalent_mass_kg, c.ball_mass_kg,      c.ball_speed_m_s,
        c.cor,          c.impact_duration_s,          c.impact_from_butt_m};
    for (int k = 0; k < 11; ++k) in[k][i] = fields[k];
  }
  const RigidCases arrays{in[0], in[1], in[2], in[3], in[4], in[5],
                          in[6], in[7], in[8], in[9], in[10]};
  const RigidOutcomes arrays_out{out[0], out[1], out[2], out[3], out[4], out[5], out[6]};
  const double arrays_seconds = median_seconds(options.repeats, [&] {
    for (int pass = 0; pass < kPasses; ++pass) {
      rigid_outcomes(arrays, arrays_out);
      sink += out[6][pass % kCases];
    }
  });
  const double arrays_ns = arrays_seconds / (double(kPasses) * kCases) * 1e9;
  // Every quantity of an Evaluation (rotation axes, system properties, ...).
  Design design{Implement::paper_racquet(0.70, 0.25, 0.8)};
  validate(design);
  constexpr int kEvaluations = 5'000'000;
  const double rigid_seconds = median_seconds(options.repeats, [&] {
    for (int i = 0; i < kEvaluations; ++i) {
      design.impact_from_butt_m = 0.30 + (i & 1023) * 3e-4;
      sink += evaluate_unchecked(design).peak_wrist_force_N;
    }
  });
  const double rigid_ns = rigid_seconds / kEvaluations * 1e9;
  // The same design at many impact points through ImpactSweep.
  const ImpactSweep sweep(design);
  const double sweep_seconds = median_seconds(options.repeats, [&] {
    for (int i = 0; i < kEvaluations; ++i)
      sink += sweep.at(0.30 + (i & 1023) * 3e-4).peak_wrist_force_N;
  });
  const double sweep_ns = sweep_seconds / kEvaluations * 1e9;
  log << fmt::format(
      "rigid: {:.1f} ns per case, {:.2f} ns per case as arrays, {:.1f} ns per Evaluation, "
      "{:.1f} ns per further impact\n",
      cases_ns, arrays_ns, rigid_ns, sweep_ns);
  const ThroughputReport cli = bench_throughput(options, log);
  const PeerFigures peers = bench_peers(options, log);
  // In-process, one core: a sweep's points set on the compiled design,
  // against the same read from JSON (the path they took before, kept as the
  // reference the tests compare with).
  const studies::Study every_point = studies::read_study(
      io::Json::parse(
          R"({"design": {"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
          "strings": {"impact_duration_ms": 4}, "hand": {"mass_kg": 0.5, "center_from_butt_m": 0.07},
          "forearm": {"equivalent_mass_kg": 0.5}, "impact": {"from_tip_m": 0.05}},
          "outputs": ["peak_wrist_force_N"],
          "variables": [{"path": "/hand/mass_kg", "min": 0.3, "max": 0.6, "points": 1000},
                        {"path": "/forearm/equivalent_mass_kg", "min": 0.1, "max": 1.0, "points": 100}]})"),
      "bench", options.designs_dir);
  const auto sweep_us = [&](bool compiled) {
    const double seconds = median_seconds(options.repeats, [&] {
      std::ostringstream csv;
      studies::run_sweep(
          every_point, csv, [](std::size_t, std::size_t) {},
          studies::SweepOptions{1, true, compiled});
      sink += static_cast<double>(csv.str().size());
    });
    return seconds / 1e5 * 1e6;
  };
  const double sweep_json_us = sweep_us(false);
  const double sweep_compiled_us = sweep_us(true);
  log << fmt::format("sweep point in-process: {:.3f} us read from JSON, {:.3f} us compiled\n",
                     sweep_json_us, sweep_compiled_us);

  std::string csv = "library,ns_per_evaluation,million_per_s\n";
  for (const auto& [name, ns] :
       {std::pair{"rigid_outcomes", cases_ns}, std::pair{"rigid_outcomes_arrays", arrays_ns},
        std::pair{"evaluate_unchecked", rigid_ns}, std::pair{"ImpactSweep::at", sweep_ns}}) {
    csv += fmt::format("{},{},{}\n", name, io::exact(ns), io::exact(1e3 / ns));
  }
  if (!cli.csv.empty()) csv += "\n" + cli.csv;
  csv += "\nstudy,algorithm,evaluations,median_ms,objective,feasible,excess_over_best\n";
  std::string md = fmt::format(
      "# Speed against error\n\nMeasured by `sweetspot bench speed` on {}. Every library time is "
      "the median "
      "of {} runs on one core.\n\n## Rigid model, in the library\n\n"
      "| what | ns per evaluation | million per second |\n|---|---:|---:|\n"
      "| `rigid_outcomes`: distinct designs as `RigidCase`s (F0, F_w, COP, M_eff, e_A, J) | {:.1f} "
      "| {:.1f} |\n"
      "| `rigid_outcomes`: the same designs as arrays (`RigidCases`), the vectorised loop | {:.2f} "
      "| {:.1f} |\n"
      "| `evaluate_unchecked`: one `Evaluation`, every quantity of the paper | {:.1f} | {:.1f} |\n"
      "| `ImpactSweep::at`: a further impact point of the same design, every quantity | {:.1f} | "
      "{:.1f} |\n\n"
      "Target: at least 150 million rigid evaluations per second on one core ({}). The cases vary "
      "in "
      "mass, balance, head/handle ratio, hand mass and impact point; 4096 of them (360 kB) are "
      "evaluated per "
      "call, as a batch or sweep chunk would be.\n{}",
      machine_description(), options.repeats, cases_ns, 1e3 / cases_ns, arrays_ns, 1e3 / arrays_ns,
      rigid_ns, 1e3 / rigid_ns, sweep_ns, 1e3 / sweep_ns,
      1e3 / arrays_ns >= 150.0 ? "met as arrays" : "NOT met", cli.markdown);
  if (cli.million_point_sweep_s > 0.0) {
    md += fmt::format(
        "\nTarget: a sweep of one million designs in a few seconds and under 50 MB resident. Along "
        "the impact "
        "point: {:.2f} s and {:.1f} MB on all cores; a sweep whose first variable is the impact "
        "point reads one "
        "design per row and evaluates the rest with `ImpactSweep`. Any other sweep, and a batch, "
        "sets each "
        "point's numbers on the design compiled once when the study or the header is read (a unit "
        "factor and a "
        "setter per variable or column; the implement rebuilt only when one of its numbers "
        "changes; a point the "
        "binding cannot vouch for is read from JSON, which says what is wrong): {:.2f} s for a "
        "million such "
        "points on all cores. In-process on one core, a point of a hand x forearm sweep costs "
        "{:.3f} us read "
        "from JSON and {:.3f} us compiled (CSV written to memory).\n",
        cli.million_point_sweep_s, cli.million_point_sweep_MB, cli.every_point_sweep_s,
        sweep_json_us, sweep_compiled_us);
  }
  md +=
      "\n## Optimizer: evaluations, wall time and the objective reached, per study and "
      "algorithm\n\n"
      "`excess` is how far the objective lands above the best any algorithm found for that study "
      "(relative); an infeasible end is marked.\n\n"
      "| study | algorithm | evaluations | median time (ms) | objective | excess |\n"
      "|---|---|---:|---:|---:|---:|\n";

  struct StudyTiming {
    double ms = 0.0;          // auto, evaluations set on the compiled design, one thread
    double json_ms = 0.0;     // auto, every evaluation read from JSON
    double threads_ms = 0.0;  // auto, on every core (optimize's default)
  };
  StudyTiming study1, study3a;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(options.designs_dir) / "studies")) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& path : files) {
    if (!io::read_json_file(path.string()).contains("objective")) continue;
    studies::Study study = studies::load_study(path.string());
    const optimizer::Problem problem = studies::make_problem(study);
    struct Row {
      std::string algorithm;
      int evaluations;
      double ms, objective;
      bool feasible;
    };
    std::vector<Row> rows;
    for (const std::string& algorithm : algorithms_for(study, problem)) {
      study.options.algorithm = algorithm;
      std::optional<studies::OptimizationResult> result;
      const double seconds = median_seconds(
          options.repeats, [&] { result.emplace(studies::run_optimization(study)); });
      rows.push_back({algorithm, result->summary.evaluations, seconds * 1e3,
                      result->summary.objective, result->summary.feasible});
      const std::string stem = path.stem().string();
      if (algorithm == "auto" && (stem.starts_with("1-") || stem.starts_with("3a-"))) {
        // The same run with every evaluation read from JSON, as before the designs were compiled.
        const std::shared_ptr<const studies::CompiledDesign> compiled = study.compiled;
        study.compiled.reset();
        const double json_ms =
            median_seconds(options.repeats, [&] { studies::run_optimization(study); }) * 1e3;
        study.compiled = compiled;
        study.options.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
        const double threads_ms =
            median_seconds(options.repeats, [&] { studies::run_optimization(study); }) * 1e3;
        study.options.threads = 1;
        (stem.starts_with("1-") ? study1 : study3a) =
            StudyTiming{seconds * 1e3, json_ms, threads_ms};
      }
    }
    double best = std::numeric_limits<double>::infinity();
    for (const Row& r : rows) {
      if (r.feasible) best = std::min(best, r.objective);
    }
    for (const Row& r : rows) {
      const double excess = (r.objective - best) / std::max(std::abs(best), 1e-300);
      csv += fmt::format("{},{},{},{},{},{},{}\n", path.stem().string(), r.algorithm, r.evaluations,
                         io::exact(r.ms), io::exact(r.objective), r.feasible ? "yes" : "no",
                         io::exact(excess));
      md += fmt::format("| {} | {} | {} | {:.2f} | {} | {} |\n", path.stem().string(), r.algorithm,
                        r.evaluations, r.ms, io::significant(r.objective),
                        r.feasible ? fmt::format("{:.1e}", excess) : std::string("infeasible"));
      if (r.algorithm == "auto") {
        log << fmt::format("{}: auto {} evaluations, {:.2f} ms\n", path.stem().string(),
                           r.evaluations, r.ms);
      }
    }
  }
  md +=
      "\nTargets (issue: optimizer): rigid-model studies in at most 5 ms, the COP-on-node study "
      "with the "
      "modal model in the loop in at most 50 ms.\n";
  md += targets_section(
      cli, peers, {study1.ms, study1.json_ms, study3a.ms, study3a.json_ms, study3a.threads_ms},
      arrays_ns, cases_ns, bench_free_fe(options));

  // What each fidelity costs, and what leaving it out costs in accuracy: the
  // Table I racquet with a 150 Hz frame whose COR is derived from cor_rigid 0.85.
  Design flexible{Implement::paper_racquet(0.70, 0.25, 0.8)};
  flexible.stiffness.fundamental_free_Hz = 150.0;
  flexible.cor_rigid = 0.85;
  const Evaluation reference = evaluate(flexible, Fidelity::kResponse);
  Design assumed = flexible;  // the cheaper models take the rigid-frame COR as the COR
  assumed.cor_rigid.reset();
  assumed.cor = 0.85;
  md +=
      "\n## Fidelity: cost against error\n\nThe Table I racquet with a 150 Hz frame, hit 5 cm from "
      "the tip, "
      "its COR derived from cor_rigid = 0.85 by the response model. The cheaper models cannot "
      "derive the COR "
      "and use 0.85: the error is theirs.\n\n"
      "| fidelity | time per evaluation (us) | COR used | peak wrist force (N) | error in F_w |\n"
      "|---|---:|---:|---:|---:|\n";
  csv += "\nfidelity,median_us,cor,peak_wrist_force_N,relative_error_Fw\n";
  for (const auto& level :
       {std::pair{"rigid", Fidelity::kRigid}, std::pair{"modal", Fidelity::kModal},
        std::pair{"response", Fidelity::kResponse}}) {
    const char* name = level.first;
    const Fidelity fidelity =
        level.second;  // a variable, not a binding: lambdas capture it everywhere
    const Design& d = fidelity == Fidelity::kResponse ? flexible : assumed;
    constexpr int kCalls = 200;
    Evaluation e = evaluate(d, fidelity);
    const double seconds = median_seconds(options.repeats, [&] {
      for (int i = 0; i < kCalls; ++i) e = evaluate(d, fidelity);
    });
    const double us = seconds / kCalls * 1e6;
    const double error = e.peak_wrist_force_N / reference.peak_wrist_force_N - 1.0;
    md += fmt::format("| {} | {:.2f} | {:.3f} | {:.1f} | {:+.1f} % |\n", name, us, e.cor,
                      e.peak_wrist_force_N, 100 * error);
    csv += fmt::format("{},{},{},{},{}\n", name, io::exact(us), io::exact(e.cor),
                       io::exact(e.peak_wrist_force_N), io::exact(error));
    log << fmt::format("fidelity {}: {:.2f} us per evaluation\n", name, us);
  }
  {
    // The solved collision of the same racquet strung at the tension that
    // gives the spring model's 4 ms: its COR, duration and force come out of it.
    Design solved = assumed;
    solved.cor_given = false;
    solved.strings = StringBed{};
    solved.strings->tension_N = *tension_for_duration(
        StringBed{}, 0.004, solved.ball.mass_kg,
        effective_mass(solved.implement.mass_properties(), solved.impact_from_butt_m));
    constexpr int kCalls = 20;
    Evaluation e = evaluate(solved, Fidelity::kCollision);
    const double seconds = median_seconds(options.repeats, [&] {
      for (int i = 0; i < kCalls; ++i) e = evaluate(solved, Fidelity::kCollision);
    });
    const double us = seconds / kCalls * 1e6;
    const double error = e.peak_wrist_force_N / reference.peak_wrist_force_N - 1.0;
    md += fmt::format("| collision | {:.2f} | {:.3f} | {:.1f} | {:+.1f} % |\n", us, e.cor,
                      e.peak_wrist_force_N, 100 * error);
    csv += fmt::format("collision,{},{},{},{}\n", io::exact(us), io::exact(e.cor),
                       io::exact(e.peak_wrist_force_N), io::exact(error));
    log << fmt::format("fidelity collision: {:.2f} us per evaluation\n", us);
  }
  md += fmt::format(
      "\n`rigid` is `evaluate()` with every check (the library's unchecked hot path is the figure "
      "at the top); "
      "`modal` adds the free modes (exact) and the hand-held ones (to 1e-6); `response` adds the "
      "frame's "
      "response to the ball; `collision` solves ball, strings (strung to the 4 ms of the others) "
      "and frame together: a different model, not a finer one, so its 'error' is the prescribed "
      "pulse's (see speed-vs-error-collision.md for its own error).\n\n(checksum {:.3g})\n",
      sink);
  md += bench_maps(options, log);
  fs::create_directories(options.out_dir);
  io::write_file_atomically(options.out_dir + "/speed-vs-error.md", md);
  io::write_file_atomically(options.out_dir + "/speed-vs-error.csv", csv);
  std::string why;
  if (cli.plot &&
      !io::render_png(*cli.plot, options.out_dir + "/speed-vs-error-threads.png", &why)) {
    log << "skipped the plot: " << why << "\n";
  }
  log << fmt::format("wrote {}/speed-vs-error.md, .csv and -threads.png\n", options.out_dir);
}

void bench_modes(const BenchOptions& options, std::ostream& log) {
  constexpr double kBudgetPerRow_ms = 150.0;
  const std::string csv = speed_vs_error_modes_csv(kBudgetPerRow_ms);
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // header
  std::string table =
      "| method | resolution | elements | time per solve (us) | f1 relative error | node error (m) "
      "| "
      "observed order | reference |\n|---|---|---:|---:|---:|---:|---:|---|\n";
  std::map<std::string, io::PlotSeries> series;
  std::vector<std::string> order;
  while (std::getline(lines, line)) {
    std::vector<std::string> f;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) f.push_back(cell);
    f.resize(10);
    table += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", f[0], f[1], f[2], f[3],
                         f[5], f[7], f[8], f[9]);
    if (!series.count(f[0])) {
      order.push_back(f[0]);
      series[f[0]] = io::PlotSeries{f[0], {}, {}, "linespoints lw 2 pt 7"};
    }
    series[f[0]].x.push_back(std::stod(f[3]));
    series[f[0]].y.push_back(std::stod(f[5]));
  }
  io::Plot plot{"Speed against error of the modal solvers (f1 of the study racquet)",
                "wall time per solve (us, one core)",
                "relative error of f1",
                std::nullopt,
                std::nullopt,
                {},
                {},
                {}};
  plot.log_x = plot.log_y = true;
  plot.key_position = "outside right";
  for (const std::string& name : order) {
    if (name != "exact") plot.series.push_back(series[name]);
  }
  const std::string md =
      "# Speed against error: vibration modes\n\nMeasured by `sweetspot bench modes` on " +
      machine_description() +
      ". Each time is the median of repeated calls on one core. The test racquet is the "
      "optimizer's: "
      "two sections of 0.35 m (head/handle mass 0.8, 0.25 kg), one EI giving a free "
      "Euler-Bernoulli "
      "fundamental of 150 Hz, 6 g of lead at 0.68 m; held with the calibrated hand.\n\n" +
      table +
      "\nReading it:\n\n"
      "- **Free, Euler-Bernoulli:** the exact transfer-matrix solver gives f1 and the node to "
      "round-off "
      "in a few microseconds (target: f1 to 1e-6 and the node to 0.1 mm in at most 10 us). Finite "
      "elements converge at order 4 (Hermite cubics) until round-off in the assembled stiffness "
      "stops "
      "them near 1e-9 (about 128 elements); past that the error grows again, which is why "
      "`rel_tol` has "
      "a floor of 1e-8 and the solver never refines further than it needs.\n"
      "- **Hand-held:** the damped problem is solved on a coarse undamped basis, then each wanted "
      "mode "
      "is refined on the full mesh with a banded complex LU (`refined`); `dense` is the full "
      "complex "
      "state-space eigen-solve it replaced, kept as the reference and the fallback. They agree to "
      "round-off.\n"
      "- **Timoshenko:** converges more slowly (about order 2 in these rows); use it where shear "
      "matters (the paper's wood beam), not in an optimizer's loop.\n"
      "- `order` is log2 of the error ratio between consecutive meshes (mesh doubled).\n";
  fs::create_directories(options.out_dir);
  io::write_file_atomically(options.out_dir + "/speed-vs-error-modes.csv", csv);
  io::write_file_atomically(options.out_dir + "/speed-vs-error-modes.md", md);
  std::string why;
  if (!io::render_png(plot, options.out_dir + "/speed-vs-error-modes.png", &why)) {
    log << "skipped the plot: " << why << "\n";
  }
  log << "wrote " << options.out_dir << "/speed-vs-error-modes.md, .csv and .png\n";
}

}  // namespace sweetspot::bench
