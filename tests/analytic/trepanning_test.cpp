#include "kerf/analytic/trepanning/trepanning.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "kerf/error.hpp"
#include "kerf/units.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// Yu et al. 2023, Table 4: K9 glass, D = 132 mm, d = 124 mm. Measured (mean of two tests) and the paper's theory.
struct Table4Row {
  double spindle_speed_rpm, feed_rate_um_s, axial_test_N, torque_test_Nm, axial_theory_N, torque_theory_Nm;
};
const std::vector<Table4Row> kTable4 = {
    {90.5, 10, 210.5, 4.63, 220.1, 5.32}, {90.5, 12, 295.8, 6.54, 264.1, 6.38},  {90.5, 15, 322.6, 8.32, 330.1, 7.98},
    {90.5, 18, 410.6, 8.82, 396.1, 9.57}, {90.5, 20, 420.7, 9.53, 440.1, 10.63}, {113.5, 20, 358.6, 8.72, 346.4, 8.37},
    {144, 20, 290.3, 6.32, 274.7, 6.64},  {181, 20, 232.6, 5.54, 221.3, 5.35},
};
const kerf::TrepanningTool kPaperTool{0.132, 0.124};

std::vector<kerf::TrepanningObservation> observations(bool theory) {
  std::vector<kerf::TrepanningObservation> rows;
  for (const auto& r : kTable4) {
    rows.push_back({kerf::TrepanningCut::from_user_units(r.feed_rate_um_s, r.spindle_speed_rpm),
                    theory ? r.axial_theory_N : r.axial_test_N, theory ? r.torque_theory_Nm : r.torque_test_Nm});
  }
  return rows;
}

}  // namespace

TEST_CASE("Eqs. 21-22 in SI equal the paper's unit form", "[trepanning]") {
  // The paper's form: F_n = 15 pi v_f tan(phi) (D - d) H / (2 n_0), M = 15 v_f (D^2 - d^2) H (1 + pi tan(phi) mu/2)
  // / (4 n_0) with v_f mm/s, n_0 rev/min, D, d mm, H N/mm^2 -> N and N mm.
  const kerf::TrepanningMaterial m{
      .hardness_Pa = 6.0e9, .half_angle_rad = kerf::units::deg_to_rad(60.0), .friction_coefficient = 0.1};
  const double vf = 0.015, n0 = 113.5, D = 132.0, d = 124.0, H = 6000.0, t = std::tan(m.half_angle_rad);
  const auto f = kerf::trepanning_forces(kPaperTool, kerf::TrepanningCut::from_user_units(15.0, 113.5), m);
  const double pi = std::numbers::pi;
  CHECK_THAT(f.axial_force_N, WithinRel(15.0 * pi * vf * t * (D - d) * H / (2.0 * n0), 1e-12));
  CHECK_THAT(f.torque_N_m * 1e3,
             WithinRel(15.0 * vf * (D * D - d * d) * H * (1.0 + pi * t * 0.1 / 2.0) / (4.0 * n0), 1e-12));
  CHECK_THAT(f.feed_per_rev_m, WithinRel(60.0 * vf / n0 * 1e-3, 1e-12));  // Eq. 7, mm -> m
}

TEST_CASE("The paper's theory column is one value of each lumped group", "[trepanning][table4]") {
  // Fitting K_F and K_M to Table 4's theoretical column reproduces all eight rows within 2 % (measured here:
  // K_F = 10.55 GPa, K_M = 6.26 GPa, max deviation 1.1 % on each; the paper rounded its spindle speeds).
  // For K9 with H = 7.2 GPa (data/materials/k9_glass.json, assumed) they imply tan(phi) = 1.465 (phi = 55.7 deg)
  // and mu = 2 (K_M - H) / (pi K_F) = -0.057 < 0: no non-negative friction reproduces them with H = 7.2 GPa.
  // The paper's column needs H <= K_M = 6.26 GPa; e.g. phi = 60 deg gives H = 6.09 GPa and mu = 0.010.
  const auto cal = kerf::calibrate_trepanning(kPaperTool, observations(/*theory=*/true));
  CHECK_THAT(cal.groups.axial_group_Pa, WithinRel(10.55e9, 2e-3));
  CHECK_THAT(cal.groups.torque_group_Pa, WithinRel(6.255e9, 2e-3));
  for (std::size_t i = 0; i < kTable4.size(); ++i) {
    INFO("row " << i + 1);
    CHECK_THAT(cal.axial.predicted[i], WithinRel(kTable4[i].axial_theory_N, 0.02));
    CHECK_THAT(cal.torque.predicted[i], WithinRel(kTable4[i].torque_theory_Nm, 0.02));
  }
  CHECK(cal.axial.fit.max_abs_error_percent < 2.0);
  CHECK(cal.torque.fit.max_abs_error_percent < 2.0);

  const auto k9 = kerf::implied_trepanning_material(cal.groups, 7.2e9);
  CHECK_THAT(kerf::units::rad_to_deg(k9.half_angle_rad), WithinAbs(55.7, 0.1));
  CHECK_THAT(k9.friction_coefficient, WithinAbs(-0.057, 0.002));
  CHECK_FALSE(k9.physical);
  const auto at_60 = kerf::implied_trepanning_material(cal.groups, cal.groups.axial_group_Pa / std::sqrt(3.0));
  CHECK_THAT(kerf::units::rad_to_deg(at_60.half_angle_rad), WithinAbs(60.0, 1e-9));
  CHECK_THAT(at_60.friction_coefficient, WithinAbs(0.010, 0.001));
  CHECK(at_60.physical);
  // Round trip: the implied material gives back the groups.
  const auto back =
      kerf::TrepanningGroups::from_material({at_60.hardness_Pa, at_60.half_angle_rad, at_60.friction_coefficient});
  CHECK_THAT(back.axial_group_Pa, WithinRel(cal.groups.axial_group_Pa, 1e-12));
  CHECK_THAT(back.torque_group_Pa, WithinRel(cal.groups.torque_group_Pa, 1e-12));
}

TEST_CASE("Fitted to the measured rows the model meets the paper's accuracy", "[trepanning][table4]") {
  // Acceptance: mean |error| at or below the paper's 5.0 % (axial) and 6.7 % (torque). Not tuned: these are the
  // relative least-squares values (axial 4.41 %, torque 6.50 % measured when written).
  const auto cal = kerf::calibrate_trepanning(kPaperTool, observations(/*theory=*/false));
  CHECK(cal.weighting == kerf::ResidualWeighting::relative);
  CHECK(cal.axial.fit.n == 8);
  CHECK(cal.axial.fit.mean_abs_error_percent <= 5.0);
  CHECK(cal.torque.fit.mean_abs_error_percent <= 6.7);
  CHECK_THAT(cal.groups.axial_group_Pa, WithinRel(10.74e9, 2e-3));
  CHECK_THAT(cal.groups.torque_group_Pa, WithinRel(6.03e9, 2e-3));
  // Relative weighting minimises sum e_i^2 through the origin: the bias is small but not zero.
  CHECK(std::abs(cal.axial.fit.bias_percent) < 1.0);
  CHECK(std::abs(cal.torque.fit.bias_percent) < 1.0);
  // Leave-one-out: every row predicted from the other seven. Out-of-sample errors exceed in-sample ones.
  REQUIRE(cal.axial.loo_error_percent.size() == 8);
  CHECK(cal.axial.loo.mean_abs_error_percent > cal.axial.fit.mean_abs_error_percent);
  CHECK(cal.torque.loo.mean_abs_error_percent > cal.torque.fit.mean_abs_error_percent);
  CHECK_THAT(cal.axial.loo.mean_abs_error_percent, WithinAbs(5.04, 0.01));
  CHECK_THAT(cal.torque.loo.mean_abs_error_percent, WithinAbs(7.44, 0.01));
  CHECK(cal.axial.standard_error_Pa > 0.0);
  CHECK(cal.axial.standard_error_Pa < 0.05 * cal.axial.value_Pa);
}

TEST_CASE("The relative fit minimises the squared relative residuals, the absolute fit the absolute ones",
          "[trepanning]") {
  const auto rows = observations(false);
  for (auto weighting : {kerf::ResidualWeighting::relative, kerf::ResidualWeighting::absolute}) {
    const auto cal = kerf::calibrate_trepanning(kPaperTool, rows, weighting);
    const auto objective = [&](double k) {
      double sum = 0.0;
      for (const auto& r : rows) {
        const double model = kerf::trepanning_forces(kPaperTool, r.cut, kerf::TrepanningGroups{k, 1e9}).axial_force_N;
        const double residual = weighting == kerf::ResidualWeighting::relative
                                    ? (model - r.axial_force_N) / r.axial_force_N
                                    : model - r.axial_force_N;
        sum += residual * residual;
      }
      return sum;
    };
    const double k = cal.groups.axial_group_Pa;
    CHECK(objective(k) < objective(k * 1.001));
    CHECK(objective(k) < objective(k * 0.999));
  }
}

TEST_CASE("Exact data is recovered exactly, and leave-one-out errors vanish", "[trepanning]") {
  const kerf::TrepanningGroups truth{9e9, 7e9};
  std::vector<kerf::TrepanningObservation> rows;
  for (double v : {5.0, 10.0, 30.0}) {
    const auto cut = kerf::TrepanningCut::from_user_units(v, 100.0 + v);
    const auto f = kerf::trepanning_forces(kPaperTool, cut, truth);
    rows.push_back({cut, f.axial_force_N, f.torque_N_m});
  }
  const auto cal = kerf::calibrate_trepanning(kPaperTool, rows, kerf::ResidualWeighting::absolute);
  CHECK_THAT(cal.groups.axial_group_Pa, WithinRel(9e9, 1e-12));
  CHECK_THAT(cal.groups.torque_group_Pa, WithinRel(7e9, 1e-12));
  CHECK(cal.axial.loo.max_abs_error_percent < 1e-9);
  CHECK(cal.torque.loo.max_abs_error_percent < 1e-9);
}

TEST_CASE("Force is linear in v_f / n_0 and torque scales with D^2 - d^2", "[trepanning][physics]") {
  const kerf::TrepanningGroups k{10e9, 6e9};
  const auto base = kerf::trepanning_forces(kPaperTool, kerf::TrepanningCut::from_user_units(10.0, 100.0), k);
  // Same v_f / n_0, different speeds: same forces (only the feed per revolution matters).
  const auto same_ratio = kerf::trepanning_forces(kPaperTool, kerf::TrepanningCut::from_user_units(30.0, 300.0), k);
  CHECK_THAT(same_ratio.axial_force_N, WithinRel(base.axial_force_N, 1e-12));
  CHECK_THAT(same_ratio.torque_N_m, WithinRel(base.torque_N_m, 1e-12));
  // Doubling the feed doubles both; doubling the speed halves both.
  const auto fast_feed = kerf::trepanning_forces(kPaperTool, kerf::TrepanningCut::from_user_units(20.0, 100.0), k);
  CHECK_THAT(fast_feed.axial_force_N, WithinRel(2.0 * base.axial_force_N, 1e-12));
  CHECK_THAT(fast_feed.torque_N_m, WithinRel(2.0 * base.torque_N_m, 1e-12));
  const auto fast_spin = kerf::trepanning_forces(kPaperTool, kerf::TrepanningCut::from_user_units(10.0, 200.0), k);
  CHECK_THAT(fast_spin.axial_force_N, WithinRel(0.5 * base.axial_force_N, 1e-12));
  // Axial force scales with the wall (D - d), torque with D^2 - d^2 = (D - d)(D + d).
  const kerf::TrepanningTool wide{0.132, 0.116};  // wall 8 mm -> 16 mm
  const auto w = kerf::trepanning_forces(wide, kerf::TrepanningCut::from_user_units(10.0, 100.0), k);
  CHECK_THAT(w.axial_force_N, WithinRel(2.0 * base.axial_force_N, 1e-12));
  CHECK_THAT(w.torque_N_m,
             WithinRel(base.torque_N_m * (0.132 * 0.132 - 0.116 * 0.116) / (0.132 * 0.132 - 0.124 * 0.124), 1e-12));
  // M / F_n = (K_M / K_F) 2 r / pi with r = (D + d) / 4: the grits' tangential force acts at the mean radius.
  CHECK_THAT(base.torque_N_m / base.axial_force_N,
             WithinRel(6.0 / 10.0 * 2.0 * kPaperTool.mean_radius_m() / std::numbers::pi, 1e-12));
  // A solid core drill (d = 0) is allowed; a vanishing wall gives vanishing force.
  CHECK(kerf::trepanning_forces({0.01, 0.0}, kerf::TrepanningCut::from_user_units(10.0, 100.0), k).axial_force_N > 0.0);
  const auto thin =
      kerf::trepanning_forces({0.132, 0.132 - 1e-9}, kerf::TrepanningCut::from_user_units(10.0, 100.0), k);
  CHECK(thin.axial_force_N < 1e-6 * base.axial_force_N);
}

TEST_CASE("Friction raises only the torque, hardness raises both", "[trepanning][physics]") {
  const auto cut = kerf::TrepanningCut::from_user_units(15.0, 90.5);
  const kerf::TrepanningMaterial dry{7e9, 1.0, 0.0}, wet{7e9, 1.0, 0.3}, hard{14e9, 1.0, 0.0};
  const auto a = kerf::trepanning_forces(kPaperTool, cut, dry);
  const auto b = kerf::trepanning_forces(kPaperTool, cut, wet);
  const auto c = kerf::trepanning_forces(kPaperTool, cut, hard);
  CHECK_THAT(b.axial_force_N, WithinRel(a.axial_force_N, 1e-15));
  CHECK_THAT(b.torque_N_m, WithinRel(a.torque_N_m * (1.0 + std::numbers::pi * std::tan(1.0) * 0.3 / 2.0), 1e-12));
  CHECK_THAT(c.axial_force_N, WithinRel(2.0 * a.axial_force_N, 1e-12));
  CHECK_THAT(c.torque_N_m, WithinRel(2.0 * a.torque_N_m, 1e-12));
  // Frictionless: K_M = H; the torque then depends on H alone, not on the half angle.
  const auto sharp = kerf::trepanning_forces(kPaperTool, cut, kerf::TrepanningMaterial{7e9, 0.3, 0.0});
  CHECK_THAT(sharp.torque_N_m, WithinRel(a.torque_N_m, 1e-12));
}

TEST_CASE("Per-grit diagnostics (Eqs. 1-20) sum to the cutter's force and torque", "[trepanning][grits]") {
  const kerf::TrepanningGroups k{10.5e9, 6.26e9};
  const auto cut = kerf::TrepanningCut::from_user_units(20.0, 90.5);
  const kerf::TrepanningGritParams grits{.grit_density_per_m2 = 20e6, .shape_coefficient = 0.8, .grit_width_m = 50e-6};
  const auto g = kerf::trepanning_grit_diagnostics(kPaperTool, cut, k, grits);
  const auto f = kerf::trepanning_forces(kPaperTool, cut, k);
  const double pi = std::numbers::pi, D = 0.132, d = 0.124;
  CHECK_THAT(g.face_area_m2, WithinRel(pi / 4 * (D * D - d * d) * 0.8, 1e-14));
  CHECK_THAT(g.cutting_edges, WithinRel(pi / 2 * 50e-6 * (D + d) * 20e6 * 0.8, 1e-12));  // Eq. 5
  CHECK_THAT(g.feed_per_edge_m,
             WithinRel(120 * 20e-3 / (pi * 90.5 * 50e-3 * (132 + 124) * 20 * 0.8) * 1e-3, 1e-12));  // Eq. 8 (mm)
  CHECK_THAT(g.grit_count * g.grit_normal_force_N, WithinRel(f.axial_force_N, 1e-12));              // Eq. 21
  CHECK_THAT(g.grit_count * g.grit_tangential_force_N * kPaperTool.mean_radius_m(),
             WithinRel(f.torque_N_m, 1e-12));  // Eq. 22
  // Eq. 15 in the paper's units: F_an = 30 v_f tan(phi) H / (n_0 (D + d) C G), mm and N/mm^2.
  CHECK_THAT(g.grit_normal_force_N, WithinRel(30 * 20e-3 * 10.5e3 / (90.5 * (132 + 124) * 20 * 0.8), 1e-12));
  // Eq. 13 with Eq. 14: a = 2 g tan(phi).
  CHECK_THAT(2.0 * g.grit_depth_m * std::tan(g.implied_half_angle_rad), WithinRel(50e-6, 1e-12));
  // Doubling C halves the per-grit depth and forces, leaving the totals alone.
  auto dense = grits;
  dense.grit_density_per_m2 *= 2.0;
  const auto g2 = kerf::trepanning_grit_diagnostics(kPaperTool, cut, k, dense);
  CHECK_THAT(g2.grit_depth_m, WithinRel(0.5 * g.grit_depth_m, 1e-12));
  CHECK_THAT(g2.grit_count * g2.grit_normal_force_N, WithinRel(f.axial_force_N, 1e-12));
}

TEST_CASE("Invalid trepanning input names the field", "[trepanning][errors]") {
  const kerf::TrepanningGroups k{10e9, 6e9};
  const auto cut = kerf::TrepanningCut::from_user_units(10.0, 100.0);
  const auto field_of = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const kerf::InputError& e) {
      return e.field();
    }
    return "(no error)";
  };
  CHECK(field_of([&] { kerf::trepanning_forces({0.124, 0.132}, cut, k); }) == "tool.inner_diameter_mm");
  CHECK(field_of([&] { kerf::trepanning_forces({0.132, 0.132}, cut, k); }) == "tool.inner_diameter_mm");
  CHECK(field_of([&] { kerf::trepanning_forces({0.0, 0.0}, cut, k); }) == "tool.outer_diameter_mm");
  CHECK(field_of([&] { kerf::trepanning_forces(kPaperTool, kerf::TrepanningCut::from_user_units(10.0, 0.0), k); }) ==
        "cut.spindle_speed_rpm");
  CHECK(field_of([&] { kerf::trepanning_forces(kPaperTool, kerf::TrepanningCut::from_user_units(-1.0, 90.0), k); }) ==
        "cut.feed_rate_um_per_s");
  CHECK(field_of([&] { kerf::trepanning_forces(kPaperTool, kerf::TrepanningCut::from_user_units(NAN, 90.0), k); }) ==
        "cut.feed_rate_um_per_s");
  CHECK(field_of([&] {
          kerf::trepanning_forces(kPaperTool, cut, kerf::TrepanningGroups{0.0, 6e9});
        }) == "groups.axial_group_MPa");
  CHECK(field_of([&] {
          kerf::trepanning_forces(kPaperTool, cut, kerf::TrepanningMaterial{7e9, 1.6, 0.1});
        }) == "material.half_angle_deg");
  CHECK(field_of([&] {
          kerf::trepanning_forces(kPaperTool, cut, kerf::TrepanningMaterial{7e9, 1.0, -0.1});
        }) == "material.friction_coefficient");
  CHECK(field_of([&] {
          kerf::trepanning_grit_diagnostics(kPaperTool, cut, k, {20e6, 1.5, 50e-6});
        }) == "grits.shape_coefficient");
  std::vector<kerf::TrepanningObservation> one{{cut, 100.0, 1.0}};
  CHECK(field_of([&] { kerf::calibrate_trepanning(kPaperTool, one); }) == "observations");
  std::vector<kerf::TrepanningObservation> bad{{cut, 100.0, 1.0}, {cut, 0.0, 1.0}};
  CHECK(field_of([&] { kerf::calibrate_trepanning(kPaperTool, bad); }) == "observations[1].axial_force_N");
  CHECK_THROWS_WITH(
      kerf::trepanning_forces({0.124, 0.132}, cut, k),
      "tool.inner_diameter_mm = 132: expected a value in [0, 124) mm (at least 0 and below the outer diameter)");
}

TEST_CASE("Plausibility: a feed per revolution beyond the cutter's wall is refused", "[trepanning][issue22]") {
  // Issue 22: a feed of 1e9 um/s gave 2.2e10 N. The physics names the cut's own key; the scene adds `cut.`.
  CHECK_THROWS_WITH(kerf::check_feed_plausible(kPaperTool, kerf::TrepanningCut::from_user_units(1e9, 90.5)),
                    Catch::Matchers::StartsWith("feed_rate_um_per_s = 1e+09: expected a feed per revolution below "
                                                "the cutter's wall width (D - d)/2 = 4000 um"));
  CHECK_NOTHROW(kerf::check_feed_plausible(kPaperTool, kerf::TrepanningCut::from_user_units(20.0, 90.5)));
}
