#include "kerf/analytic/forces/transition.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "kerf/error.hpp"
#include "kerf/field_table.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

namespace kerf {

std::string_view fracture_model_name(FractureModel model) {
  return model == FractureModel::none ? "none" : "lefm_scratch";
}

const FieldTable<TransitionParams>& transition_fields() {
  static const FieldTable<TransitionParams> table{
      number_field("ductile_layer_factor", units::kSi("(times d_c)"), Range::positive(),
                   "the layer the edge removes in the ductile mode above d_c, l = factor d_c",
                   &TransitionParams::layer_factor),
      number_field("fracture_coefficient", units::kNone, Range::non_negative(),
                   "zeta of the fracture part zeta K_c (sqrt(h) - sqrt(l)) (docs/models.md)",
                   &TransitionParams::fracture_coefficient)};
  return table;
}

void TransitionParams::validate(const std::string& path) const {
  with_path(path, [&] { check_fields(transition_fields(), *this); });
}

double ductile_layer_m(const TransitionParams& params, double critical_depth_m) {
  return params.layer_factor * critical_depth_m;
}

// Its own fields are named (params.*, fracture_toughness_Pa_sqrt_m, depth_m, friction_angle_rad); the transition
// model's unit names the scene's keys instead (forces/transition_model.cpp).
ForcePerWidth fracture_force_per_width(const TransitionParams& params, double toughness, double depth_m, double layer_m,
                                       double rake_rad, double friction_angle_rad) {
  params.validate("params");
  check_number(toughness, "fracture_toughness_Pa_sqrt_m", Range::positive(), "Pa m^0.5");
  check_number(depth_m, "depth_m", Range::non_negative(), "m");
  const double inclination = friction_angle_rad - rake_rad;  // of the rake face's force from the cutting direction
  if (!(std::fabs(inclination) < std::numbers::pi / 2.0)) {
    throw InputError("friction_angle_rad", format_value(friction_angle_rad),
                     fmt::format("friction minus rake in (-90, 90) deg for the fracture part's thrust (rake {:.6g} "
                                 "deg)",
                                 units::rad_to_deg(rake_rad)));
  }
  if (params.fracture == FractureModel::none || depth_m <= layer_m) return {};
  ForcePerWidth f;
  // Huang & Detournay (2008): F / w = zeta K_c sqrt(h) in the brittle regime (zeta: Akono & Ulm 2011); the layer's
  // share is the edge's.
  f.cutting_N_per_m = params.fracture_coefficient * toughness * (std::sqrt(depth_m) - std::sqrt(layer_m));
  f.thrust_N_per_m = f.cutting_N_per_m * std::tan(inclination);
  return f;
}

}  // namespace kerf
