// Calibration: the exact proportional trends, and a small-specimen calibration that must recover macro
// properties produced by known micro-parameters (a self-consistent target, so the test is exact about
// what is reachable).
#include "kerf/dem/calibration.hpp"

#include <catch2/catch.hpp>

#include "quick_specimen.hpp"

#include "kerf/dem/specimen.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinRel;

namespace {

Simulation tiny_specimen() {
  const SpecimenSpec spec = kerf::dem::testing::quick_random_spec(0.16e-3, 0.32e-3, 3);
  SpecimenReport report;
  return make_specimen(Material{}, spec, report);
}

LoadingSpec loading(const char* test) {
  LoadingSpec l;
  l.test = test;
  l.speed_m_per_s = 0.2;  // fast: the test is self-consistent, not quasi-static
  l.max_strain = test[0] == 't' ? 0.005 : 0.02;
  l.quasi_static_check = false;
  return l;
}

}  // namespace

TEST_CASE("calibration: E follows E*, strengths follow (sigma_c, c)", "[calibration]") {
  const Simulation specimen = tiny_specimen();
  const Material base;
  const MacroProperties a = measure_macro_properties(specimen, base, loading("tension"), loading("compression"));
  Material stiffer = base;
  stiffer.contact.effective_modulus_pa *= 1.5;
  stiffer.joint.effective_modulus_pa *= 1.5;
  stiffer.joint.tensile_strength_pa *= 1.5;  // same strain to failure: the time scale stays the same
  stiffer.joint.cohesion_pa *= 1.5;
  const MacroProperties b = measure_macro_properties(specimen, stiffer, loading("tension"), loading("compression"));
  CHECK_THAT(b.youngs_modulus_pa, WithinRel(1.5 * a.youngs_modulus_pa, 0.01));
  CHECK_THAT(b.poissons_ratio, WithinRel(a.poissons_ratio, 0.02));
  CHECK_THAT(b.tensile_strength_pa, WithinRel(1.5 * a.tensile_strength_pa, 0.03));
  CHECK_THAT(b.compressive_strength_pa, WithinRel(1.5 * a.compressive_strength_pa, 0.03));
}

TEST_CASE("calibration: recovers reachable targets within 3 % on a small specimen", "[calibration]") {
  const Simulation specimen = tiny_specimen();
  Material hidden;
  hidden.contact.effective_modulus_pa = hidden.joint.effective_modulus_pa = 80e9;
  hidden.contact.stiffness_ratio = hidden.joint.stiffness_ratio = 2.5;
  hidden.joint.tensile_strength_pa = 150e6;
  hidden.joint.cohesion_pa = 180e6;
  CalibrationSpec spec;
  spec.tension = loading("tension");
  spec.compression = loading("compression");
  spec.targets = measure_macro_properties(specimen, hidden, spec.tension, spec.compression);
  spec.max_evaluations = 16;
  int n = 0;
  const CalibrationResult r = calibrate(specimen, Material{}, spec, [&](const CalibrationEvaluation&) { ++n; });
  CHECK(r.converged);
  CHECK(n == static_cast<int>(r.log.size()));
  CHECK(r.max_relative_error <= 0.03);
  const MacroProperties check = measure_macro_properties(specimen, r.material, spec.tension, spec.compression);
  CHECK(max_relative_error(check, spec.targets) <= 0.03);
}
