#include "io/plot.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "io/atomic_file.hpp"

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
    return line;
  }

 private:
  int fd_ = -1;
};

// Runs gnuplot on `script` with the PNG on its standard output going to
// `png_fd` and its messages captured, never on ours. Throws PlotFailure.
void run_gnuplot(const std::string& script, int png_fd) {
  std::array<int, 2> sockets{};
  // A socket rather than a pipe: send() reports a gnuplot that quit early as
  // EPIPE (MSG_NOSIGNAL) instead of raising SIGPIPE in this process.
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets.data()) != 0) {
    throw PlotFailure(std::string("cannot start gnuplot: ") + std::strerror(errno));
  }
  const Messages messages;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, sockets[1], 0);
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
  char* argv[] = {name, nullptr};
  pid_t pid = -1;
  const int spawned = ::posix_spawnp(&pid, name, &actions, &attributes, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(sockets[1]);
  if (spawned != 0) {
    ::close(sockets[0]);
    if (spawned == ENOENT)
      throw PlotFailure("gnuplot is not installed (apt-get install gnuplot-nox)");
    throw PlotFailure(std::string("cannot start gnuplot: ") + std::strerror(spawned));
  }
  std::string_view left = script;
  while (!left.empty()) {
    const ssize_t n = ::send(sockets[0], left.data(), left.size(), MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;  // gnuplot has gone; its status says why
    left.remove_prefix(static_cast<std::size_t>(n));
  }
  ::close(sockets[0]);
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
  struct statvfs disk {};
  const bool full = ::fstatvfs(fd, &disk) == 0 && disk.f_bavail == 0;
  return (size == 0 ? std::string("gnuplot wrote nothing")
                    : "gnuplot wrote an incomplete PNG of " + std::to_string(size) + " bytes") +
         (full ? ": " + std::string(std::strerror(ENOSPC)) : "");
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
std::string quoted(const std::string& text) {
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
  return quoted(escaped);
}

bool on_plot(const Plot& plot, double y) {
  return !plot.y_range || (y >= plot.y_range->first && y <= plot.y_range->second);
}

}  // namespace

std::string gnuplot_script(const Plot& plot, const std::string& png_path) {
  std::string s;
  s += "set terminal pngcairo size 960,640 enhanced font 'DejaVu Sans,11'\n";
  if (!png_path.empty()) s += "set output " + quoted(png_path) + "\n";
  s += "set title " + label(plot.title) + "\n";
  s += "set xlabel " + label(plot.x_label) + "\n";
  s += "set ylabel " + label(plot.y_label) + "\n";
  s += "set grid\nset key " + plot.key_position + " box opaque\n";
  if (plot.log_x) s += "set logscale x\nset format x '10^{%L}'\n";
  if (plot.log_y) s += "set logscale y\nset format y '10^{%L}'\n";
  if (plot.x_range)
    s += fmt::format("set xrange [{}:{}]\n", plot.x_range->first, plot.x_range->second);
  if (plot.y_range)
    s += fmt::format("set yrange [{}:{}]\n", plot.y_range->first, plot.y_range->second);
  if (!plot.y2_label.empty()) {
    s += "set y2label " + label(plot.y2_label) + "\nset ytics nomirror\nset y2tics\n";
    if (plot.log_y2) s += "set logscale y2\nset format y2 '10^{%L}'\n";
  }
  int tag = 1;
  for (const auto& [x, text] : plot.vertical_lines) {
    s += fmt::format("set arrow {} from {},graph 0 to {},graph 1 nohead dt 2 lc rgb 'gray40'\n",
                     tag, x, x);
    // Stagger the labels so that neighbouring lines do not overwrite each other.
    s += fmt::format("set label {} {} at {},graph {} left offset 0.5,0 tc rgb 'gray30'\n", tag,
                     label(text), x, 0.96 - 0.06 * (tag - 1));
    ++tag;
  }
  for (const PlotMarker& m : plot.markers) {
    s += fmt::format("set label {} {} at {},{} left offset 1,-1 point pt 7 ps 1.2\n", tag++,
                     label(m.label), m.x, m.y);
  }
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& series = plot.series[i];
    s += fmt::format("$series{} << EOD\n", i);
    bool broken = true;
    for (std::size_t k = 0; k < series.x.size(); ++k) {
      const auto& y = series.y[k];
      const bool log_y = series.right_axis ? plot.log_y2 : plot.log_y;
      const bool off_log = (log_y && y && *y <= 0) || (plot.log_x && series.x[k] <= 0);
      if (!y || (!series.right_axis && !on_plot(plot, *y)) || off_log) {
        if (!broken) s += "\n";
        broken = true;
        continue;
      }
      s += fmt::format("{} {}\n", series.x[k], *y);
      broken = false;
    }
    s += "EOD\n";
  }
  s += "plot ";
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    if (i) s += ", \\\n     ";
    s += fmt::format("$series{} using 1:2{} with {} title {}", i,
                     plot.series[i].right_axis ? " axes x1y2" : "", plot.series[i].style,
                     label(plot.series[i].title));
  }
  return s + "\n";
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

}  // namespace sweetspot::io
