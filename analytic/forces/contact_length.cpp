#include "kerf/analytic/forces/contact_length.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf {

std::string_view contact_length_model_name(ContactLengthModel model) {
  switch (model) {
    case ContactLengthModel::altintas:
      return "altintas";
    case ContactLengthModel::vinogradov:
      return "vinogradov";
    case ContactLengthModel::lee_shaffer:
      return "lee_shaffer";
  }
  return "";
}

namespace {
double length_ratio(ContactLengthModel model, double shear_angle_rad, double friction_angle_rad, double rake_rad) {
  const double quarter_pi = std::numbers::pi / 4.0;
  if (model == ContactLengthModel::altintas) {
    return std::sin(shear_angle_rad + friction_angle_rad - rake_rad) /
           (std::sin(shear_angle_rad) * std::cos(friction_angle_rad));  // Eq. 1
  }
  const double ratio =
      std::sin(quarter_pi) / (std::sin(shear_angle_rad) * std::sin(quarter_pi + shear_angle_rad - rake_rad));  // Eq. 2
  return model == ContactLengthModel::lee_shaffer ? 2.0 * ratio : ratio;                                       // Eq. 3
}
}  // namespace

std::optional<std::string> contact_length_outside_domain(ContactLengthModel model, double shear_angle_rad,
                                                         double friction_angle_rad, double rake_rad) {
  if (!(shear_angle_rad > 0.0 && shear_angle_rad < std::numbers::pi / 2.0)) {
    return fmt::format("shear angle {:.4g} deg outside (0, 90) deg", units::rad_to_deg(shear_angle_rad));
  }
  const double ratio = length_ratio(model, shear_angle_rad, friction_angle_rad, rake_rad);
  if (!std::isfinite(ratio) || ratio <= 0.0) {
    return fmt::format(
        "no positive length (L/h = {:.4g}) at shear angle {:.4g} deg, friction angle {:.4g} deg, "
        "rake {:.4g} deg",
        ratio, units::rad_to_deg(shear_angle_rad), units::rad_to_deg(friction_angle_rad), units::rad_to_deg(rake_rad));
  }
  return std::nullopt;
}

double contact_length(ContactLengthModel model, double uncut_chip_thickness_m, double shear_angle_rad,
                      double friction_angle_rad, double rake_rad) {
  if (const auto why = contact_length_outside_domain(model, shear_angle_rad, friction_angle_rad, rake_rad)) {
    throw InputError("contact_length", std::string(contact_length_model_name(model)),
                     "a model inside its domain: " + *why);
  }
  return length_ratio(model, shear_angle_rad, friction_angle_rad, rake_rad) * uncut_chip_thickness_m;
}

}  // namespace kerf
