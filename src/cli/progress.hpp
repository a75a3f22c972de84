#pragma once

// How far a long command is, on standard error (never standard output): a
// map, a sweep, a catalogue. Silent for work that ends within kQuietFor; then
// a bar redrawn in place on a terminal, or a line every kLineEvery
// otherwise (a log, a pipe). Lines never start with "sweetspot: ", which
// opens only the one message a failing command ends with.

#include <chrono>
#include <cstddef>
#include <mutex>
#include <ostream>
#include <string>

namespace sweetspot::cli {

class Progress {
 public:
  static constexpr std::chrono::milliseconds kQuietFor{1500};
  static constexpr std::chrono::milliseconds kBarEvery{100};
  static constexpr std::chrono::milliseconds kLineEvery{5000};

  // `what` names the units counted ("grid points", "rows"); `enabled`
  // false (--quiet) prints nothing. `terminal`: whether `err` is one.
  Progress(std::string what, bool enabled, std::ostream& err, bool terminal);
  // On std::cerr, a terminal when stderr is one.
  Progress(std::string what, bool enabled);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // `done` of `total` units (total 0: not known); `fraction` in [0, 1], when
  // known otherwise than by done / total (a catalogue's bytes read), or < 0.
  // Safe to call from any thread.
  void update(std::size_t done, std::size_t total, double fraction = -1.0);
  // Ends the bar's line on a terminal (once anything was shown).
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  std::string text(std::size_t done, std::size_t total, double fraction) const;

  std::string what_;
  bool enabled_;
  std::ostream& err_;
  bool terminal_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_{};
  std::size_t done_ = 0, total_ = 0;
  double fraction_ = -1.0;
  bool shown_ = false;
  bool finished_ = false;
  std::mutex mutex_;
};

}  // namespace sweetspot::cli
