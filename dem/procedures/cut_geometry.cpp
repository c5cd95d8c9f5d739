// The orthogonal cut's geometry: the grooves' outline, centres and laser-damaged layer, the tool's outline.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "cut_internal.hpp"
#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

namespace {
constexpr double kPi = std::numbers::pi;

/// Breaks every element of joint k before a cut: it carries compression and friction, no tension, no shear force.
void break_joint(BondStore& b, std::size_t k) {
  const auto stride = static_cast<std::size_t>(b.stride);
  for (std::size_t e = 0; e < stride; ++e) {
    b.bonded[k * stride + e] = 0;
    b.shear_force_N[k * stride + e] = 0;
  }
}

/// Calls visit(k, x_m) for each joint k with a bonded element across the cut line y = y_cut_m (its disks' centres on
/// either side of it; a centre on the line is on neither), x_m where the line between the centres crosses it. visit may
/// break joint k.
template <class Visit>
void for_joints_across_cut_line(const Simulation& sim, double y_cut_m, Visit visit) {
  const auto& q = sim.particles();
  const auto& b = sim.bonds();
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (!b.active[k] || b.n_bonded_elements(k) == 0) continue;
    const auto i = static_cast<std::size_t>(b.i[k]), j = static_cast<std::size_t>(b.j[k]);
    if ((q.y[i] - y_cut_m) * (q.y[j] - y_cut_m) >= 0) continue;
    visit(k, q.x[i] + (y_cut_m - q.y[i]) * (q.x[j] - q.x[i]) / (q.y[j] - q.y[i]));
  }
}
}  // namespace

bool inside_groove_outline(const CutParams& p, double dx_m, double depth_m) {
  if (p.grooves.shape == GrooveShape::none || depth_m < 0 || depth_m > p.grooves.depth_m) return false;
  double width = p.grooves.width_m;
  // The laser grooves are inverted trapezoids (seed 000 Section 4, discussion of Figure 18): the width
  // falls linearly from the top width at the surface to the bottom width at the groove depth.
  if (p.grooves.shape == GrooveShape::trapezoidal)
    width += (p.grooves.bottom_width_m - p.grooves.width_m) * depth_m / p.grooves.depth_m;
  return std::abs(dx_m) <= 0.5 * width;
}

double distance_to_groove_outline(const CutParams& p, double dx_m, double depth_m) {
  if (inside_groove_outline(p, dx_m, depth_m)) return 0;
  const double top = 0.5 * p.grooves.width_m, depth = p.grooves.depth_m;
  const double bottom = p.grooves.shape == GrooveShape::trapezoidal ? 0.5 * p.grooves.bottom_width_m : top;
  // The nearest of the two walls (by symmetry, the one on the point's side) and the bottom.
  const double x = std::abs(dx_m);
  const auto to_segment = [&](double ax, double ay, double bx, double by) {
    const double ux = bx - ax, uy = by - ay;
    const double s = std::clamp(((x - ax) * ux + (depth_m - ay) * uy) / (ux * ux + uy * uy), 0.0, 1.0);
    return std::hypot(x - (ax + s * ux), depth_m - (ay + s * uy));
  };
  return std::min(to_segment(top, 0, bottom, depth), to_segment(0, depth, bottom, depth));
}

std::array<std::size_t, 2> apply_groove_damage(Simulation& workpiece, const CutParams& p,
                                               const std::array<double, 4>& box_m) {
  std::array<std::size_t, 2> count{};
  if (p.grooves.shape == GrooveShape::none || p.grooves.damage_depth_m <= 0 ||
      p.grooves.damage_model != GrooveDamageModel::broken_joints)
    return count;
  const auto& q = workpiece.particles();
  auto& b = workpiece.bonds();
  const double y_top_m = box_m[3];
  const auto centres = groove_centres(p, box_m[0], box_m[1]);
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (!b.active[k]) continue;
    const auto i = static_cast<std::size_t>(b.i[k]), j = static_cast<std::size_t>(b.j[k]);
    if (!in_groove_layer(p, centres, y_top_m, 0.5 * (q.x[i] + q.x[j]), 0.5 * (q.y[i] + q.y[j]))) continue;
    ++count[0];
    // SplitMix64's finaliser of the joint's index: a uniform draw in [0, 1) that needs no generator state.
    std::uint64_t z = (static_cast<std::uint64_t>(k) + 1) * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    if (static_cast<double>(z >> 11) * 0x1.0p-53 >= p.grooves.damage_broken_fraction) continue;
    ++count[1];
    break_joint(b, k);
  }
  return count;
}

std::size_t break_cut_line_ahead(Simulation& sim, double y_cut_m, double tip_x_m, double length_m) {
  std::size_t count = 0;
  for_joints_across_cut_line(sim, y_cut_m, [&](std::size_t k, double x_m) {
    if (x_m < tip_x_m - length_m || x_m > tip_x_m) return;
    ++count;
    sim.break_bond(k, BreakMode::tension);
  });
  return count;
}

std::size_t separate_cut_line(Simulation& workpiece, double y_cut_m) {
  std::size_t count = 0;
  for_joints_across_cut_line(workpiece, y_cut_m, [&](std::size_t k, double) {
    ++count;
    break_joint(workpiece.bonds(), k);
  });
  return count;
}

std::vector<double> groove_centres(const CutParams& p, double x_left_m, double x_right_m) {
  std::vector<double> out;
  if (p.grooves.shape == GrooveShape::none) return out;
  const double half = 0.5 * p.grooves.width_m;
  // The laser treats the whole top surface, not only the tool's path: a groove ahead of the tool's end
  // still stops a crack, and the workpiece does not change with the travel (seed 000 Section 4: grooves on
  // the top surface).
  for (double c = x_right_m - 0.5 * p.grooves.pitch_m; c - half > x_left_m; c -= p.grooves.pitch_m) out.push_back(c);
  return out;
}

bool in_groove_layer(const CutParams& p, const std::vector<double>& centres, double y_top_m, double x_m, double y_m) {
  if (p.grooves.shape == GrooveShape::none || p.grooves.damage_depth_m <= 0) return false;
  for (double c : centres)
    if (distance_to_groove_outline(p, x_m - c, y_top_m - y_m) <= p.grooves.damage_depth_m) return true;
  return false;
}

bool inside_any_groove(const CutParams& p, const std::vector<double>& centres, double y_top_m, double x_m, double y_m) {
  for (double c : centres)
    if (inside_groove_outline(p, x_m - c, y_top_m - y_m)) return true;
  return false;
}

std::vector<std::array<double, 2>> tool_outline(const CutParams& p, double x_front_m, double y_tip_m) {
  // Built with the sharp tip at the origin, then moved. The tool moves in -x, so "back" is +x.
  // Rake face (from the tip upwards): rotated from the vertical towards the back by the rake angle; a
  // negative rake leans it forwards, over the chip. Clearance face (from the tip backwards): rises from
  // the machined surface by the clearance angle.
  const double g = units::deg_to_rad(p.tool.rake_deg), a = units::deg_to_rad(p.tool.clearance_deg);
  const std::array<double, 2> r{std::sin(g), std::cos(g)}, c{std::cos(a), std::sin(a)};
  // A back face closes the outline so that no disk can get inside the tool.
  const double lr = rake_face_length_m(p), lc = clearance_face_length_m(p);
  std::vector<std::array<double, 2>> v;
  v.push_back({lr * r[0], lr * r[1]});
  if (p.tool.edge_radius_m > 0) {
    const double beta = wedge_angle_rad(p), rho = p.tool.edge_radius_m;
    const double t = rho / std::tan(0.5 * beta), h = rho / std::sin(0.5 * beta);
    const double bx = r[0] + c[0], by = r[1] + c[1], bn = std::hypot(bx, by);
    const double cx = h * bx / bn, cy = h * by / bn;  // arc centre on the bisector
    const double a0 = std::atan2(t * r[1] - cy, t * r[0] - cx);
    double sweep = std::atan2(t * c[1] - cy, t * c[0] - cx) - a0;
    while (sweep > kPi) sweep -= 2 * kPi;
    while (sweep <= -kPi) sweep += 2 * kPi;
    for (int k = 0; k <= p.tool.edge_segments; ++k) {
      const double phi = a0 + sweep * k / p.tool.edge_segments;
      v.push_back({cx + rho * std::cos(phi), cy + rho * std::sin(phi)});
    }
  } else {
    v.push_back({0, 0});
  }
  v.push_back({lc * c[0], lc * c[1]});
  double x_min = 1e300, y_min = 1e300;
  for (const auto& q : v) x_min = std::min(x_min, q[0]), y_min = std::min(y_min, q[1]);
  for (auto& q : v) q = {q[0] - x_min + x_front_m, q[1] - y_min + y_tip_m};
  return v;
}

double leading_x_in_band(const std::vector<std::array<double, 2>>& v, double y0, double y1) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < v.size(); ++k) {
    auto a = v[k], b = v[(k + 1) % v.size()];
    if (a[1] > b[1]) std::swap(a, b);
    if (b[1] < y0 || a[1] > y1) continue;
    // Clip the edge to the band; x is linear in y along it (a horizontal edge keeps both ends).
    for (double y : {std::max(a[1], y0), std::min(b[1], y1)}) {
      const double x = b[1] > a[1] ? a[0] + (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]) : std::min(a[0], b[0]);
      best = std::min(best, x);
    }
  }
  return best;
}

}  // namespace kerf::dem
