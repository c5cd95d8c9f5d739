#pragma once
// Tool-chip contact length models of Berezvai et al. 2019 (Eqs. 1-3), for uncut chip thickness h, shear angle phi,
// mean friction angle beta and rake a (radians):
//
//   L_Alt = h sin(phi + beta - a) / (sin(phi) cos(beta))         Altintas          (Eq. 1)
//   L_Vin = h sin(pi/4) / (sin(phi) sin(pi/4 + phi - a))         Vinogradov        (Eq. 2)
//   L_Lee = 2 h sin(pi/4) / (sin(phi) sin(pi/4 + phi - a))       Lee and Shaffer   (Eq. 3)
//
// each with phi from the MSSP or MEP shear-angle relation (Eq. 4). With MSSP, L_Alt = L_Vin exactly, and
// always L_Lee = 2 L_Vin. Berezvai et al. 2019 validated them for A2024-T351 up to h ~ 0.1 mm; chip segmentation
// above that breaks them.
//
//   double L_m = kerf::contact_length(kerf::ContactLengthModel::lee_shaffer, h_m, phi, beta, rake);
#include <optional>
#include <string>
#include <string_view>

namespace kerf {

enum class ContactLengthModel { altintas, vinogradov, lee_shaffer };

std::string_view contact_length_model_name(ContactLengthModel model);

/// Why a model is outside its domain at (phi, beta, a): phi outside (0, pi/2) or no finite positive length;
/// nullopt inside it.
std::optional<std::string> contact_length_outside_domain(ContactLengthModel model, double shear_angle_rad,
                                                         double friction_angle_rad, double rake_rad);

/// Contact length in m; throws kerf::InputError outside the domain (contact_length_outside_domain says why).
double contact_length(ContactLengthModel model, double uncut_chip_thickness_m, double shear_angle_rad,
                      double friction_angle_rad, double rake_rad);

}  // namespace kerf
