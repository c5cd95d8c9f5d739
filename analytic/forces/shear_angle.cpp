#include "kerf/analytic/forces/shear_angle.hpp"

#include <cmath>
#include <numbers>

namespace kerf {

std::string_view shear_angle_model_name(ShearAngleModel model) {
  return model == ShearAngleModel::merchant ? "merchant" : "lee_shaffer";
}

double shear_angle(ShearAngleModel model, double rake_rad, double friction_angle_rad) {
  const double quarter_pi = std::numbers::pi / 4.0;
  const double relative_friction = friction_angle_rad - rake_rad;
  return model == ShearAngleModel::merchant ? quarter_pi - relative_friction / 2.0 : quarter_pi - relative_friction;
}

double shear_angle_from_chip_ratio(double chip_ratio, double rake_rad) {
  return std::atan2(chip_ratio * std::cos(rake_rad), 1.0 - chip_ratio * std::sin(rake_rad));
}

double chip_ratio_from_shear_angle(double shear_angle_rad, double rake_rad) {
  return std::sin(shear_angle_rad) / std::cos(shear_angle_rad - rake_rad);
}

double friction_angle_from_forces(double cutting_force, double thrust_force, double rake_rad) {
  return std::atan2(thrust_force, cutting_force) + rake_rad;
}

}  // namespace kerf
