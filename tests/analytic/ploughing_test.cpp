#include "kerf/analytic/forces/ploughing.hpp"

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "kerf/error.hpp"
#include "kerf/units.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using kerf::units::deg_to_rad;

namespace {

constexpr double kPi = std::numbers::pi;

struct Vec {
  double x = 0.0, y = 0.0;
};
Vec operator+(Vec a, Vec b) {
  return {a.x + b.x, a.y + b.y};
}
Vec operator-(Vec a, Vec b) {
  return {a.x - b.x, a.y - b.y};
}
Vec operator*(double s, Vec a) {
  return {s * a.x, s * a.y};
}
double dot(Vec a, Vec b) {
  return a.x * b.x + a.y * b.y;
}
double norm(Vec a) {
  return std::sqrt(dot(a, a));
}
Vec direction(double angle) {
  return {std::cos(angle), std::sin(angle)};
}

/// A symmetric 2D stress tensor and its traction on a plane of unit normal n.
struct Stress {
  double xx = 0.0, yy = 0.0, xy = 0.0;
  Vec traction(Vec n) const { return {xx * n.x + xy * n.y, xy * n.x + yy * n.y}; }
  double normal(Vec a, Vec b) const { return dot(a, traction(b)); }  // a . sigma . b
};
/// -p I + c (e_r e_w^T + e_w e_r^T): the stress of a centred fan on the ray at angle w (radial slip lines).
Stress fan_stress(double p, double c, double w) {
  const Vec er = direction(w), ew = direction(w + kPi / 2.0);
  return {-p + 2.0 * c * er.x * ew.x, -p + 2.0 * c * er.y * ew.y, c * (er.x * ew.y + er.y * ew.x)};
}

/// The Challen-Oxley wave field built from its geometry, for k = 1, w = 1 and a face of length L = 1: the wedge
/// face AE rises at alpha towards the crest A (the origin); the free wave front AB falls ahead of it; the tool
/// moves along +x. Region I (triangle ABC under the free surface), the fan at A (from AC to AD), region III
/// (triangle ADE on the face, its slip line DE meeting the face at eta, f = cos(2 eta)). Nothing of the closed
/// forms is used: psi follows from B and E lying on one level, theta from the angles at A, the stresses from the
/// free surface and the fan's equilibrium (dp/dw = 2 sigma_rw).
struct WaveField {
  double f, alpha, eta, psi, theta;
  Vec a{}, b{}, c{}, d{}, e{};
  double radius = 0.0;  // AC = AD
  Stress region1, region3;
  double p_c = 0.0, shear_rw = 0.0, angle_c = 0.0, angle_d = 0.0;

  WaveField(double friction_factor, double attack_angle) : f(friction_factor), alpha(attack_angle) {
    eta = 0.5 * std::acos(f);
    // Region III is a right triangle on the face (AE = 1) with its angle eta at E: AD = sin(eta).
    radius = std::sin(eta);
    e = direction(kPi + alpha);  // E lies below and behind A
    // Region I is a right isosceles triangle on the free surface: AB = sqrt(2) AC; B lies on E's level.
    const double ab = std::numbers::sqrt2 * radius;
    psi = std::asin(-e.y / ab);
    b = ab * direction(-psi);
    angle_c = -psi - kPi / 4.0;  // AC: the slip line at 45 deg under the free surface
    c = radius * direction(angle_c);
    // Region III's angle at A is pi/2 - eta, so the fan fills the rest of the angle between AB and AE.
    const double angle_at_a = kPi - alpha - psi;
    theta = angle_at_a - kPi / 4.0 - (kPi / 2.0 - eta);
    angle_d = angle_c - theta;  // clockwise from AC
    d = radius * direction(angle_d);
    // Region I: the free surface carries no traction, so the stress is -2k along AB.
    const Vec t = direction(-psi);
    region1 = {-2.0 * t.x * t.x, -2.0 * t.y * t.y, -2.0 * t.x * t.y};
    // On the slip line AC the fan's radial and hoop stresses equal the mean stress, its shear is constant.
    const Vec er = direction(angle_c), ew = direction(angle_c + kPi / 2.0);
    p_c = -region1.normal(er, er);
    shear_rw = region1.normal(er, ew);
    region3 = fan_stress(pressure(angle_d), shear_rw, angle_d);
  }
  double pressure(double w) const { return p_c + 2.0 * shear_rw * (w - angle_c); }

  /// The outward normal of a straight side P -> Q of a triangle whose third corner is A.
  Vec outward(Vec p, Vec q) const {
    const Vec side = q - p;
    Vec n{side.y / norm(side), -side.x / norm(side)};
    return dot(n, a - p) > 0.0 ? -1.0 * n : n;
  }

  /// The force the rigid material exerts on the plastic region through its boundary BCDE.
  Vec boundary_force(int fan_intervals) const {
    Vec total = norm(c - b) * region1.traction(outward(b, c));
    total = total + norm(e - d) * region3.traction(outward(d, e));
    // The fan's arc CD: traction sigma e_r, ds = R dw (composite Simpson).
    const double h = (angle_c - angle_d) / fan_intervals;
    for (int i = 0; i <= fan_intervals; ++i) {
      const double w = angle_d + i * h;
      const double weight = (i == 0 || i == fan_intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      total = total + (weight * h / 3.0 * radius) * fan_stress(pressure(w), shear_rw, w).traction(direction(w));
    }
    return total;
  }
};

}  // namespace

TEST_CASE("Wave model: the field's equilibrium gives the closed forms", "[ploughing]") {
  for (double f : {0.0, 0.2, 0.5, 0.8, 0.95}) {
    const double eta = 0.5 * std::acos(f);
    for (double alpha_deg : {0.0, 1.0, 2.0, 5.0, 10.0, 20.0, 40.0}) {
      const double alpha = deg_to_rad(alpha_deg);
      if (alpha > eta) continue;
      CAPTURE(f, alpha_deg);
      const WaveField field(f, alpha);
      // The geometry closes: D is the right-angle corner of region III, DE meets the face at eta.
      CHECK_THAT(dot(field.d - field.a, field.e - field.d), WithinAbs(0.0, 1e-12));
      CHECK_THAT(norm(field.e - field.d), WithinRel(std::cos(eta), 1e-12));
      // The field's stress is at yield everywhere: region III's maximum shear is k.
      const Stress& s = field.region3;
      CHECK_THAT(std::hypot(0.5 * (s.xx - s.yy), s.xy), WithinRel(1.0, 1e-12));
      // The face AE carries the shear f k, up the face (against the material sliding down it).
      const Vec face_out = field.outward(field.a, field.e);
      CHECK_THAT(dot(direction(alpha), s.traction(face_out)), WithinAbs(f, 1e-12));
      // Equilibrium of the plastic region: the tool's force on the face balances the rigid boundary BCDE.
      const Vec rigid = field.boundary_force(2000);
      const Vec on_face = s.traction(face_out);  // L = 1
      CHECK_THAT(on_face.x, WithinAbs(-rigid.x, 1e-10));
      CHECK_THAT(on_face.y, WithinAbs(-rigid.y, 1e-10));
      // The closed forms: P_cut the tool's push along +x, P_th its push down.
      kerf::Guards guards;
      const auto factors = kerf::wave_model_force_factors(f, alpha, &guards);
      CHECK_FALSE(guards.any());
      CHECK_THAT(factors.fan_angle_rad, WithinAbs(field.theta, 1e-12));
      CHECK_THAT(factors.wave_front_angle_rad, WithinAbs(field.psi, 1e-12));
      CHECK_THAT(factors.cutting, WithinAbs(-rigid.x, 1e-10));  // O(1) values; P_cut = 0 at f = alpha = 0
      CHECK_THAT(factors.thrust, WithinAbs(rigid.y, 1e-10));
    }
  }
}

TEST_CASE("Wave model: a frictionless face gives P_cut / P_th = tan(alpha) and a symmetric heap", "[ploughing]") {
  for (double alpha_deg : {0.5, 3.0, 10.0, 30.0, 44.9}) {
    CAPTURE(alpha_deg);
    const double alpha = deg_to_rad(alpha_deg);
    const auto factors = kerf::wave_model_force_factors(0.0, alpha, nullptr);
    CHECK_THAT(factors.cutting / factors.thrust, WithinRel(std::tan(alpha), 1e-12));
    CHECK_THAT(factors.wave_front_angle_rad, WithinRel(alpha, 1e-12));
  }
}

TEST_CASE("Wave model: alpha = 0 is the flat rough punch", "[ploughing]") {
  for (double f : {0.0, 0.3, 0.8, 0.99}) {
    CAPTURE(f);
    const double eta = 0.5 * std::acos(f);
    const auto factors = kerf::wave_model_force_factors(f, 0.0, nullptr);
    CHECK_THAT(factors.cutting, WithinAbs(f, 1e-12));
    CHECK_THAT(factors.thrust, WithinRel(1.0 + kPi / 2.0 + 2.0 * eta + std::sin(2.0 * eta), 1e-12));
  }
  // The note's number: 3.8143 k w L at f = 0.8.
  CHECK_THAT(kerf::wave_model_force_factors(0.8, 0.0, nullptr).thrust, WithinAbs(3.8143, 5e-5));
}

TEST_CASE("Wave model: beyond alpha = eta the field is capped, reported, finite and continuous",
          "[ploughing][guards]") {
  for (double f : {0.0, 0.4, 0.9}) {
    CAPTURE(f);
    const double eta = 0.5 * std::acos(f);
    kerf::Guards below, above;
    const auto at = kerf::wave_model_force_factors(f, eta * (1.0 - 1e-12), &below);
    const auto beyond = kerf::wave_model_force_factors(f, eta * (1.0 + 1e-12), &above);
    CHECK_FALSE(below.has(kerf::Guard::ploughing_field_capped));
    CHECK(above.has(kerf::Guard::ploughing_field_capped));
    CHECK(beyond.capped);
    CHECK_THAT(beyond.cutting, WithinRel(at.cutting, 1e-9));
    CHECK_THAT(beyond.thrust, WithinRel(at.thrust, 1e-9));
    CHECK_THAT(at.fan_angle_rad, WithinAbs(0.0, 1e-9));  // the fan closes at the cap
    const auto far = kerf::wave_model_force_factors(f, deg_to_rad(80.0), nullptr);
    CHECK(far.cutting == beyond.cutting);
    CHECK(std::isfinite(far.thrust));
  }
  // Sticking (f = 1, from beta >= 45 deg) is the capped field's limit: P_cut = P_th = k L.
  const auto sticking = kerf::wave_model_force_factors(1.0, deg_to_rad(5.0), nullptr);
  CHECK_THAT(sticking.cutting, WithinRel(1.0, 1e-12));
  CHECK_THAT(sticking.thrust, WithinRel(1.0, 1e-12));
  const auto nearly = kerf::wave_model_force_factors(1.0 - 1e-12, deg_to_rad(5.0), nullptr);
  CHECK_THAT(nearly.cutting, WithinRel(1.0, 1e-5));
  CHECK_THAT(nearly.thrust, WithinRel(1.0, 1e-5));
}

TEST_CASE("Wave model: a friction factor outside 0 <= f <= 1 or a negative angle is refused", "[ploughing]") {
  CHECK_THROWS_AS(kerf::wave_model_force_factors(-0.1, 0.1, nullptr), kerf::InputError);
  CHECK_THROWS_AS(kerf::wave_model_force_factors(1.1, 0.1, nullptr), kerf::InputError);
  CHECK_THROWS_AS(kerf::wave_model_force_factors(std::nan(""), 0.1, nullptr), kerf::InputError);
  CHECK_THROWS_AS(kerf::wave_model_force_factors(0.5, -0.1, nullptr), kerf::InputError);
}

TEST_CASE("Lee-Shaffer friction factor: sin(2 beta), frictionless below 0, sticking from 45 deg", "[ploughing]") {
  CHECK_THAT(kerf::friction_factor_from_friction_angle(deg_to_rad(15.0)), WithinRel(0.5, 1e-12));
  CHECK(kerf::friction_factor_from_friction_angle(deg_to_rad(-5.0)) == 0.0);
  CHECK(kerf::friction_factor_from_friction_angle(deg_to_rad(50.0)) == 1.0);
}

TEST_CASE("Edge ploughing: the chord of the engaged arc, zero for a sharp edge", "[ploughing]") {
  const double k = 1e9, r = 1e-6, f = 0.6;
  const kerf::EdgePloughingParams p{.edge_radius_m = r, .friction_factor = f};
  // The chord rises by h_p: L sin(alpha) = h_p.
  for (double h_over_r : {1e-6, 0.01, 0.1, 0.3}) {
    CAPTURE(h_over_r);
    const auto out = kerf::edge_ploughing_force_per_width(p, k, h_over_r * r, nullptr);
    CHECK_THAT(out.chord_m * std::sin(out.factors.attack_angle_rad), WithinRel(h_over_r * r, 1e-12));
    CHECK_THAT(out.force.thrust_N_per_m, WithinRel(k * out.chord_m * out.factors.thrust, 1e-14));
  }
  // r -> 0 with the ploughed layer a fixed fraction of r: the force is proportional to r and vanishes.
  const double fraction = 0.2;
  const auto reference = kerf::edge_ploughing_force_per_width(p, k, fraction * r, nullptr);
  for (double small_r : {1e-9, 1e-12, 1e-15}) {
    CAPTURE(small_r);
    const kerf::EdgePloughingParams tiny{.edge_radius_m = small_r, .friction_factor = f};
    const auto out = kerf::edge_ploughing_force_per_width(tiny, k, fraction * small_r, nullptr);
    CHECK_THAT(out.force.cutting_N_per_m, WithinRel(reference.force.cutting_N_per_m * small_r / r, 1e-9));
    CHECK_THAT(out.force.thrust_N_per_m, WithinRel(reference.force.thrust_N_per_m * small_r / r, 1e-9));
  }
  const kerf::EdgePloughingParams sharp{.edge_radius_m = 0.0, .friction_factor = f};
  CHECK(kerf::edge_ploughing_force_per_width(sharp, k, 1e-7, nullptr).force.thrust_N_per_m == 0.0);
  CHECK(kerf::edge_ploughing_force_per_width(p, k, 0.0, nullptr).force.thrust_N_per_m == 0.0);
  // The field stops existing where the arc's chord is steeper than eta: h_p / r > 1 - f.
  kerf::Guards below, above;
  kerf::edge_ploughing_force_per_width(p, k, (1.0 - f) * r * (1.0 - 1e-9), &below);
  kerf::edge_ploughing_force_per_width(p, k, (1.0 - f) * r * (1.0 + 1e-9), &above);
  CHECK_FALSE(below.has(kerf::Guard::ploughing_field_capped));
  CHECK(above.has(kerf::Guard::ploughing_field_capped));
  // A ploughed height beyond the arc is clipped to it, never a NaN.
  const auto beyond = kerf::edge_ploughing_force_per_width(p, k, 5.0 * r, nullptr);
  CHECK(beyond.ploughed_height_m == 2.0 * r);
  CHECK(std::isfinite(beyond.force.cutting_N_per_m));
}

TEST_CASE("Edge ploughing grows with the edge radius at a fixed ploughed height", "[ploughing]") {
  for (double f : {0.0, 0.4, 0.8}) {
    CAPTURE(f);
    double previous_cut = 0.0, previous_thrust = 0.0;
    for (double r_um = 0.1; r_um <= 10.0; r_um *= 1.1) {
      CAPTURE(r_um);
      const kerf::EdgePloughingParams p{.edge_radius_m = r_um * 1e-6, .friction_factor = f};
      const auto out = kerf::edge_ploughing_force_per_width(p, 1e9, 0.05e-6, nullptr);
      CHECK(out.force.cutting_N_per_m > previous_cut);
      CHECK(out.force.thrust_N_per_m > previous_thrust);
      previous_cut = out.force.cutting_N_per_m;
      previous_thrust = out.force.thrust_N_per_m;
    }
  }
}
