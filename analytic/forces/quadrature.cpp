#include "kerf/analytic/forces/quadrature.hpp"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <memory>
#include <optional>

#include "kerf/error.hpp"

namespace kerf {

namespace {
// Each scene name with the rule it constructs: the order of the lines changes nothing.
struct RuleName {
  std::string_view name;
  QuadratureRule rule;
};
constexpr RuleName kRuleNames[] = {{"gauss_kronrod", QuadratureRule::gauss_kronrod},
                                   {"tanh_sinh", QuadratureRule::tanh_sinh},
                                   {"gsl_qag", QuadratureRule::gsl_qag},
                                   {"gauss_legendre", QuadratureRule::gauss_legendre}};
}  // namespace

std::string_view quadrature_rule_name(QuadratureRule rule) {
  for (const auto& entry : kRuleNames)
    if (entry.rule == rule) return entry.name;
  return "";
}

std::optional<QuadratureRule> quadrature_rule_from_name(std::string_view name) {
  for (const auto& entry : kRuleNames)
    if (entry.name == name) return entry.rule;
  return std::nullopt;
}

const std::vector<std::string>& quadrature_rule_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& entry : kRuleNames) out.emplace_back(entry.name);
    return out;
  }();
  return names;
}

namespace {

QuadratureResult integrate_gsl(const Integrand& f, double a, double b, const QuadratureSettings& settings) {
  // GSL reports failures through a process-wide handler that aborts by default; turn it off once and
  // read the status instead.
  static const bool handler_off = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  (void)handler_off;
  const std::size_t limit = std::size_t{1} << std::min(settings.max_depth, 12);
  struct Workspace {
    std::size_t size;
    std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> ptr;
  };
  thread_local Workspace workspace{0, {nullptr, &gsl_integration_workspace_free}};
  if (workspace.size < limit)
    workspace = {limit, {gsl_integration_workspace_alloc(limit), &gsl_integration_workspace_free}};
  gsl_function function;
  function.function = [](double x, void* params) { return (*static_cast<const Integrand*>(params))(x); };
  function.params = const_cast<Integrand*>(&f);
  QuadratureResult out;
  const int status = gsl_integration_qag(&function, a, b, 0.0, settings.relative_tolerance, limit, GSL_INTEG_GAUSS21,
                                         workspace.ptr.get(), &out.value, &out.error_estimate);
  if (status != GSL_SUCCESS) {
    // The tolerance was not reached (subdivision limit, roundoff, a bad integrand): the value is not trusted.
    throw ModelError("quadrature", fmt::format("GSL QAG on [{:.6g}, {:.6g}] failed: {} (status {}, value {:.6g}, error "
                                               "estimate {:.3g}); loosen models.quadrature.tolerance or use another "
                                               "rule",
                                               a, b, gsl_strerror(status), status, out.value, out.error_estimate));
  }
  return out;
}

}  // namespace

QuadratureResult integrate(const Integrand& f, double a, double b, const QuadratureSettings& settings) {
  QuadratureResult out;
  if (!(b > a)) return out;
  switch (settings.rule) {
    case QuadratureRule::gauss_kronrod:
      out.value = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
          f, a, b, static_cast<unsigned>(settings.max_depth), settings.relative_tolerance, &out.error_estimate);
      break;
    case QuadratureRule::tanh_sinh: {
      thread_local boost::math::quadrature::tanh_sinh<double> integrator(
          static_cast<std::size_t>(std::max(settings.max_depth, 4)));
      out.value = integrator.integrate(f, a, b, settings.relative_tolerance, &out.error_estimate);
      break;
    }
    case QuadratureRule::gsl_qag:
      return integrate_gsl(f, a, b, settings);
    case QuadratureRule::gauss_legendre:
      out.value = boost::math::quadrature::gauss<double, 30>::integrate(f, a, b);
      break;
  }
  return out;
}

double abs(const ValuePair& a) {
  return std::max(std::abs(a.first), std::abs(a.second));
}

QuadraturePairResult integrate_pair(const PairIntegrand& f, double a, double b, const QuadratureSettings& settings) {
  QuadraturePairResult out;
  if (!(b > a)) return out;
  if (settings.rule == QuadratureRule::gauss_kronrod) {
    out.value = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
        f, a, b, static_cast<unsigned>(settings.max_depth), settings.relative_tolerance, &out.error_estimate);
    return out;
  }
  const auto first = integrate([&](double x) { return f(x).first; }, a, b, settings);
  const auto second = integrate([&](double x) { return f(x).second; }, a, b, settings);
  out.value = {first.value, second.value};
  out.error_estimate = first.error_estimate + second.error_estimate;
  return out;
}

}  // namespace kerf
