#include "kerf/analytic/kinds/evaluate.hpp"

#include <catch2/catch.hpp>
#include <optional>
#include <vector>

TEST_CASE("A sweep finds where a force falls as the chip thickens", "[evaluate][issue22]") {
  // Two lines of three thicknesses, thickness the slower axis (stride 2): line 0 rises, line 1 falls at the
  // last thickness; refused points (no value) are skipped.
  const std::vector<std::optional<double>> force = {1.0, 1.0, 2.0, 3.0, 3.0, 2.5};
  CHECK(kerf::falling_points(force, 2, 3) == std::vector<std::size_t>{5});
  CHECK(kerf::falling_points({1.0, std::nullopt, 0.5}, 1, 3).empty());
  CHECK(kerf::falling_points({1.0, 2.0, 1.5}, 1, 3) == std::vector<std::size_t>{2});
  CHECK(kerf::falling_points({1.0, 1.0, 1.0}, 1, 3).empty());
}
