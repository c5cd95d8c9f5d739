// The linear contact driven through prescribed motions (as the flat joint's tests): the normal spring's
// closed form for disk-disk and disk-wall, incremental shear up to the Coulomb limit and sliding there,
// load reversal, separation resetting the shear, the energy whose derivative is the force, and validation.
#include "kerf/dem/laws/linear_contact.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "kerf/error.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("linear contact: k_n = 2 min(R) t E* / L, disk-disk and disk-wall", "[linear_contact]") {
  const LinearContactParams p;
  const double t = 1e-3;
  CHECK_THAT(linear_normal_stiffness(p, 10e-6, 10e-6, t), WithinRel(2 * 10e-6 * t * 107e9 / 20e-6, 1e-14));
  CHECK_THAT(linear_normal_stiffness(p, 8e-6, 12e-6, t), WithinRel(2 * 8e-6 * t * 107e9 / 20e-6, 1e-14));
  CHECK_THAT(linear_normal_stiffness(p, 10e-6, 0, t), WithinRel(2 * 10e-6 * t * 107e9 / 10e-6, 1e-14));  // wall: L = R
  double shear = 0;
  const ContactResult r = contact_update(p, 10e-6, 10e-6, t, 1e-8, 0, shear);
  CHECK_THAT(r.normal_force_N, WithinRel(linear_normal_stiffness(p, 10e-6, 10e-6, t) * 1e-8, 1e-14));
  CHECK(r.shear_force_N == 0);
  const TimeStepStiffness k = contact_time_step_stiffness(p, 10e-6, 10e-6, t);
  CHECK(k.normal == linear_normal_stiffness(p, 10e-6, 10e-6, t));
  CHECK_THAT(k.shear, WithinRel(k.normal / p.stiffness_ratio, 1e-15));
  CHECK(k.bending == 0);
}

TEST_CASE("linear contact: incremental shear, Coulomb sliding, reversal and separation", "[linear_contact]") {
  const LinearContactParams p;
  const double t = 1e-3, overlap = 1e-8;
  const double kn = linear_normal_stiffness(p, 10e-6, 10e-6, t), ks = kn / p.stiffness_ratio;
  const double limit = p.friction_coefficient * kn * overlap;
  double shear = 0;
  // Stick: each increment adds -k_s ds.
  const double ds = 0.1 * limit / ks;
  for (int k = 1; k <= 5; ++k) {
    const ContactResult r = contact_update(p, 10e-6, 10e-6, t, overlap, ds, shear);
    CHECK_THAT(r.shear_force_N, WithinRel(-k * ks * ds, 1e-12));
  }
  // Slide: held at -mu F_n however far it goes.
  for (int k = 0; k < 20; ++k) contact_update(p, 10e-6, 10e-6, t, overlap, ds, shear);
  CHECK_THAT(shear, WithinRel(-limit, 1e-14));
  // Reversal unloads elastically from the limit.
  const ContactResult back = contact_update(p, 10e-6, 10e-6, t, overlap, -ds, shear);
  CHECK_THAT(back.shear_force_N, WithinRel(-limit + ks * ds, 1e-12));
  // Separation: no force, the shear spring is reset.
  const ContactResult apart = contact_update(p, 10e-6, 10e-6, t, -1e-9, ds, shear);
  CHECK(apart.normal_force_N == 0);
  CHECK(apart.shear_force_N == 0);
  CHECK(shear == 0);
  // Frictionless (genesis) and a wall's own friction.
  double s0 = 0, s1 = 0;
  CHECK(contact_update(with_friction(p, 0.0), 10e-6, 10e-6, t, overlap, ds, s0).shear_force_N == 0);
  for (int k = 0; k < 50; ++k) contact_update(with_friction(p, 0.1), 10e-6, 10e-6, t, overlap, ds, s1);
  CHECK_THAT(s1, WithinRel(-0.1 * kn * overlap, 1e-14));
}

TEST_CASE("linear contact: the energy's derivative is the force", "[linear_contact]") {
  const LinearContactParams p;
  const double t = 1e-3, d = 1e-8, h = 1e-13;
  const double de = contact_energy(p, 9e-6, 11e-6, t, d + h, 0) - contact_energy(p, 9e-6, 11e-6, t, d - h, 0);
  double shear = 0;
  CHECK_THAT(de / (2 * h), WithinRel(contact_update(p, 9e-6, 11e-6, t, d, 0, shear).normal_force_N, 1e-6));
  // The shear spring's energy F_s^2 / (2 k_s); nothing when apart.
  const double kn = linear_normal_stiffness(p, 9e-6, 11e-6, t);
  CHECK_THAT(contact_energy(p, 9e-6, 11e-6, t, d, 1e-3) - contact_energy(p, 9e-6, 11e-6, t, d, 0),
             WithinRel(1e-6 / (2 * kn / p.stiffness_ratio), 1e-8));  // a difference of two energies 3e5 x larger
  CHECK(contact_energy(p, 9e-6, 11e-6, t, -d, 1e-3) == 0);
}

TEST_CASE("linear contact: parameters are validated, errors name the key", "[linear_contact]") {
  LinearContactParams p;
  p.friction_coefficient = -0.1;
  CHECK_THROWS_WITH(LinearContactParams::validated(p), "friction_coefficient = -0.1: expected a non-negative value");
  p = {};
  p.effective_modulus_Pa = 0;
  CHECK_THROWS_WITH(LinearContactParams::validated(p), "effective_modulus_GPa = 0: expected a positive value in GPa");
  CHECK_NOTHROW(LinearContactParams::validated(LinearContactParams{}));
}
