// Calibration: the exact proportional trends, a small-specimen calibration that must recover macro
// properties produced by known micro-parameters (a self-consistent target, so the test is exact about
// what is reachable), and resuming from saved evaluations (what `kerf-dem resume` relies on).
#include "kerf/dem/calibration.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <string_view>

#include "quick_specimen.hpp"

#include "kerf/dem/specimen.hpp"
#include "kerf/error.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinRel;

namespace {

Simulation tiny_specimen() {
  const SpecimenSpec spec = kerf::dem::testing::quick_random_spec(0.16e-3, 0.32e-3, 3);
  SpecimenReport report;
  return make_specimen(Material{}, spec, report);
}

LoadingSpec loading(LabTest test) {
  LoadingSpec l;
  l.test = test;
  l.speed_m_per_s = 0.2;  // fast: the test is self-consistent, not quasi-static
  l.max_strain = test == LabTest::tension ? 0.005 : 0.02;
  l.quasi_static_check = false;
  return l;
}

}  // namespace

TEST_CASE("calibration: E follows E*, strengths follow (sigma_c, c)", "[calibration]") {
  const Simulation specimen = tiny_specimen();
  const Material base;
  const MacroProperties a = measure_macro_properties(specimen, base, loading(LabTest::tension), loading(LabTest::compression));
  Material stiffer = base;
  std::get<LinearContactParams>(stiffer.contact).effective_modulus_pa *= 1.5;
  std::get<FlatJointParams>(stiffer.joint).effective_modulus_pa *= 1.5;
  std::get<FlatJointParams>(stiffer.joint).tensile_strength_pa *= 1.5;  // same strain to failure: the time scale stays the same
  std::get<FlatJointParams>(stiffer.joint).cohesion_pa *= 1.5;
  const MacroProperties b = measure_macro_properties(specimen, stiffer, loading(LabTest::tension), loading(LabTest::compression));
  CHECK_THAT(b.youngs_modulus_pa, WithinRel(1.5 * a.youngs_modulus_pa, 0.01));
  CHECK_THAT(b.poissons_ratio, WithinRel(a.poissons_ratio, 0.02));
  CHECK_THAT(b.tensile_strength_pa, WithinRel(1.5 * a.tensile_strength_pa, 0.03));
  CHECK_THAT(b.compressive_strength_pa, WithinRel(1.5 * a.compressive_strength_pa, 0.03));
}

TEST_CASE("calibration: the macro-properties converge with the time step", "[calibration]") {
  // Velocity Verlet is second order: halving the step (f 0.8 -> 0.4) must leave the specimen's response
  // unchanged, far within the calibration's 3 % tolerance (measured: E, nu, sigma_c within 0.1 %, sigma_t 0.2 %).
  // Fails if any force law integrates a rate without the step (e.g. a shear increment not scaled by dt).
  Simulation coarse = tiny_specimen();
  coarse.set_time_step_safety(SimulationOptions{}.time_step_safety);  // both steps from the same state
  Simulation fine = coarse;
  fine.set_time_step_safety(0.5 * SimulationOptions{}.time_step_safety);
  REQUIRE_THAT(fine.time_step(), WithinRel(0.5 * coarse.time_step(), 1e-12));
  const Material m;
  const MacroProperties a = measure_macro_properties(coarse, m, loading(LabTest::tension), loading(LabTest::compression));
  const MacroProperties b = measure_macro_properties(fine, m, loading(LabTest::tension), loading(LabTest::compression));
  CHECK_THAT(b.youngs_modulus_pa, WithinRel(a.youngs_modulus_pa, 0.001));
  CHECK_THAT(b.poissons_ratio, WithinRel(a.poissons_ratio, 0.002));
  CHECK_THAT(b.tensile_strength_pa, WithinRel(a.tensile_strength_pa, 0.01));
  CHECK_THAT(b.compressive_strength_pa, WithinRel(a.compressive_strength_pa, 0.01));
}

namespace {

CalibrationSpec reachable_spec(const Simulation& specimen) {
  Material hidden;
  std::get<LinearContactParams>(hidden.contact).effective_modulus_pa = std::get<FlatJointParams>(hidden.joint).effective_modulus_pa = 80e9;
  std::get<LinearContactParams>(hidden.contact).stiffness_ratio = std::get<FlatJointParams>(hidden.joint).stiffness_ratio = 2.5;
  std::get<FlatJointParams>(hidden.joint).tensile_strength_pa = 150e6;
  std::get<FlatJointParams>(hidden.joint).cohesion_pa = 180e6;
  CalibrationSpec spec;
  spec.tension = loading(LabTest::tension);
  spec.compression = loading(LabTest::compression);
  spec.targets = measure_macro_properties(specimen, hidden, spec.tension, spec.compression);
  spec.max_evaluations = 16;
  return spec;
}

void check_same_log(const std::vector<CalibrationEvaluation>& a, const std::vector<CalibrationEvaluation>& b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(same_micro_parameters(a[i].material, b[i].material));
    CHECK(a[i].macro.youngs_modulus_pa == b[i].macro.youngs_modulus_pa);
    CHECK(a[i].macro.poissons_ratio == b[i].macro.poissons_ratio);
    CHECK(a[i].macro.tensile_strength_pa == b[i].macro.tensile_strength_pa);
    CHECK(a[i].macro.compressive_strength_pa == b[i].macro.compressive_strength_pa);
  }
}

}  // namespace

TEST_CASE("calibration: recovers reachable targets within 3 % on a small specimen (hybrid)", "[calibration]") {
  const Simulation specimen = tiny_specimen();
  const CalibrationSpec spec = reachable_spec(specimen);
  REQUIRE(spec.method == CalibrationMethod::hybrid);
  int n = 0;
  const CalibrationResult r = calibrate(specimen, Material{}, spec, [&](const CalibrationEvaluation&) { ++n; });
  CHECK(r.converged);
  CHECK(n == static_cast<int>(r.log.size()));
  CHECK(r.max_relative_error <= 0.03);
  const MacroProperties check = measure_macro_properties(specimen, r.material, spec.tension, spec.compression);
  CHECK(max_relative_error(check, spec.targets) <= 0.03);

  SECTION("resumed from all but the last evaluation: the same calibration, only the last one re-run") {
    REQUIRE(r.log.size() >= 2);
    // Through the checkpoint's byte form, as kerf-dem resume does.
    const std::vector<CalibrationEvaluation> saved(r.log.begin(), r.log.end() - 1);
    const auto known = deserialize_evaluations(serialize_evaluations(saved));
    check_same_log(saved, known);
    CHECK(known.back().wall_time_s == saved.back().wall_time_s);
    const CalibrationResult resumed = calibrate(specimen, Material{}, spec, {}, known);
    check_same_log(r.log, resumed.log);
    for (std::size_t i = 0; i < resumed.log.size(); ++i) CHECK(resumed.log[i].from_checkpoint == (i + 1 < r.log.size()));
    CHECK(resumed.converged);
    CHECK(same_micro_parameters(resumed.material, r.material));
  }
}

TEST_CASE("calibration: the secant method recovers reachable targets within 3 %", "[calibration]") {
  const Simulation specimen = tiny_specimen();
  CalibrationSpec spec = reachable_spec(specimen);
  spec.method = CalibrationMethod::secant;
  const CalibrationResult r = calibrate(specimen, Material{}, spec);
  CHECK(r.converged);
  CHECK(r.max_relative_error <= 0.03);
}

TEST_CASE("calibration: evaluations serialise bit-exactly, corrupt bytes are rejected", "[calibration]") {
  CalibrationEvaluation e;
  e.index = 3;
  e.material.name = "x";
  std::get<FlatJointParams>(e.material.joint).cohesion_pa = 0.1 + 0.2;  // not a short decimal
  e.macro = {7.1e10 / 3, 0.23 / 7, 4.1e7 / 9, 3.3e8 / 11};
  e.max_relative_error = 1.0 / 3;
  e.wall_time_s = 2.0 / 3;
  const auto back = deserialize_evaluations(serialize_evaluations({e, e}));
  REQUIRE(back.size() == 2);
  check_same_log({e, e}, back);
  CHECK(back[1].index == 3);
  CHECK(back[1].material.name == "x");
  CHECK(back[1].max_relative_error == e.max_relative_error);
  CHECK_THROWS_AS(deserialize_evaluations("not a list"), kerf::ModelError);
  const std::string bytes = serialize_evaluations({e});
  CHECK_THROWS_AS(deserialize_evaluations(std::string_view(bytes).substr(0, bytes.size() - 1)), kerf::ModelError);
  Material other = e.material;
  CHECK(same_micro_parameters(other, e.material));
  std::get<FlatJointParams>(other.joint).cohesion_pa = std::nextafter(std::get<FlatJointParams>(other.joint).cohesion_pa, 1.0);
  CHECK_FALSE(same_micro_parameters(other, e.material));
}
