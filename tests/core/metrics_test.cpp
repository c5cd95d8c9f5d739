#include "kerf/metrics.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kerf/error.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("Error metrics on hand-made data are exact", "[metrics]") {
  const std::vector<double> predicted{110, 90, 100, 125}, measured{100, 100, 100, 100};
  const auto m = kerf::error_metrics(predicted, measured);  // errors +10, -10, 0, +25 %
  CHECK(m.n == 4);
  CHECK_THAT(m.mean_abs_error_percent, WithinRel(11.25, 1e-14));
  CHECK_THAT(m.max_abs_error_percent, WithinRel(25.0, 1e-14));
  CHECK_THAT(m.bias_percent, WithinRel(6.25, 1e-14));
  CHECK_THAT(m.rms_error_percent, WithinRel(std::sqrt(825.0 / 4.0), 1e-14));
  // The sign convention of Yu et al. 2023's Table 4: (theory - test) / test.
  CHECK_THAT(kerf::relative_error_percent(220.1, 210.5), WithinAbs(4.56, 0.005));
  CHECK_THAT(kerf::relative_error_percent(5.32, 4.63), WithinAbs(14.90, 0.005));
}

TEST_CASE("Metrics refuse what they cannot compare", "[metrics][errors]") {
  CHECK_THROWS_AS(kerf::relative_error_percent(1.0, 0.0), kerf::InputError);
  CHECK_THROWS_AS(kerf::relative_error_percent(NAN, 1.0), kerf::InputError);
  const std::vector<double> two{1, 2}, three{1, 2, 3}, none;
  CHECK_THROWS_AS(kerf::error_metrics(two, three), kerf::InputError);
  CHECK_THROWS_AS(kerf::error_metrics(none, none), kerf::InputError);
}

TEST_CASE("Sample statistics use n - 1", "[metrics]") {
  const std::vector<double> v{1, 2, 3, 4};
  const auto s = kerf::sample_statistics(v);
  CHECK(s.n == 4);
  CHECK_THAT(s.mean, WithinRel(2.5, 1e-15));
  CHECK_THAT(s.standard_deviation, WithinRel(std::sqrt(5.0 / 3.0), 1e-14));
  const std::vector<double> one{7};
  CHECK(std::isnan(kerf::sample_statistics(one).standard_deviation));
}
