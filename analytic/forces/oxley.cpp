// Extended Oxley machining theory with a Johnson-Cook material; see include/kerf/analytic/forces/oxley.hpp.
//
// The equation set of Lalwani, Mehta & Jain (2009): Oxley (1989) with the Johnson-Cook law, as written in
// docs/physics-analytic.md section 3 and implemented by Pantalé et al. (2022) (github.com/pantale/OxleyPython).
// Tags used below (the paper's own numbers could not be checked here):
//   (O 1)  geometry: l_AB = t1 / sin(phi), V_s = V cos(a) / cos(phi - a), V_c = V sin(phi) / cos(phi - a),
//          t2 = t1 cos(phi - a) / sin(phi)
//   (O 2)  gamma_AB = cos(a) / (2 sin(phi) cos(phi - a)), gammadot_AB = C0 V_s / l_AB; equivalent = / sqrt 3
//   (O 3)  k_AB = sigma_JC(eps_AB, epsdot_AB, T_AB) / sqrt 3, F_s = k_AB l_AB w
//   (O 4)  T_AB = T_w + eta dT_SZ, dT_SZ = (1 - beta) F_s V_s / (rho c_p V t1 w), beta(R_T tan(phi)),
//          R_T = rho c_p V t1 / K, K and c_p at T_AB
//   (O 5)  n_eq = n B eps^n / (A + B eps^n), tan(theta) = 1 + pi/2 - 2 phi - C0 n_eq
//   (O 6)  R = F_s / cos(theta), lambda = theta + a - phi, F_c = R cos(theta - phi), F_t = R sin(theta - phi),
//          F = R sin(lambda), N = R cos(lambda)
//   (O 7)  sigma_N' = k_AB (1 + pi/2 - 2 a - 2 C0 n_eq)
//   (O 8)  h = t1 sin(theta) / (cos(lambda) sin(phi)) [1 + C0 n_eq / (3 (1 + 2 (pi/4 - phi) - C0 n_eq))]
//   (O 9)  tau_int = F / (h w), sigma_N = N / (h w)
//   (O 10) gamma_int = 2 gamma_AB + h / (2 delta t2), gammadot_int = V_c / (delta t2)
//   (O 11) T_c = T_w + dT_SZ + dT_C, dT_C = F V_c / (rho c_p(T_c) V t1 w); dT_M = dT_C
//          10^(0.06 - 0.195 delta sqrt(R_T t2 / h)) sqrt(R_T t2 / h), K and c_p at T_c;
//          T_int = T_w + dT_SZ + psi dT_M
//   (O 12) k_chip = sigma_JC(gamma_int / sqrt 3, gammadot_int / sqrt 3, T_int) / sqrt 3
// Solved: sigma_N = sigma_N' for C0 and tau_int = k_chip for phi at each delta; delta minimises F_c.
// All quantities SI; w cancels from every stress and temperature, so forces are proportional to the width.
#include "kerf/analytic/forces/oxley.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSqrt3 = std::numbers::sqrt3;
constexpr double kMaxShearAngle = kPi / 3.0;  // 60 deg: tan(theta) = 1 + pi/2 - 2 phi - C0 n_eq stays sane

// ---------------------------------------------------------------------------------------------------------
// Validation without building strings on the hot path: solve_oxley calls these once per solve.

// The fields named are the arguments' own (params.*, cut.*, options.*, SI), under the arguments' names; the scene
// layer names its keys instead (forces/oxley_model.cpp).
constexpr const char* kCutArgument = "cut";

void validate_all(const OxleyParams& params, const OxleyCut& cut, const OxleySolverOptions* options) {
  params.validate("params");
  cut.validate(kCutArgument);
  if (options) options->validate("options");
  const auto& jc = params.johnson_cook;
  if (!(cut.workpiece_temperature_K < jc.melting_temperature_K)) {
    throw InputError(std::string(kCutArgument) + ".workpiece_temperature_K", format_value(cut.workpiece_temperature_K),
                     "a temperature below the Johnson-Cook melting temperature " +
                         format_value(jc.melting_temperature_K) + " K (the workpiece would be molten)");
  }
  if (params.policy.cold == ColdPolicy::error && cut.workpiece_temperature_K < jc.room_temperature_K) {
    throw InputError(std::string(kCutArgument) + ".workpiece_temperature_K", format_value(cut.workpiece_temperature_K),
                     "a temperature at or above the Johnson-Cook room temperature " +
                         format_value(jc.room_temperature_K) + " K (policy 'error')");
  }
  // K and c_p are used from the workpiece temperature up (below: validated from T_room to T_melt).
  if (cut.workpiece_temperature_K < jc.room_temperature_K) {
    params.thermal.validate("params.thermal", cut.workpiece_temperature_K, jc.melting_temperature_K);
  }
}

// ---------------------------------------------------------------------------------------------------------
// Everything fixed during one solve.

struct Context {
  const JohnsonCookParams& jc;
  const JohnsonCookPolicy& policy;
  const ThermalProperties& thermal;
  double eta, psi;
  double rake, cos_rake, t1, width, speed, T_w, T_melt;
  double rho_V_t1;  // rho V t1: mass flow per unit width, for m_chip = rho V t1 w
  double rel_tol;   // root finds in phi and C0
  double temperature_rel_tol;
  int max_iterations;
  int n_evaluations = 0;  // shear-zone states evaluated

  // K(T), c_p(T) are validated positive up to T_melt and held at their T_melt values above it: the interface
  // temperature of the model can exceed T_melt (the chip's flow stress is then zero), its properties cannot.
  double conductivity(double T) const { return thermal.conductivity_W_per_m_K.at(std::min(T, T_melt)); }
  double specific_heat(double T) const { return thermal.specific_heat_J_per_kg_K.at(std::min(T, T_melt)); }
};

Context make_context(const OxleyParams& params, const OxleyCut& cut, const OxleySolverOptions& options) {
  return Context{params.johnson_cook,
                 params.policy,
                 params.thermal,
                 params.eta,
                 params.psi,
                 cut.rake_rad,
                 std::cos(cut.rake_rad),
                 cut.uncut_chip_thickness_m,
                 cut.width_m,
                 cut.speed_m_per_s,
                 cut.workpiece_temperature_K,
                 params.johnson_cook.melting_temperature_K,
                 params.thermal.density_kg_per_m3 * cut.speed_m_per_s * cut.uncut_chip_thickness_m,
                 options.tolerance,
                 std::max(1e-2 * options.tolerance, 4.0 * std::numeric_limits<double>::epsilon()),
                 options.max_iterations};
}

// Heat partition: the fraction of the shear-zone heat conducted into the work (Oxley 1989, as in Lalwani),
// beta = 0.5 - 0.35 log10(R_T tan(phi)) up to R_T tan(phi) = 10, 0.3 - 0.15 log10(R_T tan(phi)) above. It stays
// in [0, 1] only for 0.037 <= R_T tan(phi) <= 100; sub-micron chips give beta > 1 (a negative temperature
// rise), very thick fast ones beta < 0. Clamped to [0, 1] and reported through `clamped`.
double heat_partition(double rt_tan_phi, bool* clamped) {
  const double beta = rt_tan_phi <= 10.0 ? 0.5 - 0.35 * std::log10(rt_tan_phi) : 0.3 - 0.15 * std::log10(rt_tan_phi);
  if (beta > 1.0 || beta < 0.0) {
    if (clamped) *clamped = true;
    return std::clamp(beta, 0.0, 1.0);
  }
  return beta;
}

// ---------------------------------------------------------------------------------------------------------
// Root finding. Every root below is kept inside a bracket where f changes sign; every loop has a budget.

// Bracketed root of f on [a, b] given f(a), f(b) of opposite signs (TOMS 748). Used for the cold solves, when
// no neighbouring state gives a good start.
template <class F>
double bracketed_root(F&& f, double a, double b, double fa, double fb, double rel_tol, int max_iterations) {
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  std::uintmax_t iterations = static_cast<std::uintmax_t>(max_iterations);
  const auto tolerance = [rel_tol](double x, double y) {
    return std::fabs(x - y) <= rel_tol * std::min(std::fabs(x), std::fabs(y));
  };
  const auto bracket = boost::math::tools::toms748_solve(f, a, b, fa, fb, tolerance, iterations);
  return 0.5 * (bracket.first + bracket.second);
}

struct Point {
  double x, f;
};

// Secant steps (Dekker 1969) inside the bracket between neg.x (f < 0) and pos.x (f > 0), from the iterates
// `older`, `newer`; bisection when a step leaves the bracket or, after the first two, is not below half the
// step before last. Ends when a proposed step is below rel_tol |x| and returns the last point evaluated: the
// secant converges superlinearly, so that point is within about the step of the root, and its state (the
// costly part) is already known to the caller. `slope` receives the last secant slope, the start of the next,
// neighbouring solve.
template <class F>
double secant_in_bracket(F&& f, Point neg, Point pos, Point older, Point newer, double rel_tol, int& budget,
                         double* slope) {
  double step_old = std::numeric_limits<double>::infinity(), step_older = step_old;
  for (;;) {
    if (newer.f == 0.0) return newer.x;
    (newer.f < 0.0 ? neg : pos) = newer;
    const double lo = std::min(neg.x, pos.x), hi = std::max(neg.x, pos.x);
    const double s = (newer.f - older.f) / (newer.x - older.x);
    const bool secant = std::isfinite(s) && s != 0.0;
    if (secant && slope) *slope = s;
    double next = secant ? newer.x - newer.f / s : 0.5 * (lo + hi);
    if (!(next > lo && next < hi) || std::fabs(next - newer.x) > 0.5 * step_older) next = 0.5 * (lo + hi);
    step_older = step_old;
    step_old = std::fabs(next - newer.x);
    // The last point evaluated is then within about that step of the root (superlinear convergence).
    if (step_old <= rel_tol * std::fabs(next) || hi - lo <= rel_tol * std::fabs(next) || budget <= 0) return newer.x;
    --budget;
    older = newer;
    newer = {next, f(next)};
  }
}

struct RootSearch {
  double x, slope;
  bool bracketed;  // false: no sign change in [lo, hi]; x is the point of smallest |f| seen
};

// Root of f in [lo, hi] near a start point, given an estimate of f' there (from the neighbouring solve):
// a Newton step made 2 % longer so that it usually lands just past the root, then steps along the secant (1.5
// times the predicted distance, at least doubling) while f keeps its sign; the same from the start in the other
// direction if an end is reached first. Once two points bracket a sign change, secant_in_bracket. f at an end
// is evaluated only when the search reaches it, unless known (f_lo, f_hi; NaN when not).
template <class F>
RootSearch root_near(F&& f, Point start, double slope, double lo, double hi, double f_lo, double f_hi, double rel_tol,
                     int max_iterations) {
  const bool newton = std::isfinite(slope) && slope != 0.0;
  // The start is the root when f vanishes there or the Newton step is below tolerance (the secant's own test).
  if (start.f == 0.0 || (newton && std::fabs(start.f / slope) <= rel_tol * std::fabs(start.x))) {
    return {start.x, slope, true};
  }
  int budget = max_iterations;
  Point best = start;
  const double first_dir = !newton || -start.f / slope > 0.0 ? 1.0 : -1.0;
  const double min_step = 2.0 * rel_tol * std::fabs(start.x);
  const double first_step = std::max(newton ? 1.02 * std::fabs(start.f / slope) : 0.01 * (hi - lo), min_step);
  for (const double dir : {first_dir, -first_dir}) {
    const double end = dir > 0.0 ? hi : lo;
    double step = first_step;
    Point a = start;
    while (budget > 0 && a.x != end) {
      --budget;
      const double x = a.x + dir * step;
      const bool at_end = dir > 0.0 ? !(x < end) : !(x > end);
      const double known = dir > 0.0 ? f_hi : f_lo;
      const Point b = at_end ? Point{end, std::isnan(known) ? f(end) : known} : Point{x, f(x)};
      if (std::fabs(b.f) < std::fabs(best.f)) best = b;
      if ((b.f > 0.0) != (a.f > 0.0) || b.f == 0.0) {
        double s = slope;
        const double root = secant_in_bracket(f, b.f < 0.0 ? b : a, b.f < 0.0 ? a : b, a, b, rel_tol, budget, &s);
        return {root, s, true};
      }
      const double ahead = -b.f / ((b.f - a.f) / (b.x - a.x)) * dir;  // predicted distance to the root
      step = std::isfinite(ahead) && ahead > 0.0 ? std::max(1.5 * ahead, 2.0 * min_step) : 2.0 * step;
      a = b;
    }
  }
  return {best.x, slope, false};
}

// ---------------------------------------------------------------------------------------------------------
// Shear plane AB at a given phi: everything that does not depend on C0 or delta.

struct ShearPlane {
  double phi, sin_phi, tan_phi, cos_phi_rake;
  double length;          // l_AB = t1 / sin(phi)                                          (O 1)
  double shear_velocity;  // V_s = V cos(alpha) / cos(phi - alpha)                         (O 1)
  double chip_velocity;   // V_c = V sin(phi) / cos(phi - alpha)                           (O 1)
  double chip_thickness;  // t2 = t1 cos(phi - alpha) / sin(phi)                           (O 1)
  double shear_strain;    // gamma_AB = cos(alpha) / (2 sin(phi) cos(phi - alpha))         (O 2)
  double strain;          // eps_AB = gamma_AB / sqrt 3
  double hardening;       // A + B eps_AB^n
  double n_eq;            // n B eps^n / (A + B eps^n): the local hardening exponent        (O 5)
  double tan_theta_0;     // 1 + pi/2 - 2 phi: tan(theta) at C0 = 0                        (O 5)
};

ShearPlane shear_plane(const Context& c, double phi) {
  ShearPlane s{};
  s.phi = phi;
  s.sin_phi = std::sin(phi);
  s.tan_phi = std::tan(phi);
  s.cos_phi_rake = std::cos(phi - c.rake);
  s.length = c.t1 / s.sin_phi;
  s.shear_velocity = c.speed * c.cos_rake / s.cos_phi_rake;
  s.chip_velocity = c.speed * s.sin_phi / s.cos_phi_rake;
  s.chip_thickness = c.t1 * s.cos_phi_rake / s.sin_phi;
  s.shear_strain = c.cos_rake / (2.0 * s.sin_phi * s.cos_phi_rake);
  s.strain = s.shear_strain / kSqrt3;
  const double b_term = c.jc.B_Pa * std::pow(s.strain, c.jc.n);
  s.hardening = c.jc.A_Pa + b_term;
  s.n_eq = c.jc.n * b_term / s.hardening;
  s.tan_theta_0 = 1.0 + kPi / 2.0 - 2.0 * phi;
  return s;
}

// The C0 interval on which the state is defined: the contact length h = t1 (sin(theta) + C0 n_eq cos(theta)
// / 3) / (cos(lambda) sin(phi)) must be finite and positive, i.e. |lambda| < pi/2 and
// sin(theta) + C0 n_eq cos(theta) / 3 > 0. theta decreases with C0, so each condition bounds C0 on one side.
struct Interval {
  double lo, hi;
  bool empty() const { return !(lo < hi); }
};

Interval admissible_c0(const Context& c, const ShearPlane& s, double c0_min, double c0_max) {
  constexpr double margin = 1e-9;
  double lo = c0_min, hi = c0_max;
  const double n_eq = s.n_eq;
  const double d = s.phi - c.rake;  // lambda = theta - d
  if (n_eq > 0.0) {
    hi = std::min(hi, 1.5 * s.tan_theta_0 / n_eq * (1.0 - margin));  // sin + C0 n cos / 3 > 0
    if (d > 0.0) hi = std::min(hi, (s.tan_theta_0 + 1.0 / std::tan(d)) / n_eq * (1.0 - margin));   // lambda > -pi/2
    if (d < 0.0) lo = std::max(lo, (s.tan_theta_0 - 1.0 / std::tan(-d)) / n_eq * (1.0 + margin));  // lambda < pi/2
  } else {
    // No hardening: theta does not depend on C0; the state is defined for all C0 or for none.
    const double theta = std::atan(s.tan_theta_0);
    if (!(std::sin(theta) > 0.0 && std::cos(theta - d) > 0.0)) return {1.0, 0.0};
  }
  return {lo, hi};
}

// ---------------------------------------------------------------------------------------------------------
// The primary zone at (phi, C0): T_AB, forces, and the two rake-face stresses.

struct Primary {
  double C0;
  double strain_rate;  // epsdot_AB = C0 V_s / (sqrt 3 l_AB)                                 (O 2)
  double rate_factor;
  double T_AB, dT_SZ, beta;
  double T_slope;  // d/dT of T - T_w - eta dT_SZ(T) at T_AB: the start of the neighbouring solve
  bool beta_clamped;
  double k_AB;                              // sigma_JC(eps_AB, epsdot_AB, T_AB) / sqrt 3                         (O 3)
  double F_s;                               // k_AB l_AB w                                                        (O 3)
  double theta, R, lambda, F, N, F_c, F_t;  // (O 5, O 6)
  double sigma_tip;                         // sigma_N' = k_AB (1 + pi/2 - 2 alpha - 2 C0 n_eq)                  (O 7)
  double S;                                 // sin(theta) + C0 n_eq cos(theta) / 3 (> 0 where admissible)
  double h;                                 // contact length                                                     (O 8)
  double tau_int, sigma_N;                  // F / (h w), N / (h w)                                               (O 9)
};

// T_AB = T_w + eta dT_SZ(T_AB) (O 4) with dT_SZ = (1 - beta) F_s V_s / (m_chip c_p), K and c_p at T_AB.
// f(T) = T - T_w - eta dT_SZ(T) has f(T_w) <= 0 < f(T_melt) = T_melt - T_w for every state: the root is
// bracketed in [T_w, T_melt] before anything is evaluated. (Pantalé's plain fixed-point iteration overshoots
// T_melt for strong, poorly conducting materials although the root lies below it, and then gives up.) Started
// from the temperature of the neighbouring state with its slope f'; a cold start takes the fixed-point step.
void shear_zone_temperature(const Context& c, const ShearPlane& s, double k_no_thermal, double T_hint,
                            double slope_hint, Primary& p) {
  // dT_SZ = (1 - beta) k l_AB w V_s / (rho V t1 w c_p) = (1 - beta) k V_s / (rho V c_p sin(phi)).
  const double heat_scale = s.shear_velocity * c.t1 / (c.rho_V_t1 * s.sin_phi);
  const double rt_scale = c.rho_V_t1 * s.tan_phi;  // R_T tan(phi) = rho c_p V t1 tan(phi) / K
  const auto rise = [&](double T, bool* clamped, double* beta) {
    const double cp = c.specific_heat(T);
    const double b = heat_partition(rt_scale * cp / c.conductivity(T), clamped);
    if (beta) *beta = b;
    const double k = k_no_thermal * johnson_cook_thermal_factor(c.jc, c.policy, T, nullptr);
    return (1.0 - b) * k * heat_scale / cp;
  };
  const auto f = [&](double T) { return T - c.T_w - c.eta * rise(T, nullptr, nullptr); };
  const double x0 = std::clamp(T_hint, c.T_w, c.T_melt);
  const RootSearch root = root_near(f, {x0, f(x0)}, slope_hint, c.T_w, c.T_melt, std::nan(""), c.T_melt - c.T_w,
                                    c.temperature_rel_tol, c.max_iterations);
  bool clamped = false;
  double beta = 0.0;
  p.T_AB = root.x;
  p.T_slope = root.slope;
  p.dT_SZ = rise(root.x, &clamped, &beta);
  p.beta = beta;
  p.beta_clamped = clamped;
}

Primary primary_zone(Context& c, const ShearPlane& s, double C0, double T_hint, double T_slope) {
  ++c.n_evaluations;
  Primary p{};
  p.C0 = C0;
  p.strain_rate = C0 * s.shear_velocity / s.length / kSqrt3;
  p.rate_factor = johnson_cook_rate_factor(c.jc, c.policy, p.strain_rate, nullptr);
  const double k_no_thermal = s.hardening * p.rate_factor / kSqrt3;
  shear_zone_temperature(c, s, k_no_thermal, T_hint, T_slope, p);
  p.k_AB = k_no_thermal * johnson_cook_thermal_factor(c.jc, c.policy, p.T_AB, nullptr);
  p.F_s = p.k_AB * s.length * c.width;
  const double tan_theta = s.tan_theta_0 - C0 * s.n_eq;
  p.theta = std::atan(tan_theta);
  p.R = p.F_s / std::cos(p.theta);
  p.lambda = p.theta + c.rake - s.phi;
  p.F = p.R * std::sin(p.lambda);
  p.N = p.R * std::cos(p.lambda);
  p.F_c = p.R * std::cos(p.theta - s.phi);
  p.F_t = p.R * std::sin(p.theta - s.phi);
  p.sigma_tip = p.k_AB * (1.0 + kPi / 2.0 - 2.0 * c.rake - 2.0 * C0 * s.n_eq);
  // h = t1 sin(theta) / (cos(lambda) sin(phi)) [1 + C0 n_eq / (3 tan(theta))] (O 8), written without the
  // 1/tan(theta) pole: h = t1 S / (cos(lambda) sin(phi)), S = sin(theta) + C0 n_eq cos(theta) / 3.
  p.S = std::sin(p.theta) + C0 * s.n_eq * std::cos(p.theta) / 3.0;
  const double cos_lambda = std::cos(p.lambda);
  if (p.S > 0.0 && cos_lambda > 0.0) {
    p.h = c.t1 * p.S / (cos_lambda * s.sin_phi);
    p.tau_int = p.F / (p.h * c.width);
    p.sigma_N = p.N / (p.h * c.width);
  }
  return p;
}

// ---------------------------------------------------------------------------------------------------------
// The tool-chip interface at delta.

struct Interface {
  double shear_strain, strain_rate_shear;  // gamma_int, gammadot_int                                  (O 10)
  double T_c, dT_C, dT_M, T_int;           //                                                          (O 11)
  double k_chip;                           //                                                          (O 12)
};

Interface interface_zone(const Context& c, const ShearPlane& s, const Primary& p, double delta, Guards* guards) {
  Interface q{};
  // gamma_int = 2 gamma_AB + h / (2 delta t2); gammadot_int = V_c / (delta t2)                         (O 10)
  q.shear_strain = 2.0 * s.shear_strain + p.h / (2.0 * delta * s.chip_thickness);
  q.strain_rate_shear = s.chip_velocity / (delta * s.chip_thickness);
  // Mean chip temperature T_c = T_w + dT_SZ + dT_C with dT_C = F V_c / (m_chip c_p(T_c)) (Pantalé's
  // iteration). With c_p linear in T, (T_c - a) c_p(T_c) = b is a quadratic: solved in closed form.
  const double a = c.T_w + p.dT_SZ;
  const double b = std::max(p.F, 0.0) * s.chip_velocity / (c.rho_V_t1 * c.width);
  const auto& cp_law = c.thermal.specific_heat_J_per_kg_K;
  const double cp_a = c.specific_heat(a), slope = cp_law.slope_per_K;
  double x = b / cp_a;
  if (a < c.T_melt && slope != 0.0) {
    const double disc = cp_a * cp_a + 4.0 * slope * b;
    x = disc > 0.0 ? 2.0 * b / (cp_a + std::sqrt(disc)) : x;
    if (!(a + x <= c.T_melt)) x = b / cp_law.at(c.T_melt);  // c_p held constant above T_melt
  }
  q.dT_C = x;
  q.T_c = a + x;
  // dT_M = dT_C 10^(0.06 - 0.195 delta sqrt(R_T t2 / h)) sqrt(R_T t2 / h), K and c_p at T_c            (O 11)
  const double R_T = c.rho_V_t1 * c.specific_heat(q.T_c) / c.conductivity(q.T_c);
  const double root = std::sqrt(R_T * s.chip_thickness / p.h);
  q.dT_M = q.dT_C * std::exp(std::numbers::ln10 * (0.06 - 0.195 * delta * root)) * root;  // 10^(...)
  q.T_int = c.T_w + p.dT_SZ + c.psi * q.dT_M;
  q.k_chip =
      johnson_cook_stress(c.jc, c.policy, q.shear_strain / kSqrt3, q.strain_rate_shear / kSqrt3, q.T_int, guards) /
      kSqrt3;
  return q;
}

// ---------------------------------------------------------------------------------------------------------
// The nested solve.

double relative_gap(double x, double y) {
  const double scale = std::max(std::fabs(x), std::fabs(y));
  return scale > 0.0 ? std::fabs(x - y) / scale : 0.0;
}

// sigma_N = sigma_N' (O 7, O 9) divided by k_AB, which cancels: N / (h w) = k_AB cos^2(lambda) / (cos(theta) S)
// with S = sin(theta) + C0 n_eq cos(theta) / 3, so C0 follows from the geometry of the shear plane alone and
// needs no temperature. Positive when the rake-face normal stress exceeds the tool-tip value.
double normal_stress_residual(const Context& c, const ShearPlane& s, double C0) {
  const double theta = std::atan(s.tan_theta_0 - C0 * s.n_eq);
  const double lambda = theta + c.rake - s.phi;
  const double cos_theta = std::cos(theta), cos_lambda = std::cos(lambda);
  const double S = std::sin(theta) + C0 * s.n_eq * cos_theta / 3.0;
  return cos_lambda * cos_lambda / (cos_theta * S) - (1.0 + kPi / 2.0 - 2.0 * c.rake - 2.0 * C0 * s.n_eq);
}

struct Solution {  // a shear angle with its C0 and primary-zone state: none of it depends on delta
  ShearPlane plane;
  Primary primary;
  double c0_slope = 0.0;  // d/dC0 of the normal-stress residual at the root: the start of the neighbouring solve
  double c0_miss = 0.0;   // |normal-stress residual| at C0 when c0_bracketed is false (how far from a solution)
  bool c0_bracketed = true, admissible = true;
};

class Solver {
 public:
  Solver(Context& c, const OxleySolverOptions& o) : c_(c), o_(o) {
    phi_hi_ = std::min(o.phi_max_rad, c.rake + kPi / 2.0 - 1e-6);  // cos(phi - alpha) > 0
    if (!(phi_hi_ > o.phi_min_rad)) {
      throw ModelError("oxley", fmt::format("rake angle {:.6g} deg leaves no shear angle in [{:.6g}, {:.6g}] deg "
                                            "with cos(phi - rake) > 0",
                                            units::rad_to_deg(c.rake), units::rad_to_deg(o.phi_min_rad),
                                            units::rad_to_deg(o.phi_max_rad)));
    }
    states_.reserve(64);
    order_.reserve(64);
  }

  const Solution& state(std::size_t index) const { return states_[index]; }
  /// Full solutions (phi and C0 bracketed) the cold bracket search found at the first delta: the branches.
  int full_roots() const { return full_roots_; }

  // The state at phi (memoised): C0 from sigma_N = sigma_N' by a bracketed root on the admissible part of
  // [c0_min, c0_max] (without a sign change: the end of smaller residual, c0_bracketed = false), then T_AB and
  // the forces. C0 and T_AB start from the neighbouring states in phi, interpolated, with their slopes.
  std::size_t at_phi(double phi) {
    const auto pos = std::lower_bound(order_.begin(), order_.end(), phi, by_phi);
    if (pos != order_.end() && pos->phi == phi) return pos->index;
    Solution sol;
    sol.plane = shear_plane(c_, phi);
    const Interval range = admissible_c0(c_, sol.plane, o_.c0_min, o_.c0_max);
    if (range.empty()) {
      sol.admissible = sol.c0_bracketed = false;
    } else {
      const Neighbours nb = neighbours(pos, phi);
      const auto r = [&](double C0) { return normal_stress_residual(c_, sol.plane, C0); };
      double C0 = 0.0;
      if (nb.near) {
        const double start =
            std::clamp(nb.interpolate([](const Solution& x) { return x.primary.C0; }), range.lo, range.hi);
        const RootSearch root = root_near(r, {start, r(start)}, nb.near->c0_slope, range.lo, range.hi, std::nan(""),
                                          std::nan(""), c_.rel_tol, c_.max_iterations);
        C0 = root.x;
        sol.c0_slope = root.slope;
        sol.c0_bracketed = root.bracketed;
      } else {
        const double r_lo = r(range.lo), r_hi = r(range.hi);
        if ((r_lo > 0.0) == (r_hi > 0.0) && r_lo != 0.0 && r_hi != 0.0) {
          sol.c0_bracketed = false;
          C0 = std::fabs(r_lo) <= std::fabs(r_hi) ? range.lo : range.hi;
        } else {
          C0 = bracketed_root(r, range.lo, range.hi, r_lo, r_hi, c_.rel_tol, c_.max_iterations);
        }
        // Slope for the neighbouring solves: a difference that stays inside the admissible range.
        const double h = C0 + 1e-6 * C0 < range.hi ? 1e-6 * C0 : -1e-6 * C0;
        sol.c0_slope = (r(C0 + h) - r(C0)) / h;
      }
      if (!sol.c0_bracketed) sol.c0_miss = std::fabs(r(C0));
      const double T_hint = nb.near ? nb.interpolate([](const Solution& x) { return x.primary.T_AB; }) : c_.T_w;
      sol.primary = primary_zone(c_, sol.plane, C0, T_hint, nb.near ? nb.near->primary.T_slope : 1.0);
    }
    states_.push_back(sol);
    order_.insert(pos, Key{phi, states_.size() - 1});
    return states_.size() - 1;
  }

  // tau_int - k_chip (O 9, O 12), scaled; a phi without admissible state counts as "too large" (negative).
  double shear_residual(std::size_t index, double delta) const {
    const Solution& sol = states_[index];
    if (!sol.admissible) return -1.0;
    const Interface q = interface_zone(c_, sol.plane, sol.primary, delta, nullptr);
    return (sol.primary.tau_int - q.k_chip) / (std::fabs(sol.primary.tau_int) + q.k_chip + 1.0);
  }

  struct Root {
    std::size_t index;
    bool bracketed;
  };

  // phi from tau_int = k_chip at this delta (memoised): a bracketed root in [phi_min, phi_max]; the point of
  // smallest residual (bracketed = false) when the range holds no sign change. The states do not depend on
  // delta, so after the first delta the search starts from the previous root with its slope.
  Root at_delta(double delta) {
    for (const auto& [d, root] : roots_) {
      if (d == delta) return root;
    }
    const auto g = [&](double phi) { return shear_residual(at_phi(phi), delta); };
    Root root{};
    if (!previous_) {
      // Cold: g can change sign more than once in [phi_min, phi_max] (a low shear-angle branch of high F_c
      // appears at large delta, and near c0_min the root can lie where C0 has left its range). A bracket
      // search (options.phi_scan_points) shows the sign changes; each is refined by TOMS 748, and the root that
      // is a full solution (C0 bracketed too) of lowest F_c is kept: the minimum-force state, the criterion of
      // the model itself (Lalwani's grid takes the lowest F_c among its near-solutions too). Later deltas
      // follow that branch. The scanned states are reused as starting points.
      const int n_scan = o_.phi_scan_points;
      scan_index_.resize(static_cast<std::size_t>(n_scan));
      scan_g_.resize(static_cast<std::size_t>(n_scan));
      auto& index = scan_index_;
      auto& g_scan = scan_g_;
      for (int i = 0; i < n_scan; ++i) {
        const double phi = o_.phi_min_rad + (phi_hi_ - o_.phi_min_rad) * i / (n_scan - 1.0);
        index[i] = at_phi(i == n_scan - 1 ? phi_hi_ : phi);
        g_scan[i] = shear_residual(index[i], delta);
      }
      // Refine every sign change; keep the root of a full solution (C0 bracketed there too) of lowest F_c.
      double best_score = std::numeric_limits<double>::infinity();
      for (int i = 0; i + 1 < n_scan; ++i) {
        if ((g_scan[i] > 0.0) == (g_scan[i + 1] > 0.0) && g_scan[i] != 0.0 && g_scan[i + 1] != 0.0) continue;
        const double a = state(index[i]).plane.phi, b = state(index[i + 1]).plane.phi;
        const std::size_t at = at_phi(bracketed_root(g, a, b, g_scan[i], g_scan[i + 1], c_.rel_tol, c_.max_iterations));
        const Solution& sol = state(at);
        const double score = (sol.admissible && sol.c0_bracketed ? 0.0 : 1e300) + sol.primary.F_c;
        if (sol.admissible && sol.c0_bracketed) ++full_roots_;
        if (score < best_score) {
          best_score = score;
          root = {at, true};
          // The slope for the next delta, from the nearer end of the bracket.
          const double phi = sol.plane.phi;
          const std::size_t other = phi - a < b - phi ? index[i] : index[i + 1];
          phi_slope_ = (g(phi) - shear_residual(other, delta)) / (phi - state(other).plane.phi);
        }
      }
      if (!std::isfinite(best_score)) {
        const auto smallest = std::min_element(g_scan.begin(), g_scan.end(),
                                               [](double x, double y) { return std::fabs(x) < std::fabs(y); });
        root = {index[static_cast<std::size_t>(smallest - g_scan.begin())], false};
      }
    } else {
      const double phi = state(*previous_).plane.phi;
      const RootSearch search = root_near(g, {phi, shear_residual(*previous_, delta)}, phi_slope_, o_.phi_min_rad,
                                          phi_hi_, std::nan(""), std::nan(""), c_.rel_tol, c_.max_iterations);
      root = {at_phi(search.x), search.bracketed};
      if (search.bracketed) phi_slope_ = search.slope;
    }
    roots_.emplace_back(delta, root);
    if (root.bracketed) previous_ = root.index;
    return root;
  }

 private:
  struct Key {
    double phi;
    std::size_t index;
  };
  static bool by_phi(const Key& k, double x) { return k.phi < x; }

  // The admissible states on either side of phi: starting values for a new state there.
  struct Neighbours {
    const Solution *below = nullptr, *above = nullptr, *near = nullptr;
    double phi = 0.0;
    template <class Get>
    double interpolate(Get get) const {
      if (!below || !above) return get(*near);
      const double t = (phi - below->plane.phi) / (above->plane.phi - below->plane.phi);
      return get(*below) + t * (get(*above) - get(*below));
    }
  };

  Neighbours neighbours(std::vector<Key>::const_iterator pos, double phi) const {
    Neighbours nb;
    nb.phi = phi;
    for (auto it = pos; it != order_.begin();) {
      --it;
      if (states_[it->index].c0_bracketed) {
        nb.below = &states_[it->index];
        break;
      }
    }
    for (auto it = pos; it != order_.end(); ++it) {
      if (states_[it->index].c0_bracketed) {
        nb.above = &states_[it->index];
        break;
      }
    }
    if (nb.below && nb.above) {
      nb.near = phi - nb.below->plane.phi <= nb.above->plane.phi - phi ? nb.below : nb.above;
    } else {
      nb.near = nb.below ? nb.below : nb.above;
    }
    return nb;
  }

  Context& c_;
  const OxleySolverOptions& o_;
  double phi_hi_;
  std::vector<Solution> states_;  // every state evaluated in this solve
  std::vector<Key> order_;        // states_ sorted by phi
  std::vector<std::pair<double, Root>> roots_;
  std::optional<std::size_t> previous_;
  double phi_slope_ = std::numeric_limits<double>::quiet_NaN();
  int full_roots_ = 0;
  std::vector<std::size_t> scan_index_;  // the cold bracket search
  std::vector<double> scan_g_;
};

// Fills every output field from a state; `guards` collects what the final state triggers.
OxleyResult make_result(Context& c, const ShearPlane& s, const Primary& p, double delta, Guards guards) {
  OxleyResult r;
  const Interface q = interface_zone(c, s, p, delta, &guards);
  // Re-evaluate the Johnson-Cook factors at AB with guards (the solve ran without).
  const double sigma_AB = johnson_cook_stress(c.jc, c.policy, s.strain, p.strain_rate, p.T_AB, &guards);
  if (p.beta_clamped) guards.raise(Guard::heat_partition_clamped);
  r.shear_angle_rad = s.phi;
  r.strain_rate_constant_C0 = p.C0;
  r.delta = delta;
  r.cutting_force_N = p.F_c;
  r.thrust_force_N = p.F_t;
  r.chip_thickness_m = s.chip_thickness;
  r.contact_length_m = p.h;
  r.shear_force_N = p.F_s;
  r.resultant_force_N = p.R;
  r.friction_force_N = p.F;
  r.normal_force_N = p.N;
  r.theta_rad = p.theta;
  r.friction_angle_rad = p.lambda;
  r.shear_plane_strain = s.strain;
  r.shear_plane_strain_rate_per_s = p.strain_rate;
  r.shear_plane_temperature_K = p.T_AB;
  r.shear_plane_flow_stress_Pa = sigma_AB;
  r.shear_plane_shear_stress_Pa = p.k_AB;
  r.heat_partition = p.beta;
  r.strain_hardening_index = s.n_eq;
  r.tool_tip_normal_stress_Pa = p.sigma_tip;
  r.interface_strain = q.shear_strain / kSqrt3;
  r.interface_strain_rate_per_s = q.strain_rate_shear / kSqrt3;
  r.interface_temperature_K = q.T_int;
  r.chip_temperature_K = q.T_c;
  r.interface_shear_stress_Pa = p.tau_int;
  r.interface_normal_stress_Pa = p.sigma_N;
  r.chip_shear_flow_stress_Pa = q.k_chip;
  r.residual_shear = relative_gap(p.tau_int, q.k_chip);
  r.residual_normal = relative_gap(p.sigma_N, p.sigma_tip);
  r.guards = guards;
  r.n_function_evaluations = c.n_evaluations;
  return r;
}

}  // namespace

// -------------------------------------------------------------------------------------------------------------

void OxleyParams::validate(const std::string& path) const {
  johnson_cook.validate(path + ".johnson_cook");
  thermal.validate(path + ".thermal", johnson_cook.room_temperature_K, johnson_cook.melting_temperature_K);
  check_number(eta, path + ".eta", Range{0.0, 1.0, true, false}, "");
  check_number(psi, path + ".psi", Range{0.0, 1.0, true, false}, "");
}

void OxleyCut::validate(const std::string& path) const {
  check_number(rake_rad, path + ".rake_rad", Range::open(-kPi / 2.0, kPi / 2.0), "rad");
  check_number(uncut_chip_thickness_m, path + ".uncut_chip_thickness_m", Range::positive(), "m");
  check_number(width_m, path + ".width_m", Range::positive(), "m");
  check_number(speed_m_per_s, path + ".speed_m_per_s", Range::positive(), "m/s");
  check_number(workpiece_temperature_K, path + ".workpiece_temperature_K", Range::positive(), "K");
}

void OxleySolverOptions::validate(const std::string& path) const {
  check_number(phi_min_rad, path + ".phi_min_rad", Range{0.0, kMaxShearAngle, true, true}, "rad");
  check_number(phi_max_rad, path + ".phi_max_rad", Range{phi_min_rad, kMaxShearAngle, true, false},
               "rad (above phi_min_rad, at most pi/3)");
  check_number(c0_min, path + ".c0_min", Range::positive(), "");
  check_number(c0_max, path + ".c0_max", Range::above(c0_min), "(above c0_min)");
  check_number(delta_min, path + ".delta_min", Range::open(0.0, 1.0), "");
  check_number(delta_max, path + ".delta_max", Range{delta_min, 1.0, true, false}, "(above delta_min)");
  check_number(tolerance, path + ".tolerance", Range::closed(1e-15, 1e-2), "");
  check_number(max_iterations, path + ".max_iterations", Range::closed(1.0, 100000.0), "");
  check_number(phi_scan_points, path + ".phi_scan_points", Range::closed(2.0, 1000.0), "");
  check_number(delta_scan_points, path + ".delta_scan_points", Range::closed(2.0, 1000.0), "");
}

OxleyResult solve_oxley(const OxleyParams& params, const OxleyCut& cut, const OxleySolverOptions& options) {
  validate_all(params, cut, &options);
  Context c = make_context(params, cut, options);
  Solver solver(c, options);
  Guards guards;

  // delta minimises F_c (Oxley's criterion): Brent on [delta_min, delta_max], each evaluation solving phi (and
  // C0 inside) for that delta. Brent stops at sqrt(tolerance) in delta: F_c is stationary there, so F_c and phi
  // are still found to about `tolerance`. A delta whose phi or C0 could not be bracketed scores far above any
  // solution (a force scale 1000 times the largest plausible F_c), plus the residuals it misses by, so that
  // Brent is led towards the deltas that have a solution and a true solution wins wherever the range holds
  // one; Lalwani's and Pantalé's searches would pick the clamped state.
  const double force_scale =
      1e3 * (params.johnson_cook.A_Pa + params.johnson_cook.B_Pa) * cut.uncut_chip_thickness_m * cut.width_m;
  const auto objective = [&](double delta) {
    const Solver::Root root = solver.at_delta(delta);
    const Solution& sol = solver.state(root.index);
    if (root.bracketed && sol.c0_bracketed) return sol.primary.F_c;
    const double miss = sol.admissible ? std::fabs(solver.shear_residual(root.index, delta)) + sol.c0_miss : 10.0;
    return sol.primary.F_c + force_scale * (1.0 + miss);
  };
  // Bracket the minimum first (as mnbrak before brent): options.delta_scan_points deltas, log-spaced from
  // delta_max down to delta_min; Brent then searches between the neighbours of the best of them. F_c(delta)
  // can have more than one local minimum (the phi root switches branch), and a solution can exist in part of
  // the range only.
  const int n_scan = options.delta_scan_points;
  std::vector<double> deltas(static_cast<std::size_t>(n_scan)), scores(static_cast<std::size_t>(n_scan));
  int best = 0;
  for (int k = 0; k < n_scan; ++k) {
    const int i = n_scan - 1 - k;  // from delta_max down
    deltas[i] = i == 0 ? options.delta_min
                : i == n_scan - 1
                    ? options.delta_max
                    : options.delta_min * std::pow(options.delta_max / options.delta_min, i / (n_scan - 1.0));
    scores[i] = objective(deltas[i]);
  }
  for (int i = 1; i < n_scan; ++i) {
    if (scores[i] < scores[best]) best = i;
  }
  const double lo = deltas[std::max(best - 1, 0)], hi = deltas[std::min(best + 1, n_scan - 1)];
  const int bits = std::clamp(static_cast<int>(std::ceil(1.0 - 0.5 * std::log2(options.tolerance))), 8,
                              std::numeric_limits<double>::digits / 2);
  std::uintmax_t iterations = static_cast<std::uintmax_t>(options.max_iterations);
  double delta = boost::math::tools::brent_find_minima(objective, lo, hi, bits, iterations).first;
  // Brent never evaluates the ends of its interval; a scanned delta that scores no worse wins (exactly).
  for (const double end : {lo, hi}) {
    if (objective(end) <= objective(delta)) delta = end;
  }
  if (delta == options.delta_min || delta == options.delta_max) guards.raise(Guard::solver_at_bound);

  const Solver::Root root = solver.at_delta(delta);
  const Solution& sol = solver.state(root.index);
  if (!sol.admissible) {
    throw ModelError("oxley", "no admissible state (finite, positive contact length) in the search range");
  }
  if (!sol.c0_bracketed || !root.bracketed) guards.raise(Guard::solver_at_bound);
  OxleyResult r = make_result(c, sol.plane, sol.primary, delta, guards);
  r.converged = sol.c0_bracketed && root.bracketed;
  r.shear_angle_roots = solver.full_roots();
  r.delta_at_bound = delta == options.delta_min || delta == options.delta_max;
  r.shear_angle_at_bound =
      std::fabs(r.shear_angle_rad - options.phi_min_rad) <= 1e-9 ||
      std::fabs(r.shear_angle_rad - std::min(options.phi_max_rad, cut.rake_rad + kPi / 2.0)) <= 1e-6;
  return r;
}

OxleyResult evaluate_oxley(const OxleyParams& params, const OxleyCut& cut, double shear_angle_rad,
                           double strain_rate_constant_C0, double delta) {
  validate_all(params, cut, nullptr);
  check_number(shear_angle_rad, "shear_angle_rad", Range{0.0, kMaxShearAngle, true, false}, "rad");
  check_number(strain_rate_constant_C0, "strain_rate_constant_C0", Range::positive(), "");
  check_number(delta, "delta", Range{0.0, 1.0, true, false}, "");
  const OxleySolverOptions options;
  Context c = make_context(params, cut, options);
  const ShearPlane s = shear_plane(c, shear_angle_rad);
  if (!(s.cos_phi_rake > 0.0)) {
    throw InputError("shear_angle_rad", format_value(shear_angle_rad), "cos(phi - rake) > 0");
  }
  const Primary p = primary_zone(c, s, strain_rate_constant_C0, c.T_w, 1.0);
  if (!(p.h > 0.0)) {
    throw InputError("strain_rate_constant_C0", format_value(strain_rate_constant_C0),
                     "a value where the contact length is finite and positive at this shear angle");
  }
  return make_result(c, s, p, delta, Guards{});
}

}  // namespace kerf
