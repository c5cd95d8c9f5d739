#pragma once
// Extended Oxley machining theory with a Johnson-Cook material: orthogonal cutting with a sharp tool.
//
// From the material and the cut it predicts the shear angle, the cutting and thrust forces, the chip
// thickness and tool-chip contact length, and the strain, strain rate and temperature in the primary shear
// zone (AB) and along the tool-chip interface. Equations: Oxley, "The Mechanics of Machining" (1989), with
// the Johnson-Cook flow stress of Lalwani, Mehta & Jain, J. Mater. Process. Technol. 209 (2009) 5305; the
// conventions (where K and c_p are evaluated, what is iterated) follow Pantalé, Dawoua Kaoutoing & Houé
// Ngouna, Appl. Mech. 3 (2022) 889 and its companion program (github.com/pantale/OxleyPython). See
// docs/physics-analytic.md section 3 and the comments in analytic/forces/oxley.cpp for the equation list.
//
// Three unknowns: shear angle phi, strain-rate constant C0 and secondary-zone thickness ratio delta. For a
// given delta, C0 makes the normal stress at the tool tip from the shear-plane analysis equal to the mean
// rake-face normal stress (sigma_N' = sigma_N, bracketed root in C0 for each phi), phi makes the interface
// shear stress equal to the chip's shear flow stress (tau_int = k_chip, bracketed root in phi), and delta
// minimises the cutting force (Brent). Every root is kept inside a sign change; where a condition has more
// than one root, short bracket searches (options.phi_scan_points, delta_scan_points) pick the solution of
// lowest F_c, the model's own criterion. Typically 40-70 shear-zone evaluations and ~50 us per solve.
//
//   kerf::OxleyParams steel;   // AISI 1045 (Jaspers & Dautzenberg 2002)
//   steel.johnson_cook = {.A_Pa = 553.1e6, .B_Pa = 600.8e6, .n = 0.234, .C = 0.0134, .m = 1.0,
//                         .reference_strain_rate_per_s = 1.0, .room_temperature_K = 298.15,
//                         .melting_temperature_K = 1733.15};
//   steel.thermal = {.density_kg_per_m3 = 8000.0,
//                    .conductivity_W_per_m_K = {52.61, -0.0281, 273.15},
//                    .specific_heat_J_per_kg_K = {420.0, 0.504, 273.15}};
//   steel.validate("material");
//   const kerf::OxleyCut cut{.rake_rad = kerf::units::deg_to_rad(-7.0), .uncut_chip_thickness_m = 0.15e-3,
//                            .width_m = 1.6e-3, .speed_m_per_s = 200.0 / 60.0,
//                            .workpiece_temperature_K = 298.15};
//   const kerf::OxleyResult r = kerf::solve_oxley(steel, cut);
//   // r.cutting_force_N ~ 575 N, r.thrust_force_N ~ 352 N, r.shear_angle_rad ~ 18.9 deg;
//   // check r.converged and r.guards (heat_partition_clamped, solver_at_bound, Johnson-Cook guards).
#include <string>

#include "kerf/analytic/flow_stress/johnson_cook.hpp"
#include "kerf/analytic/flow_stress/thermal.hpp"
#include "kerf/analytic/guards.hpp"

namespace kerf {

/// The work material. Validated by validate(path); solve_oxley validates again under the path "params".
struct OxleyParams {
  JohnsonCookParams johnson_cook;
  JohnsonCookPolicy policy;
  ThermalProperties thermal;  ///< density, K(T), c_p(T); held at their T_melt values above T_melt
  double eta = 0.9;           ///< Oxley's eta: T_AB = T_w + eta dT_SZ (the mean shear-plane temperature)
  double psi = 0.9;           ///< Oxley's psi: T_int = T_w + dT_SZ + psi dT_M (mean over the contact)

  /// Throws InputError naming `path`.<field>: Johnson-Cook and thermal properties as their own validate()
  /// (K and c_p positive from T_room to T_melt), eta and psi in (0, 1].
  void validate(const std::string& path) const;
};

/// One orthogonal cut, SI units.
struct OxleyCut {
  double rake_rad = 0.0;                ///< tool rake angle alpha
  double uncut_chip_thickness_m = 0.0;  ///< t1
  double width_m = 0.0;                 ///< w (forces are for this width)
  double speed_m_per_s = 0.0;           ///< cutting speed V
  double workpiece_temperature_K = 293.15;

  /// Throws InputError naming `path`.<field>: rake in (-pi/2, pi/2), t1 > 0, w > 0, V > 0, T > 0.
  void validate(const std::string& path) const;
};

/// Search ranges and tolerances: the fidelity knobs (their cost is measured in bench/analytic_oxley.cpp).
struct OxleySolverOptions {
  /// 5..45 deg: the range of Lalwani's own search (Pantalé used 8..45). Solutions below 8 deg exist, e.g.
  /// phi = 6.1 deg for AISI 1045 at t1 = 1 um, V = 20 m/s, rake -7 deg; the wider range costs about one step.
  double phi_min_rad = 5.0 * 0.017453292519943295;
  double phi_max_rad = 45.0 * 0.017453292519943295;
  double c0_min = 2.0, c0_max = 10.0;
  double delta_min = 0.005, delta_max = 0.2;
  /// Relative tolerance of the root finds in phi and C0 (and 1e-2 of it for T_AB). The delta search stops
  /// at sqrt(tolerance): F_c is stationary in delta, so F_c, F_t, phi and C0 still come out to about
  /// `tolerance` while delta and the interface strain, rate and temperature are known to ~sqrt(tolerance).
  double tolerance = 1e-8;
  int max_iterations = 200;  ///< cap of each root find and of the delta search (no solve can hang)
  /// Bracket search before the first phi root: tau_int - k_chip can change sign more than once in the phi
  /// range (another branch of higher F_c); this many equally spaced phi see the sign changes, and the root of
  /// lowest F_c is followed. Roots closer together than the spacing can be missed. 2: the range ends only.
  int phi_scan_points = 9;
  /// Bracket search before Brent in delta: this many log-spaced deltas; Brent runs between the neighbours of
  /// the best. Finds a solution that exists in part of the delta range only. 2: Brent on the whole range.
  int delta_scan_points = 7;

  /// Throws InputError naming `path`.<field>: 0 < phi_min < phi_max <= 60 deg, 0 < c0_min < c0_max,
  /// 0 < delta_min < delta_max <= 1, tolerance in [1e-15, 1e-2], max_iterations in [1, 100000], scan points
  /// in [2, 1000].
  void validate(const std::string& path) const;
};

struct OxleyResult {
  // Unknowns.
  double shear_angle_rad = 0.0;          ///< phi
  double strain_rate_constant_C0 = 0.0;  ///< C0
  double delta = 0.0;                    ///< secondary-zone thickness / chip thickness
  // Forces (for width_m) and geometry.
  double cutting_force_N = 0.0;     ///< F_c = R cos(theta - phi)
  double thrust_force_N = 0.0;      ///< F_t = R sin(theta - phi)
  double chip_thickness_m = 0.0;    ///< t2 = t1 cos(phi - alpha) / sin(phi)
  double contact_length_m = 0.0;    ///< h, tool-chip contact length
  double shear_force_N = 0.0;       ///< F_s = k_AB l_AB w
  double resultant_force_N = 0.0;   ///< R = F_s / cos(theta)
  double friction_force_N = 0.0;    ///< F = R sin(lambda), along the rake face
  double normal_force_N = 0.0;      ///< N = R cos(lambda), normal to the rake face
  double theta_rad = 0.0;           ///< angle between R and the shear plane
  double friction_angle_rad = 0.0;  ///< lambda = theta + alpha - phi
  // Primary shear zone AB (equivalent strain and rate = shear value / sqrt 3).
  double shear_plane_strain = 0.0;
  double shear_plane_strain_rate_per_s = 0.0;
  double shear_plane_temperature_K = 0.0;    ///< T_AB
  double shear_plane_flow_stress_Pa = 0.0;   ///< Johnson-Cook sigma at AB
  double shear_plane_shear_stress_Pa = 0.0;  ///< k_AB = sigma / sqrt 3
  double heat_partition = 0.0;               ///< beta_h, fraction of shear-zone heat into the work
  double strain_hardening_index = 0.0;       ///< n_eq = n B eps^n / (A + B eps^n)
  double tool_tip_normal_stress_Pa = 0.0;    ///< sigma_N' = k_AB (1 + pi/2 - 2 alpha - 2 C0 n_eq)
  // Tool-chip interface.
  double interface_strain = 0.0;
  double interface_strain_rate_per_s = 0.0;
  double interface_temperature_K = 0.0;     ///< T_int
  double chip_temperature_K = 0.0;          ///< T_c = T_w + dT_SZ + dT_C, mean chip temperature
  double interface_shear_stress_Pa = 0.0;   ///< tau_int = F / (h w)
  double interface_normal_stress_Pa = 0.0;  ///< sigma_N = N / (h w)
  double chip_shear_flow_stress_Pa = 0.0;   ///< k_chip = sigma_JC(interface) / sqrt 3
  // Solver report.
  double residual_shear = 0.0;     ///< |tau_int - k_chip| / max(|tau_int|, |k_chip|)
  double residual_normal = 0.0;    ///< |sigma_N - sigma_N'| / max(|sigma_N|, |sigma_N'|)
  bool converged = false;          ///< both conditions solved by a bracketed root (never true for evaluate_oxley)
  int n_function_evaluations = 0;  ///< evaluations of the shear-zone state (each solves its own T_AB)
  /// Branches: full solutions (both conditions bracketed) the cold phi search found at the first delta; the
  /// minimum-force one is followed. 0 when none was found there.
  int shear_angle_roots = 0;
  bool delta_at_bound = false;        ///< delta on an end of [delta_min, delta_max]: F_c's minimum lies outside
  bool shear_angle_at_bound = false;  ///< phi on an end of its search range
  Guards guards;
};

/// Solves the three unknowns and returns the state at the solution. Validates its arguments (InputError,
/// under the paths "params", "cut", "options"; a workpiece at or above T_melt is an InputError too).
/// Without a solution in the search ranges (typical of slow, thin cuts: the chip stays too cold for
/// tau_int = k_chip at any phi) it returns the state nearest to one: the end of the bracket with the smaller
/// residual, Guard::solver_at_bound, converged = false, and the residuals say by how much the conditions are
/// missed. A delta at the end of its range also raises the guard (converged stays true). Throws ModelError
/// only when no shear angle in the range has an admissible state (cos(phi - rake) > 0 and a finite, positive
/// contact length). Never returns NaN; every loop is bounded by options.max_iterations.
OxleyResult solve_oxley(const OxleyParams& params, const OxleyCut& cut, const OxleySolverOptions& options = {});

/// The state of the equation set at given unknowns (no solve): residuals say how far it is from a solution.
/// For tests, sensitivity studies and checking published solutions. Validates like solve_oxley.
OxleyResult evaluate_oxley(const OxleyParams& params, const OxleyCut& cut, double shear_angle_rad,
                           double strain_rate_constant_C0, double delta);

}  // namespace kerf
