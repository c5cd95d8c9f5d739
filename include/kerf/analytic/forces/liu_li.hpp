#pragma once
// The Liu-Li edge-radius force model (Shao et al. 2013, Eqs. 1-3; Liu & Li 2001).
//
// A round edge of radius r: the arc point with local rake gamma_k sits at height r (1 + sin gamma_k) above
// the lowest point, so a layer dy = r cos(gamma_k) d gamma_k is cut with local rake gamma_k, each layer a
// Merchant-type cut with local shear angle tan(phi_k) = r_c cos(gamma_k) / (1 - r_c sin(gamma_k)) (Eq. 3).
// Per unit width and unit shear flow stress k_s:
//
//   F_c = int_{g_L}^{g_top} r cos(g) cos(beta_k - g) / (sin(phi_k) cos(phi_k + beta_k - g)) dg
//         + t_rake cos(beta - a) / (sin(phi) cos(phi + beta - a))                (Eq. 1; F_t with sin, Eq. 2)
//
// g_top = a (nominal rake) when t0 > r (1 + sin a), with the straight rake face cutting
// t_rake = t0 - r (1 + sin a); else g_top = asin(t0 / r - 1) and t_rake = 0.
//
// Where the seed is silent (see docs/physics-analytic.md §2), kerf makes these explicit choices,
// reported with every prediction:
// - the friction closure beta_k: constant (beta), Merchant (2 phi_k + beta_k - g = pi/2) or Lee-Shaffer
//   (phi_k + beta_k - g = pi/4);
// - the lower limit g_L: the stagnation point -(pi/4 + beta/2) (Son, Lim & Ahn 2005), or just above the pole
//   of a constant closure (pole + margin), whichever the scene asks for; the stagnation rule also stays a
//   margin above a pole. The layer below g_L, r (1 + sin g_L) thick, is ploughed, not cut, and its force is
//   not part of the model. The thrust force depends strongly on this choice.
// - the cut-off holds for the whole tool: a straight rake face whose nominal rake lies at or below g_L cuts no
//   chip either (Guard::no_chip_on_rake_face); the whole uncut chip is then ploughed. With r = 0 this is the
//   sharp tool, so Merchant's force (models.force = merchant) obeys the same cut-off.
// - r cos(g) / sin(phi_k) is evaluated as r sqrt(1 - 2 r_c sin g + r_c^2) / r_c, free of the 0/0 at g = -pi/2.
//
//   kerf::LiuLiParams p{.rake_rad = 0.0, .edge_radius_m = 1e-6, .chip_ratio = 0.5,
//                       .friction_angle_rad = 0.35, .closure = kerf::FrictionClosure::merchant};
//   auto r = kerf::liu_li_force_per_width(p, k_s_Pa, 0.5e-6, nullptr);   // r.total.cutting_N_per_m
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/analytic/forces/merchant.hpp"
#include "kerf/analytic/forces/quadrature.hpp"
#include "kerf/analytic/guards.hpp"

namespace kerf {

enum class FrictionClosure { constant, merchant, lee_shaffer };
enum class LowerLimitRule { stagnation, pole };

/// The scene names of the closures and lower-limit rules (analytic/registry.cpp lists them).
std::string_view friction_closure_name(FrictionClosure closure);
std::string_view lower_limit_rule_name(LowerLimitRule rule);

struct LiuLiParams {
  double rake_rad = 0.0;            ///< nominal rake a, in (-pi/2, pi/2)
  double edge_radius_m = 0.0;       ///< r >= 0 (0: sharp tool)
  double chip_ratio = 0.5;          ///< r_c = t0 / t_chip > 0
  double friction_angle_rad = 0.0;  ///< beta of the constant closure and of the stagnation point
  FrictionClosure closure = FrictionClosure::merchant;
  LowerLimitRule lower_limit = LowerLimitRule::stagnation;
  double lower_limit_margin_rad = 0.017453292519943295;  ///< 1 deg above a pole or above -pi/2
  QuadratureSettings quadrature;

  void validate(const std::string& path) const;
};

struct LiuLiResult {
  ForcePerWidth total;      ///< N per m of width
  ForcePerWidth edge;       ///< the arc integral
  ForcePerWidth rake_face;  ///< the straight rake face above the arc
  double upper_limit_rad = 0.0;
  double lower_limit_rad = 0.0;       ///< where the integral starts (clipped to the upper limit)
  double cut_off_rad = 0.0;           ///< the lower limit before clipping: no chip forms at a local rake below it
  double stagnation_angle_rad = 0.0;  ///< -(pi/4 + beta/2)
  std::optional<double> pole_rad;     ///< the pole of the constant closure, if on the edge
  double ploughed_thickness_m = 0.0;  ///< min(t0, r (1 + sin g_L)): below the lower limit
  bool chip_on_edge_only = false;     ///< t0 <= r (1 + sin a)
  bool rake_face_ploughs = false;     ///< the nominal rake lies at or below the lower limit: no chip at all
  double quadrature_error_estimate = 0.0;
};

/// Forces per unit width for shear flow stress k_s and uncut chip thickness t0 > 0 (both SI).
/// Throws kerf::InputError where a closure's nominal beta leaves no chip above the cut-off (phi + beta - a >= pi/2).
LiuLiResult liu_li_force_per_width(const LiuLiParams& params, double shear_flow_stress_Pa,
                                   double uncut_chip_thickness_m, Guards* guards);

/// The local shear angle phi_k of Eq. 3 (atan2 form).
double local_shear_angle(double chip_ratio, double local_rake_rad);
/// The local friction angle beta_k of a closure at local rake g with local shear angle phi_k.
double local_friction_angle(FrictionClosure closure, double friction_angle_rad, double local_rake_rad,
                            double local_shear_angle_rad);

}  // namespace kerf
