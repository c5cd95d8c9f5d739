#include "kerf/analytic/flow_stress/dislocation.hpp"

#include <cmath>

#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

namespace kerf {

void DislocationParams::validate(const std::string& path) const {
  check_field(taylor_factor, path, "taylor_factor", Range::positive(), "");
  check_field(alpha, path, "alpha", Range::positive(), "");
  check_field(shear_modulus_Pa * 1e-9, path, "shear_modulus_GPa", Range::positive(), "GPa");
  check_field(burgers_vector_m * 1e9, path, "burgers_vector_nm", Range::positive(), "nm");
  check_field(boundary_constant_k, path, "boundary_constant_k", Range::positive(), "");
  check_field(units::rad_to_deg(misorientation_rad), path, "misorientation_deg", Range::closed(0.0, 90.0), "deg");
  check_field(boundary_spacing_m * 1e6, path, "boundary_spacing_um", Range::positive(), "um");
  check_field(critical_spacing_m * 1e9, path, "critical_grain_size_nm", Range::non_negative(), "nm");
  check_field(interior_density_per_m2, path, "interior_dislocation_density_per_m2", Range::non_negative(), "1/m^2");
}

double boundary_dislocation_density(const DislocationParams& d, Guards* guards) {
  double spacing = d.boundary_spacing_m;
  if (spacing < d.critical_spacing_m) {
    raise(guards, Guard::boundary_spacing_below_critical);
    spacing = d.critical_spacing_m;
  }
  return d.boundary_constant_k * d.misorientation_rad / (spacing * d.burgers_vector_m);  // Eq. 5
}

double dislocation_stress(const DislocationParams& d, Guards* guards) {
  const double total_density = d.interior_density_per_m2 + boundary_dislocation_density(d, guards);       // Eq. 4
  return d.taylor_factor * d.alpha * d.shear_modulus_Pa * d.burgers_vector_m * std::sqrt(total_density);  // Eq. 6
}

}  // namespace kerf
