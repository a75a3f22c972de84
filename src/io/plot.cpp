#include "io/plot.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <pthread.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "io/atomic_file.hpp"
#include "io/format.hpp"

extern char** environ;

namespace sweetspot::io {
namespace {

// Why a plot could not be made; render_png() turns it into its `why`.
class PlotFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// gnuplot's standard error, kept in memory (a full disk must not lose it).
class Messages {
 public:
  Messages() {
    fd_ = ::memfd_create("gnuplot-messages", MFD_CLOEXEC);
    if (fd_ < 0) fd_ = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  }
  ~Messages() {
    if (fd_ >= 0) ::close(fd_);
  }
  Messages(const Messages&) = delete;
  Messages& operator=(const Messages&) = delete;
  int fd() const { return fd_; }

  // The first messages on one line: ", " between lines, runs of blanks as one.
  std::string one_line() const {
    std::array<char, 600> buffer{};
    const ssize_t n = fd_ < 0 ? -1 : ::pread(fd_, buffer.data(), buffer.size(), 0);
    std::string line;
    bool blank = false;
    for (ssize_t i = 0; i < n; ++i) {
      const char c = buffer[static_cast<std::size_t>(i)];
      const bool space = c == ' ' || c == '\t' || c == '\n' || c == '\r';
      if (space) {
        blank = !line.empty();
        continue;
      }
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) continue;
      if (blank) line += ' ';
      blank = false;
      line += c;
    }
    if (n == static_cast<ssize_t>(buffer.size())) line += " ...";
    // gnuplot names the file it reads its script from (run_gnuplot) before
    // each line number: the name says nothing to the reader.
    static constexpr std::string_view kScript = "\"/dev/stdin\" ";
    for (std::size_t at = line.find(kScript); at != std::string::npos; at = line.find(kScript, at))
      line.erase(at, kScript.size());
    return line;
  }

 private:
  int fd_ = -1;
};

// Writes `text` into the pipe `fd` until its reader has gone, which is no
// signal here: SIGPIPE is held back in this thread while it writes, and the
// one a gone reader raised is taken (a write to a pipe has no MSG_NOSIGNAL).
void write_to_pipe(int fd, std::string_view text) {
  sigset_t pipe_signal;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  sigset_t before;
  ::pthread_sigmask(SIG_BLOCK, &pipe_signal, &before);
  sigset_t pending;
  sigemptyset(&pending);
  ::sigpending(&pending);
  const bool was_pending = sigismember(&pending, SIGPIPE) == 1;
  bool gone = false;
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      gone = true;  // gnuplot has gone; its status says why
      break;
    }
    text.remove_prefix(static_cast<std::size_t>(n));
  }
  if (gone && !was_pending) {
    const timespec now{0, 0};
    while (::sigtimedwait(&pipe_signal, nullptr, &now) < 0 && errno == EINTR) {
    }
  }
  ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
}

// An anonymous file in memory (memfd), closed with this object. Throws
// PlotFailure when none can be made.
class MemoryFile {
 public:
  explicit MemoryFile(const char* name) : fd_(::memfd_create(name, MFD_CLOEXEC)) {
    if (fd_ < 0) throw PlotFailure(std::string("cannot hold the plot: ") + std::strerror(errno));
  }
  ~MemoryFile() { ::close(fd_); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
  int fd() const { return fd_; }

 private:
  int fd_;
};

// Runs gnuplot on `script` with the PNG on its standard output going to
// `png_fd` and its messages captured, never on ours. Throws PlotFailure.
void run_gnuplot(const std::string& script, int png_fd) {
  // gnuplot reads the script as a file, the pipe on its standard input
  // opened again by name: commands it reads as standard input are read a
  // byte per system call (a heat map's 140 kB script: 60 ms of CPU so, 3 ms
  // as a file). A pipe, not a file in memory: `ulimit -f` limits no pipe.
  std::array<int, 2> pipe_fds{};
  if (::pipe2(pipe_fds.data(), O_CLOEXEC) != 0)
    throw PlotFailure(std::string("cannot start gnuplot: ") + std::strerror(errno));
  const Messages messages;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[0], 0);
  posix_spawn_file_actions_adddup2(&actions, png_fd, 1);
  posix_spawn_file_actions_adddup2(&actions, messages.fd(), 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) sigaddset(&defaults, s);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  char name[] = "gnuplot";
  char file[] = "/dev/stdin";
  char* argv[] = {name, file, nullptr};
  pid_t pid = -1;
  const int spawned = ::posix_spawnp(&pid, name, &actions, &attributes, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(pipe_fds[0]);
  if (spawned != 0) {
    ::close(pipe_fds[1]);
    if (spawned == ENOENT)
      throw PlotFailure("gnuplot is not installed (apt-get install gnuplot-nox)");
    throw PlotFailure(std::string("cannot start gnuplot: ") + std::strerror(spawned));
  }
  write_to_pipe(pipe_fds[1], script);
  ::close(pipe_fds[1]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw PlotFailure(std::string("gnuplot: ") + std::strerror(errno));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  const std::string how = WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                            : "signal " + std::to_string(WTERMSIG(status));
  const std::string said = messages.one_line();
  throw PlotFailure("gnuplot failed (" + how + ")" + (said.empty() ? "" : ": " + said));
}

// What is wrong with the PNG in `fd`, or "": the signature at the start and
// the IEND chunk at the end (a full disk truncates the file or leaves it empty).
std::string png_problem(int fd) {
  static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  static constexpr unsigned char kEnd[12] = {0,   0,   0,    0,    'I',  'E',
                                             'N', 'D', 0xae, 0x42, 0x60, 0x82};
  struct stat info {};
  if (::fstat(fd, &info) != 0) return std::strerror(errno);
  const auto size = static_cast<std::size_t>(info.st_size);
  std::array<unsigned char, 12> head{};
  std::array<unsigned char, 12> tail{};
  const bool complete = size >= sizeof kSignature + sizeof kEnd &&
                        ::pread(fd, head.data(), sizeof kSignature, 0) == sizeof kSignature &&
                        ::pread(fd, tail.data(), sizeof kEnd, info.st_size - 12) == sizeof kEnd &&
                        std::memcmp(head.data(), kSignature, sizeof kSignature) == 0 &&
                        std::memcmp(tail.data(), kEnd, sizeof kEnd) == 0;
  if (complete) return "";
  // Why it was cut short: `ulimit -f` (gnuplot inherits SIGXFSZ ignored and
  // stops at EFBIG), or a full file system (memory, for a memfd, which has
  // no blocks to count).
  struct rlimit limit {};
  const bool too_large = ::getrlimit(RLIMIT_FSIZE, &limit) == 0 &&
                         limit.rlim_cur != RLIM_INFINITY &&
                         static_cast<rlim_t>(size) >= limit.rlim_cur;
  struct statvfs disk {};
  const bool full = ::fstatvfs(fd, &disk) == 0 && disk.f_blocks > 0 && disk.f_bavail == 0;
  const int why = too_large ? EFBIG : full ? ENOSPC : 0;
  return (size == 0 ? std::string("gnuplot wrote nothing")
                    : "gnuplot wrote an incomplete PNG of " + std::to_string(size) + " bytes") +
         (why ? ": " + std::string(std::strerror(why)) : "");
}

// Copies the whole of `from` into `to`.
void copy_file(int from, OutputFile& to) {
  std::array<char, 1 << 16> buffer{};
  for (off_t at = 0;;) {
    const ssize_t n = ::pread(from, buffer.data(), buffer.size(), at);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      throw PlotFailure(std::string("cannot read the rendered plot: ") + std::strerror(errno));
    if (n == 0) return;
    to.write(std::string_view(buffer.data(), static_cast<std::size_t>(n)));
    at += n;
  }
}

// A single-quoted gnuplot string: gnuplot substitutes `commands` in backquotes
// inside double quotes (a title or file name from a user's file would run
// them), never inside single quotes, where only a quote is special (written
// twice). A control character would end the command line: it becomes a space.
std::string single_quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'') out += '\'';
    out += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? ' ' : c;
  }
  return out + "'";
}

// A label that the enhanced text mode prints as it is: its markup characters
// (an underscore is a subscript, ^ a superscript, braces group, @ & ~ space
// and overprint) are escaped, so output names in snake_case print literally.
std::string label(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '_' || c == '^' || c == '{' || c == '}' || c == '@' || c == '&' || c == '~')
      escaped += '\\';
    escaped += c;
  }
  return single_quoted(escaped);
}

bool on_plot(const Plot& plot, double y) {
  return !plot.y_range || (y >= plot.y_range->first && y <= plot.y_range->second);
}

}  // namespace

namespace {

// The plot's commands after the terminal and output.
std::string plot_commands(const Plot& plot) {
  std::string s;
  s += "set title " + label(plot.title) + "\n";
  s += "set xlabel " + label(plot.x_label) + "\n";
  s += "set ylabel " + label(plot.y_label) + "\n";
  s += plot.key_position == "off"
           ? "set grid\nunset key\n"
           : "set grid\nset key " + plot.key_position + " box opaque" +
                 (plot.key_title.empty() ? std::string() : " title " + label(plot.key_title)) +
                 "\n";
  // Labels on an opaque ground: a line under a label stops at its edge.
  s += "set style textbox opaque noborder\n";
  if (plot.log_x) s += "set logscale x\nset format x '10^{%L}'\n";
  if (plot.log_y) s += "set logscale y\nset format y '10^{%L}'\n";
  if (plot.integer_x_tics) s += "set xtics 1\nset mxtics 1\n";
  if (plot.x_range)
    s += fmt::format("set xrange [{}:{}]\n", plot.x_range->first, plot.x_range->second);
  if (plot.y_range)
    s += fmt::format("set yrange [{}:{}]\n", plot.y_range->first, plot.y_range->second);
  if (plot.x2) {
    s += "set x2label " + label(plot.x2->label) + "\nset xtics nomirror\n";
    s += fmt::format("set link x2 via x*{0} inverse x/{0}\n", plot.x2->factor);
    s += plot.x2->tic_step > 0 ? fmt::format("set x2tics {}\n", plot.x2->tic_step)
                               : std::string("set x2tics\n");
  }
  if (!plot.y2_label.empty()) {
    s += "set y2label " + label(plot.y2_label) + "\nset ytics nomirror\nset y2tics\n";
    if (plot.log_y2) s += "set logscale y2\nset format y2 '10^{%L}'\n";
  }
  int tag = 1;
  for (const auto& [x, text] : plot.vertical_lines) {
    s += fmt::format("set arrow {} from {},graph 0 to {},graph 1 nohead dt 2 lc rgb 'gray40'\n",
                     tag, x, x);
    // Written along its own line, down from the top, so that neighbouring
    // lines' labels never run into each other.
    s += fmt::format(
        "set label {} {} at {},graph 0.98 right rotate by 90 offset -0.3,0 boxed tc rgb "
        "'black' front\n",
        tag, label(text), x);
    ++tag;
  }
  for (const PlotMarker& m : plot.markers) {
    s += fmt::format("set label {} {} at {},{} left offset 1,{} boxed point pt 7 ps 1.2 front\n",
                     tag++, label(m.label), m.x, m.y, m.label_above ? 1 : -1);
  }
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& series = plot.series[i];
    s += fmt::format("$series{} << EOD\n", i);
    bool broken = true;
    const bool log_y = series.right_axis ? plot.log_y2 : plot.log_y;
    // A line that leaves the y range runs to its edge (and comes back from
    // it), interpolated linearly, rather than stopping at its last point inside.
    const auto edge_between = [&](std::size_t inside, std::size_t outside) {
      const double y0 = *series.y[inside], y1 = *series.y[outside];
      const double edge = y1 > y0 ? plot.y_range->second : plot.y_range->first;
      const double t = (edge - y0) / (y1 - y0);
      return fmt::format("{} {}\n", series.x[inside] + t * (series.x[outside] - series.x[inside]),
                         edge);
    };
    const auto clippable = [&](std::size_t k) {
      return !series.right_axis && !log_y && !plot.log_x && plot.y_range && series.y[k] &&
             std::isfinite(*series.y[k]);
    };
    // The step from k to k + 1 goes the way of the step before it (or after
    // it): a jump the other way is a pole crossed, not a line to draw on.
    const auto same_trend = [&](std::size_t a, std::size_t b, std::size_t c) {
      if (!clippable(a) || !clippable(b) || !clippable(c)) return false;
      return (*series.y[b] - *series.y[a]) * (*series.y[c] - *series.y[b]) > 0;
    };
    for (std::size_t k = 0; k < series.x.size(); ++k) {
      const auto& y = series.y[k];
      const bool off_log = (log_y && y && *y <= 0) || (plot.log_x && series.x[k] <= 0);
      if (!y || (!series.right_axis && !on_plot(plot, *y)) || off_log) {
        if (!broken && k >= 2 && same_trend(k - 2, k - 1, k)) s += edge_between(k - 1, k);
        if (!broken) s += "\n";
        broken = true;
        continue;
      }
      if (broken && k > 0 && k + 1 < series.x.size() && same_trend(k - 1, k, k + 1) &&
          !on_plot(plot, *series.y[k - 1]))
        s += edge_between(k, k - 1);
      s += fmt::format("{} {}\n", series.x[k], *y);
      broken = false;
    }
    s += "EOD\n";
  }
  s += "plot ";
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& series = plot.series[i];
    if (i) s += ", \\\n     ";
    s += fmt::format("$series{} using 1:2{} with {} lc rgb {} {}", i,
                     series.right_axis ? " axes x1y2" : "", series.style,
                     single_quoted(series.color.empty() ? plot_color(i) : series.color),
                     series.title.empty() ? "notitle" : "title " + label(series.title));
  }
  return s + "\n";
}

// What a key means in words: its unit suffix (longest first) and how to show it.
struct UnitSuffix {
  std::string_view suffix;
  std::string_view unit;
  double factor;
};
// Longest first where one suffix ends another ("_rad_s" before "_s", "_N_m"
// before "_m").
constexpr UnitSuffix kUnitSuffixes[] = {
    {"_rad_s", "rad/s", 1.0},   {"_lb_in", "lb/in", 1.0}, {"_N_m", "N·m", 1.0},
    {"_kg_cm2", "kg·cm²", 1.0}, {"_kg_m2", "kg·m²", 1.0}, {"_N_m2", "N·m²", 1.0},
    {"_N_s", "N·s", 1.0},       {"_m_s", "m/s", 1.0},     {"_cm", "cm", 1.0},
    {"_mm", "mm", 1.0},         {"_in", "in", 1.0},       {"_kg", "kg", 1.0},
    {"_oz", "oz", 1.0},         {"_lb", "lb", 1.0},       {"_Hz", "Hz", 1.0},
    {"_ms", "ms", 1.0},         {"_g", "g", 1.0},         {"_m", "cm", 100.0},
    {"_N", "N", 1.0},           {"_J", "J", 1.0},         {"_s", "ms", 1000.0},
    {"_km_h", "km/h", 1.0},     {"_mph", "mph", 1.0},     {"_s2", "1/s²", 1.0},
};

bool ends_with(std::string_view text, std::string_view end) {
  return text.size() >= end.size() && text.substr(text.size() - end.size()) == end;
}

// A key with this unit suffix: something before the suffix.
bool has_suffix(std::string_view key, std::string_view suffix) {
  return key.size() > suffix.size() && ends_with(key, suffix);
}

// snake_case words as a phrase: "cop_hand_from_tip" -> "COP hand from the tip".
std::string words(std::string_view name) {
  std::string phrase;
  std::size_t start = 0;
  while (start <= name.size()) {
    std::size_t end = name.find('_', start);
    if (end == std::string_view::npos) end = name.size();
    std::string word(name.substr(start, end - start));
    if (word == "cop" || word == "cor") {
      for (char& c : word) c = static_cast<char>(c - 'a' + 'A');
    }
    if ((word == "tip" || word == "butt" || word == "com") && ends_with(phrase, "from"))
      phrase += " the";
    if (word == "com") word = "centre of mass";
    if (!word.empty()) phrase += (phrase.empty() ? "" : " ") + word;
    start = end + 1;
  }
  return phrase;
}

AxisQuantity with_unit(std::string name_in_words, std::string_view unit, double factor) {
  // The gap between two points reads as one: "COP–node gap".
  const std::size_t pair = name_in_words.find("COP node");
  if (pair != std::string::npos) name_in_words.replace(pair, 8, "COP–node");
  std::string label = unit.empty() ? name_in_words : name_in_words + " (" + std::string(unit) + ")";
  return {std::move(label), factor, std::move(name_in_words), std::string(unit)};
}

}  // namespace

std::string plot_color(std::size_t i) {
  static constexpr const char* kColors[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                            "#e69f00", "#56b4e9", "#000000", "#8c564b",
                                            "#7f7f7f", "#6a3d9a", "#b8b800", "#17becf"};
  return kColors[i % (sizeof kColors / sizeof kColors[0])];
}

AxisQuantity output_axis(const OutputSpec& output) {
  // The words from the name, its unit suffix dropped; the unit and the factor
  // from the output's SI unit through people_unit(), the one table of people's
  // units (g, cm, kg·cm², ms) that `evaluate --units people` also reads.
  std::string_view name = output.name;
  for (const UnitSuffix& u : kUnitSuffixes) {
    if (has_suffix(name, u.suffix)) {
      name.remove_suffix(u.suffix.size());
      break;
    }
  }
  const PeopleUnit people = people_unit(output.unit, output.name);
  return with_unit(words(name), people.unit, people.factor);
}

AxisQuantity pointer_axis(std::string_view pointer) {
  std::vector<std::string> parts;
  for (std::size_t at = 0; at < pointer.size();) {
    std::size_t next = pointer.find('/', at + 1);
    if (next == std::string_view::npos) next = pointer.size();
    std::string part(pointer.substr(at + 1, next - at - 1));
    if (!part.empty()) parts.push_back(part);
    at = next;
  }
  if (parts.empty()) return with_unit(std::string(pointer), "", 1.0);
  std::string key = parts.back();
  parts.pop_back();
  std::string_view unit;
  double factor = 1.0;
  for (const UnitSuffix& u : kUnitSuffixes) {
    if (has_suffix(key, u.suffix)) {
      key.resize(key.size() - u.suffix.size());
      unit = u.unit;
      factor = u.factor;
      break;
    }
  }
  // The path in words, the implement and its frame being understood.
  std::string phrase;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    if (part == "implement" || part == "frame") continue;
    if (part == "point_masses" && i + 1 < parts.size() &&
        parts[i + 1].find_first_not_of("0123456789") == std::string::npos) {
      phrase +=
          (phrase.empty() ? "" : " ") + fmt::format("lead mass {}", std::stoul(parts[i + 1]) + 1);
      ++i;
      continue;
    }
    phrase += (phrase.empty() ? "" : " ") + words(part);
  }
  // "lead mass 1" + "mass" says mass once; "impact" + "from tip" reads "impact from the tip".
  const bool lead = phrase.rfind("lead mass", 0) == 0;
  if (!(key == "mass" && lead)) phrase += (phrase.empty() ? "" : " ") + words(key);
  // Lead tape is weighed in grams.
  if (lead && key == "mass" && unit == "kg") return with_unit(phrase, "g", 1000.0);
  return with_unit(phrase, unit, factor);
}

std::string gnuplot_script(const Plot& plot, const std::string& png_path) {
  std::string s = "set terminal pngcairo size 960,640 enhanced font 'DejaVu Sans,11'\n";
  if (!png_path.empty()) s += "set output " + single_quoted(png_path) + "\n";
  return s + plot_commands(plot);
}

std::string gnuplot_svg_script(const Plot& plot, int width, int height) {
  return fmt::format(
             "set terminal svg size {},{} dynamic enhanced font 'DejaVu Sans,13' background "
             "'#ffffff'\n",
             width, height) +
         plot_commands(plot);
}

bool render_png(const Plot& plot, const std::string& png_path, std::string* why) {
  return render_script_png(gnuplot_script(plot, ""), png_path, why);
}

std::string gnuplot_label(const std::string& text) { return label(text); }

bool render_script_png(const std::string& script, const std::string& png_path, std::string* why) {
  try {
    OutputFile out(png_path);
    // gnuplot renders into a temporary file: beside a regular target, or in
    // the scratch folder for a target written directly (then copied in).
    std::optional<TemporaryFile> scratch;
    if (out.direct()) scratch.emplace(scratch_directory(), "sweetspot-plot", png_path);
    const int png_fd = out.direct() ? scratch->fd() : out.fd();
    run_gnuplot(script, png_fd);
    const std::string problem = png_problem(png_fd);
    if (!problem.empty()) throw PlotFailure(problem);
    if (out.direct()) copy_file(png_fd, out);
    out.commit();
    return true;
  } catch (const WriteError& e) {
    if (why) *why = e.reason();
  } catch (const std::exception& e) {
    if (why) *why = e.what();
  }
  return false;
}

namespace {

// What gnuplot writes for `script`, held in an anonymous memory file and
// read back; with `png`, checked as a whole PNG first. Throws PlotFailure.
std::string gnuplot_output_in_memory(const std::string& script, const char* name, bool png) {
  const MemoryFile out(name);
  run_gnuplot(script, out.fd());
  if (png) {
    const std::string problem = png_problem(out.fd());
    if (!problem.empty()) throw PlotFailure(problem);
  }
  std::string bytes;
  std::array<char, 1 << 16> buffer{};
  for (off_t at = 0;;) {
    const ssize_t n = ::pread(out.fd(), buffer.data(), buffer.size(), at);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw PlotFailure(std::string("cannot read the plot: ") + std::strerror(errno));
    if (n == 0) return bytes;
    bytes.append(buffer.data(), static_cast<std::size_t>(n));
    at += n;
  }
}

}  // namespace

std::optional<std::string> render_png_bytes(const Plot& plot, std::string* why) {
  return render_script_png_bytes(gnuplot_script(plot, ""), why);
}

std::optional<std::string> render_script_png_bytes(const std::string& script, std::string* why) {
  try {
    return gnuplot_output_in_memory(script, "sweetspot-png", true);
  } catch (const std::exception& e) {
    if (why) *why = e.what();
  }
  return std::nullopt;
}

namespace {

// Every occurrence of `from` in `text` replaced by `to`.
std::string replace_all(std::string text, std::string_view from, std::string_view to) {
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// What gnuplot wrote for one SVG plot made fit to inline on a page (as
// render_script_svg() describes). Throws PlotFailure.
std::string inline_svg(std::string_view written, const std::string& id_prefix) {
  const std::size_t start = written.find("<svg");
  const std::size_t end = written.rfind("</svg>");
  if (start == std::string::npos || end == std::string::npos || end < start)
    throw PlotFailure("gnuplot wrote no complete SVG");
  std::string svg(written.substr(start, end + 6 - start));
  // gnuplot writes '<' in text as "&lt;" but '&' and '>' as they are: a
  // title or key with '&' (or "]]>") would break the page's XML. Every '&'
  // but those of gnuplot's "&lt;" becomes "&amp;" (a name holding "&amp;"
  // shows it as typed), and "]]>" becomes "]]&gt;".
  std::string escaped;
  escaped.reserve(svg.size());
  for (std::size_t at = 0; at < svg.size(); ++at) {
    if (svg[at] == '&' && svg.compare(at, 4, "&lt;") != 0) {
      escaped += "&amp;";
    } else if (svg[at] == '>' && at >= 2 && svg[at - 1] == ']' && svg[at - 2] == ']') {
      escaped += "&gt;";
    } else {
      escaped += svg[at];
    }
  }
  // A name's characters that XML cannot hold (U+FFFE, U+FFFF, controls)
  // reach gnuplot's text as they are: the SVG is made well-formed here, for
  // every page that inlines it.
  svg = xml_chars(escaped);
  // The ids gnuplot gives its groups serve its mouse script only (not
  // written): dropped, since each plot repeats them. The rest get the prefix.
  for (const char* group : {"gnuplot_canvas", "gnuplot_plot_"}) {
    for (std::size_t at = svg.find(std::string(" id=\"") + group); at != std::string::npos;
         at = svg.find(std::string(" id=\"") + group, at)) {
      const std::size_t close = svg.find('"', at + 5);
      svg.erase(at, close + 1 - at);
    }
  }
  svg = replace_all(std::move(svg), "id='", "id='" + id_prefix);
  svg = replace_all(std::move(svg), "href='#", "href='#" + id_prefix);
  svg = replace_all(std::move(svg), "url(#", "url(#" + id_prefix);
  return svg;
}

// What one gnuplot prints after each plot of render_svgs(): a tag of its
// own, which no SVG holds (gnuplot writes a '<' in a plot's text as "&lt;").
constexpr std::string_view kPlotEnd = "<sweetspot-plot-end/>";

// The plots drawn by one gnuplot, in order. Throws PlotFailure when that
// gnuplot fails or does not end every plot.
std::vector<std::string> svgs_of_one_gnuplot(const std::vector<SvgPlot>& plots) {
  // Each script as it is, then the tag on standard output (after the SVG,
  // which gnuplot has finished by then) and every setting, variable and
  // data block back to gnuplot's defaults for the next.
  std::string script;
  for (const SvgPlot& plot : plots) {
    script += plot.script;
    if (!plot.script.empty() && plot.script.back() != '\n') script += '\n';
    script += "set print '-'\nprint '" + std::string(kPlotEnd) + "'\nunset print\nreset session\n";
  }
  const std::string written = gnuplot_output_in_memory(script, "sweetspot-svg", false);
  std::vector<std::string> svgs;
  std::size_t from = 0;
  for (const SvgPlot& plot : plots) {
    const std::size_t end = written.find(kPlotEnd, from);
    if (end == std::string::npos) throw PlotFailure("gnuplot did not finish every plot");
    svgs.push_back(inline_svg(std::string_view(written).substr(from, end - from), plot.id_prefix));
    from = end + kPlotEnd.size();
  }
  return svgs;
}

}  // namespace

std::optional<std::string> render_svg(const Plot& plot, const std::string& id_prefix,
                                      std::string* why, int width, int height) {
  return render_script_svg(gnuplot_svg_script(plot, width, height), id_prefix, why);
}

std::optional<std::string> render_script_svg(const std::string& script,
                                             const std::string& id_prefix, std::string* why) {
  try {
    return inline_svg(gnuplot_output_in_memory(script, "sweetspot-svg", false), id_prefix);
  } catch (const std::exception& e) {
    if (why) *why = e.what();
  }
  return std::nullopt;
}

std::vector<RenderedSvg> render_svgs(const std::vector<SvgPlot>& plots) {
  std::vector<RenderedSvg> rendered(plots.size());
  std::string why;
  if (plots.size() > 1) {
    try {
      std::vector<std::string> svgs = svgs_of_one_gnuplot(plots);
      for (std::size_t i = 0; i < plots.size(); ++i) rendered[i].svg = std::move(svgs[i]);
      return rendered;
    } catch (const std::exception& e) {
      why = e.what();
    }
    if (why.rfind("gnuplot is not installed", 0) == 0) {
      for (RenderedSvg& r : rendered) r.why = why;
      return rendered;
    }
  }
  // A plot gnuplot cannot draw ends that gnuplot: each plot is then drawn by
  // one of its own, so that the others are drawn and the failing one says why.
  for (std::size_t i = 0; i < plots.size(); ++i)
    rendered[i].svg = render_script_svg(plots[i].script, plots[i].id_prefix, &rendered[i].why);
  return rendered;
}

}  // namespace sweetspot::io
