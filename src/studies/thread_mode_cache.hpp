#pragma once

// The frame's modes kept per thread for the studies' evaluations: a
// catalogue's rows, a sweep's points and a study's iterations on one thread
// share one ModeCache, so points that change only the impact, the ball or
// the strings solve no modes (the same numbers, bit for bit).

#include "sweetspot/mode_cache.hpp"

namespace sweetspot::studies {

inline ModeCache& thread_mode_cache() {
  thread_local ModeCache cache;
  return cache;
}

}  // namespace sweetspot::studies
