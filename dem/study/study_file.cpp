// A study's file (kerf/dem/study/study.hpp): its reader (read_study) and its keys' reference.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

#include "kerf/dem/study/study.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "study_internal.hpp"

namespace kerf::dem {

namespace fs = std::filesystem;

namespace {

constexpr std::array<std::string_view, 2> kPolicyNameList{"fixed", "adaptive"};
const EnumNames<ReplicatePolicy> kPolicyNames{kPolicyNameList};

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
      throw InputError(where, json_value_text(name), "a result name, e.g. cutting_force_N");
    names.push_back(name.get<std::string>());
  }
  return names;
}

/// The base scene: "scene" (a file, relative to the study file, or an object) with the study's "set" applied.
void read_base_scene(ObjectReader& root, const fs::path& study_file, const fs::path& study_dir, StudySpec& s) {
  const Json& scene = root.get("scene");
  if (scene.is_string()) {
    fs::path path = scene.get<std::string>();
    if (path.is_relative()) path = study_dir / path;
    std::error_code error;
    if (!fs::is_regular_file(path, error))
      throw InputError("scene", scene.get<std::string>(), "an existing scene file");
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
}

/// "conditions.grid": every combination of the keys' values.
void read_condition_grid(const Json& g, StudySpec& s) {
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
}

/// "conditions.list": one condition per object, with its tags.
void read_condition_list(const Json& l, StudySpec& s) {
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
          if (std::find(s.tag_names.begin(), s.tag_names.end(), name) == s.tag_names.end()) s.tag_names.push_back(name);
        }
        continue;
      }
      check_key_path(key, where);
      const Json value = scalar(v, where + "." + key);
      if (std::find(s.varied_keys.begin(), s.varied_keys.end(), key) == s.varied_keys.end())
        s.varied_keys.push_back(key);
      c.values.emplace_back(key, value);
    }
    s.conditions.push_back(std::move(c));
  }
}

/// "replicates": fixed or adaptive, each policy's keys only with it.
void read_replicates(ObjectReader& r, StudySpec& s) {
  s.replicates = read_fields(r, study_replicates_fields(), StudyReplicates{});
  const bool adaptive = s.replicates.policy == ReplicatePolicy::adaptive;
  for (const char* key : {"min_count", "max_count", "target_relative_sem_percent", "results"})
    if (!adaptive && r.has(key)) throw InputError(r.key_path(key), "(given)", "only with \"policy\": \"adaptive\"");
  if (adaptive && r.has("count")) throw InputError(r.key_path("count"), "(given)", "only with \"policy\": \"fixed\"");
  if (const Json* results = r.find("results")) s.replicates.results = result_names(*results, "replicates.results");
  if (adaptive && s.replicates.results.empty())
    throw InputError("replicates.results", "(missing)", "the results the adaptive target applies to");
  if (adaptive && s.replicates.min_count > s.replicates.max_count)
    throw InputError("replicates.max_count", std::to_string(s.replicates.max_count),
                     fmt::format("at least min_count ({})", s.replicates.min_count));
  r.finish();
}

}  // namespace

/// A condition's value in a CSV cell or a label.
std::string value_text(const Json& value) {
  return value.is_string() ? value.get<std::string>() : value.dump();
}

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
         "results each row carries (e.g. `cutting_force_N`) |\n"
         "| `description` | - | a text | none | free text, copied into summary.json |\n";
}

std::string study_replicates_keys_markdown() {
  return fields_markdown(study_replicates_fields()) +
         "| `results` | - | a non-empty list of result names | none | adaptive: the summary results (e.g. "
         "`cutting_force_N`) whose relative standard error must meet the target |\n";
}

StudySpec read_study(const Json& doc, const fs::path& study_file) {
  if (!doc.is_object()) throw InputError("study", json_value_text(doc), "a JSON object");
  ObjectReader root(doc, "");
  StudySpec s;
  s.document = doc;
  s.description = root.get_string_or("description", "");
  const fs::path study_dir = fs::absolute(study_file).parent_path();
  read_base_scene(root, study_file, study_dir, s);
  if (auto conditions = root.find_object("conditions")) {
    const bool grid = conditions->has("grid"), list = conditions->has("list");
    if (grid == list)
      throw InputError("conditions", json_value_text(doc.at("conditions")),
                       "an object with either \"grid\" or \"list\"");
    if (grid)
      read_condition_grid(conditions->get("grid"), s);
    else
      read_condition_list(conditions->get("list"), s);
    conditions->finish();
  }
  if (s.conditions.empty()) s.conditions.push_back({});
  if (auto r = root.find_object("replicates")) read_replicates(*r, s);
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

}  // namespace kerf::dem
