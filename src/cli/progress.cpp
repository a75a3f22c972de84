#include "cli/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <utility>

namespace sweetspot::cli {

Progress::Progress(std::string what, bool enabled, std::ostream& err, bool terminal)
    : what_(std::move(what)), enabled_(enabled), err_(err), terminal_(terminal) {}

Progress::Progress(std::string what, bool enabled)
    : Progress(std::move(what), enabled, std::cerr, isatty(fileno(stderr)) == 1) {}

Progress::~Progress() { finish(); }

std::string Progress::text(std::size_t done, std::size_t total, double fraction) const {
  if (fraction < 0.0 && total > 0)
    fraction = static_cast<double>(done) / static_cast<double>(total);
  const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
  const std::string count = total > 0 ? fmt::format("{} of {} {}", done, total, what_)
                                      : fmt::format("{} {}", done, what_);
  if (fraction < 0.0) return fmt::format("progress: {}, {:.0f} s", count, seconds);
  fraction = std::clamp(fraction, 0.0, 1.0);
  const std::string percent = fmt::format("{:3.0f}%", 100.0 * fraction);
  if (!terminal_) return fmt::format("progress: {} ({}), {:.0f} s", percent, count, seconds);
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(fraction * kWidth);
  return fmt::format("[{}{}] {} {}, {:.0f} s", std::string(filled, '#'),
                     std::string(kWidth - filled, ' '), percent, count, seconds);
}

void Progress::update(std::size_t done, std::size_t total, double fraction) {
  if (!enabled_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  done_ = done;
  total_ = total;
  fraction_ = fraction;
  const Clock::time_point now = Clock::now();
  if (now - start_ < kQuietFor) return;
  if (shown_ && now - last_ < (terminal_ ? kBarEvery : kLineEvery)) return;
  last_ = now;
  shown_ = true;
  if (terminal_) {
    err_ << "\r" << text(done, total, fraction) << "\x1b[K" << std::flush;
  } else {
    err_ << text(done, total, fraction) << "\n" << std::flush;
  }
}

void Progress::finish() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  finished_ = true;
  // The bar as the work ended (the last update may have come too soon to draw).
  if (shown_ && terminal_)
    err_ << "\r" << text(done_, total_, fraction_) << "\x1b[K\n" << std::flush;
}

}  // namespace sweetspot::cli
