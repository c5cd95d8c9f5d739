#pragma once
// Helpers shared by the benchmarks under bench/.
#include <algorithm>
#include <cmath>
#include <ctime>

namespace kerf::bench {

/// Thread CPU time in seconds: a per-core figure that stays meaningful on a shared, loaded machine.
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// |value - reference| / |reference| (reference 0 counts as the smallest positive double).
inline double relative_error(double value, double reference) {
  return std::abs(value - reference) / std::max(std::abs(reference), 1e-300);
}

}  // namespace kerf::bench
