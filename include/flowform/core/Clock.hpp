// Wall-clock seconds for the timings a run reports (summary.json "timings", a loop's "seconds").
#pragma once

#include <chrono>

namespace flowform {

/// Seconds of wall-clock time since `start` (steady clock: immune to clock changes).
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace flowform
