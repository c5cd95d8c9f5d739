#include "kerf/analytic/contact_length.hpp"

#include <cmath>
#include <numbers>

#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf {

std::string_view contact_length_model_name(ContactLengthModel model) {
  switch (model) {
    case ContactLengthModel::altintas: return "altintas";
    case ContactLengthModel::vinogradov: return "vinogradov";
    case ContactLengthModel::lee_shaffer: return "lee_shaffer";
  }
  return "";
}

double contact_length(ContactLengthModel model, double uncut_chip_thickness_m, double shear_angle_rad,
                      double friction_angle_rad, double rake_rad) {
  const double quarter_pi = std::numbers::pi / 4.0;
  if (!(shear_angle_rad > 0.0 && shear_angle_rad < 2.0 * quarter_pi)) {
    throw InputError("shear_angle_deg", format_value(units::rad_to_deg(shear_angle_rad)),
                     "a shear angle in (0, 90) deg for the contact-length model");
  }
  double ratio = 0.0;  // L / h
  if (model == ContactLengthModel::altintas) {
    ratio = std::sin(shear_angle_rad + friction_angle_rad - rake_rad) /
            (std::sin(shear_angle_rad) * std::cos(friction_angle_rad));  // Eq. 1
  } else {
    const double denominator = std::sin(shear_angle_rad) * std::sin(quarter_pi + shear_angle_rad - rake_rad);
    ratio = std::sin(quarter_pi) / denominator;  // Eq. 2
    if (model == ContactLengthModel::lee_shaffer) ratio *= 2.0;  // Eq. 3
  }
  if (!std::isfinite(ratio) || ratio <= 0.0) {
    throw InputError("contact_length", contact_length_model_name(model).data(),
                     "a positive contact length (shear angle, friction angle and rake give none)");
  }
  return ratio * uncut_chip_thickness_m;
}

}  // namespace kerf
