// Cell-grid neighbour search (linked cells via counting sort), O(N) per rebuild.
#include "kerf/dem/neighbor_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include "kerf/error.hpp"

namespace kerf::dem {

void find_candidate_pairs(std::span<const double> x, std::span<const double> y, std::span<const double> r,
                          double skin_m, std::vector<CandidatePair>& pairs) {
  pairs.clear();
  const std::size_t n = x.size();
  if (n < 2) return;
  double x_min = x[0], x_max = x[0], y_min = y[0], y_max = y[0], r_max = 0;
  bool finite = true;  // each one: min and max pass over a NaN, which the cell index would then cast (UBSan)
  for (std::size_t i = 0; i < n; ++i) {
    finite = finite && std::isfinite(x[i]) && std::isfinite(y[i]) && std::isfinite(r[i]);
    x_min = std::min(x_min, x[i]);
    x_max = std::max(x_max, x[i]);
    y_min = std::min(y_min, y[i]);
    y_max = std::max(y_max, y[i]);
    r_max = std::max(r_max, r[i]);
  }
  if (!finite || !std::isfinite(x_max - x_min) || !std::isfinite(y_max - y_min) || !std::isfinite(r_max))
    throw ModelError("dem", "non-finite particle position or radius in the neighbour search: the run is unstable");
  // Cells of at least 2 R_max + skin, over the particles' box. When fragments fly far from the assembly that box
  // would need huge cells (many particles in each, a search of O(N^2)): the grid then covers the bulk only, the
  // box of the central 90 % of the particles on each axis widened by a quarter of that range on each side, and
  // the particles outside it are clamped into its edge cells. Clamping never moves two particles closer than a
  // cell more than one cell apart, so no pair is lost, and the pairs are the same. Only if the bulk itself is
  // too large are the cells enlarged, so that the grid never has many more cells than particles.
  double cell = 2.0 * r_max + skin_m;
  const double max_cells = std::max(1024.0, 4.0 * static_cast<double>(n));
  const auto n_cells = [&](double x_extent, double y_extent) {
    return (std::floor(x_extent / cell) + 1.0) * (std::floor(y_extent / cell) + 1.0);
  };
  double gx0 = x_min, gx1 = x_max, gy0 = y_min, gy1 = y_max;  // the grid's box
  if (n_cells(x_max - x_min, y_max - y_min) > max_cells) {
    const auto bulk = [n](std::span<const double> v, double lo, double hi) {
      std::vector<double> sorted(v.begin(), v.end());
      const auto at = [&](double q) {
        const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(n - 1));
        std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
        return sorted[static_cast<std::size_t>(k)];
      };
      const double q05 = at(0.05), q95 = at(0.95), margin = 0.25 * (q95 - q05);
      return std::pair{std::max(lo, q05 - margin), std::min(hi, q95 + margin)};
    };
    const auto [bx0, bx1] = bulk(x, x_min, x_max);
    const auto [by0, by1] = bulk(y, y_min, y_max);
    if (n_cells(bx1 - bx0, by1 - by0) <= max_cells) gx0 = bx0, gx1 = bx1, gy0 = by0, gy1 = by1;
  }
  while (n_cells(gx1 - gx0, gy1 - gy0) > max_cells) cell *= 2;
  const auto cells_along = [&](double extent) { return static_cast<std::int64_t>(std::floor(extent / cell) + 1.0); };
  const std::int64_t nx = cells_along(gx1 - gx0), ny = cells_along(gy1 - gy0);
  const double inv_x = static_cast<double>(nx) / (gx1 - gx0 + cell);
  const double inv_y = static_cast<double>(ny) / (gy1 - gy0 + cell);
  const auto index = [](double u, std::int64_t cells) {  // clamped before the cast: no overflow far out
    return static_cast<std::int64_t>(std::clamp(u, 0.0, static_cast<double>(cells - 1)));
  };
  std::vector<std::int32_t> cell_of(n);
  std::vector<std::int32_t> start(static_cast<std::size_t>(nx * ny + 1), 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell_of[i] = static_cast<std::int32_t>(index((y[i] - gy0) * inv_y, ny) * nx + index((x[i] - gx0) * inv_x, nx));
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
