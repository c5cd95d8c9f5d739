#pragma once
// The ploughing force under a rounded edge (docs/models.md, "Ploughing"; the model is fixed in the note
// docs/physics-ploughing.md, a copy of the shared note).
//
// The Challen-Oxley wave model (Challen & Oxley 1979): a rigid wedge face of attack angle alpha and length L
// pushes a wave of rigid-perfectly-plastic material, the face carrying the interface shear stress f k
// (0 <= f < 1). Its slip-line field: a uniform triangle under the free wave front, a centred fan of angle theta,
// a uniform triangle on the wedge face. Per unit width:
//
//   eta   = acos(f) / 2
//   psi   = asin(sin(alpha) / sqrt(1 - f))            the wave-front angle
//   theta = pi/4 + eta - alpha - psi                  the fan; the field exists for theta >= 0 (alpha <= eta)
//   A     = 1 + 2 theta
//   P_cut = k L [A sin(alpha) + cos(acos(f) - alpha)]   along the cutting direction
//   P_th  = k L [A cos(alpha) + sin(acos(f) - alpha)]   normal to the machined surface
//
// Waldorf, DeVor & Kapoor (1998) use this stress solution under a rounded edge. kerf maps it onto the engaged
// arc of the edge, from its lowest point up to the ploughed height h_p = min(t0, h_s) (h_s: the stagnation
// height of the Liu-Li model), by the chord of that arc:
//
//   theta_e = acos(1 - h_p / r),   alpha = theta_e / 2,   L = 2 r sin(theta_e / 2)
//
// Where alpha > eta the field does not exist: alpha is capped at eta (theta = 0, psi = pi/4) and
// Guard::ploughing_field_capped says so; L stays the chord of the engaged arc. f = 1 (a sticking face) is the
// limit of the capped field, eta = 0: P_cut = P_th = k L for every alpha > 0.
//
//   kerf::EdgePloughingParams p{.edge_radius_m = 1e-6, .friction_factor = 0.6};
//   auto r = kerf::edge_ploughing_force_per_width(p, k_s_Pa, 0.1e-6, &guards);   // r.force.thrust_N_per_m
#include <string_view>

#include "kerf/analytic/forces/merchant.hpp"
#include "kerf/analytic/guards.hpp"

namespace kerf {

enum class PloughingModel { none, wave };

/// The scene names of the ploughing models (analytic/registry.cpp lists them).
std::string_view ploughing_model_name(PloughingModel model);

/// The wave model's forces per unit k w L: (P_cut, P_th) / (k w L).
struct WaveForceFactors {
  double cutting = 0.0;
  double thrust = 0.0;
  double attack_angle_rad = 0.0;  ///< the alpha used (capped at eta where the field does not exist)
  double wave_front_angle_rad = 0.0;
  double fan_angle_rad = 0.0;
  bool capped = false;  ///< alpha > eta was asked for
};

/// The wave model's force factors (Challen & Oxley 1979) for friction factor f in [0, 1] and attack angle
/// alpha >= 0; caps alpha at eta and raises Guard::ploughing_field_capped where the field does not exist.
/// Throws kerf::InputError for f outside [0, 1] or a negative alpha.
WaveForceFactors wave_model_force_factors(double friction_factor, double attack_angle_rad, Guards* guards);

/// The friction factor f = tau / k of a face with friction angle beta next to a uniform field under a free
/// surface (Lee & Shaffer 1951): f = sin(2 beta), for beta in [0, pi/4]; kerf's default friction factor for the
/// edge (docs/models.md). beta <= 0 gives 0 (a frictionless face), beta >= pi/4 gives 1 (sticking).
double friction_factor_from_friction_angle(double friction_angle_rad);

struct EdgePloughingParams {
  double edge_radius_m = 0.0;    ///< r >= 0 (0: no ploughing force)
  double friction_factor = 0.0;  ///< f in [0, 1] (a scene's cut.friction_factor lies in [0, 1))

  void validate() const;
};

struct EdgePloughingResult {
  ForcePerWidth force;             ///< N per m of width
  double ploughed_height_m = 0.0;  ///< h_p, the height the chord rises by (at most the arc's 2 r)
  double engaged_arc_rad = 0.0;    ///< theta_e, from the lowest point of the edge
  double chord_m = 0.0;            ///< L
  WaveForceFactors factors;
};

/// The ploughing force per unit width under the engaged arc of height h_p (>= 0, clipped to the arc's 2 r) for
/// shear flow stress k (SI). Zero for r = 0 or h_p = 0.
EdgePloughingResult edge_ploughing_force_per_width(const EdgePloughingParams& params, double shear_flow_stress_Pa,
                                                   double ploughed_height_m, Guards* guards);

}  // namespace kerf
