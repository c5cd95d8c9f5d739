// The 2D flat-joint contact: physics-dem.md section 1 (Potyondy 2012, 2015).
#include "kerf/dem/flat_joint.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kerf/error.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

namespace {

void require(bool ok, const std::string& path, const std::string& key, double value, const std::string& expected) {
  if (!ok) throw InputError(path.empty() ? key : path + "." + key, format_value(value), expected);
}

}  // namespace

FlatJointParams FlatJointParams::validated(const FlatJointParams& raw, const std::string& path) {
  require(std::isfinite(raw.effective_modulus_pa) && raw.effective_modulus_pa > 0, path, "bond_effective_modulus_GPa",
          units::pa_to_gpa(raw.effective_modulus_pa), "a positive value in GPa");
  require(std::isfinite(raw.stiffness_ratio) && raw.stiffness_ratio > 0, path, "bond_stiffness_ratio",
          raw.stiffness_ratio, "a positive value (k_n / k_s)");
  require(std::isfinite(raw.tensile_strength_pa) && raw.tensile_strength_pa >= 0, path, "tensile_strength_MPa",
          units::pa_to_mpa(raw.tensile_strength_pa), "a non-negative value in MPa");
  require(std::isfinite(raw.cohesion_pa) && raw.cohesion_pa >= 0, path, "cohesion_MPa", units::pa_to_mpa(raw.cohesion_pa),
          "a non-negative value in MPa");
  require(std::isfinite(raw.friction_angle_rad) && raw.friction_angle_rad >= 0 &&
              raw.friction_angle_rad < std::numbers::pi / 2,
          path, "friction_angle_deg", units::rad_to_deg(raw.friction_angle_rad), "a value in [0, 90) deg");
  require(std::isfinite(raw.friction_coefficient) && raw.friction_coefficient >= 0, path, "friction_coefficient",
          raw.friction_coefficient, "a non-negative value");
  require(raw.n_elements >= 2 && raw.n_elements <= 16, path, "n_elements", raw.n_elements,
          "an integer in [2, 16] (N_r >= 2 in 2D, else bending never enters the strength test)");
  require(std::isfinite(raw.radius_multiplier) && raw.radius_multiplier > 0 && raw.radius_multiplier <= 1, path,
          "radius_multiplier", raw.radius_multiplier, "a value in (0, 1]");
  FlatJointParams p = raw;
  p.tan_friction_angle = std::tan(raw.friction_angle_rad);
  return p;
}

FlatJointGeometry flat_joint_geometry(const FlatJointParams& p, double r1_m, double r2_m, double thickness_m) {
  const double r_min = r2_m > 0 ? std::min(r1_m, r2_m) : r1_m;
  const double kn = p.effective_modulus_pa / (r1_m + r2_m);  // r2 = 0: disk-wall, L = R1
  return {p.radius_multiplier * r_min, thickness_m, kn, kn / p.stiffness_ratio};
}

double flat_joint_bonded_energy(const FlatJointParams& p, const FlatJointGeometry& geo, const FlatJointKinematics& kin,
                                std::span<const double> shear_force_n, std::span<const std::uint8_t> bonded) {
  const int nr = p.n_elements;
  const double le = 2.0 * geo.half_length_m / nr;
  const double area = le * geo.thickness_m;
  double energy = 0;
  for (int e = 0; e < nr; ++e) {
    if (!bonded[e]) continue;
    const double xi_e = flat_joint_element_centroid(geo, nr, e);
    const double ge = kin.gap_m - kin.rotation_rad * xi_e;
    // 1/2 k_n t int g^2 dxi over the element, + 1/2 F_s^2 / (k_s A_e).
    energy += 0.5 * geo.normal_stiffness * geo.thickness_m *
              (le * ge * ge + kin.rotation_rad * kin.rotation_rad * le * le * le / 12.0);
    energy += 0.5 * shear_force_n[e] * shear_force_n[e] / (geo.shear_stiffness * area);
  }
  return energy;
}

}  // namespace kerf::dem
