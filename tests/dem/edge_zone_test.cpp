// The edge zone of a windowed cut (issue 54 item 4; CutParams::edge_zone, docs/dem.md "The edge zone"), on the
// constructed workpieces of cut_edge_test.cpp: off, the cut is today's to the bit; an intact block under the edge
// carries the layer's force and its reaction, equal and opposite, a bed of loose disks none; the energy books
// balance with the layer's energy as the only dissipation of a conservative block; a checkpoint round trip (with the
// lateral crack too), and an older state (KERFCUTA) read with the zone off; the lateral crack ahead of the edge; bad
// keys named.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "cut_blocks.hpp"
#include "kerf/dem/procedures/cut_window.hpp"
#include "kerf/dem/procedures/cutting.hpp"

using namespace kerf::dem;
using namespace kerf::dem::testing;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

constexpr double kCuttingNPerM = 500, kThrustNPerM = 400;  // 0.5 and 0.4 N/mm: the order of the experiments' part

CutParams zone_cut() {
  CutParams p = block_cut(true);
  p.edge_zone.enabled = true;
  p.edge_zone.cutting_force_N_per_m = kCuttingNPerM;
  p.edge_zone.thrust_force_N_per_m = kThrustNPerM;
  return p;
}

struct ZoneRun {
  CutResult result;
  std::int64_t loaded_samples = 0;  ///< samples whose disks carried loads
  std::int64_t loaded_booked = 0;   ///< those in the energy books' steady part (after the steady part's first sample)
  double worst_sum_error = 0;       ///< the largest |sum of the loads + F t| over them, relative to F t
};

/// Runs a cut to its end, checking after each sample that the loads on the disks sum to minus the layer's force on
/// the tool (Newton's third law).
ZoneRun run_zone(const Simulation& workpiece, const CutParams& p) {
  CutRun run(workpiece, p);
  ZoneRun z;
  const double t = workpiece.options().thickness_m;
  bool counted = false;  // a steady sample came before this one
  for (bool more = true; more;) {
    const std::size_t before = run.result().samples.size();
    more = run.advance();
    if (run.result().samples.size() == before) break;
    const auto& loads = run.simulation().disk_loads();
    const bool booked = counted;
    counted = counted || run.result().samples.back().travel_m >= p.cut.entry_fraction * p.cut.length_m;
    if (loads.empty()) continue;
    ++z.loaded_samples;
    z.loaded_booked += booked;
    double fx = 0, fy = 0;
    for (const auto& l : loads) fx += l.fx_N, fy += l.fy_N;
    z.worst_sum_error =
        std::max({z.worst_sum_error,
                  std::abs(fx + p.edge_zone.cutting_force_N_per_m * t) / (p.edge_zone.cutting_force_N_per_m * t),
                  std::abs(fy + p.edge_zone.thrust_force_N_per_m * t) / (p.edge_zone.thrust_force_N_per_m * t)});
  }
  z.result = run.result();
  return z;
}

}  // namespace

TEST_CASE("edge zone: off, the cut is today's to the bit, whatever its other keys", "[edge_zone]") {
  const Simulation specimen = quick_workpiece_specimen(0.6e-3, 0.25e-3, 7);
  CutParams p = windowed(3, 2, 2, 2);
  p.cut.length_m = 0.1e-3;
  CutParams keys = p;
  keys.edge_zone.cutting_force_N_per_m = kCuttingNPerM;
  keys.edge_zone.thrust_force_N_per_m = kThrustNPerM;
  keys.edge_zone.radius_m = 30e-6;
  const auto cut = [&](const CutParams& q) {
    CutRun run(specimen, q);
    while (run.advance()) {
    }
    return run.result();
  };
  const CutResult a = cut(p), b = cut(keys);
  REQUIRE(a.samples.size() == b.samples.size());
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    CHECK(a.samples[k].main_force_N == b.samples[k].main_force_N);
    CHECK(a.samples[k].thrust_force_N == b.samples[k].thrust_force_N);
  }
  CHECK(b.edge_zone.samples == 0);
  CHECK(b.window.chips.edge_tied_disks + b.window.chips.edge_loose_disks == 0);
}

TEST_CASE("edge zone: an intact block carries the layer's force and its reaction, a loose bed neither", "[edge_zone]") {
  const Simulation block = hex_workpiece(conservative_material(), 0.6e-3, 0.25e-3);
  const CutParams p = zone_cut();
  const ZoneRun intact = run_zone(block, p);
  const CutEdgeZoneRecord& z = intact.result.edge_zone;
  INFO("steady samples " << z.samples << ", intact " << z.intact_samples << ", loaded " << intact.loaded_samples);
  REQUIRE(z.samples > 10);
  // The lattice's rows leave a tied disk across the cut line within a diameter of the tip at every moment (measured:
  // all but the steady part's first sample).
  CHECK(z.intact_samples >= z.samples - 1);
  CHECK(intact.loaded_samples >= z.samples);
  CHECK(intact.worst_sum_error < 1e-12);
  CHECK(intact.result.window.chips.edge_tied_disks > 0);  // the disks the edge reached left as the layer's chip
  CHECK(intact.result.window.chips.edge_loose_disks == 0);
  CHECK(z.tool_work_J > 0);

  // A bed of the default (damped, frictional) disks, which the tool pushes rather than scatters.
  Simulation bed = hex_workpiece(Material{}, 0.6e-3, 0.25e-3);
  unbond(bed, [](double, double) { return true; });
  const ZoneRun loose = run_zone(bed, p);
  CHECK(loose.result.edge_zone.samples > 10);
  CHECK(loose.result.edge_zone.intact_samples == 0);
  CHECK(loose.loaded_samples == 0);
  CHECK(loose.result.edge_zone.tool_work_J == 0);
  CHECK(loose.result.window.chips.edge_tied_disks == 0);
  CHECK(loose.result.window.chips.edge_loose_disks > 0);  // reached fragments leave as powder
}

TEST_CASE("edge zone: the books balance, the tool's work on the layer its force times the travel in intact glass",
          "[edge_zone]") {
  // The tool's work on the layer is F t v dt per step of each sample in which the edge met intact glass (the books'
  // steady part, which starts after its first sample); it enters the books with the walls' work, and the reaction's
  // work on the disks is part of what the disks received. The disks the edge removes take their energy with them
  // (as a crushed grain's), so the books balance as today's windowed cut does, to rounding. (On this unbreakable
  // block, compressed as a whole by the tool, the dissipation the books find is 4.5-9.6 % of the work: the
  // integrator's error after the sudden release of the removed disks' joints; docs/notes/
  // 2026-12-06-toughness-damping-and-edge.md, item 4.)
  CutParams p = zone_cut();
  p.tool.friction_coefficient = 0;
  const Simulation block = hex_workpiece(conservative_material(), 0.6e-3, 0.25e-3);
  const ZoneRun z = run_zone(block, p);
  const CutResult& r = z.result;
  REQUIRE(r.energy_booked);
  const CutEnergy& e = r.energy;
  CHECK_THAT(e.dissipated_J + e.left_kinetic_J + e.left_strain_J + e.stored_change_J, WithinRel(e.tool_work_J, 1e-12));
  const double per_sample_J =
      kCuttingNPerM * block.options().thickness_m * p.cut.speed_m_per_s * r.time_step_s * p.cut.sample_every_steps;
  REQUIRE(z.loaded_booked > 10);
  CHECK_THAT(r.edge_zone.tool_work_J, WithinRel(per_sample_J * static_cast<double>(z.loaded_booked), 1e-9));
  CHECK(r.edge_zone.tool_work_J < e.tool_work_J);
  CHECK(r.energy.left_strain_J > 0);  // the removed disks' joints and contacts
}

TEST_CASE("edge zone: resumed from its checkpoint, the cut and its record go on to the bit, a KERFCUTA state read",
          "[edge_zone]") {
  const Simulation block = quick_workpiece_specimen(0.6e-3, 0.25e-3, 7);
  CutParams p = zone_cut();
  CutRun whole(block, p), half(block, p);
  while (whole.advance()) {
  }
  for (std::size_t k = 0; k < whole.result().samples.size() / 2; ++k) half.advance();
  const std::string state = half.serialize();
  CutRun restored = CutRun::deserialize(state);
  while (restored.advance()) {
  }
  const CutEdgeZoneRecord &a = whole.result().edge_zone, &b = restored.result().edge_zone;
  CHECK(restored.result().samples.back().main_force_N == whole.result().samples.back().main_force_N);
  CHECK(b.samples == a.samples);
  CHECK(b.intact_samples == a.intact_samples);
  CHECK(b.tool_work_J == a.tool_work_J);
  CHECK(b.reaction_work_J == a.reaction_work_J);
  CHECK(restored.result().window.chips.edge_tied_disks == whole.result().window.chips.edge_tied_disks);
  CHECK(restored.params().edge_zone.radius_m == whole.params().edge_zone.radius_m);

  // With the lateral crack ahead of the edge: its keys travel in the state, its broken joints in the bonds.
  CutParams crack = p;
  crack.edge_zone.lateral_crack = LateralCrack::ahead_of_edge;
  crack.edge_zone.lateral_crack_length_m = 40e-6;
  CutRun whole_crack(block, crack), half_crack(block, crack);
  while (whole_crack.advance()) {
  }
  for (std::size_t k = 0; k < whole_crack.result().samples.size() / 2; ++k) half_crack.advance();
  CutRun restored_crack = CutRun::deserialize(half_crack.serialize());
  CHECK(restored_crack.params().edge_zone.lateral_crack == LateralCrack::ahead_of_edge);
  CHECK(restored_crack.params().edge_zone.lateral_crack_length_m == crack.edge_zone.lateral_crack_length_m);
  while (restored_crack.advance()) {
  }
  CHECK(restored_crack.result().samples.back().main_force_N == whole_crack.result().samples.back().main_force_N);
  CHECK(restored_crack.result().edge_zone.intact_samples == whole_crack.result().edge_zone.intact_samples);
  CHECK(restored_crack.result().samples.back().main_force_N != whole.result().samples.back().main_force_N);

  // A KERFCUTA state is a KERFCUTB one without the zone's record at its end (its parameters, stored by key, are
  // read as their defaults when absent: the zone off).
  CutParams off = p;
  off.edge_zone.enabled = false;
  CutRun whole_off(block, off), half_off(block, off);
  while (whole_off.advance()) {
  }
  for (std::size_t k = 0; k < whole_off.result().samples.size() / 2; ++k) half_off.advance();
  std::string old = half_off.serialize();
  old.resize(old.size() - sizeof(CutEdgeZoneRecord));
  old.replace(0, 8, "KERFCUTA");
  CutRun older = CutRun::deserialize(old);
  while (older.advance()) {
  }
  CHECK(older.result().samples.back().main_force_N == whole_off.result().samples.back().main_force_N);
  CHECK(older.result().edge_zone.samples == 0);
}

TEST_CASE("edge zone: a groove's layer below the disks' scale turns the force off where the cut line lies in it",
          "[edge_zone]") {
  // Grooves every 60 um, 20 um wide and as deep as the cut (their bottoms on the cut line), a 5 um laser-affected
  // layer read by the zone: along the cut line the layer spans 20 + 2 x 5 = 30 um of every 60. On the conservative
  // block the edge meets intact glass almost everywhere (the test above); with the layer, nowhere within it.
  const Simulation block = hex_workpiece(conservative_material(), 0.6e-3, 0.25e-3);
  CutParams p = zone_cut();
  p.cut.length_m = 0.12e-3;  // two pitches
  p.grooves.shape = GrooveShape::rectangular;
  p.grooves.pitch_m = 60e-6;
  p.grooves.width_m = 20e-6;
  p.grooves.depth_m = p.cut.depth_of_cut_m;
  CutParams layer = p;
  layer.grooves.damage_depth_m = 5e-6;
  layer.grooves.damage_model = GrooveDamageModel::edge_zone;
  struct Counts {
    int in_layer = 0, outside = 0, loaded_in_layer = 0, loaded_outside = 0;
  };
  const auto cut = [&](const CutParams& q) {
    CutRun run(block, q);
    const auto& box = run.result().workpiece_box_m;
    const auto centres = groove_centres(layer, box[0], box[1]);
    Counts c;
    for (bool more = true; more;) {
      // Where the zone looks at the sample's start (on these blocks the walls are the tool's alone).
      const auto tip = tool_edge(run.simulation(), 0, static_cast<std::int32_t>(run.simulation().walls().size()));
      more = run.advance();
      const bool loaded = !run.simulation().disk_loads().empty();
      if (in_groove_layer(layer, centres, run.result().y_top_m, tip[0], run.result().y_cut_m))
        ++c.in_layer, c.loaded_in_layer += loaded;
      else
        ++c.outside, c.loaded_outside += loaded;
    }
    return std::pair{c, run.result()};
  };
  const auto [none, none_result] = cut(p);
  const auto [with, with_result] = cut(layer);
  INFO("no layer: " << none.loaded_in_layer << " of " << none.in_layer << " samples loaded in the layer's span, "
                    << none.loaded_outside << " of " << none.outside << " outside; with it: " << with.loaded_in_layer
                    << " of " << with.in_layer << ", " << with.loaded_outside << " of " << with.outside);
  REQUIRE(with.in_layer == none.in_layer);  // the tool's path is the cut's, whatever the zone does
  // Half the travel in the layer's span (30 of every 60 um), to a sample's travel at each of the four crossings.
  const double per_sample_m = p.cut.speed_m_per_s * with_result.time_step_s * p.cut.sample_every_steps;
  CHECK_THAT(with.in_layer * per_sample_m, WithinAbs(0.5 * p.cut.length_m, 4 * per_sample_m));
  CHECK(none.loaded_in_layer > none.in_layer / 2);  // without the layer the zone acts there
  CHECK(with.loaded_in_layer == 0);
  // Outside the layer's span as without a layer (there the grooves' 40 um ridges, two disks wide, often leave the edge
  // no tied disk across the cut line: measured 327 of 794 samples loaded).
  CHECK(with.loaded_outside > 0);
  CHECK(std::abs(with.loaded_outside - none.loaded_outside) <= with.outside / 20);
  CHECK(with_result.groove_damage_joints == std::array<std::size_t, 2>{0, 0});  // the joints kept
}

TEST_CASE("edge zone: the lateral crack runs its length ahead of the edge as the tool advances", "[edge_zone]") {
  // The conservative block's joints do not break under this cut (the test above: no crack): every break is the
  // lateral crack's, and at each sample's end the cut line's joints are broken from the tip to L ahead (less the
  // sample's travel since they were broken), none beyond L by more than the disks moved since.
  const Simulation block = hex_workpiece(conservative_material(), 0.6e-3, 0.25e-3);
  CutParams p = zone_cut();
  p.edge_zone.lateral_crack = LateralCrack::ahead_of_edge;
  p.edge_zone.lateral_crack_length_m = 40e-6;
  const double length = p.edge_zone.lateral_crack_length_m;
  CutRun run(block, p);
  const double y_cut = run.result().y_cut_m;
  int samples = 0, broken_ahead = 0, intact_ahead = 0;
  double beyond_m = -1;                  // how far beyond L a broken joint crosses (negative: none beyond)
  std::size_t cracks = 0, off_line = 0;  // the window's crack events after each sample (a rebuild hands them on)
  double travel = 0;
  for (bool more = true; more;) {
    more = run.advance();
    const Simulation& sim = run.simulation();
    const double per_sample = p.cut.speed_m_per_s * run.result().time_step_s * p.cut.sample_every_steps;
    const auto tip = tool_edge(sim, 0, static_cast<std::int32_t>(sim.walls().size()));
    const auto& q = sim.particles();
    const auto& b = sim.bonds();
    for (std::size_t k = 0; k < b.size(); ++k) {
      const auto i = static_cast<std::size_t>(b.i[k]), j = static_cast<std::size_t>(b.j[k]);
      if ((q.y[i] - y_cut) * (q.y[j] - y_cut) >= 0) continue;
      const double x = q.x[i] + (y_cut - q.y[i]) * (q.x[j] - q.x[i]) / (q.y[j] - q.y[i]);
      const bool intact = b.active[k] && b.n_bonded_elements(k) > 0;
      if (x >= tip[0] - length + 1.01 * per_sample && x <= tip[0]) (intact ? intact_ahead : broken_ahead) += 1;
      if (!intact) beyond_m = std::max(beyond_m, tip[0] - length - x);
    }
    for (const auto& c : sim.cracks()) ++cracks, off_line += std::abs(c.y_m - y_cut) > kRadiusM;
    ++samples;
    travel = run.result().samples.empty() ? 0 : run.result().samples.back().travel_m;
  }
  INFO(samples << " samples, " << travel * 1e3 << " mm; cut line's joints within L: " << broken_ahead << " broken, "
               << intact_ahead << " intact; a broken joint at most " << beyond_m * 1e6 << " um beyond L");
  REQUIRE(samples > 10);
  CHECK(broken_ahead > 0);
  CHECK(intact_ahead == 0);
  // Beyond L by no more than the disks moved since their joints broke (the block deforms under the tool).
  CHECK(beyond_m < 0.05 * kRadiusM);
  CHECK(cracks > 0);
  CHECK(off_line == 0);  // every crack on the cut line: the lateral crack's, no other
}

TEST_CASE("edge zone: its keys are validated with their dotted names", "[edge_zone]") {
  CutParams p = zone_cut();
  p.window.enabled = false;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("edge_zone.enabled"));
  p = zone_cut();
  p.edge_zone.thrust_force_N_per_m = -1;  // the cutting force alone
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("edge_zone.thrust_force_N_per_mm"));
  p = zone_cut();
  p.edge_zone.friction_coefficient = -0.1;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("edge_zone.friction_coefficient = -0.1"));
  p = zone_cut();
  p.edge_zone.cutting_force_N_per_m = p.edge_zone.thrust_force_N_per_m =
      -1;  // neither given nor computed by a cut kind
  CHECK_NOTHROW(validate_cut_params(p));
  CHECK_THROWS_WITH(CutRun(hex_workpiece(Material{}, 0.6e-3, 0.25e-3), p),
                    Catch::Contains("edge_zone.cutting_force_N_per_mm"));
  p = zone_cut();
  p.grooves.shape = GrooveShape::rectangular;
  p.grooves.damage_model = GrooveDamageModel::edge_zone;  // without a layer to read
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("grooves.damage_model = edge_zone"));
  p.grooves.damage_depth_m = 5e-6;
  CHECK_NOTHROW(validate_cut_params(p));
  p.edge_zone.enabled = false;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("grooves.damage_model"));
  // The lateral crack runs under the zone's edge: with the zone only; in the scene's JSON only when chosen, so that
  // the zones recorded before the choice keep their summaries.
  p = zone_cut();
  CHECK_FALSE(cut_params_to_json(p)["edge_zone"].contains("lateral_crack"));
  p.edge_zone.lateral_crack = LateralCrack::whole_cut_line;
  CHECK_NOTHROW(validate_cut_params(p));
  CHECK(cut_params_to_json(p)["edge_zone"]["lateral_crack"] == "whole_cut_line");
  p.edge_zone.enabled = false;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("edge_zone.lateral_crack = whole_cut_line"));
  p = zone_cut();
  p.edge_zone.lateral_crack = LateralCrack::ahead_of_edge;  // without a length
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("edge_zone.lateral_crack_length_um = 0"));
  p.edge_zone.lateral_crack_length_m = 50e-6;
  CHECK_NOTHROW(validate_cut_params(p));
  CHECK_THAT(cut_params_to_json(p)["edge_zone"]["lateral_crack_length_um"].get<double>(), WithinAbs(50, 1e-9));
  p.edge_zone.lateral_crack = LateralCrack::whole_cut_line;
  CHECK_FALSE(cut_params_to_json(p)["edge_zone"].contains("lateral_crack_length_um"));
}
