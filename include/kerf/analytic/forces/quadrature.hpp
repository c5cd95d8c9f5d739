#pragma once
// One-dimensional quadrature for the analytic models, from Boost.Math and GSL (not written again here).
// The rule and tolerance are fidelity knobs; bench/analytic_liu_li.cpp measures their cost and error.
//
//   kerf::QuadratureSettings q{.rule = kerf::QuadratureRule::gauss_kronrod, .relative_tolerance = 1e-8};
//   auto r = kerf::integrate([](double x) { return x * x; }, 0.0, 1.0, q);   // r.value = 1/3
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace kerf {

enum class QuadratureRule {
  gauss_kronrod,   ///< Boost adaptive Gauss-Kronrod 7/15 (default)
  tanh_sinh,       ///< Boost tanh-sinh (double exponential): robust at endpoint singularities
  gsl_qag,         ///< GSL QAG with the 21-point Gauss-Kronrod rule
  gauss_legendre,  ///< Boost fixed 30-point Gauss-Legendre, not adaptive (tolerance ignored)
};

std::string_view quadrature_rule_name(QuadratureRule rule);
/// The rule a scene name constructs; nullopt for an unknown name.
std::optional<QuadratureRule> quadrature_rule_from_name(std::string_view name);
/// Scene names of the rules.
const std::vector<std::string>& quadrature_rule_names();

struct QuadratureSettings {
  QuadratureRule rule = QuadratureRule::gauss_kronrod;
  double relative_tolerance = 1e-8;
  int max_depth = 15;  ///< adaptive bisection depth (Boost) or 2^max_depth intervals (GSL)
};

struct QuadratureResult {
  double value = 0.0;
  double error_estimate = 0.0;  ///< the rule's own estimate (indicative only); 0 for the fixed rule
};

using Integrand = std::function<double(double)>;

/// Integral of f over [a, b] (a <= b). Boost's rules never throw for finite integrands (a poorly converged
/// result carries a large error_estimate); GSL QAG reports its status, and a failure throws kerf::ModelError.
QuadratureResult integrate(const Integrand& f, double a, double b, const QuadratureSettings& settings);

/// Two integrands that share their expensive parts (the Liu-Li cutting and thrust integrands share the local
/// shear angle): one pass over the nodes evaluates both. Error control uses max(|first|, |second|), so the
/// tolerance is relative to the larger of the two integrals.
struct ValuePair {
  double first = 0.0, second = 0.0;

  ValuePair() = default;
  ValuePair(double a, double b) : first(a), second(b) {}
  ValuePair(double a) : first(a), second(a) {}  // NOLINT: implicit, as Boost writes K x = 0
  ValuePair& operator+=(const ValuePair& o) {
    first += o.first;
    second += o.second;
    return *this;
  }
  friend ValuePair operator+(ValuePair a, const ValuePair& b) { return a += b; }
  friend ValuePair operator-(const ValuePair& a, const ValuePair& b) {
    return {a.first - b.first, a.second - b.second};
  }
  friend ValuePair operator-(const ValuePair& a) { return {-a.first, -a.second}; }
  friend ValuePair operator*(const ValuePair& a, double k) { return {a.first * k, a.second * k}; }
  friend ValuePair operator*(double k, const ValuePair& a) { return a * k; }
  friend double abs(const ValuePair& a);  ///< max(|first|, |second|): the norm of the error control
};

struct QuadraturePairResult {
  ValuePair value;
  double error_estimate = 0.0;
};

using PairIntegrand = std::function<ValuePair(double)>;

/// Both integrals of f over [a, b] in one pass (Gauss-Kronrod) or one rule call each (the other rules).
QuadraturePairResult integrate_pair(const PairIntegrand& f, double a, double b, const QuadratureSettings& settings);

}  // namespace kerf
