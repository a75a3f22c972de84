// The statistics every benchmark figure is reported with.

#include "bench/bench.hpp"

#include <catch2/catch.hpp>

using sweetspot::bench::median;

TEST_CASE("The median of timings is the middle one, or the mean of the middle two") {
  CHECK(median({3.0, 1.0, 2.0}) == 2.0);
  CHECK(median({4.0, 1.0, 3.0, 2.0}) == 2.5);
  CHECK(median({7.0}) == 7.0);
}
