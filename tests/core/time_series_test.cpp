// Batch means against signals whose standard error of the mean is known: white noise (sigma / sqrt(n)),
// AR(1) x_i = phi x_{i-1} + e_i (Var(mean) -> sigma_x^2 g / n with g = (1 + phi) / (1 - phi)), and the
// spread of the means of many independent realisations.
#include "kerf/time_series.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

using Catch::Matchers::WithinRel;

namespace {
std::vector<double> ar1(double phi, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> e(0.0, 1.0);
  std::vector<double> x(n);
  double v = e(rng) / std::sqrt(1 - phi * phi);  // start in the stationary distribution
  for (auto& xi : x) xi = v = phi * v + e(rng);
  return x;
}
}  // namespace

TEST_CASE("batch means: white noise has g = 1 and SEM = sigma / sqrt(n)") {
  const auto x = ar1(0.0, 100000, 1);
  const kerf::BatchMeans bm = kerf::batch_means(x);
  CHECK(bm.statistical_inefficiency < 1.1);
  CHECK(bm.window_converged);
  CHECK_THAT(bm.standard_error, WithinRel(1.0 / std::sqrt(100000.0), 0.1));
}

TEST_CASE("batch means: AR(1) gives its closed-form inefficiency and standard error") {
  for (double phi : {0.5, 0.8, 0.95}) {
    INFO("phi = " << phi);
    const std::size_t n = 400000;
    const auto x = ar1(phi, n, 2);
    const kerf::BatchMeans bm = kerf::batch_means(x);
    const double g = (1 + phi) / (1 - phi), var_x = 1 / (1 - phi * phi);
    CHECK_THAT(bm.statistical_inefficiency, WithinRel(g, 0.15));
    CHECK(bm.batch_length >= static_cast<std::size_t>(4 * g));
    CHECK_THAT(bm.standard_error, WithinRel(std::sqrt(var_x * g / static_cast<double>(n)), 0.15));
  }
}

TEST_CASE("batch means: the reported SEM matches the spread of independent realisations' means") {
  // 300 realisations of a strongly correlated signal: the standard deviation of their means is the true SEM.
  const double phi = 0.9;
  const std::size_t n = 20000;
  std::vector<double> means;
  double sem_sum = 0;
  for (unsigned r = 0; r < 300; ++r) {
    const kerf::BatchMeans bm = kerf::batch_means(ar1(phi, n, 100 + r));
    means.push_back(bm.mean);
    sem_sum += bm.standard_error;
  }
  double m = 0;
  for (double v : means) m += v;
  m /= static_cast<double>(means.size());
  double s2 = 0;
  for (double v : means) s2 += (v - m) * (v - m);
  const double spread = std::sqrt(s2 / static_cast<double>(means.size() - 1));
  // The spread itself is known to about 4 % (300 realisations); the batch estimate is biased low by a few %.
  CHECK_THAT(sem_sum / 300, WithinRel(spread, 0.12));
  // sigma / sqrt(n), ignoring the correlation, would be about sqrt(g) = 4.4 times too small.
  CHECK(spread > 3 * std::sqrt(1 / (1 - phi * phi) / static_cast<double>(n)));
}

TEST_CASE("batch means: a series too short for batches falls back to sqrt(c0 g / n)") {
  // 20 batches' worth would need 100 g samples; 3000 samples of phi = 0.95 (g = 39) hold 15 batches of 5 g at
  // most: with 1500 samples, 7 batches, too few; the autocorrelation estimate is then used, near the truth.
  const double phi = 0.95, g = (1 + phi) / (1 - phi);
  std::vector<double> ratios;
  for (unsigned r = 0; r < 40; ++r) {
    const kerf::BatchMeans bm = kerf::batch_means(ar1(phi, 1500, 500 + r));
    const char* method = nullptr;
    const double e = bm.best_standard_error(&method);
    if (!bm.window_converged) continue;
    REQUIRE(std::string(method) == (std::isfinite(bm.standard_error) ? "batch_means" : "autocorrelation"));
    ratios.push_back(e / std::sqrt(g / (1 - phi * phi) / 1500.0));
  }
  REQUIRE(ratios.size() >= 30);
  double mean = 0;
  for (double v : ratios) mean += v;
  CHECK_THAT(mean / static_cast<double>(ratios.size()), WithinRel(1.0, 0.2));  // biased low by short windows
}

TEST_CASE("batch means: too short a series gives no standard error, a constant one g = 1") {
  const auto x = ar1(0.95, 200, 3);
  const kerf::BatchMeans bm = kerf::batch_means(x);
  CHECK(std::isnan(bm.standard_error));
  CHECK(bm.batches < kerf::kMinBatches);
  const std::vector<double> c(1000, 2.5);
  const kerf::BatchMeans flat = kerf::batch_means(c);
  CHECK(flat.statistical_inefficiency == 1.0);
  CHECK(flat.mean == 2.5);
  CHECK(flat.standard_error == 0.0);
  CHECK(std::isnan(kerf::batch_means(std::vector<double>{}).mean));
}

TEST_CASE("standard error of the mean of independent estimates: sqrt(sum s^2) / n") {
  const std::vector<double> two{3.0, 4.0};
  CHECK_THAT(kerf::standard_error_of_mean(two), WithinRel(2.5, 1e-15));
  // n equal errors s: s / sqrt(n), the error of a mean of n independent estimates.
  const std::vector<double> four(4, 0.6);
  CHECK_THAT(kerf::standard_error_of_mean(four), WithinRel(0.3, 1e-15));
  CHECK(std::isnan(kerf::standard_error_of_mean(std::vector<double>{})));
  CHECK(std::isnan(kerf::standard_error_of_mean(std::vector<double>{1.0, std::nan("")})));
  // Against realisations: the spread of the mean of AR(1) series' means equals the combined batch-means errors.
  std::vector<double> means, sems;
  for (unsigned r = 0; r < 200; ++r) {
    std::vector<double> m, s;
    for (unsigned k = 0; k < 3; ++k) {
      const auto b = kerf::batch_means(ar1(0.8, 4000, 1000 + 3 * r + k));
      m.push_back(b.mean);
      s.push_back(b.best_standard_error());
    }
    means.push_back((m[0] + m[1] + m[2]) / 3);
    sems.push_back(kerf::standard_error_of_mean(s));
  }
  double mean = 0, var = 0, sem = 0;
  for (double v : means) mean += v / 200;
  for (double v : means) var += (v - mean) * (v - mean) / 199;
  for (double v : sems) sem += v / 200;
  CHECK_THAT(sem, WithinRel(std::sqrt(var), 0.15));
}
