#include "kerf/analytic/flow_stress/flow_stress.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "kerf/error.hpp"

using Catch::Matchers::WithinRel;
using kerf::Guard;

namespace {
kerf::HallPetchParams sic_hall_petch(double grain_m) {
  kerf::HallPetchParams hp;
  hp.taylor_factor = 3.06;
  hp.shear_modulus_Pa = 180e9;
  hp.burgers_vector_m = 0.308e-9;
  hp.poissons_ratio = 0.14;
  hp.grain_size_m = grain_m;
  return hp;
}
kerf::DislocationParams sic_dislocation(double spacing_m) {
  kerf::DislocationParams d;
  d.shear_modulus_Pa = 180e9;
  d.burgers_vector_m = 0.308e-9;
  d.misorientation_rad = 2.5 * std::numbers::pi / 180.0;
  d.boundary_spacing_m = spacing_m;
  return d;
}
}  // namespace

TEST_CASE("Hall-Petch coefficient follows Shao et al. 2013, Eqs. 10-11", "[hall_petch]") {
  const auto hp = sic_hall_petch(5e-6);
  const double tau_b = 0.057 * 180e9;
  const double expected = 3.06 * std::sqrt(tau_b * 4.0 * 180e9 * 0.308e-9 / ((1.0 - 0.14) * std::numbers::pi));
  CHECK_THAT(kerf::hall_petch_coefficient(hp), WithinRel(expected, 1e-14));
  // sigma ~ D^-1/2: a four times smaller grain doubles the term.
  CHECK_THAT(kerf::hall_petch_stress(sic_hall_petch(1.25e-6), nullptr),
             WithinRel(2.0 * kerf::hall_petch_stress(hp, nullptr), 1e-14));
}

TEST_CASE("A measured Hall-Petch coefficient replaces Eqs. 10-11", "[hall_petch]") {
  auto hp = sic_hall_petch(100e-6);
  hp.coefficient_Pa_sqrt_m = 0.5e6;
  CHECK_THAT(kerf::hall_petch_stress(hp, nullptr), WithinRel(0.5e6 / std::sqrt(100e-6), 1e-14));
}

TEST_CASE("Grains below the critical size cap the microstructural terms and fire guards", "[hall_petch][guards]") {
  kerf::Guards guards;
  const double at_critical = kerf::hall_petch_stress(sic_hall_petch(20e-9), nullptr);
  CHECK(kerf::hall_petch_stress(sic_hall_petch(1e-9), &guards) == at_critical);
  CHECK(guards.has(Guard::grain_below_critical_size));
  const double d_critical = kerf::dislocation_stress(sic_dislocation(20e-9), nullptr);
  CHECK(kerf::dislocation_stress(sic_dislocation(1e-9), &guards) == d_critical);
  CHECK(guards.has(Guard::boundary_spacing_below_critical));
}

TEST_CASE("Dislocation strengthening follows Shao et al. 2013, Eqs. 4-6", "[dislocation]") {
  const auto d = sic_dislocation(1e-6);
  const double rho = 3.0 * d.misorientation_rad / (1e-6 * 0.308e-9);
  CHECK_THAT(kerf::dislocation_stress(d, nullptr), WithinRel(3.06 * 0.24 * 180e9 * 0.308e-9 * std::sqrt(rho), 1e-14));
}

TEST_CASE("The composite flow stress adds the named terms and k = sigma / sqrt(3)", "[flow_stress]") {
  kerf::FlowStressModel model;
  model.johnson_cook = kerf::JohnsonCookParams{.A_Pa = 1e9,
                                               .B_Pa = 0.0,
                                               .n = 1.0,
                                               .C = 0.0,
                                               .m = 1.0,
                                               .reference_strain_rate_per_s = 1.0,
                                               .room_temperature_K = 293.0,
                                               .melting_temperature_K = 3000.0};
  model.hall_petch = sic_hall_petch(5e-6);
  model.dislocation = sic_dislocation(1e-6);
  const kerf::DeformationState state{0.5, 1e3, 293.0};
  const auto s = kerf::flow_stress(model, state, nullptr);
  CHECK_THAT(s.total_Pa, WithinRel(1e9 + kerf::hall_petch_stress(*model.hall_petch, nullptr) +
                                       kerf::dislocation_stress(*model.dislocation, nullptr),
                                   1e-14));
  CHECK_THAT(s.shear_Pa, WithinRel(s.total_Pa / std::sqrt(3.0), 1e-14));
  model.hall_petch.reset();
  CHECK(kerf::flow_stress(model, state, nullptr).hall_petch_Pa == 0.0);
}

TEST_CASE("At the melting temperature every term is zero", "[flow_stress][guards]") {
  kerf::FlowStressModel model;
  model.hall_petch = sic_hall_petch(5e-6);
  model.melting_temperature_K = 3003.0;
  kerf::Guards guards;
  const auto s = kerf::flow_stress(model, {0.5, 1e3, 3003.0}, &guards);
  CHECK(s.total_Pa == 0.0);
  CHECK(guards.has(Guard::temperature_at_or_above_melt));
  CHECK(kerf::flow_stress(model, {0.5, 1e3, 3002.0}, nullptr).total_Pa > 0.0);
}

TEST_CASE("A flow-stress model needs at least one term", "[flow_stress]") {
  CHECK_THROWS_AS(kerf::FlowStressModel{}.validate("models.flow_stress"), kerf::InputError);
}
