// The neighbour search of two commits on the same synthetic assemblies, alternating in one process (built by
// bench/neighbor_search_ab.sh, which pastes each commit's dem/engine/neighbor_grid.cpp in as OLD_GRID and NEW_GRID).
// An assembly: a jittered lattice of 12000 disks (6 mm x 1 mm, radii 10-13 um) and `strays` disks flown off
// in a fan up to `spread` m away, as the fragments of an undamped cut without a window. CSV on stdout: the CPU
// milliseconds per call of each (the smallest of five rounds of 50 calls) and whether the pairs agree.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "kerf/dem/engine/neighbor_grid.hpp"
#include "kerf/error.hpp"

namespace kerf::dem {
namespace old_grid {
#include OLD_GRID
}
namespace new_grid {
#include NEW_GRID
}
}  // namespace kerf::dem

namespace {
using kerf::dem::CandidatePair;
using Coordinates = std::span<const double>;
// Not inlined, either of them: the library calls its search from another translation unit.
[[gnu::noinline]] void old_search(Coordinates x, Coordinates y, Coordinates r, double skin,
                                  std::vector<CandidatePair>& out) {
  kerf::dem::old_grid::find_candidate_pairs(x, y, r, skin, out);
}
[[gnu::noinline]] void new_search(Coordinates x, Coordinates y, Coordinates r, double skin,
                                  std::vector<CandidatePair>& out) {
  kerf::dem::new_grid::find_candidate_pairs(x, y, r, skin, out);
}

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
}  // namespace

int main() {
  std::printf("strays,spread_m,pairs,old_ms_per_call,new_ms_per_call,new_over_old,same_pairs\n");
  const std::array<std::pair<int, double>, 7> cases{
      {{0, 0}, {500, 0.005}, {2500, 0.025}, {2500, 0.2}, {8000, 0.01}, {8000, 0.3}, {30000, 0.3}}};
  for (const auto& [strays, spread] : cases) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> x, y, r;
    for (int k = 0; k < 12000; ++k)
      x.push_back(23e-6 * (k % 260) + 1e-6 * u(rng)), y.push_back(23e-6 * (k / 260)),
          r.push_back(10e-6 + 3e-6 * u(rng));
    for (int k = 0; k < strays; ++k) {
      const double a = 1.5 * u(rng), d = spread * u(rng);
      x.push_back(3e-3 + d * std::cos(a)), y.push_back(1e-3 + d * std::sin(a)), r.push_back(10e-6 + 3e-6 * u(rng));
    }
    std::vector<CandidatePair> a, b;
    double best_old = 1e300, best_new = 1e300;
    for (int round = 0; round < 5; ++round) {
      const double t0 = cpu_seconds();
      for (int k = 0; k < 50; ++k) old_search(x, y, r, 3e-6, a);
      const double t1 = cpu_seconds();
      for (int k = 0; k < 50; ++k) new_search(x, y, r, 3e-6, b);
      const double t2 = cpu_seconds();
      best_old = std::min(best_old, (t1 - t0) / 50), best_new = std::min(best_new, (t2 - t1) / 50);
    }
    std::printf("%d,%g,%zu,%.3f,%.3f,%.3f,%d\n", strays, spread, b.size(), 1e3 * best_old, 1e3 * best_new,
                best_new / best_old, static_cast<int>(a == b));
  }
}
