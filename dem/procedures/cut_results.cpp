// What an orthogonal cut reports from its samples and cracks: the crack counts, the steady statistics, the travel
// windows' means, forces.csv.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/io.hpp"
#include "kerf/time_series.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

CutCrackCounts count_cut_cracks(const std::vector<CrackEvent>& cracks, double y_cut_m,
                                std::array<double, 2> steady_x_m) {
  CutCrackCounts n;
  std::vector<double> steady_depths_m;
  for (const auto& c : cracks) {
    (c.mode == BreakMode::tension ? n.tensile : n.shear)++;
    if (is_chip_crack(c.y_m, y_cut_m)) {
      ++n.chip;
      continue;
    }
    ++n.subsurface;
    n.subsurface_damage_depth_m = std::max(n.subsurface_damage_depth_m, y_cut_m - c.y_m);
    if (c.x_m >= steady_x_m[0] && c.x_m <= steady_x_m[1]) {
      ++n.subsurface_steady;
      n.subsurface_steady_damage_depth_m = std::max(n.subsurface_steady_damage_depth_m, y_cut_m - c.y_m);
      steady_depths_m.push_back(y_cut_m - c.y_m);
    }
  }
  if (!steady_depths_m.empty()) {  // nearest rank: the ceil(0.95 n)-th smallest depth
    const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(steady_depths_m.size())));
    const auto at = steady_depths_m.begin() + static_cast<std::ptrdiff_t>(rank - 1);
    std::nth_element(steady_depths_m.begin(), at, steady_depths_m.end());
    n.subsurface_steady_damage_depth_p95_m = *at;
  }
  return n;
}

void steady_statistics(CutResult& res, double from_travel_m) {
  double sm = 0, st = 0, sm2 = 0, st2 = 0;
  int n = 0, touching = 0;
  for (const auto& s : res.samples) {
    if (s.travel_m < from_travel_m) continue;
    sm += s.main_force_n, st += s.thrust_force_n;
    sm2 += s.main_force_n * s.main_force_n, st2 += s.thrust_force_n * s.thrust_force_n;
    touching += s.main_force_n > 0 ? 1 : 0;
    ++n;
  }
  res.n_steady_samples = n;
  res.steady_from_travel_m = from_travel_m;
  res.steady_to_travel_m = res.samples.empty() ? from_travel_m : res.samples.back().travel_m;
  if (n == 0) {
    res.main_force_n = res.thrust_force_n = res.main_force_std_n = res.thrust_force_std_n = 0;
    res.contact_share = 0;
    res.main_force_sem_n = res.thrust_force_sem_n = std::nan("");
    res.main_force_sem_method = res.thrust_force_sem_method = "none";
    res.steady = false;
    res.not_steady_reason =
        fmt::format("no sample at or beyond {:.4g} mm of travel, where the means start", units::m_to_mm(from_travel_m));
    return;
  }
  res.contact_share = static_cast<double>(touching) / n;
  res.main_force_n = sm / n;
  res.thrust_force_n = st / n;
  res.main_force_std_n = std::sqrt(std::max(0.0, sm2 / n - res.main_force_n * res.main_force_n));
  res.thrust_force_std_n = std::sqrt(std::max(0.0, st2 / n - res.thrust_force_n * res.thrust_force_n));
  std::vector<double> main, thrust;
  for (const auto& s : res.samples)
    if (s.travel_m >= from_travel_m) main.push_back(s.main_force_n), thrust.push_back(s.thrust_force_n);
  const BatchMeans bm = batch_means(main), bt = batch_means(thrust);
  res.main_force_sem_n = bm.best_standard_error(&res.main_force_sem_method);
  res.thrust_force_sem_n = bt.best_standard_error(&res.thrust_force_sem_method);
  res.main_force_inefficiency = bm.statistical_inefficiency,
  res.thrust_force_inefficiency = bt.statistical_inefficiency;
  res.main_force_batch_samples = bm.batch_length, res.thrust_force_batch_samples = bt.batch_length;
  // Steady: the means start after the entry (to 1e-4 of it: a scene's entry_fraction x length rounds) and each
  // has a standard error.
  std::vector<std::string> why;
  const double entry_mm = units::m_to_mm(kEntryTravelM);
  if (res.steady_to_travel_m <= kEntryTravelM)
    why.push_back(
        fmt::format("the cut travels {:.4g} mm, within the entry (the first {:g} mm; docs/dem.md, \"How "
                    "long a cut must be\"): cut further (cut.length_mm)",
                    units::m_to_mm(res.steady_to_travel_m), entry_mm));
  else if (from_travel_m < kEntryTravelM * (1 - 1e-4))
    why.push_back(
        fmt::format("the means start at {:.4g} mm of travel, within the entry (the first {:g} mm; "
                    "docs/dem.md, \"How long a cut must be\"): start them later (cut.entry_fraction)",
                    units::m_to_mm(from_travel_m), entry_mm));
  if (!std::isfinite(res.main_force_sem_n) || !std::isfinite(res.thrust_force_sem_n))
    why.push_back(fmt::format(
        "the standard error of the {} cannot be computed from {} samples (too few for batch "
        "means or the autocorrelation): cut further",
        !std::isfinite(res.main_force_sem_n) && !std::isfinite(res.thrust_force_sem_n) ? "main and thrust means"
        : !std::isfinite(res.main_force_sem_n)                                         ? "main mean"
                                                                                       : "thrust mean",
        n));
  res.steady = why.empty();
  res.not_steady_reason = fmt::format("{}", fmt::join(why, "; "));
}

std::vector<TravelWindow> travel_window_means(const std::vector<CutSample>& samples, double length_m, double window_m) {
  // Whole windows, not one more for the rounding of length / window (0.6 / 0.1 is 6.000000000000001).
  const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil(length_m / window_m * (1 - 1e-12))));
  std::vector<TravelWindow> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    out[k].from_m = static_cast<double>(k) * window_m;
    out[k].to_m = std::min(length_m, static_cast<double>(k + 1) * window_m);
  }
  for (const auto& s : samples) {
    const auto k = std::min(n - 1, static_cast<std::size_t>(std::max(0.0, s.travel_m / window_m)));
    out[k].main_force_n += s.main_force_n;
    out[k].thrust_force_n += s.thrust_force_n;
    ++out[k].n_samples;
  }
  for (auto& w : out)
    if (w.n_samples > 0) w.main_force_n /= w.n_samples, w.thrust_force_n /= w.n_samples;
  return out;
}

std::string cut_forces_csv_header() {
  return csv_line({"tool_travel_mm", "time_s", "cutting_force_N", "thrust_force_N", "cutting_force_N_per_mm",
                   "thrust_force_N_per_mm", "main_force_N"});
}

std::string cut_forces_csv_row(const CutSample& s, double width_m) {
  const double width_mm = units::m_to_mm(width_m);
  return csv_line({csv_number(units::m_to_mm(s.travel_m)), csv_number(s.time_s), csv_number(s.main_force_n),
                   csv_number(s.thrust_force_n), csv_number(s.main_force_n / width_mm),
                   csv_number(s.thrust_force_n / width_mm), csv_number(s.main_force_n)});
}

std::string cut_forces_csv(const CutResult& res) {
  std::string out = cut_forces_csv_header();
  for (const auto& s : res.samples) out += cut_forces_csv_row(s, res.width_m);
  return out;
}

}  // namespace kerf::dem
