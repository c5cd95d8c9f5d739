#include "kerf/analytic/forces/contact_length.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "kerf/analytic/forces/shear_angle.hpp"
#include "kerf/error.hpp"
#include "kerf/units.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using kerf::ContactLengthModel;
using kerf::ShearAngleModel;
using kerf::units::deg_to_rad;

TEST_CASE("Berezvai et al. 2019: with the MSSP shear angle Altintas equals Vinogradov", "[contact_length]") {
  for (double rake_deg : {-10.0, 0.0, 15.0}) {
    for (double beta_deg : {15.0, 30.0, 40.0}) {
      const double a = deg_to_rad(rake_deg), beta = deg_to_rad(beta_deg), h = 0.1e-3;
      const double phi = kerf::shear_angle(ShearAngleModel::lee_shaffer, a, beta);
      if (!(phi > 0.0)) continue;
      CHECK_THAT(kerf::contact_length(ContactLengthModel::altintas, h, phi, beta, a),
                 WithinRel(kerf::contact_length(ContactLengthModel::vinogradov, h, phi, beta, a), 1e-12));
    }
  }
}

TEST_CASE("Berezvai et al. 2019: Lee-Shaffer is twice Vinogradov for any shear angle", "[contact_length]") {
  for (double phi_deg : {10.0, 25.0, 40.0, 55.0}) {
    const double phi = deg_to_rad(phi_deg), a = deg_to_rad(15.0), beta = deg_to_rad(30.0);
    CHECK_THAT(kerf::contact_length(ContactLengthModel::lee_shaffer, 0.05e-3, phi, beta, a),
               WithinRel(2.0 * kerf::contact_length(ContactLengthModel::vinogradov, 0.05e-3, phi, beta, a), 1e-14));
  }
}

TEST_CASE("Contact length is proportional to chip thickness and MSSP exceeds MEP as Berezvai et al. 2019 reports",
          "[contact_length]") {
  const double a = deg_to_rad(15.0), beta = deg_to_rad(35.0);
  const double phi_mep = kerf::shear_angle(ShearAngleModel::merchant, a, beta);
  const double phi_mssp = kerf::shear_angle(ShearAngleModel::lee_shaffer, a, beta);
  CHECK(phi_mep > phi_mssp);  // "MEP always results in larger shear angle"
  for (auto model : {ContactLengthModel::altintas, ContactLengthModel::vinogradov, ContactLengthModel::lee_shaffer}) {
    const double l1 = kerf::contact_length(model, 0.05e-3, phi_mep, beta, a);
    CHECK_THAT(kerf::contact_length(model, 0.25e-3, phi_mep, beta, a), WithinRel(5.0 * l1, 1e-12));
    CHECK(kerf::contact_length(model, 0.1e-3, phi_mssp, beta, a) >
          kerf::contact_length(model, 0.1e-3, phi_mep, beta, a));
  }
}

TEST_CASE("Contact length rejects shear angles outside (0, 90) deg", "[contact_length]") {
  CHECK_THROWS_AS(kerf::contact_length(ContactLengthModel::vinogradov, 1e-4, 0.0, 0.3, 0.0), kerf::InputError);
  CHECK_THROWS_AS(kerf::contact_length(ContactLengthModel::altintas, 1e-4, -0.2, 0.3, 0.0), kerf::InputError);
}

TEST_CASE("Shear-angle relations: chip ratio round trip and friction from forces", "[shear_angle]") {
  for (double rake_deg : {-45.0, -10.0, 0.0, 20.0}) {
    const double a = deg_to_rad(rake_deg);
    for (double phi_deg : {5.0, 20.0, 40.0}) {
      const double rc = kerf::chip_ratio_from_shear_angle(deg_to_rad(phi_deg), a);
      CHECK_THAT(kerf::shear_angle_from_chip_ratio(rc, a), WithinAbs(deg_to_rad(phi_deg), 1e-13));
    }
  }
  // beta = atan(Fz/Fx) + rake
  CHECK_THAT(kerf::friction_angle_from_forces(100.0, 100.0, deg_to_rad(10.0)), WithinAbs(deg_to_rad(55.0), 1e-14));
  // MEP and MSSP at beta = rake both give 45 deg.
  CHECK_THAT(kerf::shear_angle(ShearAngleModel::merchant, 0.2, 0.2), WithinAbs(std::atan(1.0), 1e-15));
  CHECK_THAT(kerf::shear_angle(ShearAngleModel::lee_shaffer, 0.2, 0.2), WithinAbs(std::atan(1.0), 1e-15));
}
