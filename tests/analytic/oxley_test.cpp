#include "kerf/analytic/forces/oxley.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "aisi_1045.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using kerf::Guard;
using kerf::units::deg_to_rad;
using kerf::units::rad_to_deg;

namespace {

constexpr double kZeroCelsius = 273.15;

// AISI 1045 as in Lalwani et al. (2009) and Pantalé et al. (2022): Johnson-Cook of Jaspers & Dautzenberg
// (2002); K and c_p linear in the Celsius temperature; eta = psi = 0.9. T_room = 298.15 K = the workpiece
// temperature: the value with which Pantalé's program produced the plots used below (his later script in the
// same repository uses T_room = 273.15 K in the Johnson-Cook law, which gives phi = 18.77 deg and F_c = 571 N).
kerf::OxleyParams aisi_1045() {
  kerf::OxleyParams p;
  p.johnson_cook = kerf::testing::aisi_1045_johnson_cook();
  p.thermal = {.density_kg_per_m3 = 8000.0,
               .conductivity_W_per_m_K = {52.61, -0.0281, kZeroCelsius},
               .specific_heat_J_per_kg_K = {420.0, 0.504, kZeroCelsius}};
  p.eta = 0.9;
  p.psi = 0.9;
  return p;
}

// The reference cut of Lalwani (2009) and Pantalé (2022): V = 200 m/min, t1 = 0.15 mm, w = 1.6 mm, rake -7 deg.
kerf::OxleyCut reference_cut() {
  return {.rake_rad = deg_to_rad(-7.0),
          .uncut_chip_thickness_m = 0.15e-3,
          .width_m = 1.6e-3,
          .speed_m_per_s = 200.0 / 60.0,
          .workpiece_temperature_K = 298.15};
}

// A value read off a matplotlib SVG: linear map from two axis ticks (pixel position, value).
double from_plot(double pixel, double pixel_a, double value_a, double pixel_b, double value_b) {
  return value_a + (pixel - pixel_a) * (value_b - value_a) / (pixel_b - pixel_a);
}

std::vector<double> all_numbers(const kerf::OxleyResult& r) {
  return {r.shear_angle_rad,
          r.strain_rate_constant_C0,
          r.delta,
          r.cutting_force_N,
          r.thrust_force_N,
          r.chip_thickness_m,
          r.contact_length_m,
          r.shear_force_N,
          r.resultant_force_N,
          r.friction_force_N,
          r.normal_force_N,
          r.theta_rad,
          r.friction_angle_rad,
          r.shear_plane_strain,
          r.shear_plane_strain_rate_per_s,
          r.shear_plane_temperature_K,
          r.shear_plane_flow_stress_Pa,
          r.shear_plane_shear_stress_Pa,
          r.heat_partition,
          r.strain_hardening_index,
          r.tool_tip_normal_stress_Pa,
          r.interface_strain,
          r.interface_strain_rate_per_s,
          r.interface_temperature_K,
          r.chip_temperature_K,
          r.interface_shear_stress_Pa,
          r.interface_normal_stress_Pa,
          r.chip_shear_flow_stress_Pa,
          r.residual_shear,
          r.residual_normal};
}

bool all_finite(const kerf::OxleyResult& r) {
  for (double x : all_numbers(r)) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("Oxley reproduces Pantalé's solution for AISI 1045 at 200 m/min, 0.15 mm, -7 deg", "[oxley]") {
  // Reference: the output of Pantalé's own program (github.com/pantale/OxleyPython, commit 59d947e), the
  // companion code of Pantalé, Dawoua Kaoutoing & Houé Ngouna, Appl. Mech. 3 (2022) 889, which solves this
  // case of Lalwani et al. (2009). The paper's tables could not be retrieved; the repository's plots are
  // matplotlib SVGs whose coordinates are linear maps of the computed values, so the numbers below are read from
  // them to 6-7 digits (raw pixel coordinates and axis ticks kept here for traceability):
  //   phi.svg, C0.svg, delta.svg: the annotated optimum "phi = 18.945", "C0 = 5.762", "delta = 0.036" at
  //     x = 247.205916 (axis 8 deg at 54.255319, 45 deg at 706.557319), x = 361.037393 (C0 2 .. 10 on the
  //     same pixels), x = 150.358547 (delta 0.005 at 47.42683, 0.2 at 699.72883);
  //   delta.svg: F_c at its minimum y = 146.135381, F_t y = 441.926502 (350 N at y = 444.239184, 400 N at
  //     y = 377.974506), both at the sample delta = 0.03652 next to the optimum (F_c is flat there);
  //   TAB_vs_Speed.svg, Tint_vs_Speed.svg: the t1 = 0.15 mm curve at V = 200 m/min, y = 415.634313
  //     (450 C at 255.704803, 500 C at 170.568872) and y = 291.501358 (700 C at 435.269758, 800 C at 378.816306).
  // Pantalé iterates temperatures to 1e-3 K and stops Levenberg-Marquardt at its default tolerances; measured
  // agreement is 1e-6 to 3e-5 relative, tested at 1e-4.
  const double phi_deg = from_plot(247.205916, 54.255319, 8.0, 706.557319, 45.0);
  const double c0 = from_plot(361.037393, 54.255319, 2.0, 706.557319, 10.0);
  const double delta = from_plot(150.358547, 47.42683, 0.005, 699.72883, 0.2);
  const double fc = from_plot(146.135381, 444.239184, 350.0, 377.974506, 400.0);
  const double ft = from_plot(441.926502, 444.239184, 350.0, 377.974506, 400.0);
  const double t_ab_c = from_plot(415.634313, 255.704803, 450.0, 170.568872, 500.0);
  const double t_int_c = from_plot(291.501358, 435.269758, 700.0, 378.816306, 800.0);
  // The printed labels of the plots, as a check of the read-off.
  CHECK_THAT(phi_deg, WithinAbs(18.945, 5e-4));
  CHECK_THAT(c0, WithinAbs(5.762, 5e-4));
  CHECK_THAT(delta, WithinAbs(0.036, 5e-4));

  const kerf::OxleyResult r = kerf::solve_oxley(aisi_1045(), reference_cut());
  CHECK(r.converged);
  CHECK_FALSE(r.guards.any());
  CHECK_THAT(rad_to_deg(r.shear_angle_rad), WithinRel(phi_deg, 1e-4));
  CHECK_THAT(r.strain_rate_constant_C0, WithinRel(c0, 1e-4));
  CHECK_THAT(r.delta, WithinRel(delta, 1e-3));  // delta is found to ~sqrt(tolerance) = 1e-4 by design
  CHECK_THAT(r.cutting_force_N, WithinRel(fc, 1e-4));
  CHECK_THAT(r.thrust_force_N, WithinRel(ft, 1e-4));
  CHECK_THAT(r.shear_plane_temperature_K - kZeroCelsius, WithinRel(t_ab_c, 1e-4));
  CHECK_THAT(r.interface_temperature_K - kZeroCelsius, WithinRel(t_int_c, 1e-4));
  // Orders of magnitude of the remaining outputs (Pantalé prints them; not in the plots): t2 ~ 0.42 mm,
  // h ~ 0.47 mm, eps_AB ~ 0.98, epsdot_AB ~ 2.6e4 /s, k_AB ~ 581 MPa.
  CHECK_THAT(r.chip_thickness_m, WithinRel(0.4155e-3, 1e-3));
  CHECK_THAT(r.contact_length_m, WithinRel(0.4667e-3, 1e-3));
  CHECK_THAT(r.shear_plane_strain, WithinRel(0.981, 1e-3));
}

TEST_CASE("Oxley reproduces Pantalé's speed sweep, whose script keeps m_chip of the reference cut", "[oxley]") {
  // Pantalé's sensitivity study (OxleyPython, ExtOxley_LMFIT.py, PlotVariations) changes V and t1 but computes
  // m_chip = rho V t1 w once, for the reference cut, so its temperature rises use that m_chip. The same
  // equations are obtained here by scaling rho and K by f = V0 t1_0 / (V t1): m_chip is then the reference
  // one while R_T = rho c_p V t1 / K is unchanged. This checks the equation set away from the reference cut.
  // Values: TAB_vs_Speed.svg and Tint_vs_Speed.svg (axes as in the previous test; V = 100 m/min at x = 80.002276
  // resp. 87.806263, 400 m/min at 673.004094 resp. 680.808081).
  struct Case {
    double t1_mm, v_m_per_min, tab_pixel, tint_pixel;
  };
  for (const Case& k : {Case{0.15, 400.0, 215.888517, 106.600056}, Case{0.30, 200.0, 222.060464, 108.686193},
                        Case{0.50, 100.0, 292.143653, 150.179382}}) {
    CAPTURE(k.t1_mm, k.v_m_per_min);
    kerf::OxleyCut cut = reference_cut();
    cut.uncut_chip_thickness_m = k.t1_mm * 1e-3;
    cut.speed_m_per_s = k.v_m_per_min / 60.0;
    const double f = (200.0 * 0.15) / (k.v_m_per_min * k.t1_mm);
    kerf::OxleyParams stale = aisi_1045();
    stale.thermal.density_kg_per_m3 *= f;
    stale.thermal.conductivity_W_per_m_K.value_at_reference *= f;
    stale.thermal.conductivity_W_per_m_K.slope_per_K *= f;
    const kerf::OxleyResult r = kerf::solve_oxley(stale, cut);
    CHECK(r.converged);
    CHECK_THAT(r.shear_plane_temperature_K - kZeroCelsius,
               WithinRel(from_plot(k.tab_pixel, 255.704803, 450.0, 170.568872, 500.0), 1e-4));
    CHECK_THAT(r.interface_temperature_K - kZeroCelsius,
               WithinRel(from_plot(k.tint_pixel, 435.269758, 700.0, 378.816306, 800.0), 1e-4));
  }
}

// The roots are found to `tolerance` in phi and C0; the residuals are that times their sensitivity to phi
// and C0 (up to ~20 here): 100 x tolerance is the bound tested.
constexpr double kResidualBound = 100.0 * 1e-8;

TEST_CASE("Oxley converges: both conditions hold to the tolerance", "[oxley]") {
  for (double t1 : {0.1e-3, 0.2e-3, 0.5e-3}) {
    kerf::OxleyCut cut = reference_cut();
    cut.uncut_chip_thickness_m = t1;
    const kerf::OxleyResult r = kerf::solve_oxley(aisi_1045(), cut);
    CAPTURE(t1);
    CHECK(r.converged);
    CHECK(r.residual_shear < kResidualBound);
    CHECK(r.residual_normal < kResidualBound);
    CHECK_THAT(r.interface_shear_stress_Pa, WithinRel(r.chip_shear_flow_stress_Pa, kResidualBound));
    CHECK_THAT(r.interface_normal_stress_Pa, WithinRel(r.tool_tip_normal_stress_Pa, kResidualBound));
    CHECK(r.n_function_evaluations < 200);
  }
}

TEST_CASE("Oxley forces balance: one resultant, seen from the shear plane, the rake face and the tool", "[oxley]") {
  const kerf::OxleyCut cut = reference_cut();
  const kerf::OxleyResult r = kerf::solve_oxley(aisi_1045(), cut);
  const double a = cut.rake_rad, phi = r.shear_angle_rad, theta = r.theta_rad, R = r.resultant_force_N;
  CHECK_THAT(r.friction_angle_rad, WithinAbs(theta + a - phi, 1e-15));
  CHECK_THAT(r.cutting_force_N, WithinRel(R * std::cos(theta - phi), 1e-14));
  CHECK_THAT(r.thrust_force_N, WithinRel(R * std::sin(theta - phi), 1e-14));
  CHECK_THAT(r.friction_force_N, WithinRel(R * std::sin(r.friction_angle_rad), 1e-14));
  CHECK_THAT(r.normal_force_N, WithinRel(R * std::cos(r.friction_angle_rad), 1e-14));
  CHECK_THAT(r.shear_force_N, WithinRel(R * std::cos(theta), 1e-14));
  // The same resultant in tool axes: F_c = F sin(a) + N cos(a), F_t = F cos(a) - N sin(a).
  CHECK_THAT(r.cutting_force_N, WithinRel(r.friction_force_N * std::sin(a) + r.normal_force_N * std::cos(a), 1e-13));
  CHECK_THAT(r.thrust_force_N, WithinRel(r.friction_force_N * std::cos(a) - r.normal_force_N * std::sin(a), 1e-12));
  CHECK_THAT(std::hypot(r.cutting_force_N, r.thrust_force_N), WithinRel(R, 1e-14));
  CHECK_THAT(std::hypot(r.friction_force_N, r.normal_force_N), WithinRel(R, 1e-14));
  // Shear force from the flow stress on the shear plane, stresses from forces on the contact.
  CHECK_THAT(
      r.shear_force_N,
      WithinRel(r.shear_plane_shear_stress_Pa * cut.uncut_chip_thickness_m / std::sin(phi) * cut.width_m, 1e-14));
  CHECK_THAT(r.interface_shear_stress_Pa, WithinRel(r.friction_force_N / (r.contact_length_m * cut.width_m), 1e-14));
  CHECK_THAT(r.interface_normal_stress_Pa, WithinRel(r.normal_force_N / (r.contact_length_m * cut.width_m), 1e-14));
  CHECK_THAT(r.shear_plane_flow_stress_Pa, WithinRel(std::sqrt(3.0) * r.shear_plane_shear_stress_Pa, 1e-14));
  // Continuity: t2 sin(phi) = t1 cos(phi - a); chip thicker than the cut for these shear angles.
  CHECK_THAT(r.chip_thickness_m * std::sin(phi), WithinRel(cut.uncut_chip_thickness_m * std::cos(phi - a), 1e-14));
  CHECK(r.chip_thickness_m > cut.uncut_chip_thickness_m);
  CHECK(r.contact_length_m > 0.0);
  CHECK(r.friction_angle_rad > 0.0);
  CHECK(r.interface_temperature_K > r.shear_plane_temperature_K);
  CHECK(r.shear_plane_temperature_K > cut.workpiece_temperature_K);
}

TEST_CASE("Oxley forces grow with the uncut chip thickness and linearly with the width", "[oxley]") {
  const kerf::OxleyParams steel = aisi_1045();
  kerf::OxleyCut cut = reference_cut();
  double previous_fc = 0.0, previous_ft = 0.0;
  for (double t1 : {0.05e-3, 0.1e-3, 0.15e-3, 0.2e-3, 0.3e-3, 0.5e-3}) {
    cut.uncut_chip_thickness_m = t1;
    const kerf::OxleyResult r = kerf::solve_oxley(steel, cut);
    CAPTURE(t1);
    CHECK(r.converged);
    CHECK(r.cutting_force_N > previous_fc);
    CHECK(r.thrust_force_N > previous_ft);
    previous_fc = r.cutting_force_N;
    previous_ft = r.thrust_force_N;
  }
  cut = reference_cut();
  const kerf::OxleyResult one = kerf::solve_oxley(steel, cut);
  for (double factor : {0.5, 2.0, 10.0}) {
    kerf::OxleyCut wider = cut;
    wider.width_m = factor * cut.width_m;
    const kerf::OxleyResult r = kerf::solve_oxley(steel, wider);
    CAPTURE(factor);
    CHECK_THAT(r.cutting_force_N, WithinRel(factor * one.cutting_force_N, 1e-9));
    CHECK_THAT(r.thrust_force_N, WithinRel(factor * one.thrust_force_N, 1e-9));
    CHECK_THAT(r.shear_angle_rad, WithinRel(one.shear_angle_rad, 1e-9));
    CHECK_THAT(r.interface_temperature_K, WithinRel(one.interface_temperature_K, 1e-6));
  }
}

TEST_CASE("Oxley at the extremes: a finite result or a clean error, never NaN, never a hang", "[oxley][guards]") {
  const kerf::OxleyParams steel = aisi_1045();
  const double t_melt = steel.johnson_cook.melting_temperature_K;
  int finite = 0, converged = 0;
  for (double t1 : {1e-9, 1e-6, 1e-3}) {
    for (double v : {0.01, 1.0, 20.0}) {
      for (double rake_deg : {-30.0, 0.0, 30.0}) {
        for (double t_w : {298.15, t_melt - 1.0}) {
          const kerf::OxleyCut cut{.rake_rad = deg_to_rad(rake_deg),
                                   .uncut_chip_thickness_m = t1,
                                   .width_m = 1e-3,
                                   .speed_m_per_s = v,
                                   .workpiece_temperature_K = t_w};
          CAPTURE(t1, v, rake_deg, t_w);
          try {
            const kerf::OxleyResult r = kerf::solve_oxley(steel, cut);
            CHECK(all_finite(r));
            CHECK(r.n_function_evaluations < 1000);
            CHECK(r.cutting_force_N >= 0.0);
            // Without a solution the solver says so.
            if (!r.converged) CHECK(r.guards.has(Guard::solver_at_bound));
            finite += 1;
            converged += r.converged ? 1 : 0;
          } catch (const kerf::InputError&) {
            FAIL("valid input refused");
          } catch (const kerf::ModelError&) {
            // acceptable: a clean refusal
          }
        }
      }
    }
  }
  CHECK(finite == 54);  // all of them: no refusals in this range
  CHECK(converged > 0);
}

TEST_CASE("Oxley flags the sub-micron regime: heat partition clamped, no negative temperature rise",
          "[oxley][guards]") {
  kerf::OxleyCut cut = reference_cut();
  cut.uncut_chip_thickness_m = 0.1e-6;
  cut.speed_m_per_s = 5.0;
  const kerf::OxleyResult r = kerf::solve_oxley(aisi_1045(), cut);
  CHECK(all_finite(r));
  CHECK(r.guards.has(Guard::heat_partition_clamped));
  CHECK(r.heat_partition == 1.0);  // all shear-zone heat into the work (the fit gives beta > 1)
  CHECK(r.shear_plane_temperature_K == cut.workpiece_temperature_K);
  CHECK(r.interface_temperature_K >= cut.workpiece_temperature_K);
}

TEST_CASE("Oxley without a solution in the search range says so and returns the nearest end", "[oxley][guards]") {
  // At 0.6 m/min the interface stays cool: k_chip exceeds tau_int at every shear angle, for every delta.
  kerf::OxleyCut cut = reference_cut();
  cut.speed_m_per_s = 0.01;
  cut.uncut_chip_thickness_m = 0.1e-3;
  const kerf::OxleyResult r = kerf::solve_oxley(aisi_1045(), cut);
  CHECK_FALSE(r.converged);
  CHECK(r.guards.has(Guard::solver_at_bound));
  CHECK(all_finite(r));
  CHECK(r.residual_shear > 0.1);
  CHECK_THAT(rad_to_deg(r.shear_angle_rad), WithinAbs(5.0, 1e-12));
}

TEST_CASE("Oxley near the melting point: finite, small forces", "[oxley]") {
  kerf::OxleyCut cut = reference_cut();
  const kerf::OxleyParams steel = aisi_1045();
  cut.workpiece_temperature_K = steel.johnson_cook.melting_temperature_K - 1.0;
  const kerf::OxleyResult hot = kerf::solve_oxley(steel, cut);
  const kerf::OxleyResult cold = kerf::solve_oxley(steel, reference_cut());
  CHECK(all_finite(hot));
  CHECK(hot.cutting_force_N < 0.01 * cold.cutting_force_N);
  CHECK(hot.shear_plane_temperature_K < steel.johnson_cook.melting_temperature_K);
}

TEST_CASE("Oxley delta at the end of its range raises solver_at_bound but is a solution", "[oxley][guards]") {
  kerf::OxleyCut cut = reference_cut();
  cut.uncut_chip_thickness_m = 1e-3;
  cut.speed_m_per_s = 20.0;
  const kerf::OxleyResult r = kerf::solve_oxley(aisi_1045(), cut);
  CHECK(r.converged);
  CHECK(r.delta == kerf::OxleySolverOptions{}.delta_min);
  CHECK(r.guards.has(Guard::solver_at_bound));
  CHECK(r.residual_shear < kResidualBound);
}

TEST_CASE("Oxley tolerance: tighter tolerances move F_c, F_t and phi by less than the looser one", "[oxley]") {
  kerf::OxleySolverOptions tight;
  tight.tolerance = 1e-13;
  const kerf::OxleyResult reference = kerf::solve_oxley(aisi_1045(), reference_cut(), tight);
  for (double tolerance : {1e-6, 1e-8, 1e-10}) {
    kerf::OxleySolverOptions options;
    options.tolerance = tolerance;
    const kerf::OxleyResult r = kerf::solve_oxley(aisi_1045(), reference_cut(), options);
    CAPTURE(tolerance);
    CHECK_THAT(r.cutting_force_N, WithinRel(reference.cutting_force_N, 10.0 * tolerance));
    CHECK_THAT(r.thrust_force_N, WithinRel(reference.thrust_force_N, 10.0 * tolerance));
    CHECK_THAT(r.shear_angle_rad, WithinRel(reference.shear_angle_rad, 10.0 * tolerance));
    CHECK_THAT(r.delta, WithinRel(reference.delta, 30.0 * std::sqrt(tolerance)));
  }
}

TEST_CASE("Oxley bracket searches: without them (2 points) the reference case is the same solution", "[oxley]") {
  // The searches only choose among brackets; where the root is unique they must not change the answer.
  kerf::OxleySolverOptions plain;
  plain.phi_scan_points = 2;
  plain.delta_scan_points = 2;
  kerf::OxleySolverOptions fine;
  fine.phi_scan_points = 33;
  fine.delta_scan_points = 15;
  const kerf::OxleyResult reference = kerf::solve_oxley(aisi_1045(), reference_cut());
  for (const auto& options : {plain, fine}) {
    const kerf::OxleyResult r = kerf::solve_oxley(aisi_1045(), reference_cut(), options);
    CHECK(r.converged);
    CHECK_THAT(r.cutting_force_N, WithinRel(reference.cutting_force_N, 1e-7));
    CHECK_THAT(r.shear_angle_rad, WithinRel(reference.shear_angle_rad, 1e-7));
    CHECK_THAT(r.delta, WithinRel(reference.delta, 1e-2));
  }
}

TEST_CASE("Oxley with several roots takes the minimum-force solution", "[oxley]") {
  // Cases found by comparing the solver with a brute-force search (81 deltas x 161 shear angles, every sign
  // change refined) on random cuts. The two parameter sets below are synthetic, with Ti-6Al-4V-like and
  // Inconel-718-like magnitudes, for the numerics only: they are not material data.
  const auto synthetic = [](double A_MPa, double B_MPa, double n, double C, double m, double T_melt, double rho,
                            kerf::LinearInTemperature K, kerf::LinearInTemperature cp) {
    kerf::OxleyParams p;
    p.johnson_cook = {.A_Pa = A_MPa * 1e6,
                      .B_Pa = B_MPa * 1e6,
                      .n = n,
                      .C = C,
                      .m = m,
                      .reference_strain_rate_per_s = 1.0,
                      .room_temperature_K = 298.15,
                      .melting_temperature_K = T_melt};
    p.thermal = {.density_kg_per_m3 = rho, .conductivity_W_per_m_K = K, .specific_heat_J_per_kg_K = cp};
    return p;
  };
  const auto cut = [](double v, double t1, double rake_deg) {
    return kerf::OxleyCut{.rake_rad = deg_to_rad(rake_deg),
                          .uncut_chip_thickness_m = t1,
                          .width_m = 1e-3,
                          .speed_m_per_s = v,
                          .workpiece_temperature_K = 298.15};
  };
  kerf::OxleySolverOptions plain;
  plain.phi_scan_points = 2;
  plain.delta_scan_points = 2;
  SECTION("two phi branches at the same delta: the one of higher shear angle and lower force") {
    // At delta = 0.2 tau_int = k_chip near phi = 8.3 deg (F_c ~ 130 N) and 35.5 deg (F_c = 43.19 N; the
    // brute-force search gives 43.19 N at phi = 35.5 deg, delta = 0.2).
    const kerf::OxleyParams ti = synthetic(782.7, 498.4, 0.28, 0.028, 1.0, 1878.0, 4430.0, {7.3, 0.0155, kZeroCelsius},
                                           {560.0, 0.2, kZeroCelsius});
    const kerf::OxleyResult r = kerf::solve_oxley(ti, cut(1.11, 24e-6, 19.7));
    CHECK(r.converged);
    CHECK_THAT(r.cutting_force_N, WithinRel(43.19, 1e-3));
    CHECK_THAT(rad_to_deg(r.shear_angle_rad), WithinAbs(35.51, 0.01));
    CHECK(r.delta == 0.2);
    CHECK(r.guards.has(Guard::solver_at_bound));
    CHECK(r.cutting_force_N <= kerf::solve_oxley(ti, cut(1.11, 24e-6, 19.7), plain).cutting_force_N);
  }
  SECTION("a solution only at small delta: found although the larger deltas have none") {
    // For delta above ~0.012 the root in phi lies where C0 would have to be below c0_min = 2. The brute-force
    // search gives F_c = 220.8 N at its nearest grid delta (0.007); the continuous optimum is lower.
    const kerf::OxleyParams ni = synthetic(1241.0, 622.0, 0.65, 0.0134, 1.3, 1570.0, 8190.0,
                                           {11.4, 0.013, kZeroCelsius}, {435.0, 0.2, kZeroCelsius});
    const kerf::OxleyResult r = kerf::solve_oxley(ni, cut(0.969, 92e-6, 17.1));
    CHECK(r.converged);
    CHECK(r.delta < 0.012);
    CHECK(r.cutting_force_N < 220.8);
    CHECK(r.residual_shear < kResidualBound);
    CHECK(r.cutting_force_N <= kerf::solve_oxley(ni, cut(0.969, 92e-6, 17.1), plain).cutting_force_N);
  }
  SECTION("AISI 1045 at positive rake: a low-shear-angle branch appears for delta >= 0.14") {
    // Branches near phi = 6 deg (F_c 356-440 N) and 25 deg (F_c ~ 135.5 N); a plain cold search can switch to
    // the first and stop at F_c = 137.0 N, delta = 0.14.
    const kerf::OxleyResult r = kerf::solve_oxley(aisi_1045(), cut(1.36, 66e-6, 15.2));
    CHECK(r.converged);
    CHECK(rad_to_deg(r.shear_angle_rad) > 20.0);
    CHECK(r.cutting_force_N < 136.0);
  }
}

TEST_CASE("evaluate_oxley gives the state at given unknowns", "[oxley]") {
  const kerf::OxleyResult solved = kerf::solve_oxley(aisi_1045(), reference_cut());
  const kerf::OxleyResult again = kerf::evaluate_oxley(aisi_1045(), reference_cut(), solved.shear_angle_rad,
                                                       solved.strain_rate_constant_C0, solved.delta);
  CHECK_FALSE(again.converged);
  CHECK(again.n_function_evaluations == 1);
  CHECK(again.residual_shear < kResidualBound);
  // T_AB is solved afresh (from T_w) to 1e-2 of the default tolerance.
  CHECK_THAT(again.cutting_force_N, WithinRel(solved.cutting_force_N, 1e-9));
  CHECK_THAT(again.interface_temperature_K, WithinRel(solved.interface_temperature_K, 1e-9));
  // Pantalé's rounded solution (18.945 deg, 5.762, 0.036) is close but not a solution to 3 digits.
  const kerf::OxleyResult rounded =
      kerf::evaluate_oxley(aisi_1045(), reference_cut(), deg_to_rad(18.945), 5.762, 0.036);
  CHECK(rounded.residual_shear < 1e-3);
  CHECK(rounded.residual_normal < 1e-3);
  CHECK_THROWS_AS(kerf::evaluate_oxley(aisi_1045(), reference_cut(), deg_to_rad(70.0), 5.0, 0.03), kerf::InputError);
}

TEST_CASE("Oxley inputs are validated with the field path, value and expectation", "[oxley][validation]") {
  const kerf::OxleyParams steel = aisi_1045();
  SECTION("cut") {
    kerf::OxleyCut cut = reference_cut();
    cut.uncut_chip_thickness_m = -1e-3;
    try {
      kerf::solve_oxley(steel, cut);
      FAIL("no error");
    } catch (const kerf::InputError& e) {
      CHECK(std::string(e.what()) == "cut.uncut_chip_thickness_m = -0.001: expected a positive value in m");
    }
    cut = reference_cut();
    cut.rake_rad = 2.0;
    CHECK_THROWS_AS(kerf::solve_oxley(steel, cut), kerf::InputError);
    cut = reference_cut();
    cut.speed_m_per_s = std::nan("");
    CHECK_THROWS_AS(kerf::solve_oxley(steel, cut), kerf::InputError);
  }
  SECTION("a molten workpiece") {
    kerf::OxleyCut cut = reference_cut();
    cut.workpiece_temperature_K = 1800.0;
    try {
      kerf::solve_oxley(steel, cut);
      FAIL("no error");
    } catch (const kerf::InputError& e) {
      CHECK(e.field() == "cut.workpiece_temperature_K");
    }
  }
  SECTION("material") {
    kerf::OxleyParams bad = steel;
    bad.eta = 1.5;
    try {
      bad.validate("material");
      FAIL("no error");
    } catch (const kerf::InputError& e) {
      CHECK(std::string(e.what()) == "material.eta = 1.5: expected a value in (0, 1]");
    }
    bad = steel;
    bad.johnson_cook.n = -0.2;
    CHECK_THROWS_AS(kerf::solve_oxley(bad, reference_cut()), kerf::InputError);
    bad = steel;
    bad.thermal.conductivity_W_per_m_K.slope_per_K = -0.05;  // K < 0 below T_melt
    try {
      kerf::solve_oxley(bad, reference_cut());
      FAIL("no error");
    } catch (const kerf::InputError& e) {
      CHECK(e.field() == "params.thermal.conductivity_W_per_m_K");
    }
  }
  SECTION("options") {
    kerf::OxleySolverOptions options;
    options.phi_max_rad = deg_to_rad(80.0);
    try {
      kerf::solve_oxley(steel, reference_cut(), options);
      FAIL("no error");
    } catch (const kerf::InputError& e) {
      CHECK(e.field() == "options.phi_max_rad");
    }
    options = {};
    options.delta_max = options.delta_min;
    CHECK_THROWS_AS(kerf::solve_oxley(steel, reference_cut(), options), kerf::InputError);
    options = {};
    options.tolerance = 0.0;
    CHECK_THROWS_AS(kerf::solve_oxley(steel, reference_cut(), options), kerf::InputError);
    options = {};
    options.phi_scan_points = 1;
    try {
      kerf::solve_oxley(steel, reference_cut(), options);
      FAIL("no error");
    } catch (const kerf::InputError& e) {
      CHECK(std::string(e.what()) == "options.phi_scan_points = 1: expected a value in [2, 1000]");
    }
  }
  SECTION("a rake angle that leaves no admissible shear angle is a ModelError") {
    kerf::OxleyCut cut = reference_cut();
    cut.rake_rad = deg_to_rad(-86.0);  // cos(phi - rake) <= 0 for every phi >= 5 deg
    CHECK_THROWS_AS(kerf::solve_oxley(steel, cut), kerf::ModelError);
  }
}
