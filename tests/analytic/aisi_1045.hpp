#pragma once
// AISI 1045's Johnson-Cook law, Jaspers & Dautzenberg (2002): the analytic tests' steel (johnson_cook_test.cpp,
// oxley_test.cpp, which uses it as Lalwani et al. 2009 and Pantale et al. 2022 do).
#include "kerf/analytic/flow_stress/johnson_cook.hpp"

namespace kerf::testing {

inline JohnsonCookParams aisi_1045_johnson_cook() {
  return {.A_Pa = 553.1e6,
          .B_Pa = 600.8e6,
          .n = 0.234,
          .C = 0.0134,
          .m = 1.0,
          .reference_strain_rate_per_s = 1.0,
          .room_temperature_K = 298.15,
          .melting_temperature_K = 1733.15};
}

}  // namespace kerf::testing
