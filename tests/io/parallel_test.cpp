// The helpers the batch, the sweep and the benchmarks stand on: blocks of
// work over threads.
#include "io/parallel.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace sweetspot::io {
namespace {

TEST_CASE("for_blocks covers every index once, in contiguous blocks, on as many threads as asked") {
  // Oracle: each index written once by the block that holds it; blocks are
  // contiguous, ascending and never more than the threads or the items.
  for (const int threads : {1, 2, 3, 8}) {
    for (const std::size_t count :
         {std::size_t{0}, std::size_t{1}, std::size_t{5}, std::size_t{1000}}) {
      INFO(threads << " threads, " << count << " items");
      std::vector<int> hits(count, 0);
      std::vector<std::pair<std::size_t, std::size_t>> blocks(static_cast<std::size_t>(threads),
                                                              {0, 0});
      for_blocks(count, threads, [&](std::size_t t, std::size_t from, std::size_t to) {
        blocks[t] = {from, to};
        for (std::size_t i = from; i < to; ++i) ++hits[i];
      });
      CHECK(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }));
      std::size_t next = 0;
      for (const auto& [from, to] : blocks) {
        if (to == 0) continue;
        CHECK(from == next);
        next = to;
      }
      CHECK(next == count);
    }
  }
}

TEST_CASE("for_blocks rethrows what a block throws, after every block has ended") {
  std::vector<int> done(4, 0);
  CHECK_THROWS_WITH(for_blocks(4, 4,
                               [&](std::size_t t, std::size_t, std::size_t) {
                                 done[t] = 1;
                                 if (t == 2) throw std::runtime_error("block 2 failed");
                               }),
                    "block 2 failed");
  CHECK(std::accumulate(done.begin(), done.end(), 0) == 4);
}

}  // namespace
}  // namespace sweetspot::io
