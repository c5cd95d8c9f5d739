#include "kerf/analytic/trepanning/trepanning.hpp"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {
constexpr double kPi = std::numbers::pi;

// The regressors: F_n = axial_regressor * K_F and M = torque_regressor * K_M (SI; Eqs. 21-22 with Eq. 7).
double axial_regressor(const TrepanningTool& tool, const TrepanningCut& cut) {
  return kPi / 8.0 * cut.feed_per_rev_m() * (tool.outer_diameter_m - tool.inner_diameter_m);
}
double torque_regressor(const TrepanningTool& tool, const TrepanningCut& cut) {
  const double D = tool.outer_diameter_m, d = tool.inner_diameter_m;
  return cut.feed_per_rev_m() * (D * D - d * d) / 16.0;
}
}  // namespace

void TrepanningTool::validate(const std::string& path) const {
  check_number(units::m_to_mm(outer_diameter_m), path + ".outer_diameter_mm", Range::positive(), "mm");
  check_number(units::m_to_mm(inner_diameter_m), path + ".inner_diameter_mm",
               Range{0.0, units::m_to_mm(outer_diameter_m), false, true},
               "mm (at least 0 and below the outer diameter)");
}

TrepanningCut TrepanningCut::from_user_units(double feed_rate_um_per_s, double spindle_speed_rpm) {
  return {units::um_to_m(feed_rate_um_per_s), units::rpm_to_rev_per_s(spindle_speed_rpm)};
}

void TrepanningCut::validate(const std::string& path) const {
  check_number(units::m_to_um(feed_rate_m_per_s), path + ".feed_rate_um_per_s", Range::positive(), "um/s");
  check_number(spindle_speed_rev_per_s * 60.0, path + ".spindle_speed_rpm", Range::positive(), "rev/min");
}

void TrepanningMaterial::validate(const std::string& path) const {
  check_number(units::pa_to_gpa(hardness_Pa), path + ".hardness_GPa", Range::positive(), "GPa");
  check_number(units::rad_to_deg(half_angle_rad), path + ".half_angle_deg", Range::open(0.0, 90.0), "deg");
  check_number(friction_coefficient, path + ".friction_coefficient", Range::non_negative(), "");
}

TrepanningGroups TrepanningGroups::from_material(const TrepanningMaterial& m) {
  m.validate("material");
  const double tan_phi = std::tan(m.half_angle_rad);
  return {m.hardness_Pa * tan_phi, m.hardness_Pa * (1.0 + kPi * tan_phi * m.friction_coefficient / 2.0)};
}

void TrepanningGroups::validate(const std::string& path) const {
  check_number(units::pa_to_mpa(axial_group_Pa), path + ".axial_group_MPa", Range::positive(), "MPa");
  check_number(units::pa_to_mpa(torque_group_Pa), path + ".torque_group_MPa", Range::positive(), "MPa");
}

ImpliedTrepanningMaterial implied_trepanning_material(const TrepanningGroups& groups, double hardness_Pa) {
  groups.validate("groups");
  check_number(units::pa_to_gpa(hardness_Pa), "hardness_GPa", Range::positive(), "GPa");
  ImpliedTrepanningMaterial m;
  m.hardness_Pa = hardness_Pa;
  const double tan_phi = groups.axial_group_Pa / hardness_Pa;  // K_F = H tan(phi)
  m.half_angle_rad = std::atan(tan_phi);
  m.friction_coefficient = 2.0 * (groups.torque_group_Pa - hardness_Pa) / (kPi * groups.axial_group_Pa);  // K_M
  m.physical = m.friction_coefficient >= 0.0;
  m.max_hardness_for_non_negative_friction_Pa = groups.torque_group_Pa;
  return m;
}

void check_feed_plausible(const TrepanningTool& tool, const TrepanningCut& cut) {
  // Plausibility: the abrasive face cannot advance by more than its own wall width (D - d) / 2 per turn; the
  // model's grits would then cut far deeper than any grit protrudes (docs/models.md, plausibility guards). The cut's
  // own keys are named (TrepanningCut::validate's); the scene adds its section.
  const double wall_m = 0.5 * (tool.outer_diameter_m - tool.inner_diameter_m);
  if (!std::isfinite(cut.feed_per_rev_m())) {  // a spindle speed so small that feed / speed overflows
    throw InputError("spindle_speed_rpm", format_value(cut.spindle_speed_rev_per_s * 60.0),
                     fmt::format("a spindle speed at which the feed per revolution is finite: at a feed of {} um/s "
                                 "it must be at least {:.6g} rpm for a feed per revolution below the cutter's wall "
                                 "width (D - d)/2 = {:.6g} um",
                                 format_value(units::m_to_um(cut.feed_rate_m_per_s)),
                                 60.0 * cut.feed_rate_m_per_s / wall_m, units::m_to_um(wall_m)));
  }
  if (cut.feed_per_rev_m() > wall_m) {
    throw InputError(
        "feed_rate_um_per_s", format_value(units::m_to_um(cut.feed_rate_m_per_s)),
        fmt::format("a feed per revolution below the cutter's wall width (D - d)/2 = {:.6g} um; it gives "
                    "{:.6g} um/rev at {:.6g} rpm",
                    units::m_to_um(wall_m), units::m_to_um(cut.feed_per_rev_m()), cut.spindle_speed_rev_per_s * 60.0));
  }
}

TrepanningForces trepanning_forces(const TrepanningTool& tool, const TrepanningCut& cut,
                                   const TrepanningGroups& groups) {
  tool.validate("tool");
  cut.validate("cut");
  groups.validate("groups");
  const TrepanningForces forces{axial_regressor(tool, cut) * groups.axial_group_Pa,
                                torque_regressor(tool, cut) * groups.torque_group_Pa, cut.feed_per_rev_m()};
  // A product beyond a double (a feed of 1e308 um/s, a speed of 1e-320 rpm) is refused, not written as inf.
  for (const auto& [name, value] : {std::pair<const char*, double>{"axial_force_N", forces.axial_force_N},
                                    {"torque_N_m", forces.torque_N_m},
                                    {"feed_per_rev_um", forces.feed_per_rev_m}}) {
    if (!std::isfinite(value) || (value == 0.0 && cut.feed_rate_m_per_s > 0.0)) {
      throw ModelError("trepanning", fmt::format("{} is {} for a feed rate of {} um/s at {} rpm: the inputs lie "
                                                 "beyond what a double holds",
                                                 name, value, format_value(units::m_to_um(cut.feed_rate_m_per_s)),
                                                 format_value(cut.spindle_speed_rev_per_s * 60.0)));
    }
  }
  return forces;
}

TrepanningForces trepanning_forces(const TrepanningTool& tool, const TrepanningCut& cut,
                                   const TrepanningMaterial& material) {
  return trepanning_forces(tool, cut, TrepanningGroups::from_material(material));
}

void TrepanningGritParams::validate(const std::string& path) const {
  check_number(grit_density_per_m2 * 1e-6, path + ".grit_density_per_mm2", Range::positive(), "1/mm^2");
  check_number(shape_coefficient, path + ".shape_coefficient", Range{0.0, 1.0, true, false}, "");
  check_number(units::m_to_um(grit_width_m), path + ".grit_width_um", Range::positive(), "um");
}

TrepanningGritDiagnostics trepanning_grit_diagnostics(const TrepanningTool& tool, const TrepanningCut& cut,
                                                      const TrepanningGroups& groups,
                                                      const TrepanningGritParams& grits) {
  tool.validate("tool");
  cut.validate("cut");
  groups.validate("groups");
  grits.validate("grits");
  const double D = tool.outer_diameter_m, d = tool.inner_diameter_m;
  const double a = grits.grit_width_m, C = grits.grit_density_per_m2, G = grits.shape_coefficient;
  TrepanningGritDiagnostics out;
  out.face_area_m2 = kPi / 4.0 * (D * D - d * d) * G;              // Eq. 4
  out.grit_count = out.face_area_m2 * C;                           // Eq. 2
  out.grits_per_edge_set = (D - d) / (2.0 * a);                    // Eq. 3
  out.cutting_edges = out.grit_count / out.grits_per_edge_set;     // Eq. 1 (= pi a (D + d) C G / 2, Eq. 5)
  out.feed_per_edge_m = cut.feed_per_rev_m() / out.cutting_edges;  // Eqs. 6-8
  out.grit_depth_m = out.feed_per_edge_m;                          // Eq. 14
  const double g = out.grit_depth_m;
  out.implied_half_angle_rad = std::atan(a / (2.0 * g));  // Eq. 13: a = 2 g tan(phi)
  // Eq. 11 with tan(phi) = a / (2 g): F_an1 = (pi/2) g^2 tan^2(phi) H = (pi/4) g a (H tan(phi)); F_an2 = 0 (Eq. 17).
  out.grit_normal_force_N = kPi / 4.0 * g * a * groups.axial_group_Pa;
  // Eqs. 12, 18, 20: F_at = g^2 tan(phi) H (1 + pi tan(phi) mu / 2) = (1/2) g a K_M.
  out.grit_tangential_force_N = 0.5 * g * a * groups.torque_group_Pa;
  return out;
}

// ---- Calibration -------------------------------------------------------------------------------------

std::string_view residual_weighting_name(ResidualWeighting weighting) {
  return weighting == ResidualWeighting::relative ? "relative" : "absolute";
}

namespace {

struct GslMatrixDeleter {
  void operator()(gsl_matrix* m) const { gsl_matrix_free(m); }
};
struct GslVectorDeleter {
  void operator()(gsl_vector* v) const { gsl_vector_free(v); }
};
struct GslWorkspaceDeleter {
  void operator()(gsl_multifit_linear_workspace* w) const { gsl_multifit_linear_free(w); }
};

struct LineFit {
  double slope = 0.0;
  double standard_error = 0.0;
};

/// Weighted least squares y ~ k x through the origin (one column), solved by gsl_multifit_wlinear.
LineFit fit_through_origin(const std::vector<double>& x, const std::vector<double>& y, ResidualWeighting weighting) {
  // GSL's default error handler aborts; read the status instead (as analytic/forces/quadrature.cpp does).
  static const bool handler_off = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  (void)handler_off;
  const std::size_t n = x.size();
  std::unique_ptr<gsl_matrix, GslMatrixDeleter> X(gsl_matrix_alloc(n, 1));
  std::unique_ptr<gsl_vector, GslVectorDeleter> w(gsl_vector_alloc(n)), yv(gsl_vector_alloc(n)), c(gsl_vector_alloc(1));
  std::unique_ptr<gsl_matrix, GslMatrixDeleter> cov(gsl_matrix_alloc(1, 1));
  std::unique_ptr<gsl_multifit_linear_workspace, GslWorkspaceDeleter> work(gsl_multifit_linear_alloc(n, 1));
  for (std::size_t i = 0; i < n; ++i) {
    gsl_matrix_set(X.get(), i, 0, x[i]);
    gsl_vector_set(yv.get(), i, y[i]);
    gsl_vector_set(w.get(), i, weighting == ResidualWeighting::relative ? 1.0 / (y[i] * y[i]) : 1.0);
  }
  double chisq = 0.0;
  if (gsl_multifit_wlinear(X.get(), w.get(), yv.get(), c.get(), cov.get(), &chisq, work.get()) != GSL_SUCCESS) {
    throw ModelError("trepanning", "gsl_multifit_wlinear failed");
  }
  LineFit fit;
  fit.slope = gsl_vector_get(c.get(), 0);
  // GSL's covariance assumes the weights are 1 / sigma^2; scale it by the residual variance (n - 1 dof).
  const double dof = static_cast<double>(n) - 1.0;
  fit.standard_error = dof > 0.0 ? std::sqrt(gsl_matrix_get(cov.get(), 0, 0) * chisq / dof) : 0.0;
  return fit;
}

GroupFit fit_group(const std::vector<double>& x, const std::vector<double>& y, ResidualWeighting weighting) {
  GroupFit out;
  const LineFit all = fit_through_origin(x, y, weighting);
  out.value_Pa = all.slope;
  out.standard_error_Pa = all.standard_error;
  const std::size_t n = x.size();
  for (std::size_t i = 0; i < n; ++i) {
    out.predicted.push_back(all.slope * x[i]);
    out.error_percent.push_back(relative_error_percent(out.predicted.back(), y[i]));
  }
  out.fit = metrics_of_errors(out.error_percent);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double> xs, ys;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      xs.push_back(x[j]);
      ys.push_back(y[j]);
    }
    const double k = fit_through_origin(xs, ys, weighting).slope;
    out.loo_value_Pa.push_back(k);
    out.loo_predicted.push_back(k * x[i]);
    out.loo_error_percent.push_back(relative_error_percent(out.loo_predicted.back(), y[i]));
  }
  out.loo = metrics_of_errors(out.loo_error_percent);
  return out;
}

}  // namespace

TrepanningCalibration calibrate_trepanning(const TrepanningTool& tool, std::span<const TrepanningObservation> rows,
                                           ResidualWeighting weighting) {
  tool.validate("tool");
  if (rows.size() < 2) {
    throw InputError("observations", fmt::format("{} rows", rows.size()),
                     "at least 2 measured rows (leave-one-out needs one left to fit)");
  }
  std::vector<double> x_axial, x_torque, y_axial, y_torque;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string path = fmt::format("observations[{}]", i);
    rows[i].cut.validate(path);
    check_number(rows[i].axial_force_N, path + ".axial_force_N", Range::positive(), "N");
    check_number(rows[i].torque_N_m, path + ".torque_N_m", Range::positive(), "N m");
    x_axial.push_back(axial_regressor(tool, rows[i].cut));
    x_torque.push_back(torque_regressor(tool, rows[i].cut));
    y_axial.push_back(rows[i].axial_force_N);
    y_torque.push_back(rows[i].torque_N_m);
  }
  TrepanningCalibration out;
  out.weighting = weighting;
  out.axial = fit_group(x_axial, y_axial, weighting);
  out.torque = fit_group(x_torque, y_torque, weighting);
  out.groups = {out.axial.value_Pa, out.torque.value_Pa};
  return out;
}

}  // namespace kerf
