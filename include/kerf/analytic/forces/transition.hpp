#pragma once
// The force of a brittle material across its ductile-brittle transition (models.force = transition;
// docs/models.md, "Glass and ceramics from 10 nm to 0.2 mm"). Per unit width, at depth of cut h:
//
//   h <= l:  F = F_d(h)                                   the ductile model (liu_li with an edge radius, else merchant)
//   h >  l:  F = F_d(l) + F_f(h)                          the edge's ductile layer plus a fracture part
//   l = lambda d_c,  d_c = 0.15 (E / H) (K_c / H)^2       the ductile layer (Bifano, Dow & Scattergood 1991)
//   F_f,c = zeta K_c (sqrt(h) - sqrt(l))                  LEFM scaling of the brittle regime (Huang & Detournay
//                                                          2008); zeta = sqrt(2), Akono & Ulm's (2011) scratch
//                                                          model F = K_c sqrt(2 p A) for a blade (p = w, A = w h)
//   F_f,t = F_f,c tan(beta - alpha)                       the chip's force leaves along the rake face's friction
//
// The split is Detournay & Defourny's (1992): a part that grows with the depth (here, fracture) and a contact part
// that does not (here, the edge on the ductile layer the edge still removes, the layer the DEM's disks cannot
// see). F is continuous at l (F_f(l) = 0), rises monotonically with h, and reduces to the ductile model below l;
// as K_c grows, d_c grows as K_c^2 and the fracture part vanishes at any fixed depth. `none` keeps only the edge
// part (the contact force alone, a lower bound).
//
//   kerf::TransitionParams t;                                  // lambda = 1, zeta = sqrt(2)
//   double l_m = kerf::ductile_layer_m(t, 36e-9);
//   kerf::ForcePerWidth f = kerf::fracture_force_per_width(t, 0.75e6, 1e-4, l_m, -0.26, 0.3);
#include <string>
#include <string_view>

#include "kerf/analytic/forces/merchant.hpp"
#include "kerf/field_table.hpp"

namespace kerf {

enum class FractureModel { lefm_scratch, none };
std::string_view fracture_model_name(FractureModel model);

/// zeta of F_f,c = zeta K_c sqrt(h): Akono & Ulm (Eng. Fract. Mech. 78:334, 2011), K_c = F_T / sqrt(2 p A) with
/// perimeter p = w + 2h and area A = w h of a blade, for w >> h (docs/models.md).
inline constexpr double kAkonoUlmZeta = 1.4142135623730951;

struct TransitionParams {
  FractureModel fracture = FractureModel::lefm_scratch;  ///< models.fracture
  double layer_factor = 1.0;                             ///< lambda = l / d_c > 0 (its key: ductile_layer_factor)
  double fracture_coefficient = kAkonoUlmZeta;           ///< zeta >= 0 (its key: fracture_coefficient)

  /// Checks lambda and zeta against transition_fields()' ranges; InputError naming `path.<key>`.
  void validate(const std::string& path) const;
};

/// The numbers' field table (ductile_layer_factor, fracture_coefficient): the one place their units and ranges live.
/// validate() checks through it; the scene reads the object models.transition with it (forces/transition_model.cpp),
/// and `kerf-forces keys` lists it.
const FieldTable<TransitionParams>& transition_fields();

/// l = lambda d_c in m.
double ductile_layer_m(const TransitionParams& params, double critical_depth_m);

/// The fracture part per unit width (N/m): zero at and below the layer; rake alpha and friction angle beta in rad.
/// InputError, naming its own field (params.*, fracture_toughness_Pa_sqrt_m, depth_m, friction_angle_rad), for
/// parameters out of range, a toughness <= 0, a negative depth, or a rake and friction with beta - alpha outside
/// (-pi/2, pi/2) (a rake above the friction angle gives a negative thrust, as Merchant's circle does).
ForcePerWidth fracture_force_per_width(const TransitionParams& params, double fracture_toughness_Pa_sqrt_m,
                                       double depth_m, double layer_m, double rake_rad, double friction_angle_rad);

}  // namespace kerf
