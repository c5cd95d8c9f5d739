// The cell-grid neighbour search against brute force: a packed assembly, fragments flown far away (the grid
// then covers the bulk, the strays outside it are paired through their occupied cells), strays touching the
// bulk's edge, so many flown that no grid fits (every disk a stray), a long thin strip, all disks at one point.
#include "kerf/dem/engine/neighbor_grid.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

using namespace kerf::dem;

namespace {

struct Cloud {
  std::vector<double> x, y, r;
  void add(double xi, double yi, double ri) { x.push_back(xi), y.push_back(yi), r.push_back(ri); }
};

std::vector<CandidatePair> brute_force(const Cloud& c, double skin) {
  std::vector<CandidatePair> out;
  for (std::size_t i = 0; i < c.x.size(); ++i)
    for (std::size_t j = i + 1; j < c.x.size(); ++j) {
      const double dx = c.x[j] - c.x[i], dy = c.y[j] - c.y[i], reach = c.r[i] + c.r[j] + skin;
      if (dx * dx + dy * dy < reach * reach)
        out.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
    }
  return out;
}

/// A jittered triangular lattice of nx x ny disks (radii 10-13 um, spacing 24 um: touching and near pairs).
Cloud lattice(int nx, int ny, unsigned seed) {
  Cloud c;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-1e-6, 1e-6), radius(10e-6, 13e-6);
  for (int row = 0; row < ny; ++row)
    for (int col = 0; col < nx; ++col)
      c.add((col + 0.5 * (row % 2)) * 24e-6 + jitter(rng), row * 24e-6 * std::sqrt(3.0) / 2 + jitter(rng), radius(rng));
  return c;
}

void require_same_as_brute_force(const Cloud& c, double skin) {
  std::vector<CandidatePair> grid;
  find_candidate_pairs(c.x, c.y, c.r, skin, grid);
  const std::vector<CandidatePair> expected = brute_force(c, skin);
  REQUIRE(!expected.empty());
  REQUIRE(grid.size() == expected.size());
  CHECK(grid == expected);
}

}  // namespace

TEST_CASE("neighbour grid: the pairs of brute force, near and far", "[neighbor_grid]") {
  const double skin = 3e-6;
  SECTION("a packed assembly") {
    require_same_as_brute_force(lattice(40, 40, 1), skin);
  }
  SECTION("fragments far away: a flying pair, a cluster and lone disks up to 1 m out") {
    Cloud c = lattice(40, 40, 2);
    c.add(0.05, 0.02, 12e-6);  // a pair 5 cm away, touching
    c.add(0.05 + 23e-6, 0.02, 11e-6);
    for (int k = 0; k < 30; ++k) c.add(-0.3 + 20e-6 * (k % 6), 1.0 + 20e-6 * (k / 6), 10e-6);  // a chip
    c.add(1.0, -1.0, 13e-6);
    c.add(-1.0, 0.5, 13e-6);
    c.add(2e-3, 0.9e-3, 12e-6);  // just outside the bulk, next to nothing
    require_same_as_brute_force(c, skin);
  }
  SECTION("a long thin strip (the bulk itself is wide)") {
    require_same_as_brute_force(lattice(600, 3, 3), skin);
  }
  SECTION("many flown disks (more than the 5 % the bulk box leaves out)") {
    Cloud c = lattice(30, 30, 4);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> far(-0.01, 0.01);
    for (int k = 0; k < 200; ++k) c.add(far(rng), 0.02 + far(rng), 12e-6);
    c.add(0.0, 0.02, 12e-6);  // two of them touching
    c.add(20e-6, 0.02, 12e-6);
    require_same_as_brute_force(c, skin);
  }
  SECTION("a row of disks running out of the lattice, among strays (pairs across the grid's edge)") {
    Cloud c = lattice(40, 40, 6);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> far(-0.05, 0.05);
    for (int k = 0; k < 300; ++k) c.add(far(rng), far(rng), 12e-6);  // enough strays to shrink the grid to the bulk
    for (int k = 0; k < 60; ++k)
      c.add(0.5e-3 + 22e-6 * k, 0.4e-3, 11e-6);  // a row of disks across the lattice's right side
    require_same_as_brute_force(c, skin);
  }
  SECTION("40 % flown in a wide fan (no central part fits a grid: every disk a stray)") {
    Cloud c = lattice(40, 25, 8);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> angle(0, 3), distance(0, 0.3);
    for (int k = 0; k < 700; ++k) {
      const double a = angle(rng), d = distance(rng);
      c.add(0.5e-3 + d * std::cos(a), 0.5e-3 + d * std::sin(a), 12e-6);
    }
    for (int k = 0; k < 5; ++k) c.add(0.1 + 23e-6 * k, 0.1, 12e-6);  // a flown chip, touching along its row
    require_same_as_brute_force(c, skin);
  }
  SECTION("every disk at one point") {
    Cloud c;
    for (int k = 0; k < 50; ++k) c.add(1e-3, 1e-3, 10e-6);
    require_same_as_brute_force(c, skin);
  }
}
