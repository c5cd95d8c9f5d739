// One item of a study (kerf/dem/study/study.hpp): its name and scene, its run into DIR/items/ (reused by its scene,
// continued from its checkpoint), its result as JSON; the items' directories made ready for a rerun.
#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <exception>
#include <map>
#include <optional>

#include "kerf/dem/engine/checkpoint.hpp"
#include "kerf/dem/scene.hpp"
#include "kerf/dem/study/study.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/metrics.hpp"
#include "kerf/version.hpp"
#include "study_internal.hpp"

namespace kerf::dem {

namespace fs = std::filesystem;

namespace {

/// The --set text of a condition's value: a string as it is, anything else as JSON.
std::string override_text(const std::string& key, const Json& value) {
  return key + "=" + value_text(value);
}

std::string host_name() {
  std::array<char, 256> name{};
  if (gethostname(name.data(), name.size() - 1) != 0) return "unknown";
  return name.data();
}

}  // namespace

StudyItem study_item(const StudySpec& spec, int condition, int replicate) {
  return {condition, replicate, spec.base_seed + static_cast<std::uint64_t>(replicate)};
}

std::string study_item_name(const StudyItem& item) {
  return fmt::format("condition_{}_seed_{}", item.condition + 1, item.seed);
}

Json study_item_result_to_json(const StudyItemResult& r) {
  Json results = Json::array();
  for (const auto& [name, value] : r.results) results.push_back(Json::array({name, value}));
  return Json{{"condition", r.item.condition},
              {"replicate", r.item.replicate},
              {"seed", r.item.seed},
              {"ok", r.ok},
              {"error", r.error},
              {"results", results},
              {"wall_time_s", r.wall_time_s},
              {"host", r.host},
              {"rank", r.rank},
              {"reused", r.reused},
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

/// Why an item whose run ended with a status of its own is no sample of its condition.
std::string failed_status_text(int status) {
  return fmt::format("the run ended with exit status {} (a calibration that did not converge)", status);
}

/// An item finished before with the same scene (its description aside): its result into `r`, and true.
bool reuse_finished_item(const fs::path& summary_file, const Json& doc, StudyItemResult& r) {
  std::error_code error;
  if (!fs::is_regular_file(summary_file, error)) return false;
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
      if (r.ok)
        r.results = numeric_results(old);
      else
        r.error = failed_status_text(status);
      return true;
    }
  } catch (const std::exception&) {
    // Not a study item's summary (or a damaged one): run it again.
  }
  return false;
}

}  // namespace

std::string study_scene_key(const Json& scene) {
  return text_hash_fnv1a64(without_description(scene).dump());
}

std::string study_item_scene_key(const StudySpec& spec, const StudyItem& item) {
  std::vector<std::string> overrides;
  return study_scene_key(item_scene(spec, item, overrides));
}

Json read_study_item_summary(const fs::path& out, const StudyItem& item) {
  return read_json_file((out / "items" / study_item_name(item) / "summary.json").string());
}

StudyItemResult run_study_item(const StudySpec& spec, const StudyItem& item, const fs::path& out, int threads, int rank,
                               double checkpoint_every_s, const ProgressCallback& on_progress) {
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
    if (reuse_finished_item(final_dir / "summary.json", doc, r)) return r;
    std::error_code error;
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
    summary["study_item"] = Json{{"condition", item.condition + 1},
                                 {"replicate", item.replicate + 1},
                                 {"seed", item.seed},
                                 {"scene", doc},
                                 {"wall_time_s", r.wall_time_s},
                                 {"host", r.host},
                                 {"rank", rank},
                                 {"threads", std::max(1, threads)},
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
    if (r.ok)
      r.results = numeric_results(summary);
    else
      r.error = failed_status_text(outcome.exit_status);
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

}  // namespace kerf::dem
