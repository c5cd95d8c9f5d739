#include "kerf/analytic/flow_stress/hall_petch.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kerf/json_reader.hpp"

namespace kerf {

void HallPetchParams::validate(const std::string& path) const {
  check_field(taylor_factor, path, "taylor_factor", Range::positive(), "");
  check_field(grain_size_m * 1e6, path, "grain_size_um", Range::positive(), "um");
  check_field(critical_grain_size_m * 1e9, path, "critical_grain_size_nm", Range::non_negative(), "nm");
  if (coefficient_Pa_sqrt_m) {
    check_field(*coefficient_Pa_sqrt_m * 1e-6, path, "hall_petch_coefficient_MPa_sqrt_m", Range::non_negative(),
                "MPa m^0.5");
    return;
  }
  check_field(shear_modulus_Pa * 1e-9, path, "shear_modulus_GPa", Range::positive(), "GPa");
  check_field(burgers_vector_m * 1e9, path, "burgers_vector_nm", Range::positive(), "nm");
  check_field(poissons_ratio, path, "poissons_ratio", Range{-1.0, 0.5, true, true}, "");
  check_field(grain_boundary_stress_ratio, path, "grain_boundary_stress_ratio", Range::positive(), "");
}

double hall_petch_coefficient(const HallPetchParams& hp) {
  if (hp.coefficient_Pa_sqrt_m) return *hp.coefficient_Pa_sqrt_m;
  const double tau_b = hp.grain_boundary_stress_ratio * hp.shear_modulus_Pa;  // Eq. 11
  return hp.taylor_factor * std::sqrt(tau_b * 4.0 * hp.shear_modulus_Pa * hp.burgers_vector_m /
                                      ((1.0 - hp.poissons_ratio) * std::numbers::pi));  // Eq. 10
}

double hall_petch_stress(const HallPetchParams& hp, Guards* guards) {
  double grain = hp.grain_size_m;
  if (grain < hp.critical_grain_size_m) {
    raise(guards, Guard::grain_below_critical_size);
    grain = hp.critical_grain_size_m;
  }
  return hall_petch_coefficient(hp) / std::sqrt(grain);  // Eq. 7
}

}  // namespace kerf
