#include "kerf/metrics.hpp"

#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "kerf/error.hpp"

namespace kerf {

double relative_error_percent(double predicted, double measured, const std::string& field) {
  if (!std::isfinite(measured) || measured == 0.0) {
    throw InputError(field, format_value(measured), "a finite, non-zero measurement (errors are relative to it)");
  }
  if (!std::isfinite(predicted)) throw InputError(field + " (prediction)", format_value(predicted), "a finite number");
  return 100.0 * (predicted - measured) / measured;
}

ErrorMetrics metrics_of_errors(std::span<const double> errors_percent) {
  if (errors_percent.empty()) throw InputError("errors", "(none)", "at least one compared row");
  ErrorMetrics m;
  m.n = errors_percent.size();
  double sum_abs = 0.0, sum = 0.0, sum_sq = 0.0;
  for (double e : errors_percent) {
    sum_abs += std::abs(e);
    sum += e;
    sum_sq += e * e;
    m.max_abs_error_percent = std::max(m.max_abs_error_percent, std::abs(e));
  }
  const double n = static_cast<double>(m.n);
  m.mean_abs_error_percent = sum_abs / n;
  m.bias_percent = sum / n;
  m.rms_error_percent = std::sqrt(sum_sq / n);
  return m;
}

ErrorMetrics error_metrics(std::span<const double> predicted, std::span<const double> measured) {
  if (predicted.size() != measured.size()) {
    throw InputError("predicted", std::to_string(predicted.size()) + " values",
                     std::to_string(measured.size()) + " values, one per measurement");
  }
  std::vector<double> errors(predicted.size());
  for (std::size_t i = 0; i < predicted.size(); ++i) errors[i] = relative_error_percent(predicted[i], measured[i]);
  return metrics_of_errors(errors);
}

SampleStatistics sample_statistics(std::span<const double> values) {
  SampleStatistics s;
  s.n = values.size();
  if (values.empty()) {
    s.mean = s.standard_deviation = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  s.mean = gsl_stats_mean(values.data(), 1, values.size());
  s.standard_deviation = values.size() < 2 ? std::numeric_limits<double>::quiet_NaN()
                                           : gsl_stats_sd_m(values.data(), 1, values.size(), s.mean);
  return s;
}

}  // namespace kerf
