#pragma once

// Work over [0, count) on several threads, for the batch and the sweep: each
// thread takes one contiguous block (so a worker's caches, such as a sweep's
// row, stay warm), the calling thread the first. Results go into slots the
// caller owns, so the output order is the input order whatever the threads.

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace sweetspot::io {

// The threads to use by default: every core the machine shows.
inline int all_cores() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// Calls work(thread, begin, end) for `threads` (>= 1, at most `count`)
// contiguous blocks covering [0, count), concurrently, and returns when all
// are done. The first exception a block throws is rethrown here.
template <class Work>
void for_blocks(std::size_t count, int threads, Work&& work) {
  const std::size_t n =
      std::min<std::size_t>(static_cast<std::size_t>(std::max(1, threads)), count);
  if (n <= 1) {
    if (count > 0) work(std::size_t{0}, std::size_t{0}, count);
    return;
  }
  std::vector<std::exception_ptr> errors(n);
  const auto block = [&](std::size_t t) {
    try {
      work(t, count * t / n, count * (t + 1) / n);
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(n - 1);
  for (std::size_t t = 1; t < n; ++t) pool.emplace_back(block, t);
  block(0);
  for (std::thread& thread : pool) thread.join();
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace sweetspot::io
