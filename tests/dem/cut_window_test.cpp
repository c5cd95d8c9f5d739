// The active window of a steady-state cut (kerf/dem/procedures/cut_window.hpp, issue 20): a window covering the whole
// workpiece is the full cut to the bit; bookkeeping of disks crossing its edge, chips and held disks; the
// window's size independent of the workpiece's length; restart equals uninterrupted (with and without an
// absorbing layer, and with one along the held rows).
#include "kerf/dem/procedures/cut_window.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <utility>

#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/dem/procedures/specimen.hpp"
#include "quick_specimen.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinRel;

namespace {

using kerf::dem::testing::quick_workpiece_specimen;
using kerf::dem::testing::windowed;

}  // namespace

TEST_CASE("cut window: a window covering the whole workpiece is the full cut to the bit", "[cut_window]") {
  const Simulation specimen = quick_workpiece_specimen(0.4e-3, 0.25e-3, 3);
  CutParams full = windowed(100, 100, 100, 100);
  full.window.enabled = false;
  CutRun a(specimen, full), b(specimen, windowed(100, 100, 100, 100));
  std::size_t k = 0;
  bool more = true;
  while (more) {
    more = a.advance();
    REQUIRE(b.advance() == more);
    ++k;
    const auto& pa = a.simulation().particles();
    const auto& pb = b.simulation().particles();
    REQUIRE(pa.size() == pb.size());
    INFO("sample " << k);
    REQUIRE(pa.x == pb.x);
    REQUIRE(pa.vx == pb.vx);
    // Forces on the free disks (a held disk's leave out the joints and contacts between two held disks).
    for (std::size_t u = 0; u < pa.size(); ++u)
      if (pa.group[u] == 0) REQUIRE(pa.fx[u] == pb.fx[u]);
    REQUIRE(a.result().samples.back().main_force_N == b.result().samples.back().main_force_N);
  }
  CHECK(b.result().window.rebuilds > 5);
  CHECK(b.result().window.chips.particles == 0);
  CHECK(a.result().cracks.tensile == b.result().cracks.tensile);
  CHECK(a.result().cracks.subsurface == b.result().cracks.subsurface);
  CHECK(a.result().main_force_N == b.result().main_force_N);
}

TEST_CASE("cut window: the window's size does not grow with the workpiece: chips, frozen and untouched disks",
          "[cut_window]") {
  // The same cut (depth, travel) on workpieces 0.6 and 1.2 mm long: twice the disks, the same window.
  CutParams p = windowed(3, 1, 2, 2);
  p.cut.length_m = 0.2e-3;
  const auto cut = [&](double width_m) {
    CutRun run(quick_workpiece_specimen(width_m, 0.25e-3, 5), p);
    while (run.advance()) {
    }
    return run;
  };
  const CutRun small = cut(0.6e-3), large = cut(1.2e-3);
  const CutResult &a = small.result(), &b = large.result();
  INFO("disks " << a.n_particles << " / " << b.n_particles << ", largest windows " << a.window.largest_window_particles
                << " / " << b.window.largest_window_particles);
  const auto count = [](std::size_t n) { return static_cast<double>(n); };
  REQUIRE(count(b.n_particles) > 1.8 * count(a.n_particles));
  CHECK(count(b.window.largest_window_particles) < 1.2 * count(a.window.largest_window_particles));
  CHECK(count(a.window.largest_window_particles) < 0.7 * count(a.n_particles));
  const double steps_a = static_cast<double>(a.samples.size() - 1), steps_b = static_cast<double>(b.samples.size() - 1);
  CHECK(b.particle_steps / steps_b < 1.2 * a.particle_steps / steps_a);  // particle-steps per sample
  CHECK(b.window.rebuilds >= 15);                                        // 0.2 mm of travel in shifts of 0.01 mm

  // The finished workpiece: disks far ahead of the window never moved; every disk at rest but the window's
  // own; the chip's disks are counted with their mass, and cracks of their joints among the cut's cracks.
  REQUIRE(large.window() != nullptr);
  const auto& q = large.window()->workpiece().particles();  // every disk, in the specimen's order
  CHECK(large.workpiece().particles().size() == q.size() - b.window.chips.particles);  // the picture's
  const Simulation specimen = quick_workpiece_specimen(1.2e-3, 0.25e-3, 5);
  const double x_edge_end = b.steady_machined_x_m[0];
  std::size_t untouched = 0, ahead = 0;
  for (std::size_t u = 0; u < q.size(); ++u) {
    // (A chip flung ahead stays where it was removed, above the uncut surface.)
    if (q.x[u] < x_edge_end - 3 * p.cut.depth_of_cut_m - 4 * 13e-6 - 1e-6 && q.y[u] < b.y_top_m) {
      ++ahead;
      untouched += q.x[u] == specimen.particles().x[u] && q.y[u] == specimen.particles().y[u];
    }
  }
  CHECK(ahead > 100);
  CHECK(untouched == ahead);
  // Disks the window left behind: frozen where they were (at rest, many of them moved by the cut).
  std::size_t behind = 0, at_rest = 0, moved = 0;
  for (std::size_t u = 0; u < q.size(); ++u) {
    if (q.x[u] > x_edge_end + (1 + p.window.shift_depths) * p.cut.depth_of_cut_m + 4 * 13e-6 + 1e-6 &&
        q.y[u] < b.y_top_m) {
      ++behind;
      at_rest += q.vx[u] == 0 && q.vy[u] == 0 && q.omega[u] == 0;
      moved += q.x[u] != specimen.particles().x[u];
    }
  }
  CHECK(behind > 15);
  CHECK(at_rest == behind);
  CHECK(moved > behind / 4);
  const ChipAccount& chips = b.window.chips;
  CHECK(chips.particles > 0);
  const double m_min = Material{}.density_kg_per_m3 * 3.14159265358979 * 10e-6 * 10e-6 * 1e-3;
  CHECK(chips.mass_kg >= 0.999 * m_min * static_cast<double>(chips.particles));
  CHECK(chips.mass_kg <= 1.001 * m_min * 1.69 * static_cast<double>(chips.particles));
  CHECK(chips.cracks <= b.cracks.tensile + b.cracks.shear);
  CHECK(static_cast<std::size_t>(b.cracks.tensile + b.cracks.shear) == large.cracks().size());
}

TEST_CASE("cut window: restored halfway, a windowed cut goes on to the bit", "[cut_window]") {
  const Simulation specimen = quick_workpiece_specimen(0.6e-3, 0.25e-3, 7);
  // Without and with an absorbing layer, and with one along the held rows as well (the window then reaching
  // the bottom rows): the per-disk rates are part of the saved state.
  for (const auto& [layer, held_layer] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}}) {
    INFO("absorbing layer " << layer << " depths, along the held rows " << held_layer);
    CutParams p = windowed(3, 2, held_layer > 0 ? 4 : 2, 2);
    p.cut.length_m = 0.15e-3;
    p.window.absorbing_depths = layer;
    p.cut.held_absorbing_depths = held_layer;
    CutRun whole(specimen, p);
    REQUIRE(whole.simulation().absorbing_rates().empty() == (layer == 0));
    while (whole.advance()) {
    }
    CutRun half(specimen, p);
    for (std::size_t k = 0; k < whole.result().samples.size() / 2; ++k) half.advance();
    CutRun restored = CutRun::deserialize(half.serialize());
    CHECK(restored.simulation().absorbing_rates() == half.simulation().absorbing_rates());
    while (restored.advance()) {
    }
    const CutResult &a = whole.result(), &b = restored.result();
    REQUIRE(a.samples.size() == b.samples.size());
    for (std::size_t k = 0; k < a.samples.size(); ++k) {
      REQUIRE(a.samples[k].main_force_N == b.samples[k].main_force_N);
      REQUIRE(a.samples[k].thrust_force_N == b.samples[k].thrust_force_N);
    }
    CHECK(a.window.rebuilds == b.window.rebuilds);
    CHECK(a.window.chips.particles == b.window.chips.particles);
    CHECK(a.window.chips.cracks == b.window.chips.cracks);
    REQUIRE(whole.cracks().size() == restored.cracks().size());
    for (std::size_t k = 0; k < whole.cracks().size(); ++k) CHECK(whole.cracks()[k].bond == restored.cracks()[k].bond);
    CHECK(whole.window()->workpiece().particles().x == restored.window()->workpiece().particles().x);
    CHECK(a.particle_steps == b.particle_steps);
    // The energy books go on as well.
    REQUIRE(a.energy_booked);
    REQUIRE(b.energy_booked);
    CHECK(a.energy.tool_work_J == b.energy.tool_work_J);
    CHECK(a.energy.dissipated_J == b.energy.dissipated_J);
    CHECK(a.energy.left_kinetic_J == b.energy.left_kinetic_J);
    CHECK(a.energy.left_strain_J == b.energy.left_strain_J);
  }
}

TEST_CASE("cut window: loose fragments above the cut line are removed at a rebuild, those below stay", "[cut_window]") {
  // The bound of active_window.remove_loose_fragments: two clusters of disks cut loose from the workpiece (every
  // joint between them and the rest broken), one above the cut line, one below it. With the option the window's
  // build removes the first as a chip, every disk of it, and nothing else; without it nothing is removed.
  const Simulation specimen = quick_workpiece_specimen(0.6e-3, 0.25e-3, 7);
  CutParams p = windowed(3, 2, 2, 2);
  std::size_t n_grooves = 0;
  const Simulation workpiece = make_workpiece(specimen, p, n_grooves);
  const auto& q = workpiece.particles();
  double y_top = -1;
  for (std::size_t u = 0; u < q.size(); ++u) y_top = std::max(y_top, q.y[u] + q.radius[u]);
  const double y_cut = y_top - p.cut.depth_of_cut_m;
  const auto cluster = [&](std::size_t u, double y_centre) {
    return std::hypot(q.x[u] - 0.3e-3, q.y[u] - y_centre) < 25e-6 ? 1 : 0;
  };
  std::vector<int> in(q.size());
  std::size_t above = 0;
  for (std::size_t u = 0; u < q.size(); ++u) {
    in[u] = cluster(u, y_top - 20e-6) + 2 * cluster(u, y_cut - 60e-6);
    above += in[u] == 1;
  }
  REQUIRE(above > 3);
  const auto run = [&](bool remove) {
    Simulation w = workpiece;
    auto& b = w.bonds();
    for (std::size_t k = 0; k < b.size(); ++k)
      if (in[static_cast<std::size_t>(b.i[k])] != in[static_cast<std::size_t>(b.j[k])])
        for (int e = 0; e < b.stride; ++e)
          b.bonded[k * static_cast<std::size_t>(b.stride) + static_cast<std::size_t>(e)] = 0;
    w.initialise();
    CutWindow window(std::move(w), window_box_m(p), y_top, y_cut);
    window.set_remove_loose_fragments(remove);
    window.build(nullptr, 0.35e-3);
    return window.chips().particles;
  };
  CHECK(run(false) == 0);
  CHECK(run(true) == above);
}

TEST_CASE("cut window: a cut resumed from a checkpoint without energy books (KERFCUT8) goes on without them",
          "[cut_window]") {
  const Simulation specimen = quick_workpiece_specimen(0.6e-3, 0.25e-3, 7);
  CutParams p = windowed(3, 2, 2, 2);
  p.cut.length_m = 0.1e-3;
  CutRun whole(specimen, p), half(specimen, p);
  while (whole.advance()) {
  }
  for (std::size_t k = 0; k < whole.result().samples.size() / 2; ++k) half.advance();
  // A KERFCUT8 state is a KERFCUTB one without the books, the edge's record and the edge zone's record at its end:
  // two flags and two books of five numbers, then a flag, the last observation and the record, then the zone's.
  std::string old = half.serialize();
  old.resize(old.size() - (2 + 10 * sizeof(double)) - (1 + sizeof(std::int64_t) + sizeof(CutEdgeRecord)) -
             sizeof(CutEdgeZoneRecord));
  old.replace(0, 8, "KERFCUT8");
  CutRun restored = CutRun::deserialize(old);
  while (restored.advance()) {
  }
  CHECK(restored.result().samples.back().main_force_N == whole.result().samples.back().main_force_N);
  CHECK(whole.result().energy_booked);
  CHECK_FALSE(restored.result().energy_booked);
}

TEST_CASE("cut window: the energy books balance, and what leaves the window is what its disks carried",
          "[cut_window]") {
  // The tool's work is the mean force times the steady travel (the same samples, to their first one); the disks
  // that leave take kinetic energy away (joining ones bring none: at rest); what stays dissipates
  // (friction, broken joints) and is positive.
  const Simulation specimen = quick_workpiece_specimen(0.6e-3, 0.25e-3, 7);
  CutParams p = windowed(3, 2, 2, 2);
  p.cut.length_m = 0.3e-3;
  p.cut.entry_fraction = 0.2;
  CutRun run(specimen, p);
  while (run.advance()) {
  }
  const CutResult& r = run.result();
  REQUIRE(r.energy_booked);
  const double travel = r.steady_to_travel_m - r.steady_from_travel_m;
  const double one_sample = p.cut.speed_m_per_s * p.cut.sample_every_steps * r.time_step_s;
  CHECK_THAT(r.energy.tool_work_J, WithinRel(r.main_force_N * travel, 2 * one_sample / travel + 1e-9));
  CHECK(r.energy.left_kinetic_J > 0);
  CHECK(r.energy.dissipated_J > 0);
  const CutEnergy& e = r.energy;
  CHECK_THAT(e.dissipated_J + e.left_kinetic_J + e.left_strain_J + e.stored_change_J, WithinRel(e.tool_work_J, 1e-12));
}

namespace {
/// One crushing law (active_window.grain_strength_MPa or tied_grain_strength_MPa: `strength`) on a short windowed
/// cut: at a strength no contact reaches the cut is the cut without it, to the bit (the check alone changes nothing);
/// at `weak_Pa` disks are crushed, counted (`count`, `mass`: the law's own counters, the other law's staying 0) among
/// the removed disks, the window rebuilt for each crush, the energy books balanced (what a crushed disk held leaves
/// with it), the peak force no higher; restored halfway, the cut goes on to the bit; the key needs a window.
void check_crushing(double CutParams::ActiveWindow::*strength, double weak_Pa, std::size_t ChipAccount::*count,
                    double ChipAccount::*mass, std::size_t ChipAccount::*other_count, const std::string& key) {
  const Simulation specimen = quick_workpiece_specimen(0.6e-3, 0.25e-3, 7);
  CutParams p = windowed(3, 2, 2, 2);
  p.cut.length_m = 0.3e-3;
  p.cut.entry_fraction = 0.2;
  const auto cut = [&](double strength_Pa) {
    CutParams q = p;
    q.window.*strength = strength_Pa;
    CutRun run(specimen, q);
    while (run.advance()) {
    }
    return run.result();
  };
  const CutResult none = cut(0), never = cut(1e15), weak = cut(weak_Pa);
  CHECK(never.samples.back().main_force_N == none.samples.back().main_force_N);
  CHECK(never.main_force_N == none.main_force_N);
  CHECK(never.window.chips.*count == 0);
  CHECK(none.window.chips.*count == 0);
  CHECK(weak.window.chips.*count > 0);
  CHECK(weak.window.chips.*other_count == 0);
  CHECK(weak.window.chips.*count <= weak.window.chips.particles);
  CHECK(weak.window.chips.*mass > 0);
  CHECK(weak.window.chips.*mass <= weak.window.chips.mass_kg);
  CHECK(weak.window.rebuilds > none.window.rebuilds);  // a crush rebuilds the window
  REQUIRE(weak.energy_booked);
  const CutEnergy& e = weak.energy;
  CHECK_THAT(e.dissipated_J + e.left_kinetic_J + e.left_strain_J + e.stored_change_J, WithinRel(e.tool_work_J, 1e-12));
  const auto peak = [](const CutResult& r) {
    double m = 0;
    for (const auto& x : r.samples) m = std::max(m, x.main_force_N);
    return m;
  };
  CHECK(peak(weak) <= peak(none));
  CutParams q = p;
  q.window.*strength = weak_Pa;
  CutRun half(specimen, q);
  for (std::size_t k = 0; k < weak.samples.size() / 2; ++k) half.advance();
  CutRun restored = CutRun::deserialize(half.serialize());
  while (restored.advance()) {
  }
  CHECK(restored.result().samples.back().main_force_N == weak.samples.back().main_force_N);
  CHECK(restored.result().window.chips.*count == weak.window.chips.*count);
  p.window.enabled = false;
  p.window.*strength = 85e6;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains(key + " = 85"));
}
}  // namespace

TEST_CASE("cut window: loose grains the tool presses beyond their splitting load are crushed", "[cut_window]") {
  // At 1 MPa: a splitting load of 0.03 N for a 10 um disk, 1 mm thick.
  check_crushing(&CutParams::ActiveWindow::grain_strength_Pa, 1e6, &ChipAccount::crushed_grains,
                 &ChipAccount::crushed_mass_kg, &ChipAccount::crushed_tied_disks, "active_window.grain_strength_MPa");
}

TEST_CASE("cut window: the workpiece's own disks the tool presses beyond their splitting load are crushed",
          "[cut_window]") {
  // At 20 MPa: 0.6 N for a 10 um disk; the loose grains' law off, so none of them is crushed.
  check_crushing(&CutParams::ActiveWindow::tied_grain_strength_Pa, 20e6, &ChipAccount::crushed_tied_disks,
                 &ChipAccount::crushed_tied_mass_kg, &ChipAccount::crushed_grains,
                 "active_window.tied_grain_strength_MPa");
}

TEST_CASE("cut window: contacts between two held disks are left out when asked", "[cut_window]") {
  for (const bool skip : {false, true}) {
    SimulationOptions o;
    o.skip_held_pairs = skip;
    Simulation sim(Material{}, o);
    const int a = sim.add_particle(0, 0, 10e-6), b = sim.add_particle(19.9e-6, 0, 10e-6);  // overlapping
    const int c = sim.add_particle(-19.9e-6, 0, 10e-6);                                    // free, touching a
    sim.particles().group[static_cast<std::size_t>(a)] = 1;
    sim.particles().group[static_cast<std::size_t>(b)] = 1;
    sim.initialise();
    INFO("skip_held_pairs " << skip);
    CHECK(sim.n_touching_pairs() == (skip ? 1 : 2));             // held-held left out; held-free kept
    CHECK(sim.particles().fx[static_cast<std::size_t>(c)] < 0);  // the free disk is pushed off the held one
  }
}

TEST_CASE("cut window: the window's keys are validated with their dotted names", "[cut_window]") {
  CutParams p = windowed(3, 2, 2, 2);
  p.window.shift_depths = 3;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("active_window.shift_depths = 3"));
  p = windowed(0, 2, 2, 2);
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::Contains("active_window.ahead_depths = 0"));
  p = windowed(3, 2, 2, 2);
  p.window.enabled = false;
  p.window.ahead_depths = 0;  // not read without a window
  CHECK_NOTHROW(validate_cut_params(p));
}
