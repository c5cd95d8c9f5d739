#pragma once
// The standard error of the mean of a correlated time series (a force signal from one long DEM cut).
//
// Successive samples of a cutting force are correlated over many samples (a chip forms and breaks), so
// sigma / sqrt(n) understates the error of their mean. kerf estimates it by batch means (e.g. Law & Kelton,
// Simulation Modeling and Analysis; Flyvbjerg & Petersen, J. Chem. Phys. 91 (1989) 461 for the blocking view):
// the series is cut into k consecutive batches of b samples, and SEM = s(batch means) / sqrt(k). The batch
// length comes from the signal itself: b = ceil(5 g), with g = 1 + 2 sum_t rho(t) the statistical inefficiency
// (twice Sokal's integrated autocorrelation time), the sum cut by Sokal's automatic window (the smallest W with
// W >= 5 g(W); A. Sokal, Monte Carlo Methods in Statistical Mechanics, 1997 lecture notes, section 3). Batches
// of 5 g keep the bias of the batch variance to about 1 / 10 (about 5 % on the SEM) for an AR(1)-like signal.
//
// A series too short for kMinBatches batches has no batch estimate; sqrt(c0 g / n) (c0 the variance), the
// estimate from the autocorrelation alone (Sokal, same notes), is then the one to use, when the window
// converged: best_standard_error() picks.
//
//   BatchMeans bm = batch_means(main_force_samples);
//   // bm.mean, bm.standard_error, bm.batch_length, bm.batches, bm.statistical_inefficiency
#include <cstddef>
#include <span>

namespace kerf {

struct BatchMeans {
  std::size_t n = 0;  ///< samples
  double mean = 0;
  double standard_error = 0;            ///< of the mean; NaN with fewer than kMinBatches batches
  double statistical_inefficiency = 1;  ///< g = 1 + 2 sum rho(t), in samples (1: uncorrelated)
  std::size_t batch_length = 1;         ///< b, samples per batch
  std::size_t batches = 0;              ///< k = floor(n / b); the trailing n - k b samples are left out of the SEM
  bool window_converged = true;         ///< false when the automatic window ran out of samples (g underestimated)
  double standard_error_autocorrelation = 0;  ///< sqrt(c0 g / n)

  /// The batch estimate with enough batches, else the autocorrelation one if its window converged, else NaN;
  /// `method` gets "batch_means", "autocorrelation" or "none".
  double best_standard_error(const char** method = nullptr) const;
};

/// Fewer batches than this give no standard error (NaN): their variance is itself too uncertain.
inline constexpr std::size_t kMinBatches = 8;

/// g = 1 + 2 sum_{t=1}^{W} rho(t) with Sokal's automatic window (c = 5); the normalised autocorrelation by
/// direct sums (O(n W)). `converged` is false when the window would pass n / 4. A constant series has g = 1.
double statistical_inefficiency(std::span<const double> x, bool* converged = nullptr);

/// Mean and its batch-means standard error (see the top of this header).
BatchMeans batch_means(std::span<const double> x);

/// The standard error of the mean of n independent estimates with standard errors `sems`: sqrt(sum s_k^2) / n
/// (replicate cuts, each with its own error bar). NaN when `sems` is empty or holds a NaN.
double standard_error_of_mean(std::span<const double> sems);

}  // namespace kerf
