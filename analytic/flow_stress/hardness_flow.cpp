#include "kerf/analytic/flow_stress/hardness_flow.hpp"

#include <fmt/format.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>

#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/units.hpp"

namespace kerf {

namespace {
double johnson_tan_beta() {
  return std::tan(units::deg_to_rad(kVickersConeInclinationDeg));
}

/// The modulus of each form: E for Marsh, E* = E / (1 - nu^2) for Johnson's cavity.
double form_modulus_Pa(ConstraintModel model, double youngs_modulus_Pa, double poissons_ratio) {
  return model == ConstraintModel::johnson_cavity ? youngs_modulus_Pa / (1.0 - poissons_ratio * poissons_ratio)
                                                  : youngs_modulus_Pa;
}

/// ln(M / Y) where the form's constraint factor is 1 (Y = H): (1 - B) / K for Marsh; ln(3 e^0.5 / tan(beta)) for
/// Johnson. Both lie above the maximum of Y C(M / Y) (at 1 - B/K and ln(3 / tan(beta))), on the branch where H
/// rises with Y.
double log_ratio_at_unit_constraint(ConstraintModel model) {
  return model == ConstraintModel::marsh ? (1.0 - kMarshB) / kMarshK : 0.5 + std::log(3.0 / johnson_tan_beta());
}
}  // namespace

std::string_view constraint_model_name(ConstraintModel model) {
  switch (model) {
    case ConstraintModel::given:
      return "hardness";
    case ConstraintModel::marsh:
      return "hardness_marsh";
    case ConstraintModel::johnson_cavity:
      return "hardness_johnson";
  }
  return "hardness";
}

double constraint_factor(ConstraintModel model, double modulus_over_yield, double) {
  switch (model) {
    case ConstraintModel::marsh:
      return kMarshB + kMarshK * std::log(modulus_over_yield);
    case ConstraintModel::johnson_cavity:
      return 2.0 / 3.0 * (1.0 + std::log(modulus_over_yield * johnson_tan_beta() / 3.0));
    case ConstraintModel::given:
      break;
  }
  throw std::logic_error("constraint_factor: the given form has no modulus dependence");
}

double largest_hardness_over_modulus(ConstraintModel model, double poissons_ratio) {
  if (model == ConstraintModel::given) return std::numeric_limits<double>::infinity();
  const double x = std::exp(log_ratio_at_unit_constraint(model));  // M / Y where H = Y
  return form_modulus_Pa(model, 1.0, poissons_ratio) / x;
}

void HardnessFlowParams::validate(const std::string& path, ConstraintModel model) const {
  check_number(units::pa_to_gpa(youngs_modulus_Pa), path + ".elastic.youngs_modulus_GPa", Range::positive(), "GPa");
  check_number(poissons_ratio, path + ".elastic.poissons_ratio", Range{0.0, 0.5, false, true}, "(-)");
  check_number(units::pa_to_gpa(hardness_Pa), path + ".brittle.hardness_GPa",
               Range::open(0.0, units::pa_to_gpa(youngs_modulus_Pa)), "GPa (below Young's modulus)");
  if (model == ConstraintModel::given) {
    if (!constraint_factor) {
      throw InputError(path + ".brittle.constraint_factor", "(missing)",
                       "a number >= 1 (H / Y; glasses 1.5-2, Marsh 1964): models.flow_stress = hardness needs it "
                       "(or use hardness_marsh or hardness_johnson, which compute it from E / Y)");
    }
    check_number(*constraint_factor, path + ".brittle.constraint_factor", Range::at_least(1.0), "(H / Y)");
    return;
  }
  const double largest = largest_hardness_over_modulus(model, poissons_ratio);
  if (hardness_Pa / youngs_modulus_Pa > largest) {
    throw InputError(path + ".brittle.hardness_GPa", fmt::format("{:g}", units::pa_to_gpa(hardness_Pa)),
                     fmt::format("H / E at most {:.4g} for models.flow_stress = {} (beyond it the form gives a "
                                 "constraint factor below 1, a yield stress above the hardness); here H / E = {:.4g}: "
                                 "use models.flow_stress = hardness with a measured brittle.constraint_factor",
                                 largest, constraint_model_name(model), hardness_Pa / youngs_modulus_Pa));
  }
}

double hardness_yield_stress_Pa(const HardnessFlowParams& p, ConstraintModel model) {
  p.validate("material", model);
  if (model == ConstraintModel::given) return p.hardness_Pa / *p.constraint_factor;
  // Solve H / M = C(x) / x for u = ln(M / Y) where C >= 1 (beyond the maximum of Y C: Y below H).
  const double modulus = form_modulus_Pa(model, p.youngs_modulus_Pa, p.poissons_ratio);
  const double target = p.hardness_Pa / modulus;
  const auto residual = [&](double u) {
    const double x = std::exp(u);
    return constraint_factor(model, x, p.poissons_ratio) / x - target;
  };
  double lo = log_ratio_at_unit_constraint(model), hi = lo + 1.0;
  while (residual(hi) > 0.0) hi += 1.0;  // C(x) / x falls to 0 as x grows: ends within ln(1 / target) + a few
  if (residual(lo) <= 0.0) return modulus / std::exp(lo);  // H / E at the limit itself: Y = H
  const auto tolerance = [](double a, double b) { return std::fabs(b - a) < 1e-14 * std::max(1.0, std::fabs(a)); };
  const auto [a, b] = boost::math::tools::bisect(residual, lo, hi, tolerance);
  return modulus / std::exp(0.5 * (a + b));
}

}  // namespace kerf
