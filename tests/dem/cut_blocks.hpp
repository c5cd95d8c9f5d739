#pragma once
// Constructed workpieces for tests of what a cut's edge meets (cut_edge_test.cpp, edge_zone_test.cpp): a block of
// equal disks on a triangular lattice, joints cut where a test says, the default tool put where a test says.
#include <algorithm>
#include <array>
#include <cstdint>

#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/dem/procedures/specimen.hpp"
#include "quick_specimen.hpp"

namespace kerf::dem::testing {

inline constexpr double kRadiusM = 10e-6;

/// A block of equal disks on a triangular lattice, every touching pair jointed (nothing locked in: without its
/// joints it is a bed of disks at rest), its left side and bottom held as a cut's workpiece.
inline Simulation hex_workpiece(const Material& material, double width_m, double height_m) {
  SpecimenSpec spec;
  spec.width_m = width_m;
  spec.height_m = height_m;
  spec.radius_min_m = spec.radius_max_m = kRadiusM;
  spec.packing = Packing::hexagonal;
  spec.relax_steps = 10;
  SpecimenReport report;
  const Simulation specimen = make_specimen(material, spec, report);
  std::size_t removed = 0;
  return make_workpiece(specimen, CutParams{}, removed);
}

inline double top_of(const Simulation& sim) {
  const auto& y = sim.particles().y;
  return *std::max_element(y.begin(), y.end()) + kRadiusM;
}

/// Unbonds every joint with an end that `cut(x, y)` says.
template <class F>
inline void unbond(Simulation& sim, F cut) {
  const auto& p = sim.particles();
  auto& b = sim.bonds();
  for (std::size_t k = 0; k < b.size(); ++k) {
    const auto i = static_cast<std::size_t>(b.i[k]), j = static_cast<std::size_t>(b.j[k]);
    if (cut(p.x[i], p.y[i]) || cut(p.x[j], p.y[j])) b.active[k] = 0;
  }
}

/// Puts the default tool with its tip at `tip_m` (its lowest point; the front-most of them) and initialises; returns
/// the tip as edge_meets takes it.
inline std::array<double, 2> place_tool(Simulation& sim, std::array<double, 2> tip_m, std::int32_t& first_wall,
                                        std::int32_t& n_walls) {
  CutParams p;
  auto outline = tool_outline(p, 0, tip_m[1]);
  double x_tip = outline[0][0], y_low = outline[0][1];
  for (const auto& q : outline)
    if (q[1] < y_low - 1e-12 || (q[1] < y_low + 1e-12 && q[0] < x_tip)) x_tip = q[0], y_low = q[1];
  first_wall = static_cast<std::int32_t>(sim.walls().size());
  for (auto& q : outline) q[0] += tip_m[0] - x_tip;
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const auto& a = outline[k];
    const auto& e = outline[(k + 1) % outline.size()];
    sim.add_wall(Wall{a[0], a[1], e[0], e[1]});
  }
  n_walls = static_cast<std::int32_t>(outline.size());
  sim.invalidate_neighbours();
  sim.initialise();
  return {tip_m[0], y_low};
}

/// A 0.03 mm deep cut, 0.04 mm of travel, through an active window or not.
inline CutParams block_cut(bool window) {
  CutParams p = windowed(6, 6, 4, 2);
  p.cut.depth_of_cut_m = 0.03e-3;
  p.cut.length_m = 0.04e-3;
  p.window.enabled = window;
  return p;
}

}  // namespace kerf::dem::testing
