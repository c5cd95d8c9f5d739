#include "kerf/analytic/forces/ploughing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

namespace kerf {

std::string_view ploughing_model_name(PloughingModel model) {
  switch (model) {
    case PloughingModel::none:
      return "none";
    case PloughingModel::wave:
      return "wave";
  }
  return "";
}

WaveForceFactors wave_model_force_factors(double friction_factor, double attack_angle_rad, Guards* guards) {
  check_number(friction_factor, "friction_factor", Range::closed(0.0, 1.0), "(tau/k)");
  check_number(units::rad_to_deg(attack_angle_rad), "attack_angle_deg", Range::non_negative(), "deg");
  const double f = friction_factor;
  const double two_eta = std::acos(f);
  const double eta = 0.5 * two_eta;
  WaveForceFactors out;
  out.capped = attack_angle_rad > eta;
  if (out.capped) raise(guards, Guard::ploughing_field_capped);
  const double alpha = std::min(attack_angle_rad, eta);
  // Challen & Oxley 1979: the wave front falls by as much as the face rises (sqrt(1 - f) = sqrt(2) sin(eta)).
  // At alpha = eta the fan closes: psi = pi/4 and theta = 0 exactly (also the sticking limit f = 1, eta = 0).
  const double psi = alpha >= eta ? std::numbers::pi / 4.0 : std::asin(std::sin(alpha) / std::sqrt(1.0 - f));
  const double theta = alpha >= eta ? 0.0 : std::max(0.0, std::numbers::pi / 4.0 + eta - alpha - psi);
  const double a = 1.0 + 2.0 * theta;  // the face pressure is k (A + sin(2 eta))
  out.attack_angle_rad = alpha;
  out.wave_front_angle_rad = psi;
  out.fan_angle_rad = theta;
  out.cutting = a * std::sin(alpha) + std::cos(two_eta - alpha);
  out.thrust = a * std::cos(alpha) + std::sin(two_eta - alpha);
  return out;
}

double friction_factor_from_friction_angle(double friction_angle_rad) {
  // Lee & Shaffer 1951: tau = k sin(2 beta) on a face next to a free surface; sticking from beta = pi/4 on.
  return std::sin(2.0 * std::clamp(friction_angle_rad, 0.0, std::numbers::pi / 4.0));
}

void EdgePloughingParams::validate() const {
  check_number(edge_radius_m, "edge_radius_m", Range::non_negative(), "m");
  check_number(friction_factor, "friction_factor", Range::closed(0.0, 1.0), "(tau/k)");
}

EdgePloughingResult edge_ploughing_force_per_width(const EdgePloughingParams& p, double shear_flow_stress_Pa,
                                                   double ploughed_height_m, Guards* guards) {
  p.validate();
  EdgePloughingResult out;
  const double r = p.edge_radius_m;
  if (!(r > 0.0) || !(ploughed_height_m > 0.0)) {
    out.factors = wave_model_force_factors(p.friction_factor, 0.0, nullptr);
    return out;
  }
  // The chord of the engaged arc (the arc from the lowest point to the height h_p) is the wedge face.
  out.ploughed_height_m = std::min(ploughed_height_m, 2.0 * r);
  // theta_e = acos(1 - h_p / r) written as 2 asin(sqrt(h_p / 2r)), exact for h_p << r (1 - cos = 2 sin^2).
  const double half_chord_sine = std::sqrt(out.ploughed_height_m / (2.0 * r));
  out.engaged_arc_rad = 2.0 * std::asin(std::min(1.0, half_chord_sine));
  out.chord_m = 2.0 * r * half_chord_sine;  // L = 2 r sin(theta_e / 2) = sqrt(2 r h_p)
  out.factors = wave_model_force_factors(p.friction_factor, out.engaged_arc_rad / 2.0, guards);
  const double k_l = shear_flow_stress_Pa * out.chord_m;
  out.force = {k_l * out.factors.cutting, k_l * out.factors.thrust};
  return out;
}

}  // namespace kerf
