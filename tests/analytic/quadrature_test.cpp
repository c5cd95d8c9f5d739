#include "kerf/analytic/forces/quadrature.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "kerf/error.hpp"

using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;

TEST_CASE("Every rule integrates a smooth function", "[quadrature]") {
  for (auto rule : {kerf::QuadratureRule::gauss_kronrod, kerf::QuadratureRule::tanh_sinh, kerf::QuadratureRule::gsl_qag,
                    kerf::QuadratureRule::gauss_legendre}) {
    kerf::QuadratureSettings q{.rule = rule, .relative_tolerance = 1e-10};
    CHECK_THAT(kerf::integrate([](double x) { return std::exp(x); }, 0.0, 1.0, q).value,
               WithinRel(std::exp(1.0) - 1.0, 1e-10));
  }
}

TEST_CASE("GSL QAG's status is checked: an integration that fails throws ModelError", "[quadrature][issue22]") {
  // 1/sqrt(x) on (0, 1] with two subintervals and a 1e-14 tolerance: GSL stops at its subdivision limit.
  kerf::QuadratureSettings q{.rule = kerf::QuadratureRule::gsl_qag, .relative_tolerance = 1e-14, .max_depth = 1};
  CHECK_THROWS_AS(kerf::integrate([](double x) { return 1.0 / std::sqrt(x); }, 0.0, 1.0, q), kerf::ModelError);
  CHECK_THROWS_WITH(kerf::integrate([](double x) { return 1.0 / std::sqrt(x); }, 0.0, 1.0, q), Contains("GSL QAG"));
}

TEST_CASE("Quadrature rule names construct their rule by name", "[quadrature][registry]") {
  for (const auto& name : kerf::quadrature_rule_names()) {
    const auto rule = kerf::quadrature_rule_from_name(name);
    REQUIRE(rule.has_value());
    CHECK(kerf::quadrature_rule_name(*rule) == name);
  }
  CHECK_FALSE(kerf::quadrature_rule_from_name("simpson").has_value());
}
