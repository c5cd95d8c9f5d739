#pragma once
// Agreement metrics between predictions and measurements, in percent of the measurement.
//
// The per-row error is e_i = (predicted_i - measured_i) / measured_i (the sign convention of Yu et al. 2023's
// Table 4: positive when the model over-predicts). Over n rows:
//   mean |error| = sum |e_i| / n,  max |error| = max |e_i|,  bias = sum e_i / n,  rms = sqrt(sum e_i^2 / n).
//
//   std::vector<double> predicted{110, 90}, measured{100, 100};
//   kerf::ErrorMetrics m = kerf::error_metrics(predicted, measured);  // mean 10 %, max 10 %, bias 0 %
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace kerf {

struct ErrorMetrics {
  std::size_t n = 0;
  double mean_abs_error_percent = 0.0;
  double max_abs_error_percent = 0.0;
  double bias_percent = 0.0;  ///< mean signed error: > 0 when the model over-predicts on average
  double rms_error_percent = 0.0;
};

/// (predicted - measured) / measured in percent. Throws InputError when `measured` is zero or either is not
/// finite (`field` names what is compared).
double relative_error_percent(double predicted, double measured, const std::string& field = "measured");

/// Metrics over paired values. Throws InputError when the sizes differ or the input is empty.
ErrorMetrics error_metrics(std::span<const double> predicted, std::span<const double> measured);

/// Metrics of per-row errors already in percent.
ErrorMetrics metrics_of_errors(std::span<const double> errors_percent);

/// Sample mean and standard deviation (n - 1 in the denominator; NaN standard deviation for n < 2).
struct SampleStatistics {
  std::size_t n = 0;
  double mean = 0.0;
  double standard_deviation = 0.0;
};
SampleStatistics sample_statistics(std::span<const double> values);

}  // namespace kerf
