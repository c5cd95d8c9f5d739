// Orthogonal cutting (Yang et al. 2018, Section 4): groove and tool geometry, force sign convention, parameter
// validation, and a small cut as a regression (forces, cracks, determinism, grooves).
#include "kerf/dem/procedures/cutting.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "kerf/dem/procedures/specimen.hpp"
#include "kerf/error.hpp"
#include "quick_specimen.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

CutParams grooved(GrooveShape shape) {
  CutParams p;
  p.grooves.shape = shape;
  p.grooves.depth_m = 0.1e-3;
  p.grooves.pitch_m = 0.2e-3;
  p.grooves.width_m = 0.06e-3;
  p.grooves.bottom_width_m = 0.02e-3;
  p.cut.length_m = 1e-3;
  return p;
}

/// A small random specimen with the Yang et al. 2018 workpiece's disk radii (10-13 um), default material.
using kerf::dem::testing::quick_workpiece_specimen;

double angle_deg(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  return std::atan2(b[1] - a[1], b[0] - a[0]) * 180 / std::numbers::pi;
}

}  // namespace

TEST_CASE("cutting: groove outline membership", "[cutting]") {
  const CutParams rect = grooved(GrooveShape::rectangular);
  CHECK(inside_groove_outline(rect, 0, 0.05e-3));
  CHECK(inside_groove_outline(rect, 0.029e-3, 0.099e-3));
  CHECK_FALSE(inside_groove_outline(rect, 0.031e-3, 0.05e-3));  // beyond the half-width
  CHECK_FALSE(inside_groove_outline(rect, 0, 0.101e-3));        // below the groove bottom
  CHECK_FALSE(inside_groove_outline(rect, 0, -1e-6));           // above the surface
  const CutParams trap = grooved(GrooveShape::trapezoidal);
  // Top as wide as the rectangle, bottom 0.02 mm: at mid-depth the half-width is 0.02 mm.
  CHECK(inside_groove_outline(trap, 0.029e-3, 0.001e-3));
  CHECK(inside_groove_outline(trap, 0.019e-3, 0.05e-3));
  CHECK_FALSE(inside_groove_outline(trap, 0.021e-3, 0.05e-3));
  CHECK_FALSE(inside_groove_outline(trap, 0.011e-3, 0.1e-3));  // bottom narrower than the top
  CHECK(inside_groove_outline(trap, 0.009e-3, 0.1e-3));
  CHECK_FALSE(inside_groove_outline(CutParams{}, 0, 0.05e-3));  // shape none
}

TEST_CASE("cutting: distance to a groove's walls and bottom", "[cutting]") {
  const CutParams rect = grooved(GrooveShape::rectangular);        // half-width 0.03 mm, depth 0.1 mm
  CHECK(distance_to_groove_outline(rect, 0.01e-3, 0.05e-3) == 0);  // inside
  CHECK_THAT(distance_to_groove_outline(rect, 0.04e-3, 0.05e-3), WithinAbs(0.01e-3, 1e-12));   // beside a wall
  CHECK_THAT(distance_to_groove_outline(rect, -0.04e-3, 0.05e-3), WithinAbs(0.01e-3, 1e-12));  // symmetric
  CHECK_THAT(distance_to_groove_outline(rect, 0, 0.12e-3), WithinAbs(0.02e-3, 1e-12));         // below the bottom
  CHECK_THAT(distance_to_groove_outline(rect, 0.06e-3, 0.14e-3), WithinAbs(0.05e-3, 1e-12));   // off the corner: 3-4-5
  // The inverted trapezoid: the wall from (0.03, 0) to (0.01, 0.1) mm. A point on the wall's outward normal
  // through its midpoint (0.02, 0.05), 0.01 mm out, is 0.01 mm from it.
  const CutParams trap = grooved(GrooveShape::trapezoidal);
  const double len = std::hypot(0.02e-3, 0.1e-3), nx = 0.1e-3 / len, ny = 0.02e-3 / len;
  CHECK_THAT(distance_to_groove_outline(trap, 0.02e-3 + 0.01e-3 * nx, 0.05e-3 + 0.01e-3 * ny),
             WithinAbs(0.01e-3, 1e-12));
  CHECK_THAT(distance_to_groove_outline(trap, 0, 0.13e-3), WithinAbs(0.03e-3, 1e-12));  // below the narrow bottom
}

TEST_CASE("cutting: the layer along the cut line spans a groove's bottom and the layer's depth on either side",
          "[cutting]") {
  // Grooves as deep as the cut (seed 000): on the cut line, the layer of depth d covers |x - c| <= w / 2 + d of each.
  CutParams p = grooved(GrooveShape::rectangular);  // width 0.06 mm, depth 0.1 mm, pitch 0.2 mm
  const double y_top = 1e-3, y_line = y_top - p.grooves.depth_m, c = 0.5e-3, d = 4e-6;
  const std::vector<double> centres{c, c + p.grooves.pitch_m};
  CHECK_FALSE(in_groove_layer(p, centres, y_top, c, y_line));  // no layer
  p.grooves.damage_depth_m = d;
  for (double side : {-1.0, 1.0}) {
    CHECK(in_groove_layer(p, centres, y_top, c + side * (0.03e-3 + 0.99 * d), y_line));
    CHECK_FALSE(in_groove_layer(p, centres, y_top, c + side * (0.03e-3 + 1.01 * d), y_line));
  }
  CHECK(in_groove_layer(p, centres, y_top, c, y_line - 0.99 * d));  // below the bottom
  CHECK_FALSE(in_groove_layer(p, centres, y_top, c, y_line - 1.01 * d));
  CHECK(in_groove_layer(p, centres, y_top, c + p.grooves.pitch_m + 0.03e-3, y_line));    // the next groove's
  CHECK_FALSE(in_groove_layer(p, centres, y_top, c + 0.5 * p.grooves.pitch_m, y_line));  // mid-ridge
}

TEST_CASE("cutting: the grooves' laser-affected layer breaks the joints near the walls and bottom", "[cutting]") {
  const Simulation specimen = quick_workpiece_specimen(0.4e-3, 0.3e-3, 11);
  CutParams g = grooved(GrooveShape::rectangular);
  g.grooves.depth_m = 0.08e-3;
  g.grooves.pitch_m = 0.2e-3;
  std::size_t removed = 0;
  const Simulation pristine = make_workpiece(specimen, g, removed);
  // The specimen's box, as CutRun finds it (disk edges).
  std::array<double, 4> box{1, -1, 1, -1};
  const auto& sp = specimen.particles();
  for (std::size_t k = 0; k < sp.size(); ++k) {
    box[0] = std::min(box[0], sp.x[k] - sp.radius[k]), box[1] = std::max(box[1], sp.x[k] + sp.radius[k]);
    box[2] = std::min(box[2], sp.y[k] - sp.radius[k]), box[3] = std::max(box[3], sp.y[k] + sp.radius[k]);
  }
  const double y_top = box[3];
  const auto broken_elements = [](const Simulation& s) {
    std::size_t n = 0;
    for (auto e : s.bonds().bonded) n += e == 0;
    return n;
  };
  // No layer: nothing broken.
  Simulation none = pristine;
  CHECK(apply_groove_damage(none, g, box) == std::array<std::size_t, 2>{0, 0});
  CHECK(broken_elements(none) == broken_elements(pristine));
  // A layer of 20 um, every joint in it broken: exactly those joints, each whole.
  g.grooves.damage_depth_m = 20e-6;
  g.grooves.damage_broken_fraction = 1;
  Simulation all = pristine;
  const auto counts = apply_groove_damage(all, g, box);
  CHECK(counts[0] >= 10);  // a layer, not a few joints (about 20 in this packing)
  CHECK(counts[1] == counts[0]);
  CHECK(broken_elements(all) - broken_elements(pristine) == counts[1] * static_cast<std::size_t>(all.bonds().stride));
  const auto& q = all.particles();
  const auto& b = all.bonds();
  const auto centres = groove_centres(g, box[0], box[1]);
  for (std::size_t k = 0; k < b.size(); ++k) {
    const auto i = static_cast<std::size_t>(b.i[k]), j = static_cast<std::size_t>(b.j[k]);
    const double x = 0.5 * (q.x[i] + q.x[j]), depth = y_top - 0.5 * (q.y[i] + q.y[j]);
    double d = 1;
    for (double c : centres) d = std::min(d, distance_to_groove_outline(g, x - c, depth));
    if (d > g.grooves.damage_depth_m)
      CHECK(b.n_bonded_elements(k) == pristine.bonds().n_bonded_elements(k));
    else
      CHECK(b.n_bonded_elements(k) == 0);
  }
  // Half of them: a binomial share (6 sigma), the same joints on a second call, none when the share is 0.
  g.grooves.damage_broken_fraction = 0.5;
  Simulation half = pristine, again = pristine;
  const auto h = apply_groove_damage(half, g, box);
  CHECK(h[0] == counts[0]);
  const double n = static_cast<double>(h[0]);
  CHECK(std::abs(static_cast<double>(h[1]) - 0.5 * n) < 6 * std::sqrt(0.25 * n));
  apply_groove_damage(again, g, box);
  CHECK(again.bonds().bonded == half.bonds().bonded);
  g.grooves.damage_broken_fraction = 0;
  Simulation zero = pristine;
  CHECK(apply_groove_damage(zero, g, box)[1] == 0);
  CHECK(zero.bonds().bonded == pristine.bonds().bonded);
  // A thicker layer holds more joints.
  g.grooves.damage_depth_m = 40e-6;
  Simulation thick = pristine;
  CHECK(apply_groove_damage(thick, g, box)[0] > counts[0]);
}

TEST_CASE("cutting: the separated cut line keeps no joint across it and every other joint", "[cutting]") {
  const Simulation specimen = quick_workpiece_specimen(0.4e-3, 0.3e-3, 11);
  std::size_t removed = 0;
  CutParams p;
  p.cut.depth_of_cut_m = 0.1e-3;
  const Simulation pristine = make_workpiece(specimen, p, removed);
  double y_top = -1;
  for (std::size_t k = 0; k < pristine.particles().size(); ++k)
    y_top = std::max(y_top, pristine.particles().y[k] + pristine.particles().radius[k]);
  const double y_cut = y_top - p.cut.depth_of_cut_m;
  const auto across = [&](const Simulation& s, std::size_t k) {
    const auto& q = s.particles();
    const auto i = static_cast<std::size_t>(s.bonds().i[k]), j = static_cast<std::size_t>(s.bonds().j[k]);
    return std::min(q.y[i], q.y[j]) < y_cut && std::max(q.y[i], q.y[j]) > y_cut;
  };
  std::size_t expected = 0;
  for (std::size_t k = 0; k < pristine.bonds().size(); ++k)
    expected += across(pristine, k) && pristine.bonds().n_bonded_elements(k) > 0;
  Simulation cut = pristine;
  const std::size_t broken = separate_cut_line(cut, y_cut);
  // A line 0.4 mm long through disks of 20-26 um diameter: a joint across it every disk or so.
  CHECK(broken >= 10);
  CHECK(broken == expected);
  for (std::size_t k = 0; k < cut.bonds().size(); ++k) {
    if (across(cut, k))
      CHECK(cut.bonds().n_bonded_elements(k) == 0);
    else
      CHECK(cut.bonds().n_bonded_elements(k) == pristine.bonds().n_bonded_elements(k));
  }
  // Joints already broken are not counted again; the disks did not move.
  CHECK(separate_cut_line(cut, y_cut) == 0);
  CHECK(cut.particles().y == pristine.particles().y);
  // A line above the workpiece crosses nothing.
  Simulation above = pristine;
  CHECK(separate_cut_line(above, y_top + 1e-3) == 0);
  CHECK(above.bonds().bonded == pristine.bonds().bonded);
}

TEST_CASE("cutting: the lateral crack ahead of the edge breaks the cut line's joints within its length", "[cutting]") {
  const Simulation specimen = quick_workpiece_specimen(0.4e-3, 0.3e-3, 11);
  std::size_t removed = 0;
  const Simulation pristine = make_workpiece(specimen, CutParams{}, removed);
  double x_min = 1, x_max = -1, y_top = -1;
  const auto& q = pristine.particles();
  for (std::size_t k = 0; k < q.size(); ++k)
    x_min = std::min(x_min, q.x[k]), x_max = std::max(x_max, q.x[k]), y_top = std::max(y_top, q.y[k] + q.radius[k]);
  const double y_cut = y_top - 0.1e-3, tip = 0.5 * (x_min + x_max), length = 0.1e-3;
  // Where each joint crosses the cut line (NaN: it does not).
  const auto crossing = [&](std::size_t k) {
    const auto i = static_cast<std::size_t>(pristine.bonds().i[k]), j = static_cast<std::size_t>(pristine.bonds().j[k]);
    if (std::min(q.y[i], q.y[j]) >= y_cut || std::max(q.y[i], q.y[j]) <= y_cut) return std::nan("");
    return q.x[i] + (y_cut - q.y[i]) * (q.x[j] - q.x[i]) / (q.y[j] - q.y[i]);
  };
  Simulation sim = pristine;
  const std::size_t broken = break_cut_line_ahead(sim, y_cut, tip, length);
  CHECK(broken >= 3);  // 0.1 mm of line through 20-26 um disks
  std::size_t elements = 0;
  for (std::size_t k = 0; k < sim.bonds().size(); ++k) {
    const double x = crossing(k);
    if (x >= tip - length && x <= tip) {
      CHECK(sim.bonds().n_bonded_elements(k) == 0);
      elements += static_cast<std::size_t>(pristine.bonds().n_bonded_elements(k));
    } else {
      CHECK(sim.bonds().n_bonded_elements(k) == pristine.bonds().n_bonded_elements(k));  // behind the tip, beyond L
    }
  }
  // Each element's break is a crack event (the engine's own break), in tension, on the cut line's joints.
  REQUIRE(sim.cracks().size() == elements);
  for (const auto& c : sim.cracks()) {
    CHECK(c.mode == BreakMode::tension);
    CHECK(crossing(static_cast<std::size_t>(c.bond)) >= tip - length);
  }
  CHECK(break_cut_line_ahead(sim, y_cut, tip, length) == 0);  // none twice
  // Ahead of the whole workpiece, it is the separated cut line.
  Simulation whole = pristine, separated = pristine;
  CHECK(break_cut_line_ahead(whole, y_cut, x_max + 1e-3, 1) == separate_cut_line(separated, y_cut));
  CHECK(whole.bonds().bonded == separated.bonds().bonded);
}

TEST_CASE("cutting: grooves every pitch across the cut path", "[cutting]") {
  CutParams p = grooved(GrooveShape::rectangular);
  auto c = groove_centres(p, 0, 1e-3);
  REQUIRE(c.size() == 5);  // 0.9, 0.7, 0.5, 0.3, 0.1 mm: the last still right of the left edge
  for (std::size_t k = 0; k < c.size(); ++k)
    CHECK_THAT(c[k], WithinAbs(0.9e-3 - 0.2e-3 * static_cast<double>(k), 1e-12));
  p.cut.length_m = 0.3e-3;  // the whole surface is grooved, not only the tool's path
  CHECK(groove_centres(p, 0, 1e-3) == c);
  CHECK(groove_centres(p, 0.15e-3, 1e-3).size() == 4);  // 0.1 mm would reach past a left edge at 0.15 mm
  CHECK(inside_any_groove(p, c, 1e-3, 0.9e-3, 0.95e-3));
  CHECK_FALSE(inside_any_groove(p, c, 1e-3, 0.8e-3, 0.95e-3));  // between grooves
  CHECK(groove_centres(CutParams{}, 0, 1e-3).empty());
}

TEST_CASE("cutting: tool faces have the rake and clearance angles, tip at the cut depth", "[cutting]") {
  CutParams p;
  p.cut.depth_of_cut_m = 0.1e-3;
  const auto v = tool_outline(p, 2e-3, 0.5e-3);
  REQUIRE(v.size() == 3);  // rake top, tip, clearance end (closed by the back face)
  // Tip = lowest point at the cut line; front-most point at x_front.
  CHECK_THAT(v[1][1], WithinAbs(0.5e-3, 1e-15));
  CHECK_THAT(std::min({v[0][0], v[1][0], v[2][0]}), WithinAbs(2e-3, 1e-15));
  // Rake face from the tip upwards: the tool moves in -x, a rake of -15 deg leans the face forwards
  // (towards -x) by 15 deg from the vertical.
  CHECK_THAT(angle_deg(v[1], v[0]), WithinAbs(90 + 15, 1e-9));
  // Clearance face from the tip backwards (+x): rises 15 deg above the machined surface.
  CHECK_THAT(angle_deg(v[1], v[2]), WithinAbs(15, 1e-9));
  // First contact with a workpiece whose top is one depth of cut above the tip: the rake face there,
  // 0.1 mm tan 15 deg ahead of the tip.
  CHECK_THAT(leading_x_in_band(v, 0.5e-3, 0.6e-3),
             WithinAbs(v[1][0] - 0.1e-3 * std::tan(15 * std::numbers::pi / 180), 1e-12));
  p.tool.rake_deg = 10;
  p.tool.clearance_deg = 7;
  const auto w = tool_outline(p, 0, 0);
  CHECK_THAT(angle_deg(w[1], w[0]), WithinAbs(90 - 10, 1e-9));
  CHECK_THAT(angle_deg(w[1], w[2]), WithinAbs(7, 1e-9));
  CHECK_THAT(leading_x_in_band(w, 0, 0.1e-3), WithinAbs(w[1][0], 1e-12));  // positive rake: the tip leads
}

TEST_CASE("cutting: the rake face reaches 3 depths of cut above the tip, or tool.rake_face_height_mm", "[cutting]") {
  CutParams p;
  p.cut.depth_of_cut_m = 0.1e-3;
  CHECK_THAT(tool_outline(p, 0, 0)[0][1], WithinAbs(0.3e-3, 1e-15));  // v[0] is the rake face's top
  p.cut.depth_of_cut_m = 0.2e-3;
  CHECK_THAT(tool_outline(p, 0, 0)[0][1], WithinAbs(0.6e-3, 1e-15));
  // One tool for every depth: the same height whatever the depth, the rake angle kept.
  p.tool.rake_face_height_m = 0.25e-3;
  validate_cut_params(p);
  const auto v = tool_outline(p, 0, 0);
  CHECK_THAT(v[0][1] - v[1][1], WithinAbs(0.25e-3, 1e-15));
  CHECK_THAT(angle_deg(v[1], v[0]), WithinAbs(105, 1e-9));
  // Not above the uncut surface: an error naming the key.
  p.tool.rake_face_height_m = 0.2e-3;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Matchers::Contains("tool.rake_face_height_mm"));
}

TEST_CASE("cutting: a rounded edge is tangent to both faces and touches the cut line", "[cutting]") {
  CutParams p;
  p.tool.edge_radius_m = 5e-6;
  p.tool.edge_segments = 6;
  const auto v = tool_outline(p, 0, 1e-3);
  REQUIRE(v.size() == 2 + 7);
  CHECK_THAT(angle_deg(v[1], v[0]), WithinAbs(105, 1e-9));  // rake face direction kept
  CHECK_THAT(angle_deg(v[7], v[8]), WithinAbs(15, 1e-9));   // clearance face direction kept
  double y_min = 1e300;
  for (const auto& q : v) y_min = std::min(y_min, q[1]);
  CHECK_THAT(y_min, WithinAbs(1e-3, 1e-15));
  // Arc points all at the radius from a common centre: equal chords.
  const double chord = std::hypot(v[2][0] - v[1][0], v[2][1] - v[1][1]);
  for (int k = 2; k < 7; ++k)
    CHECK_THAT(std::hypot(v[static_cast<std::size_t>(k + 1)][0] - v[static_cast<std::size_t>(k)][0],
                          v[static_cast<std::size_t>(k + 1)][1] - v[static_cast<std::size_t>(k)][1]),
               WithinRel(chord, 1e-9));
}

TEST_CASE("cutting: force signs (material resisting the tool gives positive main and thrust)", "[cutting]") {
  // The tool moves in -x: disks pushed ahead of it push it back (+x) and up (+y).
  const auto f = tool_force_components(3.0, 2.0);
  CHECK(f[0] == 3.0);
  CHECK(f[1] == 2.0);
  // Engine check: one held disk in the tool's path.
  Material m;
  Simulation sim(m, {});
  const int d = sim.add_particle(0, 0, 10e-6);
  sim.particles().group[static_cast<std::size_t>(d)] = 1;
  CutParams p;
  p.cut.depth_of_cut_m = 20e-6;
  for (auto [a, b] : {std::pair{0, 1}, std::pair{1, 2}, std::pair{2, 0}}) {
    // Tip 5 um below the disk's centre, rake face crossing y = 0 at x = 8 um: it overlaps the disk's right side.
    const double x_front = 8e-6 - 55e-6 * std::tan(15 * std::numbers::pi / 180);
    const auto v = tool_outline(p, x_front, -5e-6);
    sim.add_wall({v[static_cast<std::size_t>(a)][0], v[static_cast<std::size_t>(a)][1],
                  v[static_cast<std::size_t>(b)][0], v[static_cast<std::size_t>(b)][1], -1, 0});
  }
  sim.initialise();
  sim.evaluate_forces();
  double fx = 0, fy = 0;
  for (const auto& w : sim.walls()) fx += w.fx, fy += w.fy;
  const auto g = tool_force_components(fx, fy);
  CHECK(g[0] > 0);
  CHECK(g[1] > 0);  // the negative rake face presses the disk down: the disk pushes the tool up
}

TEST_CASE("cutting: without friction or fracture, the tool's work is the energy the workpiece stores", "[cutting]") {
  // Nothing dissipates (conservative_material: no friction, no fracture, no damping; every disk integrated), so
  // the books' dissipated energy is the integrator's error only (the tool's contacts included: without their
  // springs' energy, 7.5 % of the work went missing).
  SpecimenSpec spec = kerf::dem::testing::quick_random_spec(0.4e-3, 0.2e-3, 3);
  spec.radius_min_m = 10e-6;
  spec.radius_max_m = 13e-6;
  SpecimenReport report;
  const Simulation specimen = make_specimen(kerf::dem::testing::conservative_material(), spec, report);
  CutParams p;
  p.cut.depth_of_cut_m = 0.03e-3;
  p.cut.speed_m_per_s = 2;
  p.cut.length_m = 0.03e-3;
  p.cut.entry_fraction = 0.1;
  p.tool.friction_coefficient = 0;
  CutRun run(specimen, p);
  while (run.advance()) {
  }
  const CutResult& r = run.result();
  REQUIRE(r.energy_booked);
  INFO("work " << r.energy.tool_work_J << " J, dissipated " << r.energy.dissipated_J << " J, stored change "
               << r.energy.stored_change_J << " J");
  CHECK(r.cracks.tensile + r.cracks.shear == 0);
  CHECK(r.energy.left_kinetic_J == 0);  // no window: nothing leaves
  CHECK(r.energy.tool_work_J > 0);
  CHECK(std::abs(r.energy.dissipated_J) < 1e-3 * r.energy.tool_work_J);  // measured: 9e-5
}

TEST_CASE("cutting: parameters are validated with the dotted key", "[cutting]") {
  CutParams p = grooved(GrooveShape::trapezoidal);
  p.grooves.bottom_width_m = 0.07e-3;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("grooves.bottom_width_mm = 0.07"));
  p = grooved(GrooveShape::rectangular);
  p.grooves.width_m = 0.3e-3;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("grooves.width_mm = 0.3"));
  p = CutParams{};
  p.tool.rake_deg = 60;
  p.tool.clearance_deg = 40;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("tool.clearance_deg = 40"));
  p = CutParams{};
  p.tool.edge_radius_m = 1e-3;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("tool.edge_radius_um = 1000"));
  kerf::Json scene{{"cut", {{"depth_of_cut_mm", 0.1}, {"length_mm", 0.2}}}, {"grooves", {{"shape", "triangular"}}}};
  kerf::ObjectReader root(scene, "");
  CHECK_THROWS_AS(read_cut_params(root), kerf::InputError);
}

TEST_CASE("cutting: a checkpoint of another format version is refused by name", "[cutting]") {
  CHECK_THROWS_WITH(CutRun::deserialize("KERFCUT1 and the rest"), Catch::Contains("KERFCUT1"));
  CHECK_THROWS_WITH(CutRun::deserialize("something else"), Catch::Contains("not a kerf-dem cut checkpoint"));
}

TEST_CASE("cutting: mean forces per travel window", "[cutting]") {
  // A force that steps from 1 N to 3 N (main) at 0.3 mm, sampled every 0.001 mm up to 0.6 mm; thrust = travel in mm.
  std::vector<CutSample> samples;
  for (int k = 0; k <= 600; ++k) {
    const double travel = k * 1e-6;
    samples.push_back({travel, 0, travel < 0.3e-3 ? 1.0 : 3.0, travel * 1e3});
  }
  const auto w = travel_window_means(samples, 0.6e-3, 0.1e-3);
  REQUIRE(w.size() == 6);  // 0.6 / 0.1 rounds to 6.000000000000001: no seventh, empty window
  int n = 0;
  double sum = 0;
  for (const auto& x : w) n += x.n_samples, sum += x.main_force_N * x.n_samples;
  CHECK(n == static_cast<int>(samples.size()));  // every sample in exactly one window
  double direct = 0;
  for (const auto& s : samples) direct += s.main_force_N;
  CHECK_THAT(sum, WithinRel(direct, 1e-12));  // the windows' weighted means give back the whole mean
  CHECK(w[0].main_force_N == 1.0);
  CHECK(w[4].main_force_N == 3.0);
  CHECK_THAT(w[5].to_m, WithinAbs(0.6e-3, 1e-18));
  CHECK(w[5].n_samples == 101);               // the sample at the end of the travel goes to the last window
  for (std::size_t k = 0; k < w.size(); ++k)  // a linear force: each window's mean is its mid-travel value
    CHECK_THAT(w[k].thrust_force_N, WithinAbs(0.1 * (static_cast<double>(k) + 0.5), 0.001));
  // A window longer than the travel: one window, the whole mean.
  const auto one = travel_window_means(samples, 0.6e-3, 1e-3);
  REQUIRE(one.size() == 1);
  CHECK_THAT(one[0].main_force_N, WithinRel(direct / static_cast<double>(samples.size()), 1e-12));
  CutParams p;
  p.cut.window_m = 0;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("cut.window_mm = 0"));
}

TEST_CASE("cutting: means say whether they are steady (after the entry, with standard errors)", "[cutting]") {
  // Forces of independent noise about 5 N (main) and 2 N (thrust), a sample every um of travel up to `to_mm`.
  const auto cut_to = [](double to_mm) {
    CutResult r;
    std::uint64_t state = 12345;
    const auto noise = [&state] {  // uniform in [-0.5, 0.5), a fixed LCG: the same samples on every machine
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5;
    };
    for (int k = 0; k <= static_cast<int>(std::lround(to_mm * 1000)); ++k)
      r.samples.push_back({k * 1e-6, 0, 5 + noise(), 2 + noise()});
    return r;
  };
  // Long enough, means from 0.3 mm (the entry, kEntryTravelM): steady; the range is the one averaged.
  CutResult steady = cut_to(2.0);
  steady_statistics(steady, kEntryTravelM);
  CHECK(steady.steady);
  CHECK(steady.not_steady_reason.empty());
  CHECK(std::isfinite(steady.main_force_sem_N));
  CHECK(steady.steady_from_travel_m == kEntryTravelM);
  CHECK_THAT(steady.steady_to_travel_m, WithinAbs(2e-3, 1e-15));
  // A scene's entry_fraction x length a hair short of 0.3 mm (0.0272727 x 11 mm) still counts as after the entry.
  CutResult rounded = cut_to(2.0);
  steady_statistics(rounded, 0.0272727 * 11e-3);
  CHECK(rounded.steady);
  // The same signal averaged from 0.1 mm: the entry is in the means.
  CutResult early = cut_to(2.0);
  steady_statistics(early, 0.1e-3);
  CHECK_FALSE(early.steady);
  CHECK_THAT(early.not_steady_reason, Catch::Contains("the means start at 0.1 mm of travel, within the entry") &&
                                          Catch::Contains("cut.entry_fraction"));
  // A cut that ends within the entry (issue 40: cut.length_mm=0.1, means over 0.025-0.1 mm).
  CutResult short_cut = cut_to(0.1);
  steady_statistics(short_cut, 0.025e-3);
  CHECK_FALSE(short_cut.steady);
  CHECK_THAT(short_cut.not_steady_reason, Catch::Contains("the cut travels 0.1 mm, within the entry"));
  CHECK_THAT(short_cut.steady_to_travel_m, WithinAbs(0.1e-3, 1e-15));
  // Past the entry but with too few samples for a standard error: not steady either, and said why.
  CutResult few = cut_to(0.303);
  steady_statistics(few, kEntryTravelM);
  REQUIRE_FALSE(std::isfinite(few.main_force_sem_N));
  CHECK_FALSE(few.steady);
  CHECK_THAT(few.not_steady_reason,
             Catch::Contains("cannot be computed from " + std::to_string(few.n_steady_samples) + " samples"));
  // No sample in the range at all.
  CutResult none = cut_to(0.2);
  steady_statistics(none, kEntryTravelM);
  CHECK_FALSE(none.steady);
  CHECK(none.n_steady_samples == 0);
  CHECK_THAT(none.not_steady_reason, Catch::Contains("no sample"));
}

TEST_CASE("cutting: crack places and subsurface damage depth", "[cutting]") {
  // Cut line at 0.9 mm; the steady part machined x in [0.2, 0.5] mm. The deepest crack (x 0.7 mm, the
  // entry's side) is outside the steady span; so is the chip crack, which lies inside it but above the line.
  std::vector<CrackEvent> cracks{{0, 0.3e-3, 1.0e-3, 0, 1e-6, BreakMode::tension, 0, 0},
                                 {0, 0.4e-3, 0.85e-3, 0, 1e-6, BreakMode::shear, 1, 0},
                                 {0, 0.7e-3, 0.80e-3, 0, 1e-6, BreakMode::tension, 2, 0},
                                 {0, 0.2e-3, 0.88e-3, 0, 1e-6, BreakMode::tension, 3, 0}};
  const CutCrackCounts n = count_cut_cracks(cracks, 0.9e-3, {0.2e-3, 0.5e-3});
  CHECK(n.tensile == 3);
  CHECK(n.shear == 1);
  CHECK(n.chip == 1);
  CHECK(n.subsurface == 3);
  CHECK_THAT(n.subsurface_damage_depth_m, WithinAbs(0.1e-3, 1e-15));
  CHECK(n.subsurface_steady == 2);  // x 0.4 and 0.2 mm (the span's end included)
  CHECK_THAT(n.subsurface_steady_damage_depth_m, WithinAbs(0.05e-3, 1e-15));
  CHECK(std::string(crack_place(0.95e-3, 0.9e-3)) == "chip");
  // No steady span: no steady cracks, the whole-workpiece counts unchanged.
  const CutCrackCounts none = count_cut_cracks(cracks, 0.9e-3, {1.0, 1.0});
  CHECK(none.subsurface_steady == 0);
  CHECK(none.subsurface_steady_damage_depth_m == 0);
  CHECK(none.subsurface_steady_damage_depth_p95_m == 0);
  CHECK(none.subsurface == 3);
}

TEST_CASE("cutting: the steady damage depth's 95th percentile is not the sparse tail's", "[cutting]") {
  // 100 steady subsurface cracks at depths 1..100 um (in shuffled order): the nearest-rank 95th percentile is the
  // 95th smallest, 95 um; the deepest is 100 um. A tail of five cracks at the window's floor (400 um) moves the
  // deepest to 400 um; the percentile moves only by the ranks they add (to the 100th of 105: 100 um).
  const double y_cut = 0.9e-3;
  std::vector<CrackEvent> cracks;
  for (int k = 0; k < 100; ++k) {
    const int depth_um = 1 + (k * 37) % 100;  // a permutation of 1..100
    cracks.push_back({0, 0.3e-3, y_cut - depth_um * 1e-6, 0, 1e-6, BreakMode::tension, k, 0});
  }
  const CutCrackCounts n = count_cut_cracks(cracks, y_cut, {0.2e-3, 0.5e-3});
  REQUIRE(n.subsurface_steady == 100);
  CHECK_THAT(n.subsurface_steady_damage_depth_p95_m, WithinAbs(95e-6, 1e-12));
  CHECK_THAT(n.subsurface_steady_damage_depth_m, WithinAbs(100e-6, 1e-12));
  for (int k = 0; k < 5; ++k) cracks.push_back({0, 0.4e-3, y_cut - 400e-6, 0, 1e-6, BreakMode::shear, 100 + k, 0});
  const CutCrackCounts tail = count_cut_cracks(cracks, y_cut, {0.2e-3, 0.5e-3});
  CHECK_THAT(tail.subsurface_steady_damage_depth_m, WithinAbs(400e-6, 1e-12));
  CHECK_THAT(tail.subsurface_steady_damage_depth_p95_m, WithinAbs(100e-6, 1e-12));
  // One crack: it is its own percentile.
  const CutCrackCounts one = count_cut_cracks({cracks.front()}, y_cut, {0.2e-3, 0.5e-3});
  CHECK(one.subsurface_steady_damage_depth_p95_m == one.subsurface_steady_damage_depth_m);
}

// Long (~110 lines) for a reason: one small cut, run once, checked from every side (forces, cracks, a rerun to the
// bit, the grooved surface beside it).
TEST_CASE("cutting: a small cut regression (forces, cracks, determinism, grooves)", "[cutting]") {
  const Simulation specimen = quick_workpiece_specimen(0.4e-3, 0.25e-3, 3);
  CutParams p;
  p.cut.depth_of_cut_m = 0.05e-3;
  p.cut.speed_m_per_s = 2;
  p.cut.length_m = 0.08e-3;
  const auto run = [&](const CutParams& params) {
    CutRun r(specimen, params);
    while (r.advance()) {
    }
    return r.result();
  };
  const CutResult a = run(p);
  INFO("main " << a.main_force_N << " N, thrust " << a.thrust_force_N << " N, cracks " << a.cracks.tensile << "+"
               << a.cracks.shear << " (chip " << a.cracks.chip << ")");
  CHECK(std::isfinite(a.main_force_N));
  CHECK(std::isfinite(a.thrust_force_N));
  CHECK(a.main_force_N > 0);
  CHECK(a.thrust_force_N > 0);
  CHECK(a.main_force_std_N > 0);
  CHECK(a.n_steady_samples > 10);
  CHECK(a.cracks.tensile + a.cracks.shear > 0);
  CHECK(a.cracks.chip > 0);
  CHECK(a.samples.back().travel_m >= p.cut.length_m);
  CHECK(a.n_removed_by_grooves == 0);
  // The steady part machined the surface from the edge's final x over the travel after the entry; a sharp
  // edge starts half a largest radius right of the workpiece (box[1]) and the rake face leans forwards over
  // the depth of cut, so the final edge lies that far right of box[1] - travel.
  const double edge_start =
      a.workpiece_box_m[1] + 0.5 * 13e-6 + p.cut.depth_of_cut_m * std::tan(15 * std::numbers::pi / 180);
  CHECK_THAT(a.steady_machined_x_m[1] - a.steady_machined_x_m[0],
             WithinRel(a.samples.back().travel_m - p.cut.entry_fraction * p.cut.length_m, 1e-9));
  CHECK_THAT(a.steady_machined_x_m[0], WithinAbs(edge_start - a.samples.back().travel_m, 1.5e-6));
  CHECK(a.cracks.subsurface_steady <= a.cracks.subsurface);
  CHECK(a.cracks.subsurface_steady_damage_depth_m <= a.cracks.subsurface_damage_depth_m);
  // Same specimen and parameters: bit-identical forces.
  const CutResult b = run(p);
  REQUIRE(b.samples.size() == a.samples.size());
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    CHECK(a.samples[k].main_force_N == b.samples[k].main_force_N);
    CHECK(a.samples[k].thrust_force_N == b.samples[k].thrust_force_N);
  }
  // Saved halfway and restored: the rest of the cut is bit-identical.
  CutRun half(specimen, p);
  for (std::size_t k = 0; k < a.samples.size() / 2; ++k) half.advance();
  CutRun restored = CutRun::deserialize(half.serialize());
  while (restored.advance()) {
  }
  REQUIRE(restored.result().samples.size() == a.samples.size());
  CHECK(restored.result().samples.back().main_force_N == a.samples.back().main_force_N);
  CHECK(restored.result().main_force_N == a.main_force_N);
  CHECK(restored.result().cracks.chip == a.cracks.chip);
  // A frictionless tool (the engine test checks the law itself): other forces, and a checkpoint keeps the
  // tool's friction (restored halfway, the rest of the cut is bit-identical to the uninterrupted one).
  CutParams frictionless = p;
  frictionless.tool.friction_coefficient = 0;
  const CutResult smooth = run(frictionless);
  CHECK(smooth.main_force_N != a.main_force_N);
  CutRun smooth_half(specimen, frictionless);
  for (std::size_t k = 0; k < smooth.samples.size() / 2; ++k) smooth_half.advance();
  CutRun smooth_restored = CutRun::deserialize(smooth_half.serialize());
  while (smooth_restored.advance()) {
  }
  CHECK(smooth_restored.params().tool.friction_coefficient == 0.0);
  // ... and the rake face's height.
  CutParams short_rake = p;
  short_rake.tool.rake_face_height_m = 1.5 * p.cut.depth_of_cut_m;
  CHECK(CutRun::deserialize(CutRun(specimen, short_rake).serialize()).params().tool.rake_face_height_m ==
        short_rake.tool.rake_face_height_m);
  CHECK(smooth_restored.result().main_force_N == smooth.main_force_N);
  CHECK(smooth_restored.result().thrust_force_N == smooth.thrust_force_N);
  // Neither the tool nor a groove may reach the held bottom rows (workpiece 0.25 mm tall, held rows 26 um).
  CutParams too_deep = p;
  too_deep.cut.depth_of_cut_m = 0.24e-3;
  CHECK_THROWS_WITH(CutRun(specimen, too_deep), Catch::Contains("cut.depth_of_cut_mm = 0.24"));
  too_deep = grooved(GrooveShape::rectangular);
  too_deep.cut.length_m = p.cut.length_m;
  too_deep.grooves.depth_m = 0.24e-3;
  CHECK_THROWS_WITH(CutRun(specimen, too_deep), Catch::Contains("grooves.depth_mm = 0.24"));
  too_deep.grooves.depth_m = 0.2e-3;  // deep, but above the held rows: a valid workpiece
  CHECK_NOTHROW(CutRun(specimen, too_deep));
  // Grooves: fewer particles.
  CutParams g = p;
  g.grooves.shape = GrooveShape::rectangular;
  g.grooves.depth_m = p.cut.depth_of_cut_m;
  g.grooves.pitch_m = 0.1e-3;
  g.grooves.width_m = 0.04e-3;
  std::size_t removed = 0;
  const Simulation work = make_workpiece(specimen, g, removed);
  CHECK(removed > 0);
  CHECK(work.particles().size() + removed == specimen.particles().size());
  CHECK(work.bonds().size() < specimen.bonds().size());
  // An inverted trapezoid with the same top width removes fewer disks than the rectangle.
  g.grooves.width_m = 0.08e-3;
  std::size_t removed_rectangle = 0, removed_trapezoid = 0;
  make_workpiece(specimen, g, removed_rectangle);
  g.grooves.shape = GrooveShape::trapezoidal;
  g.grooves.bottom_width_m = 0.01e-3;
  make_workpiece(specimen, g, removed_trapezoid);
  CHECK(removed_trapezoid > 0);
  CHECK(removed_trapezoid < removed_rectangle);
  // Held disks: the left and bottom boundary (group 1), none at the free top right.
  int held = 0;
  std::size_t top_right = 0;
  const auto& q = work.particles();
  for (std::size_t k = 0; k < q.size(); ++k) {
    held += q.group[k] == 1;
    if (q.x[k] + q.y[k] > q.x[top_right] + q.y[top_right]) top_right = k;
  }
  CHECK(held > 0);
  CHECK(q.group[top_right] == 0);
}

TEST_CASE("cutting: a cut the disks cannot resolve or the workpiece cannot hold is an input error", "[cutting]") {
  // Stable at the extremes: each of these ran before as a silent zero force, a tool jumping through the
  // workpiece in one step, a run of years, or a tool crushing the held disks.
  const Simulation specimen = quick_workpiece_specimen(0.3e-3, 0.2e-3, 5);
  const auto& q = specimen.particles();
  double r_min = 1, r_max = 0, x_min = 1, x_max = -1;
  for (std::size_t k = 0; k < q.size(); ++k) {
    r_min = std::min(r_min, q.radius[k]), r_max = std::max(r_max, q.radius[k]);
    x_min = std::min(x_min, q.x[k] - q.radius[k]), x_max = std::max(x_max, q.x[k] + q.radius[k]);
  }
  CutParams p;
  p.cut.depth_of_cut_m = 0.05e-3;
  p.cut.speed_m_per_s = 2;
  p.cut.length_m = 0.05e-3;
  const double dt = CutRun(specimen, p).result().time_step_s;
  const auto throws_on = [&](const CutParams& bad, const std::string& key) {
    CHECK_THROWS_WITH(CutRun(specimen, bad), Catch::Contains(key + " = "));
  };
  // Depth: at least the smallest disk radius.
  CutParams c = p;
  c.cut.depth_of_cut_m = 0.99 * r_min;
  throws_on(c, "cut.depth_of_cut_mm");
  c.cut.depth_of_cut_m = 1.01 * r_min;
  CHECK_NOTHROW(CutRun(specimen, c));
  // Travel: the tool's leading edge, half a largest radius right of the workpiece at the start, stops
  // before the held left disks (centres within 2 largest radii of the left side, so reaching 3 of them).
  const double max_travel = (x_max - x_min) - 2.5 * r_max;
  c = p;
  c.cut.length_m = 1.001 * max_travel;
  throws_on(c, "cut.length_mm");
  c.cut.length_m = 0.999 * max_travel;
  CHECK_NOTHROW(CutRun(specimen, c));
  // Speed: at most 1 % of the smallest radius per step; at least fast enough to finish within 1e9 steps.
  c = p;
  c.cut.speed_m_per_s = 1.001 * 0.01 * r_min / dt;
  throws_on(c, "cut.speed_m_per_s");
  c.cut.speed_m_per_s = 0.999 * 0.01 * r_min / dt;
  CHECK_NOTHROW(CutRun(specimen, c));
  c.cut.speed_m_per_s = 0.999 * p.cut.length_m / (1e9 * dt);
  throws_on(c, "cut.speed_m_per_s");
  c.cut.speed_m_per_s = 1.001 * p.cut.length_m / (1e9 * dt);
  CHECK_NOTHROW(CutRun(specimen, c));
  // Grooves that remove no disk: too narrow to hold a disk's centre, or a pitch with no groove on the
  // surface. A groove as wide as a disk removes some.
  c = grooved(GrooveShape::rectangular);
  c.cut.length_m = p.cut.length_m;
  c.grooves.depth_m = p.cut.depth_of_cut_m;
  c.grooves.width_m = 0.01 * r_min;
  throws_on(c, "grooves.width_mm");
  c.grooves.width_m = 2 * r_max;
  CHECK_NOTHROW(CutRun(specimen, c));
  c.grooves.pitch_m = 3 * (x_max - x_min);
  throws_on(c, "grooves.pitch_mm");
}
