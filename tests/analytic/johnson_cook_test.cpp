#include "kerf/analytic/flow_stress/johnson_cook.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "aisi_1045.hpp"
#include "kerf/error.hpp"

using Catch::Matchers::WithinRel;
using kerf::Guard;
using kerf::Guards;

namespace {
// AISI 1045, Jaspers & Dautzenberg (2002).
kerf::JohnsonCookParams aisi_1045() {
  return kerf::testing::aisi_1045_johnson_cook();
}
}  // namespace

TEST_CASE("Johnson-Cook reduces to A at zero strain, reference rate and room temperature", "[johnson_cook]") {
  const auto jc = aisi_1045();
  Guards guards;
  CHECK_THAT(kerf::johnson_cook_stress(jc, {}, 0.0, 1.0, 298.15, &guards), WithinRel(553.1e6, 1e-12));
  CHECK(guards.has(Guard::zero_strain));
  CHECK_FALSE(guards.has(Guard::strain_rate_below_reference));
}

TEST_CASE("Johnson-Cook factors follow the closed form", "[johnson_cook]") {
  const auto jc = aisi_1045();
  const double strain = 0.8, rate = 1e4, temperature = 700.0;
  const double expected = (553.1e6 + 600.8e6 * std::pow(0.8, 0.234)) * (1 + 0.0134 * std::log(1e4)) *
                          (1 - (700.0 - 298.15) / (1733.15 - 298.15));
  Guards guards;
  CHECK_THAT(kerf::johnson_cook_stress(jc, {}, strain, rate, temperature, &guards), WithinRel(expected, 1e-12));
  CHECK_FALSE(guards.any());
}

TEST_CASE("Johnson-Cook stress is monotonic in strain, rate and temperature", "[johnson_cook]") {
  const auto jc = aisi_1045();
  double previous = 0.0;
  for (double strain = 0.0; strain < 3.0; strain += 0.1) {
    const double s = kerf::johnson_cook_stress(jc, {}, strain, 10.0, 400.0, nullptr);
    CHECK(s > previous);
    previous = s;
  }
  CHECK(kerf::johnson_cook_stress(jc, {}, 0.5, 1e5, 400.0, nullptr) >
        kerf::johnson_cook_stress(jc, {}, 0.5, 1e2, 400.0, nullptr));
  CHECK(kerf::johnson_cook_stress(jc, {}, 0.5, 1e3, 1200.0, nullptr) <
        kerf::johnson_cook_stress(jc, {}, 0.5, 1e3, 500.0, nullptr));
}

TEST_CASE("Johnson-Cook guards: melt, cold, slow, negative strain", "[johnson_cook][guards]") {
  const auto jc = aisi_1045();
  SECTION("at and above the melting temperature the stress is zero") {
    Guards guards;
    CHECK(kerf::johnson_cook_stress(jc, {}, 0.5, 1e3, 1733.15, &guards) == 0.0);
    CHECK(kerf::johnson_cook_stress(jc, {}, 0.5, 1e3, 5000.0, &guards) == 0.0);
    CHECK(guards.has(Guard::temperature_at_or_above_melt));
  }
  SECTION("below room temperature: clamp gives the room-temperature value, error refuses") {
    auto jc_m = jc;
    jc_m.m = 0.7;  // pow(negative, 0.7) would be NaN
    Guards guards;
    const double cold = kerf::johnson_cook_stress(jc_m, {}, 0.5, 1e3, 200.0, &guards);
    CHECK(std::isfinite(cold));
    CHECK(cold == kerf::johnson_cook_stress(jc_m, {}, 0.5, 1e3, 298.15, nullptr));
    CHECK(guards.has(Guard::temperature_below_room));
    kerf::JohnsonCookPolicy strict;
    strict.cold = kerf::ColdPolicy::error;
    CHECK_THROWS_AS(kerf::johnson_cook_stress(jc_m, strict, 0.5, 1e3, 200.0, nullptr), kerf::InputError);
  }
  SECTION("below the reference rate: no rate effect (clamp) or the power law, never negative") {
    auto jc_c = jc;
    jc_c.C = 0.5;  // with ln, the factor would be negative below exp(-2)
    Guards guards;
    CHECK(kerf::johnson_cook_rate_factor(jc_c, {}, 1e-6, &guards) == 1.0);
    CHECK(kerf::johnson_cook_rate_factor(jc_c, {}, 0.0, &guards) == 1.0);
    CHECK(guards.has(Guard::strain_rate_below_reference));
    kerf::JohnsonCookPolicy power;
    power.strain_rate = kerf::StrainRatePolicy::power_law;
    CHECK_THAT(kerf::johnson_cook_rate_factor(jc_c, power, 0.0, nullptr), WithinRel(1.0, 1e-15));
    CHECK_THAT(kerf::johnson_cook_rate_factor(jc_c, power, 3.0, nullptr), WithinRel(2.0, 1e-15));
  }
  SECTION("negative or non-finite strain is an input error") {
    CHECK_THROWS_AS(kerf::johnson_cook_stress(jc, {}, -0.1, 1.0, 300.0, nullptr), kerf::InputError);
    CHECK_THROWS_AS(kerf::johnson_cook_stress(jc, {}, NAN, 1.0, 300.0, nullptr), kerf::InputError);
    CHECK_THROWS_AS(kerf::johnson_cook_stress(jc, {}, 0.1, -1.0, 300.0, nullptr), kerf::InputError);
  }
}

TEST_CASE("Johnson-Cook parameters are validated with the field named", "[johnson_cook]") {
  auto jc = aisi_1045();
  jc.melting_temperature_K = 200.0;
  CHECK_THROWS_WITH(jc.validate("material.johnson_cook"),
                    Catch::Matchers::StartsWith("material.johnson_cook.melting_temperature_K = 200"));
}
