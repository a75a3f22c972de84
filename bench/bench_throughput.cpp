// `sweetspot bench`: the command line end to end. Each figure runs the
// sweetspot program itself (posix_spawn) on a generated study or catalogue,
// output to a file, and reads the child's wall time and peak resident memory.
#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench.hpp"
#include "io/format.hpp"
#include "io/parallel.hpp"
#include "io/plot.hpp"

extern char** environ;

namespace sweetspot::bench {
namespace {

namespace fs = std::filesystem;

struct ChildRun {
  double seconds = 0.0;
  double max_rss_MB = 0.0;
};

// Runs `program args...` with stdout to `out_path`, stderr discarded.
ChildRun run_child(const std::string& program, const std::vector<std::string>& args,
                   const fs::path& out_path) {
  std::vector<std::string> argv_text{program};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
    throw std::runtime_error("cannot run " + program + ": " + std::strerror(spawned));
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0) {
    if (errno != EINTR)
      throw std::runtime_error(std::string("waiting for the benchmark run: ") +
                               std::strerror(errno));
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error(fmt::format("the benchmark run `{} {}` failed (status {})", program,
                                         fmt::join(args, " "), status));
  }
  return ChildRun{seconds, usage.ru_maxrss / 1024.0};  // ru_maxrss is in kB on Linux
}

// A Table I racquet (row 1) as the inline design of the generated studies.
constexpr const char* kRow1Design =
    R"({"implement": {"length_m": 0.7, "mass_kg": 0.25, "head_to_handle_mass_ratio": 0.8},
        "frame": {"cor": 0.8}, "strings": {"impact_duration_ms": 4},
        "hand": {"mass_kg": 0.5, "center_from_butt_m": 0.07}, "forearm": {"equivalent_mass_kg": 0.5},
        "ball": {"mass_kg": 0.057, "speed_m_s": 50}, "impact": {"from_tip_m": 0.05}})";

struct Workload {
  std::string name;
  std::string what;
  std::size_t points = 0;
  std::vector<std::string> args;  // before --threads
};

std::vector<Workload> workloads(const fs::path& dir) {
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  std::vector<Workload> list;
  const std::string along_impact = write(
      "sweep-impact.json",
      fmt::format(
          R"({{"design": {}, "outputs": ["peak_wrist_force_N", "wrist_force_ratio", "peak_impact_force_N"],
          "variables": [{{"path": "/impact/from_tip_m", "min": 0, "max": 0.4, "points": 1000}},
                        {{"path": "/hand/mass_kg", "min": 0.3, "max": 0.6, "points": 1000}}]}})",
          kRow1Design));
  list.push_back({"sweep-impact",
                  "sweep: 1000 impact points x 1000 hand masses, 3 outputs (a design read per row)",
                  1'000'000,
                  {"sweep", "--quiet", "-o", (dir / "sweep-impact.csv").string(), along_impact}});
  const std::string every_point = write(
      "sweep-every-point.json", fmt::format(R"({{"design": {}, "outputs": ["peak_wrist_force_N"],
          "variables": [{{"path": "/hand/mass_kg", "min": 0.3, "max": 0.6, "points": 1000}},
                        {{"path": "/forearm/equivalent_mass_kg", "min": 0.1, "max": 1.0, "points": 1000}}]}})",
                                            kRow1Design));
  list.push_back(
      {"sweep-every-point",
       "sweep: 1000 hand masses x 1000 forearm masses (every point read)",
       1'000'000,
       {"sweep", "--quiet", "-o", (dir / "sweep-every-point.csv").string(), every_point}});
  constexpr std::size_t kRows = 100'000;
  std::string catalogue =
      "name,implement.length_in,implement.mass_g,implement.balance_cm,"
      "implement.swingweight_kg_cm2,impact.from_tip_m\n";
  for (std::size_t i = 0; i < kRows; ++i) {
    catalogue += fmt::format("r{},{},{},{},{},{}\n", i, 27.0 + 0.5 * (i % 2), 280 + i % 41,
                             31.0 + 0.1 * (i % 31), 300 + i % 37, 0.10 + 0.01 * (i % 13));
  }
  const std::string csv = write("catalogue.csv", catalogue);
  const std::string base =
      write("base.json", R"({"implement": {"length_in": 27, "mass_g": 305, "balance_cm": 32.5,
      "swingweight_kg_cm2": 320}, "frame": {"cor": 0.8}})");
  list.push_back({"batch-csv",
                  "evaluate --batch: 100000 racquets by industry specs (CSV), every output",
                  kRows,
                  {"evaluate", "--batch", csv, "--base", base}});
  return list;
}

std::vector<int> thread_counts() {
  std::vector<int> counts;
  for (int t = 1; t < io::all_cores(); t *= 2) counts.push_back(t);
  counts.push_back(io::all_cores());
  return counts;
}

}  // namespace

ThroughputReport bench_throughput(const BenchOptions& options, std::ostream& log) {
  ThroughputReport report;
  if (options.executable.empty()) {
    report.markdown =
        "\n## Command line, end to end\n\nNot measured: no sweetspot program given.\n";
    return report;
  }
  const fs::path dir = fs::temp_directory_path() / fmt::format("sweetspot-bench-{}", getpid());
  fs::create_directories(dir);
  report.csv =
      "workload,points,threads,median_s,million_points_per_s,ns_per_point,speedup,peak_rss_MB\n";
  report.markdown =
      "\n## Command line, end to end\n\nThe `sweetspot` program itself, started afresh for each "
      "run (reading, "
      "evaluating, formatting every number to round-trip precision, writing the file): median wall "
      "time of {} "
      "runs, and the largest peak resident memory of any run.\n\n"
      "| workload | points | threads | median time (s) | points per second | per point (us) | "
      "speed-up | "
      "peak memory (MB) |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
  report.markdown = fmt::format(fmt::runtime(report.markdown), options.repeats);
  io::Plot plot{"Command-line throughput against threads",
                "threads",
                "points per second (millions)",
                std::nullopt,
                std::nullopt,
                {},
                {},
                {}};
  plot.log_y = true;
  plot.integer_x_tics = true;  // threads are counted
  plot.key_position = "outside bottom";
  try {
    for (const Workload& w : workloads(dir)) {
      io::PlotSeries series{w.name, {}, {}, "linespoints lw 2 pt 7"};
      double one_thread_s = 0.0;
      for (const int threads : thread_counts()) {
        std::vector<std::string> args = w.args;
        args.insert(args.end(), {"--threads", std::to_string(threads)});
        std::vector<double> seconds;
        double rss_MB = 0.0;
        for (int r = 0; r < options.repeats; ++r) {
          const ChildRun run = run_child(options.executable, args, dir / "stdout");
          seconds.push_back(run.seconds);
          rss_MB = std::max(rss_MB, run.max_rss_MB);
        }
        const double s = median(seconds);
        if (threads == 1) one_thread_s = s;
        const double rate = w.points / s;
        report.csv +=
            fmt::format("{},{},{},{},{},{},{},{}\n", w.name, w.points, threads, io::exact(s),
                        io::exact(rate / 1e6), io::exact(s / w.points * 1e9),
                        io::exact(one_thread_s / s), io::exact(rss_MB));
        report.markdown +=
            fmt::format("| {} | {} | {} | {:.3f} | {:.2f} million | {:.3f} | {:.2f} | {:.1f} |\n",
                        threads == 1 ? w.what : "", w.points, threads, s, rate / 1e6,
                        s / w.points * 1e6, one_thread_s / s, rss_MB);
        series.x.push_back(threads);
        series.y.push_back(rate / 1e6);
        log << fmt::format("{} on {} threads: {:.3f} s, {:.1f} MB\n", w.name, threads, s, rss_MB);
        if (w.name == "sweep-impact" && threads == io::all_cores()) {
          report.million_point_sweep_s = s;
          report.million_point_sweep_MB = rss_MB;
        }
        if (w.name == "sweep-every-point" && threads == io::all_cores())
          report.every_point_sweep_s = s;
        if (w.name == "sweep-every-point" && threads == 1) report.every_point_sweep_1_thread_s = s;
        if (w.name == "batch-csv" && threads == 1) report.batch_1_thread_s = s;
      }
      plot.series.push_back(series);
    }
  } catch (...) {
    fs::remove_all(dir);
    throw;
  }
  fs::remove_all(dir);
  report.plot = plot;
  return report;
}

namespace {

// The one JSON line an in-process peer prints.
nlohmann::json peer_output(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return nlohmann::json::parse(line);
}

}  // namespace

PeerFigures bench_peers(const BenchOptions& options, std::ostream& log) {
  PeerFigures peers;
  const fs::path scripts = fs::absolute(options.peers_dir);
  if (!fs::exists(scripts / "rigid_model.py")) {
    peers.skipped = fmt::format("the peer scripts are not in {}", options.peers_dir);
    return peers;
  }
  const fs::path dir = fs::temp_directory_path() / fmt::format("sweetspot-peers-{}", getpid());
  fs::create_directories(dir);
  try {
    try {
      run_child(options.python, {"-c", "import numpy, scipy"}, dir / "stdout");
    } catch (const std::exception&) {
      peers.skipped = fmt::format("{} cannot import numpy and scipy", options.python);
      fs::remove_all(dir);
      return peers;
    }
    const auto script = [&](const char* name) { return (scripts / name).string(); };
    const auto whole_process = [&](const std::vector<std::string>& args) {
      std::vector<double> seconds;
      for (int r = 0; r < options.repeats; ++r)
        seconds.push_back(run_child(options.python, args, dir / "stdout").seconds);
      return median(seconds);
    };
    peers.every_point_sweep_s =
        whole_process({script("sweep_every_point.py"), (dir / "sweep.csv").string()});
    const std::string catalogue = [&] {
      for (const Workload& w : workloads(dir)) {
        if (w.name == "batch-csv") return w.args[2];
      }
      return std::string();
    }();
    peers.batch_s =
        whole_process({script("batch_specs.py"), catalogue, (dir / "batch.csv").string()});
    run_child(options.python, {script("study1_slsqp.py"), std::to_string(options.repeats)},
              dir / "study1.json");
    const nlohmann::json study1 = peer_output(dir / "study1.json");
    peers.study1_ms = study1["seconds"].get<double>() * 1e3;
    peers.study1_evaluations = study1["evaluations"].get<int>();
    peers.study1_objective = study1["objective"].get<double>();
    run_child(options.python, {script("rigid_kernel.py"), std::to_string(options.repeats)},
              dir / "kernel.json");
    peers.rigid_ns = peer_output(dir / "kernel.json")["ns_per_design"].get<double>();
    run_child(options.python,
              {script("free_fe_eigh.py"), std::to_string(kFreeFeElements),
               std::to_string(options.repeats)},
              dir / "free_fe.json");
    const nlohmann::json free_fe = peer_output(dir / "free_fe.json");
    peers.free_fe_us = free_fe["seconds"].get<double>() * 1e6;
    peers.free_fe_f1_Hz = free_fe["f1_Hz"].get<double>();
    log << fmt::format(
        "peers: sweep {:.3f} s, batch {:.3f} s, study 1 {:.2f} ms, rigid {:.1f} ns per design, "
        "free FE {:.1f} us\n",
        peers.every_point_sweep_s, peers.batch_s, peers.study1_ms, peers.rigid_ns,
        peers.free_fe_us);
  } catch (...) {
    fs::remove_all(dir);
    throw;
  }
  fs::remove_all(dir);
  return peers;
}

}  // namespace sweetspot::bench
