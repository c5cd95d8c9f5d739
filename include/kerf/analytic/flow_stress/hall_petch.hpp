#pragma once
// Hall-Petch strengthening from high-angle (geometrically necessary) boundaries, Shao et al. 2013:
//
//   sigma_GNB = K_HP / sqrt(D)                                  (Eq. 7)
//   K_HP      = M sqrt(tau_b 4 G b / ((1 - nu) pi))             (Eq. 10, Nes et al. 2005)
//   tau_b     = 0.057 G                                          (Eq. 11, von Blanckenhagen et al. 2001)
//
// Below a critical grain size (roughly 10-50 nm) Hall-Petch is known to break down (inverse Hall-Petch);
// kerf caps the term at its value there and raises Guard::grain_below_critical_size.
//
//   kerf::HallPetchParams hp{.taylor_factor = 3.06, .shear_modulus_Pa = 192e9, .burgers_vector_m = 0.307e-9,
//                            .poissons_ratio = 0.16, .grain_size_m = 5e-6};
//   double sigma_Pa = kerf::hall_petch_stress(hp, nullptr);
#include <optional>
#include <string>

#include "kerf/analytic/guards.hpp"

namespace kerf {

struct HallPetchParams {
  double taylor_factor = 3.06;                 ///< M
  double shear_modulus_Pa = 0.0;               ///< G
  double burgers_vector_m = 0.0;               ///< b
  double poissons_ratio = 0.3;                 ///< nu
  double grain_boundary_stress_ratio = 0.057;  ///< tau_b / G (Eq. 11)
  double grain_size_m = 0.0;                   ///< D
  double critical_grain_size_m = 20e-9;        ///< below it the term is capped
  /// A measured Hall-Petch coefficient (Pa m^0.5) replaces Eqs. 10-11 when given.
  std::optional<double> coefficient_Pa_sqrt_m;

  void validate(const std::string& path) const;
};

/// K_HP in Pa m^0.5: the given coefficient, else Eqs. 10-11.
double hall_petch_coefficient(const HallPetchParams& hp);
/// K_HP / sqrt(max(D, D_crit)) in Pa (Eq. 7).
double hall_petch_stress(const HallPetchParams& hp, Guards* guards);

}  // namespace kerf
