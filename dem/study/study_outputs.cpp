// A study's outputs (kerf/dem/study/study.hpp, write_study_outputs): the table of items, the statistics per condition,
// the plots, summary.json.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "kerf/comparison_config.hpp"
#include "kerf/dem/study/study.hpp"
#include "kerf/error.hpp"
#include "kerf/interval95.hpp"
#include "kerf/io.hpp"
#include "kerf/metrics.hpp"
#include "kerf/plot.hpp"
#include "kerf/version.hpp"
#include "study_internal.hpp"

namespace kerf::dem {

namespace fs = std::filesystem;

namespace {

struct ResultStats {
  std::size_t n = 0;
  double mean = NAN, std = NAN, sem = NAN, ci_low = NAN, ci_high = NAN;
};

ResultStats stats_of(const std::vector<double>& v) {
  ResultStats r;
  r.n = v.size();
  if (v.empty()) return r;
  const SampleStatistics st = sample_statistics(v);
  r.mean = st.mean;
  if (v.size() >= 2) {
    r.std = st.standard_deviation;
    r.sem = r.std / std::sqrt(static_cast<double>(v.size()));
    const double t = quantile95(static_cast<double>(v.size() - 1));
    r.ci_low = r.mean - t * r.sem;
    r.ci_high = r.mean + t * r.sem;
  }
  return r;
}

/// A file name part from a key ("cut.depth_of_cut_mm" -> "cut_depth_of_cut_mm").
std::string file_part(const std::string& key) {
  std::string out;
  for (char ch : key) out += (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-') ? ch : '_';
  return out;
}

/// Every result any item has, in the order they first appear.
std::vector<std::string> result_names_of(const std::vector<StudyItemResult>& rows) {
  std::vector<std::string> names;
  for (const auto& r : rows)
    for (const auto& [name, v] : r.results)
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

std::optional<double> value_of(const StudyItemResult& r, const std::string& name) {
  for (const auto& [n, v] : r.results)
    if (n == name) return v;
  return std::nullopt;
}

/// A row's first cells: the condition's number and its value of each varied key.
std::vector<std::string> condition_cells(const StudySpec& spec, int ci) {
  std::vector<std::string> cells{std::to_string(ci + 1)};
  const StudyCondition& c = spec.conditions[static_cast<std::size_t>(ci)];
  for (const std::string& key : spec.varied_keys) {
    std::string cell;
    for (const auto& [k, v] : c.values)
      if (k == key) cell = csv_escape(value_text(v));
    cells.push_back(cell);
  }
  return cells;
}

/// items.csv: one row per item; `failed` counts the failed ones.
std::string items_csv(const StudySpec& spec, const std::vector<StudyItemResult>& rows,
                      const std::vector<std::string>& names, std::size_t& failed) {
  std::vector<std::string> header{"condition"};
  for (const std::string& key : spec.varied_keys) header.push_back(csv_escape(key));
  for (const char* h : {"replicate", "seed", "status"}) header.emplace_back(h);
  for (const std::string& n : names) header.push_back(csv_escape(n));
  for (const char* h : {"wall_time_s", "host", "rank", "error"}) header.emplace_back(h);
  std::string csv = csv_line(header);
  failed = 0;
  for (const auto& r : rows) {
    std::vector<std::string> cells = condition_cells(spec, r.item.condition);
    cells.push_back(std::to_string(r.item.replicate + 1));
    cells.push_back(std::to_string(r.item.seed));
    cells.emplace_back(r.ok ? "ok" : "failed");
    failed += r.ok ? 0 : 1;
    for (const std::string& n : names) {
      const auto v = value_of(r, n);
      cells.push_back(v ? csv_number(*v) : "");
    }
    cells.push_back(csv_number(r.wall_time_s));
    cells.push_back(csv_escape(r.host));
    cells.push_back(std::to_string(r.rank));
    cells.push_back(csv_escape(r.error));
    csv += csv_line(cells);
  }
  return csv;
}

/// The statistics of every result over each condition's items: conditions.csv, the summary's conditions, and
/// by_result[result][condition] for the plots.
struct ConditionTables {
  std::string csv;
  Json conditions = Json::array();
  std::map<std::string, std::vector<ResultStats>> by_result;
};

ConditionTables condition_tables(const StudySpec& spec, const StudyScheduler& scheduler,
                                 const std::vector<StudyItemResult>& rows, const std::vector<std::string>& names) {
  const StudyReplicates& policy = spec.replicates;
  const bool adaptive = policy.policy == ReplicatePolicy::adaptive;
  std::vector<std::string> cheader{"condition"};
  for (const std::string& key : spec.varied_keys) cheader.push_back(csv_escape(key));
  for (const char* h : {"result", "n", "failed", "mean", "std", "sem", "ci95_low", "ci95_high", "relative_sem_percent",
                        "target_relative_sem_percent", "target_met"})
    cheader.emplace_back(h);
  ConditionTables t;
  t.csv = csv_line(cheader);
  for (std::size_t ci = 0; ci < spec.conditions.size(); ++ci) {
    Json cj{{"condition", ci + 1}, {"count", scheduler.count(static_cast<int>(ci))}};
    Json values = Json::object();
    for (const auto& [k, v] : spec.conditions[ci].values) values[k] = v;
    cj["values"] = values;
    std::size_t cfailed = 0;
    std::vector<const StudyItemResult*> mine;
    for (const auto& r : rows)
      if (static_cast<std::size_t>(r.item.condition) == ci) {
        mine.push_back(&r);
        cfailed += r.ok ? 0 : 1;
      }
    cj["failed"] = cfailed;
    Json results = Json::object();
    for (const std::string& n : names) {
      std::vector<double> v;
      for (const auto* r : mine)
        if (const auto x = value_of(*r, n)) v.push_back(*x);
      const ResultStats st = stats_of(v);
      t.by_result[n].push_back(st);
      const double rel = st.sem / std::abs(st.mean) * 100;
      const bool targeted =
          adaptive && std::find(policy.results.begin(), policy.results.end(), n) != policy.results.end();
      const bool met = targeted && cfailed == 0 && std::isfinite(st.sem) &&
                       (st.sem == 0 || st.sem <= policy.target_relative_sem * std::abs(st.mean));
      std::vector<std::string> cells = condition_cells(spec, static_cast<int>(ci));
      cells.push_back(csv_escape(n));
      cells.push_back(std::to_string(st.n));
      cells.push_back(std::to_string(cfailed));
      for (double x : {st.mean, st.std, st.sem, st.ci_low, st.ci_high, rel}) cells.push_back(csv_number(x));
      cells.push_back(targeted ? csv_number(policy.target_relative_sem * 100) : "");
      cells.emplace_back(targeted ? (met ? "yes" : "no") : "");
      t.csv += csv_line(cells);
      Json rj{{"n", st.n},
              {"mean", finite_or_null(st.mean)},
              {"std", finite_or_null(st.std)},
              {"sem", finite_or_null(st.sem)},
              {"ci95", Json::array({finite_or_null(st.ci_low), finite_or_null(st.ci_high)})}};
      if (targeted) rj["target_met"] = met;
      results[n] = rj;
    }
    cj["results"] = results;
    t.conditions.push_back(cj);
  }
  return t;
}

/// Each condition's legend label: its entries that tell it apart, its tags when the study has tags (a list study's
/// labels), else its overrides; only those whose value is not the same in every condition, and not `skip` (the x
/// axis's key).
std::vector<std::string> condition_labels(const StudySpec& spec, const std::string& skip) {
  const bool by_tags = !spec.tag_names.empty();
  const auto entries = [&](std::size_t c) -> const auto& {
    return by_tags ? spec.conditions[c].tags : spec.conditions[c].values;
  };
  const auto value_in = [&](std::size_t c, const std::string& k) -> std::optional<std::string> {
    for (const auto& [key, v] : entries(c))
      if (key == k) return v.dump();
    return std::nullopt;
  };
  std::vector<std::string> labels(spec.conditions.size());
  for (std::size_t ci = 0; ci < spec.conditions.size(); ++ci)
    for (const auto& [k, v] : entries(ci)) {
      if (k == skip) continue;
      bool varies = false;
      for (std::size_t c = 0; c < spec.conditions.size() && !varies; ++c) varies = value_in(c, k) != v.dump();
      if (varies) labels[ci] += (labels[ci].empty() ? "" : ", ") + (by_tags ? k : key_label(k)) + " = " + value_text(v);
    }
  return labels;
}

/// The varied keys worth an x axis: numeric, with at least two values among the conditions that set them (in a list
/// study a key that only some conditions set, with one value, says nothing as an axis).
std::vector<std::string> axis_keys(const StudySpec& spec) {
  std::vector<std::string> keys;
  for (const std::string& key : spec.varied_keys) {
    std::set<double> values;
    for (const auto& c : spec.conditions)
      for (const auto& [k, v] : c.values)
        if (k == key && v.is_number()) values.insert(v.get<double>());
    if (values.size() >= 2) keys.push_back(key);
  }
  return keys;
}

/// One point per condition of a result in the figure: x from `x_of` (no point where it gives none), the series by
/// the condition's label (condition_labels). Returns false when the figure says nothing: no point, a result that only
/// repeats the x key (the loading speed) or one that is the same in every condition (a setting echoed as a result).
bool fill_points(const std::vector<ResultStats>& stats, const std::vector<std::string>& labels,
                 const std::string& x_key, const std::function<std::optional<double>(std::size_t)>& x_of,
                 FigureSpec& fig) {
  std::map<std::string, std::size_t> series_of;
  bool echoes_key = !x_key.empty();
  std::optional<double> first_mean;
  bool constant = true;
  for (std::size_t ci = 0; ci < labels.size(); ++ci) {
    const ResultStats& st = stats[ci];
    const std::optional<double> x = x_of(ci);
    if (!x || !std::isfinite(st.mean)) continue;
    echoes_key = echoes_key && st.mean == *x && st.std == 0;
    if (!first_mean) first_mean = st.mean;
    constant = constant && st.mean == *first_mean && st.std == 0;
    auto [it, fresh] = series_of.try_emplace(labels[ci], fig.series.size());
    if (fresh) {
      PlotSeries s;
      s.label = labels[ci];
      s.style = x_key.empty() ? SeriesStyle::points : SeriesStyle::points_and_line;
      s.color = static_cast<int>(fig.series.size());
      s.marker = static_cast<int>(fig.series.size() % 5);
      fig.series.push_back(s);
    }
    PlotSeries& s = fig.series[it->second];
    s.x.push_back(*x);
    s.y.push_back(st.mean);
    s.y_error.push_back(std::isfinite(st.ci_high) ? st.ci_high - st.mean : NAN);
  }
  return !fig.series.empty() && !echoes_key && !constant;
}

/// Plots: each result against each varied key with two or more numeric values, a line per combination of the other
/// conditions' entries; when no key has (a list study of surfaces, models, ...), each result by condition, a point
/// per condition named in the legend. Error bars are the 95 % intervals. The files written, relative to `out`.
std::vector<std::string> write_plots(const StudySpec& spec, const std::vector<std::string>& names,
                                     std::map<std::string, std::vector<ResultStats>>& by_result, const fs::path& out) {
  std::vector<std::string> plots;
  const auto render = [&](FigureSpec& fig, const std::string& file) {
    if (fig.series.size() > 1) leave_room_for_legend(fig);
    fs::create_directories(out / "plots");
    render_png(fig, out / file);
    plots.push_back(file);
  };
  const std::vector<std::string> keys = axis_keys(spec);
  for (const std::string& key : keys) {
    const std::vector<std::string> labels = condition_labels(spec, key);
    const auto x_of = [&](std::size_t ci) -> std::optional<double> {
      for (const auto& [k, v] : spec.conditions[ci].values)
        if (k == key && v.is_number()) return v.get<double>();
      return std::nullopt;
    };
    for (const std::string& n : names) {
      FigureSpec fig;
      fig.title = "mean and 95 % interval over the packings";
      fig.x_label = key_label(key);  // "cut.depth_of_cut_mm" -> "depth of cut (mm)"
      fig.y_label = key_label(n);
      if (!fill_points(by_result[n], labels, key, x_of, fig)) continue;
      for (PlotSeries& s : fig.series) sort_by_x(s);  // in x order
      render(fig, fmt::format("plots/{}_vs_{}.png", file_part(n), file_part(key)));
    }
  }
  if (!keys.empty() || spec.conditions.size() < 2) return plots;
  const std::vector<std::string> labels = condition_labels(spec, "");
  const auto x_of = [](std::size_t ci) -> std::optional<double> { return static_cast<double>(ci + 1); };
  for (const std::string& n : names) {
    FigureSpec fig;
    fig.title = "mean and 95 % interval by condition";
    fig.x_label = "condition";
    fig.y_label = key_label(n);
    fig.x_min = 0.5, fig.x_max = static_cast<double>(spec.conditions.size()) + 0.5, fig.x_tick_step = 1;
    if (!fill_points(by_result[n], labels, "", x_of, fig)) continue;
    render(fig, fmt::format("plots/{}_by_condition.png", file_part(n)));
  }
  return plots;
}

}  // namespace

Json write_study_outputs(const StudySpec& spec, const StudyScheduler& scheduler, const StudyOptions& options,
                         double wall_time_s, int workers) {
  const std::vector<StudyItemResult> rows = scheduler.table();
  const std::vector<std::string> names = result_names_of(rows);
  std::size_t failed = 0;
  const std::string items = items_csv(spec, rows, names, failed);
  ConditionTables tables = condition_tables(spec, scheduler, rows, names);
  const fs::path& out = options.out;
  write_file_atomically(out / "items.csv", items);
  write_file_atomically(out / "conditions.csv", tables.csv);
  const std::vector<std::string> plots = write_plots(spec, names, tables.by_result, out);
  const StudyReplicates& policy = spec.replicates;
  Json summary{{"kind", "study"},
               {"description", spec.description},
               {"scene", spec.scene_path},
               {"set", spec.set},
               {"varied_keys", spec.varied_keys},
               {"replicates", fields_to_json(study_replicates_fields(), policy)},
               {"items", rows.size()},
               {"items_failed", failed},
               {"items_reused", std::count_if(rows.begin(), rows.end(), [](const auto& r) { return r.reused; })},
               {"conditions", tables.conditions},
               {"plots", plots},
               {"workers", workers},
               {"wall_time_s", wall_time_s}};
  if (policy.policy == ReplicatePolicy::adaptive) summary["replicates"]["results"] = policy.results;
  summary["provenance"] = run_provenance(options.command_line, spec.scene_path, spec.set);
  summary["provenance"]["study_as_run"] = spec.document;
  write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
  return summary;
}

}  // namespace kerf::dem
