// A study's scheduler (kerf/dem/study/study.hpp, StudyScheduler): which item to hand out next and when a condition
// is done (fixed or adaptive replicates); and its progress line (StudyProgress).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>

#include "kerf/dem/study/study.hpp"
#include "kerf/error.hpp"
#include "kerf/interval95.hpp"
#include "kerf/io.hpp"
#include "kerf/metrics.hpp"

namespace kerf::dem {

namespace fs = std::filesystem;

StudyScheduler::StudyScheduler(const StudySpec& spec) : spec_(spec), conditions_(spec.conditions.size()) {
  if (spec.replicates.policy == ReplicatePolicy::fixed)
    for (auto& c : conditions_) c.decided = spec.replicates.count;
}

int StudyScheduler::needed(const ConditionState& c) const {
  return c.decided >= 0 ? c.decided : spec_.replicates.min_count;
}

std::optional<StudyItem> StudyScheduler::next() {
  const auto issue = [&](std::size_t ci) {
    ConditionState& c = conditions_[ci];
    const StudyItem item = study_item(spec_, static_cast<int>(ci), c.issued);
    ++c.issued;
    ++n_issued_;
    return item;
  };
  // What every condition needs, replicate by replicate (every condition gets its first packings first).
  int lowest = std::numeric_limits<int>::max();
  std::size_t pick = conditions_.size();
  for (std::size_t ci = 0; ci < conditions_.size(); ++ci) {
    const ConditionState& c = conditions_[ci];
    if (c.issued < needed(c) && c.issued < lowest) {
      lowest = c.issued;
      pick = ci;
    }
  }
  if (pick < conditions_.size()) return issue(pick);
  // Then one more of the least advanced undecided adaptive condition (the rule looks at prefixes only).
  for (std::size_t ci = 0; ci < conditions_.size(); ++ci) {
    const ConditionState& c = conditions_[ci];
    if (c.decided < 0 && c.issued < spec_.replicates.max_count && c.issued < lowest) {
      lowest = c.issued;
      pick = ci;
    }
  }
  if (pick < conditions_.size()) return issue(pick);
  return std::nullopt;
}

void StudyScheduler::complete(StudyItemResult result) {
  ConditionState& c = conditions_[static_cast<std::size_t>(result.item.condition)];
  if (result.ok)
    for (const std::string& name : spec_.replicates.results)
      if (std::none_of(result.results.begin(), result.results.end(), [&](const auto& p) { return p.first == name; })) {
        std::string names;
        for (const auto& p : result.results) names += (names.empty() ? "" : ", ") + p.first;
        result.ok = false;
        result.error = fmt::format("replicates.results: the summary has no result '{}' (it has: {})", name, names);
        result.results.clear();
      }
  ++n_done_;
  if (!result.reused) {
    ++n_run_;
    run_wall_s_ += result.wall_time_s;
  }
  c.done[result.item.replicate] = std::move(result);
  if (c.decided < 0) decide(c);
}

void StudyScheduler::decide(ConditionState& c) {
  const StudyReplicates& p = spec_.replicates;
  std::vector<std::vector<double>> values(p.results.size());
  for (int n = 1; n <= p.max_count; ++n) {
    const auto it = c.done.find(n - 1);
    if (it == c.done.end()) return;  // the prefix is not complete yet
    const StudyItemResult& r = it->second;
    if (!r.ok) {
      c.decided = n;  // a failed item ends its condition
      return;
    }
    for (std::size_t i = 0; i < p.results.size(); ++i)
      for (const auto& [name, v] : r.results)
        if (name == p.results[i]) values[i].push_back(v);
    if (n < p.min_count) continue;
    bool met = true;
    for (const auto& v : values) {
      const SampleStatistics st = sample_statistics(v);
      const double sem = st.standard_deviation / std::sqrt(static_cast<double>(n));
      met = met && std::isfinite(sem) && (sem == 0 || sem <= p.target_relative_sem * std::abs(st.mean));
    }
    if (met || n == p.max_count) {
      c.decided = n;
      return;
    }
  }
}

bool StudyScheduler::finished() const {
  for (const ConditionState& c : conditions_) {
    if (c.decided < 0) return false;
    for (int k = 0; k < c.decided; ++k)
      if (!c.done.count(k)) return false;
  }
  return true;
}

std::size_t StudyScheduler::queued() const {
  std::size_t n = 0;
  for (const ConditionState& c : conditions_) n += static_cast<std::size_t>(std::max(0, needed(c) - c.issued));
  return n;
}

std::vector<StudyItemResult> StudyScheduler::table() const {
  std::vector<StudyItemResult> rows;
  for (const ConditionState& c : conditions_)
    for (int k = 0; k < c.decided; ++k) rows.push_back(c.done.at(k));
  return rows;
}

StudyProgress::StudyProgress(const StudyOptions& options, int workers)
    : bar_(options.show_progress && is_terminal(stderr)),
      log_(options.log_lines),
      workers_(std::max(1, workers)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

namespace {
/// "45 s", "12 min", "3.4 h".
std::string duration_text(double s) {
  if (s < 120) return fmt::format("{:.0f} s", s);
  if (s < 7200) return fmt::format("{:.0f} min", s / 60);
  return fmt::format("{:.1f} h", s / 3600);
}
}  // namespace

std::string StudyProgress::line(const StudyScheduler& s) const {
  std::string text = fmt::format("study: {} done, {} running, {} queued", s.done(), s.running(), s.queued());
  if (s.mean_item_wall_s() > 0) {
    const double left =
        s.mean_item_wall_s() * (static_cast<double>(s.queued()) + 0.5 * static_cast<double>(s.running())) / workers_;
    text += ", ETA " + duration_text(left);
  }
  return text;
}

void StudyProgress::item_done(const StudyItemResult& r, const StudyScheduler& s) {
  if (log_) {
    const std::string resumed =
        r.resumed_from_sample > 0 ? fmt::format(" (resumed from sample {})", r.resumed_from_sample) : std::string();
    std::cout << fmt::format("study: {} {}{} in {:.3g} s on {} rank {}{} | {}\n", study_item_name(r.item),
                             r.reused ? "reused" : (r.ok ? "done" : "FAILED"), resumed, r.wall_time_s, r.host, r.rank,
                             r.ok ? "" : ": " + r.error, line(s));
    std::cout.flush();
  }
  last_draw_ = {};
  tick(s);
}

void StudyProgress::tick(const StudyScheduler& s) {
  if (!bar_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(250)) return;
  last_draw_ = now;
  std::cerr << "\r\x1b[K" << line(s) << std::flush;
}

void StudyProgress::finish(const StudyScheduler& s) {
  if (bar_) std::cerr << "\r\x1b[K" << line(s) << "\n" << std::flush;
}

}  // namespace kerf::dem
