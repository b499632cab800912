// The entry points' phase reports (Options::on_progress) and the clock their Stats times read.
#pragma once

#include <chrono>
#include <cstddef>

#include "kergen/kergen.h"

namespace kergen {

// Tells the caller, when it listens, that `phase` starts on `count` items.
inline void report(const Options& options, Progress::Phase phase, size_t count) {
  if (options.on_progress) options.on_progress(Progress{phase, count});
}

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

}  // namespace kergen
