#pragma once
// Brittle-regime axial force and torque of a fixed-abrasive diamond trepanning drill (Yu, Li, Zou &
// Liang 2023, Micromachines 14, 1270, Eqs. 1-22; notes in docs/physics-analytic.md §5).
//
// Diamond grits on the annular end face (outer diameter D, inner d) indent the work like small cones of half
// angle phi; material of hardness H is removed by brittle fracture. Summed over all N_c = S C grits (Eq. 2),
// in the paper's units (v_f mm/s, n_0 rev/min, D and d mm, H in N/mm^2, F_n in N, M in N mm):
//
//   F_n = 15 pi v_f tan(phi) (D - d) H / (2 n_0)                            (Eq. 21)
//   M   = 15 v_f (D^2 - d^2) H (1 + pi tan(phi) mu / 2) / (4 n_0)            (Eq. 22)
//
// With the feed per revolution f = v_f / n (n in rev/s; Eq. 7: f = 60 v_f / n_0) this is, in SI,
//
//   F_n = (pi / 8) f (D - d) K_F,        K_F = H tan(phi)                    (axial group)
//   M   = (1 / 16) f (D^2 - d^2) K_M,    K_M = H (1 + pi tan(phi) mu / 2)    (torque group)
//
// Grit density C and tool-shape coefficient G cancel, so only the two lumped groups K_F and K_M matter; they
// are what calibrate_trepanning() fits. The per-grit quantities (Eqs. 1-20) are diagnostics that need C, G and
// the grit's cutting width a (or its half angle).
//
//   kerf::TrepanningTool tool{.outer_diameter_m = 0.132, .inner_diameter_m = 0.124};
//   kerf::TrepanningCut cut = kerf::TrepanningCut::from_user_units(20.0, 90.5);   // um/s, rev/min
//   kerf::TrepanningGroups k{.axial_group_Pa = 10.5e9, .torque_group_Pa = 6.26e9};
//   kerf::TrepanningForces f = kerf::trepanning_forces(tool, cut, k);             // f.axial_force_N ~ 440
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kerf/metrics.hpp"

namespace kerf {

/// The cutter's annular end face. Scene keys tool.outer_diameter_mm, tool.inner_diameter_mm.
struct TrepanningTool {
  double outer_diameter_m = 0.0;  ///< D
  double inner_diameter_m = 0.0;  ///< d, 0 <= d < D (d = 0: a solid core drill)

  /// InputError naming path.outer_diameter_mm or path.inner_diameter_mm (d >= D is an error).
  void validate(const std::string& path) const;
  double mean_radius_m() const { return (outer_diameter_m + inner_diameter_m) / 4.0; }  ///< r of Eq. 22
};

namespace units {
constexpr double rpm_to_rev_per_s(double rpm) {
  return rpm / 60.0;
}
constexpr double rev_per_s_to_rpm(double rev_per_s) {
  return rev_per_s * 60.0;
}
}  // namespace units

/// Feed rate and spindle speed. Scene keys cut.feed_rate_um_per_s, cut.spindle_speed_rpm.
struct TrepanningCut {
  double feed_rate_m_per_s = 0.0;        ///< v_f > 0
  double spindle_speed_rev_per_s = 0.0;  ///< n_0 / 60 > 0

  /// From the units of the experiments: feed rate in um/s and spindle speed in rev/min (not validated).
  static TrepanningCut from_user_units(double feed_rate_um_per_s, double spindle_speed_rpm);
  /// InputError naming path.feed_rate_um_per_s or path.spindle_speed_rpm.
  void validate(const std::string& path) const;
  /// f = v_f / n, Eq. 7 (m per revolution).
  double feed_per_rev_m() const { return feed_rate_m_per_s / spindle_speed_rev_per_s; }
};

/// Material and abrasive parameters of Eqs. 21-22: hardness H, grit half angle phi, friction coefficient mu.
struct TrepanningMaterial {
  double hardness_Pa = 0.0;           ///< H > 0
  double half_angle_rad = 0.0;        ///< phi in (0, pi/2)
  double friction_coefficient = 0.0;  ///< mu >= 0

  void validate(const std::string& path) const;  ///< names path.hardness_GPa, .half_angle_deg, .friction_coefficient
};

/// The two lumped groups, all that Eqs. 21-22 depend on besides geometry and kinematics.
struct TrepanningGroups {
  double axial_group_Pa = 0.0;   ///< K_F = H tan(phi) > 0
  double torque_group_Pa = 0.0;  ///< K_M = H (1 + pi tan(phi) mu / 2) > 0

  /// K_F and K_M of a material (validated).
  static TrepanningGroups from_material(const TrepanningMaterial& material);
  /// Names path.axial_group_MPa, path.torque_group_MPa.
  void validate(const std::string& path) const;
};

/// What the groups imply for a given hardness H: tan(phi) = K_F / H, mu = 2 (K_M - H) / (pi K_F).
/// mu < 0 means the groups cannot come from that hardness with non-negative friction (H would have to be
/// at most K_M); it is reported, not clamped.
struct ImpliedTrepanningMaterial {
  double hardness_Pa = 0.0;
  double half_angle_rad = 0.0;
  double friction_coefficient = 0.0;
  bool physical = false;                                   ///< mu >= 0
  double max_hardness_for_non_negative_friction_Pa = 0.0;  ///< = K_M
};
ImpliedTrepanningMaterial implied_trepanning_material(const TrepanningGroups& groups, double hardness_Pa);

struct TrepanningForces {
  double axial_force_N = 0.0;   ///< F_n, Eq. 21
  double torque_N_m = 0.0;      ///< M, Eq. 22
  double feed_per_rev_m = 0.0;  ///< f, Eq. 7
};

/// Plausibility guard: throws InputError on the cut's own key (feed_rate_um_per_s; spindle_speed_rpm where the feed
/// per revolution overflows) when the feed per revolution exceeds the cutter's wall width (D - d) / 2. A trepanning
/// scene applies it when read, adding its section (`cut.`).
void check_feed_plausible(const TrepanningTool& tool, const TrepanningCut& cut);

/// Eqs. 21-22 from the lumped groups. Inputs are validated (InputError names tool.*, cut.*, groups.*).
TrepanningForces trepanning_forces(const TrepanningTool& tool, const TrepanningCut& cut,
                                   const TrepanningGroups& groups);
/// Eqs. 21-22 from H, phi and mu.
TrepanningForces trepanning_forces(const TrepanningTool& tool, const TrepanningCut& cut,
                                   const TrepanningMaterial& material);

/// The per-grit picture of Eqs. 1-20 (diagnostics; the totals do not depend on C or G).
struct TrepanningGritParams {
  double grit_density_per_m2 = 0.0;  ///< C > 0 (the paper's 1/mm^2 times 1e6)
  double shape_coefficient = 1.0;    ///< G in (0, 1]: the fraction of the end face that carries grits
  double grit_width_m = 0.0;         ///< a > 0: cutting width of one grit (Eqs. 3, 13)

  void validate(
      const std::string& path) const;  ///< names path.grit_density_per_mm2, .shape_coefficient, .grit_width_um
};

struct TrepanningGritDiagnostics {
  double face_area_m2 = 0.0;            ///< S = pi (D^2 - d^2) G / 4, Eq. 4
  double grit_count = 0.0;              ///< N_c = S C, Eq. 2
  double grits_per_edge_set = 0.0;      ///< N_0 = (D - d) / (2 a), Eq. 3
  double cutting_edges = 0.0;           ///< Z = N_c / N_0 = pi a (D + d) C G / 2, Eqs. 1, 5
  double feed_per_edge_m = 0.0;         ///< a_f = f / Z, Eqs. 6, 8
  double grit_depth_m = 0.0;            ///< g = a_f, Eq. 14
  double implied_half_angle_rad = 0.0;  ///< phi from a = 2 g tan(phi), Eq. 13
  double grit_normal_force_N = 0.0;  ///< F_an = F_an1 = (pi/2) g^2 tan^2(phi) H = (pi/4) g a K_F, Eqs. 11, 15, 17, 19
  double grit_tangential_force_N =
      0.0;  ///< F_at = F_at1 + F_at2 = g^2 tan(phi) K_M = (1/2) g a K_M, Eqs. 12, 16, 18, 20
};

/// Eqs. 1-20 for one cut. Consistency (tested): N_c F_an = F_n and N_c F_at r = M with r = (D + d) / 4.
/// Note that a, C and G with Eq. 13 fix phi: the implied half angle is reported so that a caller can compare
/// it with the one in the groups. Per-grit forces need only the lumped groups.
TrepanningGritDiagnostics trepanning_grit_diagnostics(const TrepanningTool& tool, const TrepanningCut& cut,
                                                      const TrepanningGroups& groups,
                                                      const TrepanningGritParams& grits);

// ---- Calibration -------------------------------------------------------------------------------------

/// One measured row: conditions and the two measured responses (SI).
struct TrepanningObservation {
  TrepanningCut cut;
  double axial_force_N = 0.0;
  double torque_N_m = 0.0;
};

/// How residuals are weighted in the least-squares fit.
///  relative: minimise sum ((model - y) / y)^2, i.e. weights 1 / y^2 (kerf's default). The acceptance metric
///            is a relative error, the measured forces span a factor of two, and a force sensor's scatter
///            grows with the load; an absolute fit would let the largest forces dominate.
///  absolute: minimise sum (model - y)^2 (ordinary least squares).
enum class ResidualWeighting { relative, absolute };
std::string_view residual_weighting_name(ResidualWeighting weighting);

/// The fit of one lumped group to one measured quantity (axial force or torque).
struct GroupFit {
  double value_Pa = 0.0;              ///< the fitted group
  double standard_error_Pa = 0.0;     ///< from the weighted residuals (GSL covariance scaled by chi^2 / (n - 1))
  std::vector<double> predicted;      ///< model at each row with the fitted group (N or N m)
  std::vector<double> error_percent;  ///< (predicted - measured) / measured
  ErrorMetrics fit;                   ///< metrics of error_percent
  // Leave-one-out cross-validation: each row predicted by the group fitted to the other n - 1 rows.
  std::vector<double> loo_value_Pa;
  std::vector<double> loo_predicted;
  std::vector<double> loo_error_percent;
  ErrorMetrics loo;
};

struct TrepanningCalibration {
  TrepanningGroups groups;
  ResidualWeighting weighting = ResidualWeighting::relative;
  GroupFit axial;   ///< K_F from the axial forces
  GroupFit torque;  ///< K_M from the torques
};

/// Least-squares fit of K_F to the axial forces and of K_M to the torques, each a straight line through the
/// origin in its regressor (the model is linear in each group: F_n = x_F K_F, M = x_M K_M), solved with GSL's
/// gsl_multifit_wlinear. Needs at least 2 rows (leave-one-out needs n - 1 >= 1); throws InputError naming
/// observations[i].* for a non-positive measurement or invalid conditions.
TrepanningCalibration calibrate_trepanning(const TrepanningTool& tool, std::span<const TrepanningObservation> rows,
                                           ResidualWeighting weighting = ResidualWeighting::relative);

}  // namespace kerf
