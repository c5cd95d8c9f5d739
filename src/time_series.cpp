// Batch means with the batch length from the autocorrelation (kerf/time_series.hpp).
#include "kerf/time_series.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace kerf {

double statistical_inefficiency(std::span<const double> x, bool* converged) {
  const std::size_t n = x.size();
  if (converged) *converged = true;
  if (n < 2) return 1.0;
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(n);
  double c0 = 0;
  for (double v : x) c0 += (v - mean) * (v - mean);
  c0 /= static_cast<double>(n);
  if (!(c0 > 0)) return 1.0;
  constexpr double kWindowFactor = 5.0;  // Sokal's c
  double g = 1.0;
  for (std::size_t t = 1; t < n; ++t) {
    if (static_cast<double>(t) >= kWindowFactor * g) return g;  // the automatic window: W >= c g(W)
    if (t > n / 4) break;
    double ct = 0;
    for (std::size_t i = 0; i + t < n; ++i) ct += (x[i] - mean) * (x[i + t] - mean);
    g += 2 * (ct / static_cast<double>(n)) / c0;
  }
  if (converged) *converged = false;
  return std::max(g, 1.0);
}

double BatchMeans::best_standard_error(const char** method) const {
  const char* m = "none";
  double e = std::numeric_limits<double>::quiet_NaN();
  if (std::isfinite(standard_error)) {
    m = "batch_means", e = standard_error;
  } else if (window_converged && n > 0) {
    m = "autocorrelation", e = standard_error_autocorrelation;
  }
  if (method) *method = m;
  return e;
}

BatchMeans batch_means(std::span<const double> x) {
  BatchMeans r;
  r.n = x.size();
  if (r.n == 0) {
    r.mean = r.standard_error = std::numeric_limits<double>::quiet_NaN();
    return r;
  }
  for (double v : x) r.mean += v;
  r.mean /= static_cast<double>(r.n);
  r.statistical_inefficiency = std::max(1.0, statistical_inefficiency(x, &r.window_converged));
  double c0 = 0;
  for (double v : x) c0 += (v - r.mean) * (v - r.mean);
  c0 /= static_cast<double>(r.n);
  r.standard_error_autocorrelation = std::sqrt(c0 * r.statistical_inefficiency / static_cast<double>(r.n));
  r.batch_length = static_cast<std::size_t>(std::ceil(5 * r.statistical_inefficiency));
  r.batches = r.n / r.batch_length;
  if (r.batches < kMinBatches) {
    r.standard_error = std::numeric_limits<double>::quiet_NaN();
    return r;
  }
  std::vector<double> means(r.batches, 0.0);
  for (std::size_t k = 0; k < r.batches; ++k) {
    for (std::size_t i = k * r.batch_length; i < (k + 1) * r.batch_length; ++i) means[k] += x[i];
    means[k] /= static_cast<double>(r.batch_length);
  }
  double m = 0;
  for (double v : means) m += v;
  m /= static_cast<double>(r.batches);
  double s2 = 0;
  for (double v : means) s2 += (v - m) * (v - m);
  s2 /= static_cast<double>(r.batches - 1);
  r.standard_error = std::sqrt(s2 / static_cast<double>(r.batches));
  return r;
}

double standard_error_of_mean(std::span<const double> sems) {
  if (sems.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum2 = 0;
  for (double s : sems) sum2 += s * s;
  return std::sqrt(sum2) / static_cast<double>(sems.size());
}

}  // namespace kerf
