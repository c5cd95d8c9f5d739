#pragma once
// Strengthening by incidental dislocation boundaries (Hughes & Hansen; Shao et al. 2013, Eqs. 4-6):
//
//   rho_b = k theta_av / (D_avg b)                    (Eq. 5; theta_av in radians)
//   sigma_IDB = M alpha G b sqrt(rho_0 + rho_b)        (Eqs. 4 and 6)
//
// k is geometric (k = 3 when the boundary area per volume is 2/D). Below a critical boundary spacing the
// term is capped (Guard::boundary_spacing_below_critical), as for Hall-Petch.
//
//   kerf::DislocationParams d{.taylor_factor = 3.06, .alpha = 0.24, .shear_modulus_Pa = 192e9,
//                             .burgers_vector_m = 0.307e-9, .boundary_constant_k = 3.0,
//                             .misorientation_rad = 0.035, .boundary_spacing_m = 1e-6};
//   double sigma_Pa = kerf::dislocation_stress(d, nullptr);
#include <string>

#include "kerf/analytic/guards.hpp"

namespace kerf {

struct DislocationParams {
  double taylor_factor = 3.06;           ///< M
  double alpha = 0.24;                   ///< alpha, dislocation interaction constant
  double shear_modulus_Pa = 0.0;         ///< G
  double burgers_vector_m = 0.0;         ///< b
  double boundary_constant_k = 3.0;      ///< k
  double misorientation_rad = 0.0;       ///< theta_av
  double boundary_spacing_m = 0.0;       ///< D_avg
  double critical_spacing_m = 20e-9;     ///< below it the term is capped
  double interior_density_per_m2 = 0.0;  ///< rho_0 (often negligible, Eq. 4)

  void validate(const std::string& path) const;
};

/// Dislocation density in the boundaries, 1/m^2 (Eq. 5), at max(D_avg, D_crit).
double boundary_dislocation_density(const DislocationParams& d, Guards* guards);
/// sigma_IDB in Pa (Eq. 6).
double dislocation_stress(const DislocationParams& d, Guards* guards);

}  // namespace kerf
