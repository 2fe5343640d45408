// Wall-clock seconds for the timings a run reports (summary.json "timings", a loop's "seconds").
#pragma once

#include <chrono>
#include <map>
#include <string>

namespace flowform {

/// Seconds of wall-clock time since `start` (steady clock: immune to clock changes).
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Where the seconds of a piece of work went: each call adds the seconds since the previous one
/// (or since construction) to `timings[what]`.
class Laps {
 public:
  explicit Laps(std::map<std::string, double>& timings) : m_timings(timings) {}
  void operator()(const std::string& what) {
    m_timings[what] += secondsSince(m_last);
    m_last = std::chrono::steady_clock::now();
  }

 private:
  std::map<std::string, double>& m_timings;
  std::chrono::steady_clock::time_point m_last = std::chrono::steady_clock::now();
};

}  // namespace flowform
