#include "kerf/analytic/flow_stress/hardness_flow.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "kerf/error.hpp"

using Catch::Matchers::WithinRel;
using kerf::ConstraintModel;

namespace {
kerf::HardnessFlowParams glass(double hardness_GPa, double modulus_GPa = 71.0) {
  return {.hardness_Pa = hardness_GPa * 1e9,
          .youngs_modulus_Pa = modulus_GPa * 1e9,
          .poissons_ratio = 0.23,
          .constraint_factor = 1.7};
}
std::string field_of(const kerf::HardnessFlowParams& p, ConstraintModel model) {
  try {
    kerf::hardness_yield_stress_Pa(p, model);
  } catch (const kerf::InputError& e) {
    return e.field();
  }
  return "(no error)";
}
}  // namespace

TEST_CASE("Hardness flow stress: a given constraint factor divides the hardness", "[hardness_flow]") {
  CHECK_THAT(kerf::hardness_yield_stress_Pa(glass(5.5), ConstraintModel::given), WithinRel(5.5e9 / 1.7, 1e-15));
  auto no_factor = glass(5.5);
  no_factor.constraint_factor.reset();
  CHECK(field_of(no_factor, ConstraintModel::given) == "material.brittle.constraint_factor");
  auto below_one = glass(5.5);
  below_one.constraint_factor = 0.9;
  CHECK(field_of(below_one, ConstraintModel::given) == "material.brittle.constraint_factor");
}

TEST_CASE("Hardness flow stress: the cavity forms' roots satisfy their equations on the physical branch",
          "[hardness_flow]") {
  const double tan_beta = std::tan(19.7 * M_PI / 180.0);
  for (double h_GPa : {0.5, 3.0, 4.0, 5.0}) {
    const auto p = glass(h_GPa);
    const double y_marsh = kerf::hardness_yield_stress_Pa(p, ConstraintModel::marsh);
    CHECK_THAT(p.hardness_Pa / y_marsh, WithinRel(0.07 + 0.60 * std::log(p.youngs_modulus_Pa / y_marsh), 1e-10));
    CHECK(y_marsh <= p.hardness_Pa);  // the root with C >= 1
    const double e_star = p.youngs_modulus_Pa / (1.0 - 0.23 * 0.23);
    const double y_johnson = kerf::hardness_yield_stress_Pa(p, ConstraintModel::johnson_cavity);
    CHECK_THAT(p.hardness_Pa / y_johnson,
               WithinRel(2.0 / 3.0 * (1.0 + std::log(e_star * tan_beta / (3.0 * y_johnson))), 1e-10));
    CHECK(y_johnson <= p.hardness_Pa);
  }
  // Soda-lime glass (E 71, H 5.5 GPa): Marsh's constraint factor about 2, within glasses' measured 1.5-2.3.
  const double c_marsh = 5.5e9 / kerf::hardness_yield_stress_Pa(glass(5.5), ConstraintModel::marsh);
  CHECK(c_marsh > 1.9);
  CHECK(c_marsh < 2.2);
}

TEST_CASE("Hardness flow stress: monotone in H, finite at the extremes, refused beyond the forms' reach",
          "[hardness_flow][extremes]") {
  for (auto model : {ConstraintModel::given, ConstraintModel::marsh, ConstraintModel::johnson_cavity}) {
    double previous = 0.0;
    for (double h_GPa : {1e-6, 1e-3, 0.1, 1.0, 4.0, 5.0}) {
      const double y = kerf::hardness_yield_stress_Pa(glass(h_GPa), model);
      CHECK(std::isfinite(y));
      CHECK(y > previous);
      previous = y;
    }
  }
  // At the largest H / E a form allows the yield stress is the hardness (C = 1); just beyond it, refused.
  for (auto model : {ConstraintModel::marsh, ConstraintModel::johnson_cavity}) {
    const double largest = kerf::largest_hardness_over_modulus(model, 0.23);
    const auto at_limit = glass(71.0 * largest * (1.0 - 1e-12));
    CHECK_THAT(kerf::hardness_yield_stress_Pa(at_limit, model), WithinRel(at_limit.hardness_Pa, 1e-9));
    CHECK(field_of(glass(71.0 * largest * 1.001), model) == "material.brittle.hardness_GPa");
  }
  CHECK_THAT(kerf::largest_hardness_over_modulus(ConstraintModel::marsh, 0.23),
             WithinRel(std::exp(-0.93 / 0.6), 1e-12));
  // Soda-lime glass lies beyond Johnson's cavity model (it would need Y above H).
  CHECK(field_of(glass(5.5), ConstraintModel::johnson_cavity) == "material.brittle.hardness_GPa");
  // H -> E and beyond: bad input, named.
  CHECK(field_of(glass(71.0), ConstraintModel::given) == "material.brittle.hardness_GPa");
  CHECK(field_of(glass(0.0), ConstraintModel::given) == "material.brittle.hardness_GPa");
  CHECK(field_of(glass(5.5, 0.0), ConstraintModel::marsh) == "material.elastic.youngs_modulus_GPa");
}
