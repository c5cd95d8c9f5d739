// Cell-grid neighbour search (linked cells via counting sort), O(N) per rebuild; strays by sorted cell keys.
#include "kerf/dem/engine/neighbor_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kerf/error.hpp"

namespace kerf::dem {

namespace {
/// The occupied cells of a point set as sorted keys (row * stride + column, cells of `cell` over the box from
/// (x0, y0)), and for each point the three ranges of that order holding the cells next to its own, one per row:
/// the three cells of row cy + d next to a cell of key k have the keys k + d stride - 1 .. + 1, which grow with
/// k, so one sweep in key order finds every range. O(M log M) for M points, however far apart.
struct SparseCells {
  std::vector<std::pair<std::int64_t, std::int32_t>> keyed;  ///< (cell key, point), sorted
  std::vector<std::array<std::int32_t, 6>> ranges;           ///< per point: [begin, end) of rows cy - 1, cy, cy + 1

  SparseCells(std::span<const std::int32_t> points, std::span<const double> x, std::span<const double> y, double x0,
              double y0, double x_extent, double y_extent, double cell) {
    constexpr double kMaxCellsPerAxis = 1 << 30;  // keys below 2^62
    while (std::max(x_extent, y_extent) / cell > kMaxCellsPerAxis) cell *= 2;
    const auto stride = static_cast<std::int64_t>(std::floor(x_extent / cell)) + 3;  // a free column each side
    const std::size_t m = points.size();
    keyed.resize(m);
    for (std::size_t s = 0; s < m; ++s) {
      const auto u = static_cast<std::size_t>(points[s]);
      const auto column = static_cast<std::int64_t>(std::floor((x[u] - x0) / cell)) + 1;
      const auto row = static_cast<std::int64_t>(std::floor((y[u] - y0) / cell)) + 1;
      keyed[s] = {row * stride + column, static_cast<std::int32_t>(s)};
    }
    std::sort(keyed.begin(), keyed.end());
    ranges.resize(m);
    std::array<std::size_t, 6> at{};
    for (const auto& [k, s] : keyed) {
      for (std::size_t d = 0; d < 3; ++d) {
        const std::int64_t lo = k + (static_cast<std::int64_t>(d) - 1) * stride - 1, hi = lo + 2;
        std::size_t &b = at[2 * d], &e = at[2 * d + 1];
        while (b < m && keyed[b].first < lo) ++b;
        e = std::max(e, b);
        while (e < m && keyed[e].first <= hi) ++e;
        ranges[static_cast<std::size_t>(s)][2 * d] = static_cast<std::int32_t>(b);
        ranges[static_cast<std::size_t>(s)][2 * d + 1] = static_cast<std::int32_t>(e);
      }
    }
  }
};

/// The dense grid: nx x ny cells, each particle's cell (or kStray) and the cells' members (CSR).
constexpr std::int32_t kStray = -1;
struct GridCells {
  std::int64_t nx, ny;
  const std::int32_t *cell_of, *start, *members;
};
/// The strays and the grid's particles near its edge (`sparse`), and their cells.
struct StrayCells {
  const std::int32_t* sparse = nullptr;     ///< the points of `cells`
  const std::int32_t* sparse_of = nullptr;  ///< per particle: its index in `sparse`, or -1
  const SparseCells* cells = nullptr;
};

/// Particle by particle, its partners j > i in increasing j: from the grid, and (kStrays) the pairs with a stray.
/// Everything it reads is a local or an argument by value, so no reload follows a push_back's allocation.
template <bool kStrays>
void grid_pairs(std::span<const double> x, std::span<const double> y, std::span<const double> r, double skin_m,
                const GridCells g, const StrayCells s, std::vector<CandidatePair>& pairs) {
  const std::size_t n = x.size();
  std::vector<std::int32_t> found;
  const auto consider = [&found, x, y, r, skin_m](std::size_t i, std::int32_t j) {
    if (j <= static_cast<std::int32_t>(i)) return;
    const double dx = x[j] - x[i], dy = y[j] - y[i], reach = r[i] + r[j] + skin_m;
    if (dx * dx + dy * dy < reach * reach) found.push_back(j);
  };
  for (std::size_t i = 0; i < n; ++i) {
    found.clear();
    if (!kStrays || g.cell_of[i] != kStray) {
      const std::int64_t cx = g.cell_of[i] % g.nx, cy = g.cell_of[i] / g.nx;
      for (std::int64_t jy = std::max<std::int64_t>(cy - 1, 0); jy <= std::min(cy + 1, g.ny - 1); ++jy) {
        for (std::int64_t jx = std::max<std::int64_t>(cx - 1, 0); jx <= std::min(cx + 1, g.nx - 1); ++jx) {
          const auto c = static_cast<std::size_t>(jy * g.nx + jx);
          for (std::int32_t k = g.start[c]; k < g.start[c + 1]; ++k)
            consider(i, g.members[static_cast<std::size_t>(k)]);
        }
      }
    }
    if constexpr (kStrays) {
      if (s.sparse_of[i] >= 0) {  // the pairs with a stray (the grid found the others)
        const auto& range = s.cells->ranges[static_cast<std::size_t>(s.sparse_of[i])];
        for (std::size_t d = 0; d < 3; ++d)
          for (auto k = range[2 * d]; k < range[2 * d + 1]; ++k) {
            const std::int32_t j =
                s.sparse[static_cast<std::size_t>(s.cells->keyed[static_cast<std::size_t>(k)].second)];
            if (g.cell_of[i] == kStray || g.cell_of[j] == kStray) consider(i, j);
          }
      }
    }
    std::sort(found.begin(), found.end());
    for (std::int32_t j : found) pairs.push_back({static_cast<std::int32_t>(i), j});
  }
}
}  // namespace

// Long (~90 lines) for a reason: the search as one pass (the grid over the bulk, strays through their cells), the
// hot part of every rebuild, measured whole by bench/neighbor_search_ab.sh.
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
  // box of the central 90 % (or 80, ..., 50 %: the first that fits) of the particles on each axis widened by a
  // quarter of that range on each side, and the particles outside it (the strays) are paired through their
  // occupied cells only (SparseCells), among themselves and with the grid's particles within reach of its edge.
  // If even the central half would need more cells than a few per particle, every particle is a stray. The
  // pairs are the same whichever way they are found.
  const double reach_max = 2.0 * r_max + skin_m;
  const double cell = reach_max;
  const double max_cells = std::max(1024.0, 4.0 * static_cast<double>(n));
  const auto n_cells = [&](double x_extent, double y_extent) {
    return (std::floor(x_extent / cell) + 1.0) * (std::floor(y_extent / cell) + 1.0);
  };
  double gx0 = x_min, gx1 = x_max, gy0 = y_min, gy1 = y_max;  // the grid's box
  bool grid_fits = n_cells(x_max - x_min, y_max - y_min) <= max_cells;
  if (!grid_fits) {
    // The central part of the particles on each axis (quantiles q and 1 - q), widened by a quarter of its range
    // on each side; the narrower the more particles have flown off, down to the central half.
    std::vector<double> sx(x.begin(), x.end()), sy(y.begin(), y.end());
    const auto quantile = [n](std::vector<double>& v, double q) {
      const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(n - 1));
      std::nth_element(v.begin(), v.begin() + k, v.end());
      return v[static_cast<std::size_t>(k)];
    };
    for (double q : {0.05, 0.1, 0.15, 0.2, 0.25}) {
      const double xl = quantile(sx, q), xh = quantile(sx, 1 - q), yl = quantile(sy, q), yh = quantile(sy, 1 - q);
      gx0 = std::max(x_min, xl - 0.25 * (xh - xl)), gx1 = std::min(x_max, xh + 0.25 * (xh - xl));
      gy0 = std::max(y_min, yl - 0.25 * (yh - yl)), gy1 = std::min(y_max, yh + 0.25 * (yh - yl));
      if ((grid_fits = n_cells(gx1 - gx0, gy1 - gy0) <= max_cells)) break;
    }
  }
  if (!grid_fits) gx0 = gy0 = 0, gx1 = gy1 = -1;  // no grid: every particle a stray
  const auto cells_along = [&](double extent) {
    return std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor(extent / cell) + 1.0));
  };
  const std::int64_t nx = cells_along(gx1 - gx0), ny = cells_along(gy1 - gy0);
  const double inv_x = static_cast<double>(nx) / (gx1 - gx0 + cell);
  const double inv_y = static_cast<double>(ny) / (gy1 - gy0 + cell);
  const auto index = [](double u, std::int64_t cells) {  // clamped before the cast (rounding at the grid's edge)
    return static_cast<std::int64_t>(std::clamp(u, 0.0, static_cast<double>(cells - 1)));
  };
  // The grid's particles; the strays and the grid's particles within reach of its edge, which may pair with them.
  const bool bulk_only = gx0 > x_min || gx1 < x_max || gy0 > y_min || gy1 < y_max;
  bool any_stray = false;
  std::vector<std::int32_t> cell_of(n), sparse;
  std::vector<std::int32_t> start(static_cast<std::size_t>(nx * ny + 1), 0);
  for (std::size_t i = 0; i < n; ++i) {
    const bool inside = x[i] >= gx0 && x[i] <= gx1 && y[i] >= gy0 && y[i] <= gy1;
    if (!inside) {
      cell_of[i] = kStray, any_stray = true;
      sparse.push_back(static_cast<std::int32_t>(i));
      continue;
    }
    cell_of[i] = static_cast<std::int32_t>(index((y[i] - gy0) * inv_y, ny) * nx + index((x[i] - gx0) * inv_x, nx));
    ++start[static_cast<std::size_t>(cell_of[i]) + 1];
    if (bulk_only &&
        (x[i] < gx0 + reach_max || x[i] > gx1 - reach_max || y[i] < gy0 + reach_max || y[i] > gy1 - reach_max))
      sparse.push_back(static_cast<std::int32_t>(i));
  }
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<std::int32_t> fill(start.begin(), start.end() - 1), members(static_cast<std::size_t>(start.back()));
  for (std::size_t i = 0; i < n; ++i)
    if (cell_of[i] != kStray)
      members[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_of[i])]++)] = static_cast<std::int32_t>(i);
  std::vector<std::int32_t> sparse_of;
  std::optional<SparseCells> strays;
  if (any_stray) {
    sparse_of.assign(n, -1);
    for (std::size_t s = 0; s < sparse.size(); ++s)
      sparse_of[static_cast<std::size_t>(sparse[s])] = static_cast<std::int32_t>(s);
    strays.emplace(sparse, x, y, x_min, y_min, x_max - x_min, y_max - y_min, reach_max);
  }

  const GridCells grid{nx, ny, cell_of.data(), start.data(), members.data()};
  if (strays)
    grid_pairs<true>(x, y, r, skin_m, grid, {sparse.data(), sparse_of.data(), &*strays}, pairs);
  else
    grid_pairs<false>(x, y, r, skin_m, grid, {}, pairs);
}

}  // namespace kerf::dem
