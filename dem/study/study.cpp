// A study: a base scene under several conditions, each on several packings, one table of results
// (kerf/dem/study/study.hpp). The MPI transport is dem/study/study_mpi.cpp.
#include "kerf/dem/study/study.hpp"
#include "kerf/dem/study/study_record.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <iostream>
#include <limits>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include "kerf/dem/engine/checkpoint.hpp"
#include "kerf/dem/scene.hpp"
#include "kerf/dem/study/study_mpi.hpp"
#include "kerf/error.hpp"
#include "kerf/interval95.hpp"
#include "kerf/io.hpp"
#include "kerf/metrics.hpp"
#include "kerf/plot.hpp"
#include "kerf/version.hpp"

namespace kerf::dem {

namespace fs = std::filesystem;

namespace {

constexpr std::array<std::string_view, 2> kPolicyNameList{"fixed", "adaptive"};
const EnumNames<ReplicatePolicy> kPolicyNames{kPolicyNameList};

/// The --set text of a condition's value: a string as it is, anything else as JSON.
std::string override_text(const std::string& key, const Json& value) {
  return key + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
}

/// A condition's value in a CSV cell or a label.
std::string value_text(const Json& value) { return value.is_string() ? value.get<std::string>() : value.dump(); }

std::string host_name() {
  std::array<char, 256> name{};
  if (gethostname(name.data(), name.size() - 1) != 0) return "unknown";
  return name.data();
}

/// A key path of an override: dotted names, no '='.
void check_key_path(const std::string& key, const std::string& where) {
  const bool bad = key.empty() || key.find('=') != std::string::npos || key.front() == '.' || key.back() == '.' ||
                   key.find("..") != std::string::npos;
  if (bad) throw InputError(where, key, "a dotted scene key path, e.g. cut.depth_of_cut_mm");
}

/// A condition's value or tag: a number, a text or true/false (InputError naming `where`).
const Json& scalar(const Json& v, const std::string& where) {
  if (v.is_array() || v.is_object() || v.is_null())
    throw InputError(where, json_value_text(v), "a number, text or true/false");
  return v;
}

/// A non-empty list of summary result names ("replicates.results", "record.results").
std::vector<std::string> result_names(const Json& list, const std::string& where) {
  if (!list.is_array() || list.empty())
    throw InputError(where, json_value_text(list), "a non-empty list of result names");
  std::vector<std::string> names;
  for (const Json& name : list) {
    if (!name.is_string() || name.get<std::string>().empty())
      throw InputError(where, json_value_text(name), "a result name, e.g. main_force_N");
    names.push_back(name.get<std::string>());
  }
  return names;
}

}  // namespace

const FieldTable<StudyReplicates>& study_replicates_fields() {
  static const FieldTable<StudyReplicates> table{
      choice_field("policy", kPolicyNames,
                   "fixed: `count` packings per condition; adaptive: packings until the relative standard error of "
                   "the mean of `results` meets the target",
                   &StudyReplicates::policy),
      int_field("count", 1, 100000, "fixed: packings per condition (specimen.seed + 0 .. count - 1)",
                &StudyReplicates::count),
      int_field("min_count", 2, 100000, "adaptive: packings before the target is first tested",
                &StudyReplicates::min_count),
      int_field("max_count", 2, 100000, "adaptive: packings at most (the condition stops there, target met or not)",
                &StudyReplicates::max_count),
      number_field("target_relative_sem_percent", units::kPercent, Range{0.0, 100.0, true, false},
                   "adaptive: the relative standard error of the mean (sample std / sqrt(n) / abs(mean)) to reach",
                   &StudyReplicates::target_relative_sem)};
  return table;
}

std::string study_keys_markdown() {
  return "| key | unit | valid | default | meaning |\n|---|---|---|---|---|\n"
         "| `scene` | - | a file name or an object | required | the base scene (any kind): a scene file, relative to "
         "the study file, or the scene itself |\n"
         "| `set` | - | a list of `key.path=value` | none | overrides of the base scene for every condition (as "
         "`--set`) |\n"
         "| `conditions.grid` | - | an object of non-empty lists | one condition | every combination of the values "
         "listed for each scene key path (the first key varies slowest) |\n"
         "| `conditions.list` | - | a non-empty list of objects | one condition | the conditions one by one, each "
         "an object of scene key path: value, and optionally `tags`, an object of name: value that labels the "
         "condition in the record (no override) |\n"
         "| `replicates` | - | an object | `{\"policy\": \"fixed\", \"count\": 1}` | the packings per condition "
         "(`study.replicates`) |\n"
         "| `record.file` | - | a CSV file name | none | one row per finished item, written as each finishes and "
         "reused by a rerun on any machine (relative to the study file; e.g. `results/NAME.csv`) |\n"
         "| `record.results` | - | a non-empty list of result names | required with `record.file` | the summary "
         "results each row carries (e.g. `main_force_N`) |\n"
         "| `description` | - | a text | none | free text, copied into summary.json |\n";
}

std::string study_replicates_keys_markdown() {
  return fields_markdown(study_replicates_fields()) +
         "| `results` | - | a non-empty list of result names | none | adaptive: the summary results (e.g. "
         "`main_force_N`) whose relative standard error must meet the target |\n";
}

StudySpec read_study(const Json& doc, const fs::path& study_file) {
  if (!doc.is_object()) throw InputError("study", json_value_text(doc), "a JSON object");
  ObjectReader root(doc, "");
  StudySpec s;
  s.document = doc;
  s.description = root.get_string_or("description", "");
  const fs::path study_dir = fs::absolute(study_file).parent_path();
  const Json& scene = root.get("scene");
  if (scene.is_string()) {
    fs::path path = scene.get<std::string>();
    if (path.is_relative()) path = study_dir / path;
    std::error_code error;
    if (!fs::is_regular_file(path, error)) throw InputError("scene", scene.get<std::string>(), "an existing scene file");
    s.base = read_json_file(path.string());
    s.scene_path = path.string();
    s.scene_dir = fs::absolute(path).parent_path();
  } else if (scene.is_object()) {
    s.base = scene;
    s.scene_path = study_file.string();
    s.scene_dir = study_dir;
  } else {
    throw InputError("scene", json_value_text(scene), "a scene file name or a scene object");
  }
  if (const Json* set = root.find("set")) {
    if (!set->is_array()) throw InputError("set", json_value_text(*set), "a list of key.path=value texts");
    for (const Json& item : *set) {
      if (!item.is_string()) throw InputError("set", json_value_text(item), "a key.path=value text");
      apply_override(s.base, item.get<std::string>(), "set");
      s.set.push_back(item.get<std::string>());
    }
  }
  if (auto conditions = root.find_object("conditions")) {
    const bool grid = conditions->has("grid"), list = conditions->has("list");
    if (grid == list)
      throw InputError("conditions", json_value_text(doc.at("conditions")), "an object with either \"grid\" or \"list\"");
    if (grid) {
      const Json& g = conditions->get("grid");
      if (!g.is_object() || g.empty())
        throw InputError("conditions.grid", json_value_text(g), "an object of key path: list of values");
      s.conditions.push_back({});
      for (const auto& [key, values] : g.items()) {
        check_key_path(key, "conditions.grid");
        if (!values.is_array() || values.empty())
          throw InputError("conditions.grid." + key, json_value_text(values), "a non-empty list of values");
        s.varied_keys.push_back(key);
        std::vector<Json> checked;  // each value once, not once per condition it multiplies
        for (const Json& v : values) checked.push_back(scalar(v, "conditions.grid." + key));
        std::vector<StudyCondition> next;
        for (const StudyCondition& c : s.conditions)
          for (const Json& v : checked) {
            StudyCondition more = c;
            more.values.emplace_back(key, v);
            next.push_back(std::move(more));
          }
        s.conditions = std::move(next);
      }
    } else {
      const Json& l = conditions->get("list");
      if (!l.is_array() || l.empty())
        throw InputError("conditions.list", json_value_text(l), "a non-empty list of objects (key path: value)");
      for (std::size_t i = 0; i < l.size(); ++i) {
        const std::string where = fmt::format("conditions.list[{}]", i);
        if (!l[i].is_object()) throw InputError(where, json_value_text(l[i]), "an object (key path: value)");
        StudyCondition c;
        for (const auto& [key, v] : l[i].items()) {
          if (key == "tags") {  // labels of the condition (the record's columns), not overrides
            if (!v.is_object()) throw InputError(where + ".tags", json_value_text(v), "an object of name: value");
            for (const auto& [name, t] : v.items()) {
              c.tags.emplace_back(name, scalar(t, where + ".tags." + name));
              if (std::find(s.tag_names.begin(), s.tag_names.end(), name) == s.tag_names.end())
                s.tag_names.push_back(name);
            }
            continue;
          }
          check_key_path(key, where);
          const Json value = scalar(v, where + "." + key);
          if (std::find(s.varied_keys.begin(), s.varied_keys.end(), key) == s.varied_keys.end()) s.varied_keys.push_back(key);
          c.values.emplace_back(key, value);
        }
        s.conditions.push_back(std::move(c));
      }
    }
    conditions->finish();
  }
  if (s.conditions.empty()) s.conditions.push_back({});
  if (auto r = root.find_object("replicates")) {
    s.replicates = read_fields(*r, study_replicates_fields(), StudyReplicates{});
    const bool adaptive = s.replicates.policy == ReplicatePolicy::adaptive;
    for (const char* key : {"min_count", "max_count", "target_relative_sem_percent", "results"})
      if (!adaptive && r->has(key)) throw InputError(r->key_path(key), "(given)", "only with \"policy\": \"adaptive\"");
    if (adaptive && r->has("count")) throw InputError(r->key_path("count"), "(given)", "only with \"policy\": \"fixed\"");
    if (const Json* results = r->find("results"))
      s.replicates.results = result_names(*results, "replicates.results");
    if (adaptive && s.replicates.results.empty())
      throw InputError("replicates.results", "(missing)", "the results the adaptive target applies to");
    if (adaptive && s.replicates.min_count > s.replicates.max_count)
      throw InputError("replicates.max_count", std::to_string(s.replicates.max_count),
                       fmt::format("at least min_count ({})", s.replicates.min_count));
    r->finish();
  }
  if (auto record = root.find_object("record")) {
    StudyRecordSpec r;
    const std::string file = record->get_string("file");
    if (file.empty()) throw InputError("record.file", "(empty)", "a CSV file name, relative to the study file");
    r.file = fs::path(file).is_relative() ? study_dir / file : fs::path(file);
    r.results = result_names(record->get("results"), "record.results");
    record->finish();
    s.record = std::move(r);
  }
  root.finish();
  // The base scene as the items will read it (its kind, its sections); errors name the scene's key.
  try {
    const Scene base = read_scene(s.base, s.scene_dir);
    s.seeded = !base.common.specimen_file.has_value();
    s.base_seed = base.common.specimen.seed;
  } catch (const InputError& e) {
    throw e.with_prefix("scene");
  }
  const int most = s.replicates.policy == ReplicatePolicy::fixed ? s.replicates.count : s.replicates.max_count;
  if (!s.seeded && most > 1)
    throw InputError("replicates", std::to_string(most),
                     "one packing: the base scene loads specimen.file (replicates differ in specimen.seed)");
  return s;
}

StudyItem study_item(const StudySpec& spec, int condition, int replicate) {
  return {condition, replicate, spec.base_seed + static_cast<std::uint64_t>(replicate)};
}

std::string study_item_name(const StudyItem& item) {
  return fmt::format("condition_{}_seed_{}", item.condition + 1, item.seed);
}

Json study_item_result_to_json(const StudyItemResult& r) {
  Json results = Json::array();
  for (const auto& [name, value] : r.results) results.push_back(Json::array({name, value}));
  return Json{{"condition", r.item.condition}, {"replicate", r.item.replicate}, {"seed", r.item.seed},
              {"ok", r.ok},           {"error", r.error},         {"results", results},
              {"wall_time_s", r.wall_time_s}, {"host", r.host}, {"rank", r.rank}, {"reused", r.reused},
              {"resumed_from_sample", r.resumed_from_sample}};
}

StudyItemResult study_item_result_from_json(const Json& j) {
  StudyItemResult r;
  r.item = {j.at("condition").get<int>(), j.at("replicate").get<int>(), j.at("seed").get<std::uint64_t>()};
  r.ok = j.at("ok").get<bool>();
  r.error = j.at("error").get<std::string>();
  for (const Json& p : j.at("results")) r.results.emplace_back(p.at(0).get<std::string>(), p.at(1).get<double>());
  r.wall_time_s = j.at("wall_time_s").get<double>();
  r.host = j.at("host").get<std::string>();
  r.rank = j.at("rank").get<int>();
  r.reused = j.at("reused").get<bool>();
  r.resumed_from_sample = j.at("resumed_from_sample").get<int>();
  return r;
}

namespace {

/// The numeric results of a summary, in its order (nested objects, texts and flags are left out).
std::vector<std::pair<std::string, double>> numeric_results(const Json& summary) {
  std::vector<std::pair<std::string, double>> out;
  if (!summary.contains("results") || !summary.at("results").is_object()) return out;
  for (const auto& [name, value] : summary.at("results").items())
    if (value.is_number()) out.emplace_back(name, value.get<double>());
  return out;
}

/// The item's scene: the base, the condition's overrides, its packing seed.
Json item_scene(const StudySpec& spec, const StudyItem& item, std::vector<std::string>& overrides) {
  Json doc = spec.base;
  overrides = spec.set;
  for (const auto& [key, value] : spec.conditions[static_cast<std::size_t>(item.condition)].values) {
    overrides.push_back(override_text(key, value));
    apply_override(doc, overrides.back(), key);
  }
  if (spec.seeded) {
    overrides.push_back(fmt::format("specimen.seed={}", item.seed));
    apply_override(doc, overrides.back(), "specimen.seed");
  }
  return doc;
}

/// The scene less its top-level free text: what an item's result depends on (a reworded description of the
/// base scene keeps the finished items).
Json without_description(Json scene) {
  if (scene.is_object()) scene.erase("description");
  return scene;
}

/// The checkpoint a killed run of the item left in its directory `partial`, if it is of the item's scene `doc`
/// (its description aside); none when there is none, or it is damaged or of another scene.
std::optional<Checkpoint> item_checkpoint(const fs::path& partial, const Json& doc) {
  std::error_code error;
  if (!fs::is_regular_file(partial / "checkpoint.bin", error)) return std::nullopt;
  try {
    Checkpoint c = read_checkpoint(partial);
    if (without_description(c.scene) == without_description(doc)) return c;
  } catch (const std::exception&) {
    // Damaged or of another version: the item runs from its start.
  }
  return std::nullopt;
}

double thread_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

std::string study_scene_key(const Json& scene) { return text_hash_fnv1a64(without_description(scene).dump()); }

std::string study_item_scene_key(const StudySpec& spec, const StudyItem& item) {
  std::vector<std::string> overrides;
  return study_scene_key(item_scene(spec, item, overrides));
}

Json read_study_item_summary(const fs::path& out, const StudyItem& item) {
  return read_json_file((out / "items" / study_item_name(item) / "summary.json").string());
}

StudyItemResult run_study_item(const StudySpec& spec, const StudyItem& item, const fs::path& out, int threads,
                               int rank, double checkpoint_every_s, const ProgressCallback& on_progress) {
  StudyItemResult r;
  r.item = item;
  r.host = host_name();
  r.rank = rank;
  const fs::path items = out / "items";
  const fs::path final_dir = items / study_item_name(item);
  // One name per item, so that a rerun finds a killed run's checkpoint (one process runs an item at a time).
  const fs::path partial = items / (std::string(OutputManifest::kInFlightPrefix) + study_item_name(item));
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = thread_cpu_s();
  try {
    std::vector<std::string> overrides;
    const Json doc = item_scene(spec, item, overrides);
    // A finished item with the same scene: reused as it is.
    const fs::path summary_file = final_dir / "summary.json";
    std::error_code error;
    if (fs::is_regular_file(summary_file, error)) {
      try {
        const Json old = read_json_file(summary_file.string());
        const Json& mark = old.at("study_item");
        if (without_description(mark.at("scene")) == without_description(doc)) {
          r.reused = true;
          r.wall_time_s = mark.at("wall_time_s").get<double>();
          r.host = mark.at("host").get<std::string>();
          r.rank = mark.at("rank").get<int>();
          const int status = mark.value("exit_status", 0);
          r.ok = status == 0;
          if (r.ok) r.results = numeric_results(old);
          else r.error = fmt::format("the run ended with exit status {} (a calibration that did not converge)", status);
          return r;
        }
      } catch (const std::exception&) {
        // Not a study item's summary (or a damaged one): run it again.
      }
    }
    const Scene scene = read_scene(doc, spec.scene_dir);
    RunOptions options;
    options.out = partial;
    options.show_progress = false;
    options.command_line = fmt::format("(study item {} of {})", study_item_name(item), spec.scene_path);
    options.overrides = overrides;
    if (on_progress)
      options.on_progress = [&on_progress, name = study_item_name(item)](const ProgressUpdate& u) {
        ProgressUpdate named = u;
        named.stage = name + ": " + u.stage;
        on_progress(named);
      };
    if (scene.kind->writes_checkpoints()) options.checkpoint_every_s = checkpoint_every_s;
    scene.kind->check_options(options, scene.common);
    const std::optional<Checkpoint> saved = item_checkpoint(partial, doc);
    if (!saved) {
      fs::remove_all(partial, error);
      fs::create_directories(partial);
    }
    omp_set_num_threads(std::max(1, threads));
    const SceneRun run{doc, spec.scene_dir.string(), options};
    SceneOutcome outcome = saved ? scene.kind->resume(scene.common, run, *saved) : scene.kind->run(scene.common, run);
    if (saved) r.resumed_from_sample = saved->sample_index;  // >= 1: none is written before the first sample
    r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Json summary = outcome.summary;
    summary["provenance"] = run_provenance(options.command_line, spec.scene_path, overrides);
    summary["study_item"] = Json{{"condition", item.condition + 1}, {"replicate", item.replicate + 1},
                                 {"seed", item.seed},        {"scene", doc},
                                 {"wall_time_s", r.wall_time_s}, {"host", r.host},
                                 {"rank", rank},             {"threads", std::max(1, threads)},
                                 // This thread's CPU time: the item's, when it ran on one thread (this run's
                                 // part of a resumed item).
                                 {"cpu_time_s", threads <= 1 ? Json(thread_cpu_s() - cpu_start) : Json(nullptr)},
                                 {"exit_status", outcome.exit_status},
                                 {"resumed_from_sample", r.resumed_from_sample}};
    write_file_atomically(partial / "summary.json", summary.dump(2) + "\n");
    // Whole or not at all: the finished directory replaces a stale one in one rename.
    fs::remove_all(final_dir, error);
    fs::rename(partial, final_dir);
    // A run that finished with a status of its own (a calibration that did not converge) is kept, but its
    // results are not a sample of the condition.
    r.ok = outcome.exit_status == 0;
    if (r.ok) r.results = numeric_results(summary);
    else r.error = fmt::format("the run ended with exit status {} (a calibration that did not converge)", outcome.exit_status);
  } catch (const std::exception& e) {
    std::error_code ignored;
    // A checkpoint stays for the rerun (a run stopped by its caller, e.g. Ctrl-C in Python, continues there).
    if (!fs::is_regular_file(partial / "checkpoint.bin", ignored)) fs::remove_all(partial, ignored);
    r.ok = false;
    r.error = printable(e.what());
    r.exception = std::current_exception();
    r.results.clear();
    r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return r;
}

// ---- the scheduler ----

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

// ---- progress ----

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
    const double left = s.mean_item_wall_s() * (static_cast<double>(s.queued()) + 0.5 * static_cast<double>(s.running())) /
                        workers_;
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

// ---- the outputs ----

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

}  // namespace

Json write_study_outputs(const StudySpec& spec, const StudyScheduler& scheduler, const StudyOptions& options,
                         double wall_time_s, int workers) {
  const std::vector<StudyItemResult> rows = scheduler.table();
  // Every result any item has, in the order they first appear.
  std::vector<std::string> names;
  for (const auto& r : rows)
    for (const auto& [name, v] : r.results)
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  const auto value_of = [](const StudyItemResult& r, const std::string& name) -> std::optional<double> {
    for (const auto& [n, v] : r.results)
      if (n == name) return v;
    return std::nullopt;
  };
  const auto condition_cells = [&](int ci) {
    std::vector<std::string> cells{std::to_string(ci + 1)};
    const StudyCondition& c = spec.conditions[static_cast<std::size_t>(ci)];
    for (const std::string& key : spec.varied_keys) {
      std::string cell;
      for (const auto& [k, v] : c.values)
        if (k == key) cell = csv_escape(value_text(v));
      cells.push_back(cell);
    }
    return cells;
  };
  // items.csv
  std::vector<std::string> header{"condition"};
  for (const std::string& key : spec.varied_keys) header.push_back(csv_escape(key));
  for (const char* h : {"replicate", "seed", "status"}) header.emplace_back(h);
  for (const std::string& n : names) header.push_back(csv_escape(n));
  for (const char* h : {"wall_time_s", "host", "rank", "error"}) header.emplace_back(h);
  std::string items_csv = csv_line(header);
  std::size_t failed = 0;
  for (const auto& r : rows) {
    std::vector<std::string> cells = condition_cells(r.item.condition);
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
    items_csv += csv_line(cells);
  }
  // conditions.csv and the summary's conditions
  const StudyReplicates& policy = spec.replicates;
  const bool adaptive = policy.policy == ReplicatePolicy::adaptive;
  std::vector<std::string> cheader{"condition"};
  for (const std::string& key : spec.varied_keys) cheader.push_back(csv_escape(key));
  for (const char* h : {"result", "n", "failed", "mean", "std", "sem", "ci95_low", "ci95_high", "relative_sem_percent",
                        "target_relative_sem_percent", "target_met"})
    cheader.emplace_back(h);
  std::string conditions_csv = csv_line(cheader);
  Json conditions = Json::array();
  // stats[result][condition]
  std::map<std::string, std::vector<ResultStats>> by_result;
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
      by_result[n].push_back(st);
      const double rel = st.sem / std::abs(st.mean) * 100;
      const bool targeted = adaptive && std::find(policy.results.begin(), policy.results.end(), n) != policy.results.end();
      const bool met = targeted && cfailed == 0 && std::isfinite(st.sem) &&
                       (st.sem == 0 || st.sem <= policy.target_relative_sem * std::abs(st.mean));
      std::vector<std::string> cells = condition_cells(static_cast<int>(ci));
      cells.push_back(csv_escape(n));
      cells.push_back(std::to_string(st.n));
      cells.push_back(std::to_string(cfailed));
      for (double x : {st.mean, st.std, st.sem, st.ci_low, st.ci_high, rel}) cells.push_back(csv_number(x));
      cells.push_back(targeted ? csv_number(policy.target_relative_sem * 100) : "");
      cells.emplace_back(targeted ? (met ? "yes" : "no") : "");
      conditions_csv += csv_line(cells);
      Json rj{{"n", st.n},
              {"mean", finite_or_null(st.mean)},
              {"std", finite_or_null(st.std)},
              {"sem", finite_or_null(st.sem)},
              {"ci95", Json::array({finite_or_null(st.ci_low), finite_or_null(st.ci_high)})}};
      if (targeted) rj["target_met"] = met;
      results[n] = rj;
    }
    cj["results"] = results;
    conditions.push_back(cj);
  }
  const fs::path& out = options.out;
  write_file_atomically(out / "items.csv", items_csv);
  write_file_atomically(out / "conditions.csv", conditions_csv);
  // Plots: each result against each varied key with numeric values, a line per combination of the other keys;
  // error bars are the 95 % intervals.
  std::vector<std::string> plots;
  for (std::size_t ki = 0; ki < spec.varied_keys.size(); ++ki) {
    const std::string& key = spec.varied_keys[ki];
    for (const std::string& n : names) {
      FigureSpec fig;
      fig.title = "mean and 95 % interval over the packings";
      fig.x_label = key;
      fig.y_label = n;
      std::map<std::string, std::size_t> series_of;
      bool echoes_key = true;  // a result that only repeats the varied input (the loading speed) is not plotted
      for (std::size_t ci = 0; ci < spec.conditions.size(); ++ci) {
        const ResultStats& st = by_result[n][ci];
        std::optional<double> x;
        std::string label;
        for (const auto& [k, v] : spec.conditions[ci].values) {
          if (k == key) {
            if (v.is_number()) x = v.get<double>();
          } else {
            label += (label.empty() ? "" : ", ") + k + " = " + value_text(v);
          }
        }
        if (!x || !std::isfinite(st.mean)) continue;
        echoes_key = echoes_key && st.mean == *x && st.std == 0;
        auto [it, fresh] = series_of.try_emplace(label, fig.series.size());
        if (fresh) {
          PlotSeries s;
          s.label = label;
          s.style = SeriesStyle::points_and_line;
          s.color = static_cast<int>(fig.series.size());
          s.marker = static_cast<int>(fig.series.size() % 5);
          fig.series.push_back(s);
        }
        PlotSeries& s = fig.series[it->second];
        s.x.push_back(*x);
        s.y.push_back(st.mean);
        s.y_error.push_back(std::isfinite(st.ci_high) ? st.ci_high - st.mean : NAN);
      }
      if (fig.series.empty() || echoes_key) continue;
      for (PlotSeries& s : fig.series) sort_by_x(s);  // in x order
      if (fig.series.size() > 1) leave_room_for_legend(fig);
      const std::string file = fmt::format("plots/{}_vs_{}.png", file_part(n), file_part(key));
      fs::create_directories(out / "plots");
      render_png(fig, out / file);
      plots.push_back(file);
    }
  }
  Json summary{{"kind", "study"},
               {"description", spec.description},
               {"scene", spec.scene_path},
               {"set", spec.set},
               {"varied_keys", spec.varied_keys},
               {"replicates", fields_to_json(study_replicates_fields(), policy)},
               {"items", rows.size()},
               {"items_failed", failed},
               {"items_reused", std::count_if(rows.begin(), rows.end(), [](const auto& r) { return r.reused; })},
               {"conditions", conditions},
               {"plots", plots},
               {"workers", workers},
               {"wall_time_s", wall_time_s}};
  if (adaptive) summary["replicates"]["results"] = policy.results;
  summary["provenance"] = run_provenance(options.command_line, spec.scene_path, spec.set);
  summary["provenance"]["study_as_run"] = spec.document;
  write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
  return summary;
}

// ---- running on this machine ----

StudyOutcome run_study_local(const StudySpec& spec, const StudyOptions& options) {
  std::optional<OutputManifest> hold;
  if (options.hold_output_directory) hold.emplace(options.out, /*fresh=*/true);  // writable? (exit 4 before any work)
  const auto start = std::chrono::steady_clock::now();
  prepare_study_directory(spec, options.out);
  StudyScheduler scheduler(spec);
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  const std::size_t first_wave = scheduler.queued();
  const int side_by_side = std::max(1, std::min(threads, static_cast<int>(first_wave)));
  const int inner = std::max(1, threads / side_by_side);
  StudyProgress progress(options, side_by_side);
  const std::unique_ptr<StudyRecord> record = open_study_record(spec);
  StudyRecord* const recorded = record.get();
  std::mutex mutex;
  std::exception_ptr failure;   // a bug or no memory: rethrown
  std::exception_ptr stopped;   // stop_at_first_failure: the first failed item's error, rethrown
  const int max_levels = omp_get_max_active_levels();
  omp_set_max_active_levels(2);
#pragma omp parallel num_threads(side_by_side)
  {
    while (true) {
      std::optional<StudyItem> item;
      {
        const std::lock_guard<std::mutex> lock(mutex);
        if (failure || stopped || scheduler.finished()) break;
        item = next_item_to_run(scheduler, recorded, options.out, progress);
        progress.tick(scheduler);
      }
      if (!item) {  // an adaptive condition waits for results before it asks for more
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        continue;
      }
      try {
        StudyItemResult r =
            run_study_item(spec, *item, options.out, inner, 0, options.checkpoint_every_s, options.on_progress);
        const std::lock_guard<std::mutex> lock(mutex);
        if (!r.ok && options.stop_at_first_failure && !stopped)
          stopped = r.exception ? r.exception : std::make_exception_ptr(ModelError(study_item_name(r.item), r.error));
        record_finished_item(recorded, r, options.out);
        scheduler.complete(r);
        progress.item_done(r, scheduler);
      } catch (...) {  // run_study_item keeps the item's own failures; this is a bug or no memory
        const std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
      }
    }
  }
  omp_set_max_active_levels(max_levels);
  if (failure) std::rethrow_exception(failure);
  progress.finish(scheduler);
  if (stopped) std::rethrow_exception(stopped);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return finish_study(spec, scheduler, options, wall, side_by_side, "");
}

std::size_t prepare_study_directory(const StudySpec& spec, const fs::path& out) {
  const fs::path items = out / "items";
  fs::create_directories(items);
  // A killed run's items in flight: those with a checkpoint stay (their items continue from it).
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(items)) {
    if (OutputManifest::in_flight(entry.path().filename()) && !fs::is_regular_file(entry.path() / "checkpoint.bin"))
      stale.push_back(entry.path());
  }
  for (const fs::path& dir : stale) fs::remove_all(dir);
  // The finished items there, by the scene they ran (a directory of a killed re-homing included).
  std::map<std::string, fs::path> finished;
  for (const auto& entry : fs::directory_iterator(items)) {
    try {
      const Json old = read_json_file((entry.path() / "summary.json").string());
      finished.try_emplace(without_description(old.at("study_item").at("scene")).dump(), entry.path());
    } catch (const std::exception&) {
      // Not a finished item: its item runs again.
    }
  }
  if (finished.empty()) return 0;
  // Each item this study may run whose scene finished under another name goes there.
  const int most = spec.replicates.policy == ReplicatePolicy::fixed ? spec.replicates.count : spec.replicates.max_count;
  std::vector<std::pair<fs::path, fs::path>> moves;  // from, to
  for (std::size_t c = 0; c < spec.conditions.size(); ++c)
    for (int k = 0; k < most; ++k) {
      const StudyItem item = study_item(spec, static_cast<int>(c), k);
      std::vector<std::string> overrides;
      Json scene;
      try {
        scene = item_scene(spec, item, overrides);
      } catch (const std::exception&) {
        continue;  // an override that does not apply: the item fails when it runs, not the study here
      }
      const auto found = finished.find(without_description(std::move(scene)).dump());
      const fs::path to = items / study_item_name(item);
      if (found == finished.end()) continue;
      if (found->second != to) moves.emplace_back(found->second, to);
      finished.erase(found);  // two conditions with the same scene: the second runs its own
    }
  // In two passes, so that two items that swap names both arrive: first aside, then in place (a stale item
  // in the way is one that no item of this study ran: it would be replaced when its item runs).
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const fs::path aside = items / fmt::format(".rehome-{}-{}", getpid(), i);
    fs::rename(moves[i].first, aside);
    moves[i].first = aside;
  }
  for (const auto& [aside, to] : moves) {
    fs::remove_all(to);
    fs::rename(aside, to);
  }
  return moves.size();
}

StudyOutcome finish_study(const StudySpec& spec, const StudyScheduler& scheduler, const StudyOptions& options,
                          double wall_time_s, int workers, const std::string& where) {
  StudyOutcome outcome{0, write_study_outputs(spec, scheduler, options, wall_time_s, workers)};
  const std::size_t failed = outcome.summary["items_failed"].get<std::size_t>();
  std::cout << fmt::format("study: {} items ({} failed, {} reused){} in {:.1f} s -> {}\n",
                           outcome.summary["items"].get<std::size_t>(), failed,
                           outcome.summary["items_reused"].get<std::size_t>(), where, wall_time_s, options.out.string());
  if (failed > 0) outcome.exit_status = kExitModelError;
  return outcome;
}

StudyOutcome run_study(const fs::path& study_file, const StudyOptions& options) {
  std::error_code error;
  if (!fs::is_regular_file(study_file, error)) throw InputError("study", study_file.string(), "a study JSON file");
  if (study_mpi_built() && study_mpi_launched()) return run_study_mpi(study_file, options);
  const StudySpec spec = read_study(read_json_file(study_file.string()), study_file);
  return run_study_local(spec, options);
}

}  // namespace kerf::dem
