// Seeded flaws: straight cracks of pre-broken joints (docs/physics-dem.md section 6, "strong bonds with seeded
// flaws"). A real glass breaks at its few largest flaws, a lattice of uniform joints at any joint; flaws let a
// glass have joints stronger than its macroscopic strength, which is then the flaws'.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "kerf/dem/procedures/specimen.hpp"

namespace kerf::dem {

namespace {

// Twice the signed area of (a, b, c): > 0 when c lies to the left of a -> b.
double orientation(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

// Whether segments p0-p1 and q0-q1 cross (each one's ends strictly on the two sides of the other's line).
bool segments_cross(double p0x, double p0y, double p1x, double p1y, const Flaw& q) {
  const double a = orientation(p0x, p0y, p1x, p1y, q.x0_m, q.y0_m), b = orientation(p0x, p0y, p1x, p1y, q.x1_m, q.y1_m);
  const double c = orientation(q.x0_m, q.y0_m, q.x1_m, q.y1_m, p0x, p0y);
  const double d = orientation(q.x0_m, q.y0_m, q.x1_m, q.y1_m, p1x, p1y);
  return ((a > 0 && b < 0) || (a < 0 && b > 0)) && ((c > 0 && d < 0) || (c < 0 && d > 0));
}

}  // namespace

std::vector<Flaw> seed_flaws(Simulation& sim, const Material& material, std::uint64_t seed) {
  std::vector<Flaw> flaws;
  const double length = material.flaw_length_m, density = material.flaw_density_per_m2;
  const auto& p = sim.particles();
  if (length <= 0 || density <= 0 || p.size() == 0) return flaws;
  double x_lo = p.x[0], x_hi = p.x[0], y_lo = p.y[0], y_hi = p.y[0];
  for (std::size_t k = 1; k < p.size(); ++k) {
    x_lo = std::min(x_lo, p.x[k]), x_hi = std::max(x_hi, p.x[k]);
    y_lo = std::min(y_lo, p.y[k]), y_hi = std::max(y_hi, p.y[k]);
  }
  // Centres in the disks' box widened by half a flaw on every side: a flaw reaching in from outside is drawn
  // as often as one inside, so every part of the specimen sees the same density of flaw length.
  x_lo -= 0.5 * length, x_hi += 0.5 * length, y_lo -= 0.5 * length, y_hi += 0.5 * length;
  // A stream of its own (not the packing's draws), 53-bit uniforms from the generator's bits (portable).
  std::mt19937_64 rng(seed ^ 0xF1A3D5EEDC0FFEE1ull);
  const auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const double expected = density * (x_hi - x_lo) * (y_hi - y_lo);
  const auto count = static_cast<std::size_t>(std::floor(expected + uniform()));  // unbiased rounding
  for (std::size_t f = 0; f < count; ++f) {
    const double cx = x_lo + (x_hi - x_lo) * uniform(), cy = y_lo + (y_hi - y_lo) * uniform();
    const double angle = std::numbers::pi * uniform(), hx = 0.5 * length * std::cos(angle);
    const double hy = 0.5 * length * std::sin(angle);
    flaws.push_back({cx - hx, cy - hy, cx + hx, cy + hy});
  }
  auto& b = sim.bonds();
  const auto stride = static_cast<std::size_t>(b.stride);
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (!b.active[k]) continue;
    const auto i = static_cast<std::size_t>(b.i[k]), j = static_cast<std::size_t>(b.j[k]);
    if (std::none_of(flaws.begin(), flaws.end(),
                     [&](const Flaw& f) { return segments_cross(p.x[i], p.y[i], p.x[j], p.y[j], f); }))
      continue;
    for (std::size_t e = 0; e < stride; ++e) {  // a closed crack: compression and friction, no tension
      b.bonded[k * stride + e] = 0;
      b.shear_force_N[k * stride + e] = 0;
    }
  }
  return flaws;
}

}  // namespace kerf::dem
