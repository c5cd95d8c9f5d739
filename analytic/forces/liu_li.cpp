#include "kerf/analytic/forces/liu_li.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {
constexpr double kHalfPi = std::numbers::pi / 2.0;
constexpr double kQuarterPi = std::numbers::pi / 4.0;
}  // namespace

std::string_view friction_closure_name(FrictionClosure closure) {
  switch (closure) {
    case FrictionClosure::constant:
      return "constant";
    case FrictionClosure::merchant:
      return "merchant";
    case FrictionClosure::lee_shaffer:
      return "lee_shaffer";
  }
  return "";
}

std::string_view lower_limit_rule_name(LowerLimitRule rule) {
  switch (rule) {
    case LowerLimitRule::stagnation:
      return "stagnation";
    case LowerLimitRule::pole:
      return "pole";
  }
  return "";
}

void LiuLiParams::validate(const std::string& path) const {
  check_number(units::rad_to_deg(rake_rad), path + ".rake_deg", Range::open(-90.0, 90.0), "deg");
  check_number(units::m_to_um(edge_radius_m), path + ".edge_radius_um", Range::non_negative(), "um");
  check_number(chip_ratio, path + ".chip_ratio", Range::positive(), "");
  check_number(units::rad_to_deg(friction_angle_rad), path + ".friction_angle_deg", Range::open(-90.0, 90.0), "deg");
  check_number(units::rad_to_deg(lower_limit_margin_rad), path + ".lower_limit_margin_deg", Range::open(0.0, 45.0),
               "deg");
  check_number(quadrature.relative_tolerance, path + ".quadrature_tolerance", Range::open(0.0, 1.0), "");
}

double local_shear_angle(double chip_ratio, double local_rake_rad) {
  return std::atan2(chip_ratio * std::cos(local_rake_rad), 1.0 - chip_ratio * std::sin(local_rake_rad));  // Eq. 3
}

double local_friction_angle(FrictionClosure closure, double friction_angle_rad, double local_rake_rad,
                            double local_shear_angle_rad) {
  switch (closure) {
    case FrictionClosure::constant:
      return friction_angle_rad;
    case FrictionClosure::merchant:
      return kHalfPi + local_rake_rad - 2.0 * local_shear_angle_rad;
    case FrictionClosure::lee_shaffer:
      return kQuarterPi + local_rake_rad - local_shear_angle_rad;
  }
  return friction_angle_rad;
}

namespace {

/// The arc integrands per unit k_s: r cos(g) / sin(phi_k) times cos or sin(beta_k - g) / cos(phi_k + beta_k - g).
/// Each closure is written out so that the cancellations are exact (Merchant: the denominator is sin(phi_k)).
struct EdgeIntegrand {
  const LiuLiParams& p;

  // r cos(g) / sin(phi_k) without the 0/0 at g = -pi/2.
  double layer_over_sin_phi(double g) const {
    const double rc = p.chip_ratio;
    return p.edge_radius_m * std::sqrt(1.0 - 2.0 * rc * std::sin(g) + rc * rc) / rc;
  }

  /// (cutting, thrust) integrands at local rake g: they share phi_k and the layer factor.
  ValuePair operator()(double g) const {
    const double phi = local_shear_angle(p.chip_ratio, g);
    const double layer = layer_over_sin_phi(g);
    switch (p.closure) {
      case FrictionClosure::merchant:  // beta_k - g = pi/2 - 2 phi_k; the denominator is sin(phi_k)
        return {layer * 2.0 * std::cos(phi), layer * std::cos(2.0 * phi) / std::sin(phi)};
      case FrictionClosure::lee_shaffer:  // phi_k + beta_k - g = pi/4
        return {layer * std::numbers::sqrt2 * std::cos(kQuarterPi - phi),
                layer * std::numbers::sqrt2 * std::sin(kQuarterPi - phi)};
      case FrictionClosure::constant:
        break;
    }
    const double psi = p.friction_angle_rad - g;
    const double denominator = std::cos(phi + psi);
    return {layer * std::cos(psi) / denominator, layer * std::sin(psi) / denominator};
  }
};

/// The pole of the constant closure on [-pi/2, g_max]: phi_k + beta - g = pi/2. The left side minus pi/2
/// equals beta at g = -pi/2 and decreases strictly while r_c sin(g) < 1 (d phi_k / dg < 1), so a root exists
/// iff beta > 0 and the function is negative at g_max; toms748 brackets it.
std::optional<double> constant_closure_pole(const LiuLiParams& p, double g_max) {
  if (p.closure != FrictionClosure::constant || p.friction_angle_rad <= 0.0) return std::nullopt;
  const auto excess = [&](double g) { return local_shear_angle(p.chip_ratio, g) + p.friction_angle_rad - g - kHalfPi; };
  if (excess(g_max) >= 0.0) return g_max;  // the whole edge lies at or below the pole
  boost::math::tools::eps_tolerance<double> tolerance(48);
  std::uintmax_t max_iterations = 100;
  const auto bracket = boost::math::tools::toms748_solve(excess, -kHalfPi, g_max, p.friction_angle_rad, excess(g_max),
                                                         tolerance, max_iterations);
  return 0.5 * (bracket.first + bracket.second);
}

}  // namespace

LiuLiResult liu_li_force_per_width(const LiuLiParams& p, double shear_flow_stress_Pa, double uncut_chip_thickness_m,
                                   Guards* guards) {
  check_number(uncut_chip_thickness_m, "uncut_chip_thickness_m", Range::positive(), "m");  // its own name (SI)
  const double k_s = shear_flow_stress_Pa;
  const double r = p.edge_radius_m;
  LiuLiResult out;
  out.stagnation_angle_rad = -(kQuarterPi + p.friction_angle_rad / 2.0);

  const double arc_height = r * (1.0 + std::sin(p.rake_rad));  // height of the arc's top above its lowest point
  out.chip_on_edge_only = r > 0.0 && uncut_chip_thickness_m <= arc_height;
  out.upper_limit_rad =
      out.chip_on_edge_only ? std::asin(std::clamp(uncut_chip_thickness_m / r - 1.0, -1.0, 1.0)) : p.rake_rad;

  // The lower limit g_L: no chip forms where the local rake lies below it, on the arc or on the straight rake
  // face (the tool is one surface: a rake face below the stagnation point ploughs like the edge below it).
  out.pole_rad = constant_closure_pole(p, p.rake_rad);
  double lower = -kHalfPi;
  if (out.pole_rad) {
    lower = *out.pole_rad + p.lower_limit_margin_rad;
    if (r > 0.0 || lower >= p.rake_rad) raise(guards, Guard::lower_limit_above_pole);
  } else if (p.closure == FrictionClosure::merchant) {
    lower += p.lower_limit_margin_rad;  // the Merchant-closure thrust diverges logarithmically at -pi/2
  }
  if (p.lower_limit == LowerLimitRule::stagnation) lower = std::max(lower, out.stagnation_angle_rad);
  out.cut_off_rad = lower;
  out.lower_limit_rad = std::min(lower, out.upper_limit_rad);
  out.rake_face_ploughs = p.rake_rad <= lower;
  if (out.rake_face_ploughs) raise(guards, Guard::no_chip_on_rake_face);

  // Straight rake face above the arc: the sharp-tool force at the nominal rake (the r -> 0 limit).
  const double rake_face_thickness =
      uncut_chip_thickness_m - (out.chip_on_edge_only ? uncut_chip_thickness_m : arc_height);
  if (rake_face_thickness > 0.0 && !out.rake_face_ploughs) {
    const double phi_nominal = local_shear_angle(p.chip_ratio, p.rake_rad);
    const double beta_nominal = local_friction_angle(p.closure, p.friction_angle_rad, p.rake_rad, phi_nominal);
    out.rake_face = sharp_tool_force_per_width(k_s, rake_face_thickness, phi_nominal, beta_nominal, p.rake_rad);
  }

  const bool no_chip_on_edge = lower >= out.upper_limit_rad;
  if (r > 0.0 && no_chip_on_edge) raise(guards, Guard::no_chip_on_edge);
  if (out.rake_face_ploughs || (no_chip_on_edge && out.chip_on_edge_only)) {
    out.ploughed_thickness_m = uncut_chip_thickness_m;  // no chip at all: the whole cut passes under the tool
  } else if (r > 0.0) {
    out.ploughed_thickness_m = std::min(uncut_chip_thickness_m, r * (1.0 + std::sin(out.lower_limit_rad)));
  }
  if (r > 0.0) {
    const auto edge = integrate_pair(EdgeIntegrand{p}, out.lower_limit_rad, out.upper_limit_rad, p.quadrature);
    out.edge = {k_s * edge.value.first, k_s * edge.value.second};
    out.quadrature_error_estimate = k_s * edge.error_estimate;
  }
  out.total = {out.edge.cutting_N_per_m + out.rake_face.cutting_N_per_m,
               out.edge.thrust_N_per_m + out.rake_face.thrust_N_per_m};
  return out;
}

}  // namespace kerf
