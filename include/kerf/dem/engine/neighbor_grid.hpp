#pragma once
// Neighbour search with a cell grid (counting sort of particles into cells of size >= 2 R_max + skin), O(N);
// fragments flown far from the bulk are paired through their occupied cells only (sorted keys), O(M log M).
//
//   std::vector<Pair> pairs;
//   find_candidate_pairs(x, y, r, skin_m, pairs);  // every i < j with |xj - xi| < ri + rj + skin, sorted
#include <cstdint>
#include <span>
#include <vector>

namespace kerf::dem {

struct CandidatePair {
  std::int32_t i, j;  ///< i < j
  friend bool operator<(const CandidatePair& a, const CandidatePair& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; }
  friend bool operator==(const CandidatePair& a, const CandidatePair& b) = default;
};

/// Every pair closer than ri + rj + skin (surface gap below the skin), sorted by (i, j). Cost O(N) for
/// bounded size ratios: each particle visits its own and 8 neighbouring cells (the strays theirs among the
/// occupied cells, O(M log M) for M strays, however far they have flown).
void find_candidate_pairs(std::span<const double> x, std::span<const double> y, std::span<const double> r,
                          double skin_m, std::vector<CandidatePair>& pairs);

}  // namespace kerf::dem
