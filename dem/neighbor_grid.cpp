// Cell-grid neighbour search (linked cells via counting sort), O(N) per rebuild.
#include "kerf/dem/neighbor_grid.hpp"

#include <algorithm>
#include <cmath>

#include "kerf/error.hpp"

namespace kerf::dem {

void find_candidate_pairs(std::span<const double> x, std::span<const double> y, std::span<const double> r,
                          double skin_m, std::vector<CandidatePair>& pairs) {
  pairs.clear();
  const std::size_t n = x.size();
  if (n < 2) return;
  double x_min = x[0], x_max = x[0], y_min = y[0], y_max = y[0], r_max = 0;
  for (std::size_t i = 0; i < n; ++i) {
    x_min = std::min(x_min, x[i]);
    x_max = std::max(x_max, x[i]);
    y_min = std::min(y_min, y[i]);
    y_max = std::max(y_max, y[i]);
    r_max = std::max(r_max, r[i]);
  }
  if (!std::isfinite(x_max - x_min) || !std::isfinite(y_max - y_min) || !std::isfinite(r_max))
    throw ModelError("dem", "non-finite particle position or radius in the neighbour search: the run is unstable");
  // Cells of at least 2 R_max + skin; enlarged when the assembly is spread out (fragments flying apart)
  // so that the grid never has many more cells than particles.
  double cell = 2.0 * r_max + skin_m;
  const double max_cells = std::max(1024.0, 4.0 * static_cast<double>(n));
  while ((std::floor((x_max - x_min) / cell) + 1.0) * (std::floor((y_max - y_min) / cell) + 1.0) > max_cells) cell *= 2;
  const auto cells_along = [&](double extent) { return static_cast<std::int64_t>(std::floor(extent / cell) + 1.0); };
  const std::int64_t nx = cells_along(x_max - x_min), ny = cells_along(y_max - y_min);
  const double inv_x = static_cast<double>(nx) / (x_max - x_min + cell);
  const double inv_y = static_cast<double>(ny) / (y_max - y_min + cell);
  std::vector<std::int32_t> cell_of(n);
  std::vector<std::int32_t> start(static_cast<std::size_t>(nx * ny + 1), 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto cx = std::min<std::int64_t>(static_cast<std::int64_t>((x[i] - x_min) * inv_x), nx - 1);
    const auto cy = std::min<std::int64_t>(static_cast<std::int64_t>((y[i] - y_min) * inv_y), ny - 1);
    cell_of[i] = static_cast<std::int32_t>(cy * nx + cx);
    ++start[static_cast<std::size_t>(cell_of[i]) + 1];
  }
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<std::int32_t> fill(start.begin(), start.end() - 1), members(n);
  for (std::size_t i = 0; i < n; ++i) members[static_cast<std::size_t>(fill[cell_of[i]]++)] = static_cast<std::int32_t>(i);

  std::vector<std::int32_t> found;
  for (std::size_t i = 0; i < n; ++i) {
    found.clear();
    const std::int64_t cx = cell_of[i] % nx, cy = cell_of[i] / nx;
    for (std::int64_t jy = std::max<std::int64_t>(cy - 1, 0); jy <= std::min(cy + 1, ny - 1); ++jy) {
      for (std::int64_t jx = std::max<std::int64_t>(cx - 1, 0); jx <= std::min(cx + 1, nx - 1); ++jx) {
        const auto c = static_cast<std::size_t>(jy * nx + jx);
        for (std::int32_t k = start[c]; k < start[c + 1]; ++k) {
          const std::int32_t j = members[static_cast<std::size_t>(k)];
          if (j <= static_cast<std::int32_t>(i)) continue;
          const double dx = x[j] - x[i], dy = y[j] - y[i], reach = r[i] + r[j] + skin_m;
          if (dx * dx + dy * dy < reach * reach) found.push_back(j);
        }
      }
    }
    std::sort(found.begin(), found.end());
    for (std::int32_t j : found) pairs.push_back({static_cast<std::int32_t>(i), j});
  }
}

}  // namespace kerf::dem
