#pragma once
// What the DEM engine's files (simulation*.cpp) share, internal to the library: the encoding of an incidence entry
// and the closest point of a wall. In an unnamed namespace, as when they were one file's: each file has its own
// copy, which inlines as it did.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "kerf/dem/engine/simulation.hpp"

namespace kerf::dem {
namespace {

enum Kind : std::uint32_t { kBond = 0, kPair = 1, kWall = 2 };

constexpr std::uint32_t encode(std::size_t index, Kind kind, std::uint32_t role) {
  return static_cast<std::uint32_t>(index) << 3 | kind << 1 | role;
}

/// Closest point of segment (x0, y0)-(x1, y1) to (px, py).
inline std::array<double, 2> closest_on_segment(const Wall& w, double px, double py) {
  const double ex = w.x1 - w.x0, ey = w.y1 - w.y0;
  const double len2 = ex * ex + ey * ey;
  const double s = len2 > 0 ? std::clamp(((px - w.x0) * ex + (py - w.y0) * ey) / len2, 0.0, 1.0) : 0.0;
  return {w.x0 + s * ex, w.y0 + s * ey};
}

}  // namespace
}  // namespace kerf::dem
