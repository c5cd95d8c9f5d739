#pragma once
// A study: one base scene (any kind) run under several conditions, each on several packings, with one table
// of results (`kerf-dem study STUDY.json --out DIR`, issue 21).
//
// The study file (JSON; keys in docs/dem-keys.md, reference in docs/studies.md, generated from the field tables below):
//
//   {"scene": "../scenes/dem_tension.json",                    // or the scene itself, inline
//    "set": ["specimen.width_mm=0.2", "output.frame_every_samples=0"],   // for every condition
//    "conditions": {"grid": {"loading.speed_m_per_s": [0.05, 0.1], "specimen.radius_min_um": [7.5, 8]}},
//    //          or {"list": [{"cut.depth_of_cut_mm": 0.01}, {"cut.depth_of_cut_mm": 0.02, "tool.rake_deg": 0}]}
//    "replicates": {"policy": "adaptive", "results": ["tensile_strength_MPa"],
//                   "target_relative_sem_percent": 5, "min_count": 3, "max_count": 20}}
//
// A work item is (condition, replicate k): the base scene with the study's `set`, the condition's overrides
// and specimen.seed = base seed + k. Its result depends only on that scene, so the tables are the same however
// the items were run (side by side on one machine, or over MPI ranks: kerf/dem/study/study_mpi.hpp). Each finished
// item lives in DIR/items/condition_C_seed_S/ (moved there whole from a temporary directory); a rerun reuses
// every item whose scene is unchanged.
//
// Adaptive replicates: a condition's count is the smallest n in [min_count, max_count] for which the relative
// standard error of the mean (sample std / sqrt(n) / |mean|) of every named result over replicates 0..n-1 is
// at most the target; a failed item ends its condition. The rule looks at prefixes only, so extra items run
// ahead (to keep workers busy) never change the tables.
//
//   const StudySpec spec = read_study(read_json_file("s.json"), "s.json");
//   StudyOptions options;
//   options.out = "out/study";
//   StudyOutcome done = run_study_local(spec, options);  // writes items.csv, conditions.csv, summary.json, plots/
#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "kerf/dem/scene.hpp"
#include "kerf/field_table.hpp"
#include "kerf/json_reader.hpp"

namespace kerf::dem {

enum class ReplicatePolicy { fixed, adaptive };

/// The study's "replicates" section.
struct StudyReplicates {
  ReplicatePolicy policy = ReplicatePolicy::fixed;
  int count = 1;                      ///< fixed: packings per condition
  int min_count = 5;                  ///< adaptive: packings before the first test of the target (fewer may stop
                                      ///< on a lucky few that agree)
  int max_count = 30;                 ///< adaptive: packings at most
  double target_relative_sem = 0.05;  ///< adaptive: sem / |mean| to reach (fraction; key in %)
  std::vector<std::string> results;   ///< adaptive: the summary results the target applies to
};
const FieldTable<StudyReplicates>& study_replicates_fields();

/// One condition: the overrides (key path, value) it applies to the base scene, in the study's key order, and
/// its tags (name, value: a list condition's "tags", e.g. {"domain": "default"}), which label it in the record
/// and change nothing in its scene.
struct StudyCondition {
  std::vector<std::pair<std::string, Json>> values;
  std::vector<std::pair<std::string, Json>> tags;
};

/// The study's "record": a CSV file with one row per finished item (kerf/dem/study/study_record.hpp), which a rerun
/// anywhere reuses, so that a study's results outlive its output directory.
struct StudyRecordSpec {
  std::filesystem::path file;        ///< absolute (the study file's key is relative to the study file)
  std::vector<std::string> results;  ///< the summary results each row carries
};

struct StudySpec {
  std::string description;
  std::string scene_path;           ///< where the base scene came from (the study file for an inline one)
  std::filesystem::path scene_dir;  ///< absolute: resolves the scene's specimen.file
  Json base;                        ///< the base scene with the study's `set` applied
  std::vector<std::string> set;     ///< the study's overrides of every condition
  std::vector<std::string> varied_keys;
  std::vector<StudyCondition> conditions;
  StudyReplicates replicates;
  std::optional<StudyRecordSpec> record;
  std::vector<std::string> tag_names;  ///< every condition's tag names, in first-seen order
  bool seeded = true;                  ///< the base scene generates its specimen (replicates differ in seed)
  std::uint64_t base_seed = 0;         ///< the base scene's specimen.seed
  Json document;                       ///< the study file as read (summary.json's provenance)
};

/// Reads and validates a study (InputError naming the key: "replicates.min_count", "conditions.grid", ...).
/// The base scene is read and checked as well; a condition's overrides are checked only when its items run
/// (a bad one fails those items, not the study).
StudySpec read_study(const Json& doc, const std::filesystem::path& study_file);

/// The Markdown key tables of a study file and of its "replicates" section (kerf-dem keys study,
/// study.replicates; docs/dem-keys.md).
std::string study_keys_markdown();
std::string study_replicates_keys_markdown();

/// One work item.
struct StudyItem {
  int condition = 0;
  int replicate = 0;
  std::uint64_t seed = 0;
};

/// What one item gave: its summary's numeric results, or the error that stopped it.
struct StudyItemResult {
  StudyItem item;
  bool ok = false;
  std::string error;
  std::vector<std::pair<std::string, double>> results;  ///< summary.json's numeric "results", in its order
  double wall_time_s = 0;
  std::string host;
  int rank = 0;
  bool reused = false;  ///< found finished in DIR/items or in the record (wall time, host, rank: the original run's)
  int resumed_from_sample = 0;   ///< > 0: continued from a killed run's checkpoint (wall time: this run's part)
  std::exception_ptr exception;  ///< on this machine: what stopped the item (not sent between ranks)
};
Json study_item_result_to_json(const StudyItemResult& r);
StudyItemResult study_item_result_from_json(const Json& j);

/// Item (condition, replicate) of the study: its packing seed is the base scene's + replicate.
StudyItem study_item(const StudySpec& spec, int condition, int replicate);

/// The item's directory name under DIR/items ("condition_2_seed_7").
std::string study_item_name(const StudyItem& item);

/// Runs one item into DIR/items/NAME (or reuses it there) with `threads` OpenMP threads. It runs in
/// DIR/items/.partial-NAME; a kind that writes checkpoints writes one there every `checkpoint_every_s` of wall
/// time (0: none), and a checkpoint of the item's scene found there (a killed run's) is continued, not begun
/// again. Never throws for the item's own failures (bad override, bad scene, unstable run): they are the
/// result's error. `on_progress`, if set, gets the item's progress reports, each stage named "NAME: stage".
StudyItemResult run_study_item(const StudySpec& spec, const StudyItem& item, const std::filesystem::path& out,
                               int threads, int rank, double checkpoint_every_s,
                               const ProgressCallback& on_progress = {});
/// What an item's result depends on, as a key: the 64-bit FNV-1a (16 hex digits) of its scene (the base scene,
/// the study's `set`, the condition's overrides, its packing seed), top-level description aside.
std::string study_item_scene_key(const StudySpec& spec, const StudyItem& item);
/// The same key of a scene as an item ran it (its summary's study_item.scene).
std::string study_scene_key(const Json& scene);
/// DIR/items/NAME/summary.json of a finished item, read.
Json read_study_item_summary(const std::filesystem::path& out, const StudyItem& item);

/// Which items to run next and when each condition is done: the coordinator's bookkeeping, without threads
/// or messages (run_study_local and the MPI coordinator both drive it).
class StudyScheduler {
 public:
  explicit StudyScheduler(const StudySpec& spec);
  const StudySpec& spec() const { return spec_; }
  /// The next item to hand out: the items every condition needs first (replicate-major), then, while an
  /// adaptive condition is undecided, one more of the least advanced one. None: nothing now (finished(), or
  /// wait for results).
  std::optional<StudyItem> next();
  void complete(StudyItemResult result);
  bool finished() const;
  std::size_t done() const { return n_done_; }
  std::size_t running() const { return n_issued_ - n_done_; }
  /// Items every condition still needs and that are not handed out yet (adaptive: at least min_count).
  std::size_t queued() const;
  /// The items of the tables: replicates 0..n-1 of each condition, condition-major.
  std::vector<StudyItemResult> table() const;
  /// The condition's decided count (adaptive: once decided); -1 while open.
  int count(int condition) const { return conditions_[static_cast<std::size_t>(condition)].decided; }
  /// The mean wall time of the items run (not reused) so far; 0 before the first.
  double mean_item_wall_s() const { return n_run_ > 0 ? run_wall_s_ / static_cast<double>(n_run_) : 0.0; }

 private:
  struct ConditionState {
    int issued = 0;
    int decided = -1;
    std::map<int, StudyItemResult> done;
  };
  const StudySpec& spec_;
  std::vector<ConditionState> conditions_;
  std::size_t n_issued_ = 0, n_done_ = 0, n_run_ = 0;
  double run_wall_s_ = 0;
  int needed(const ConditionState& c) const;
  void decide(ConditionState& c);
};

/// How to run a study (the command line's options).
struct StudyOptions {
  std::filesystem::path out = "out";
  int threads = 0;            ///< local: threads in all (0: OpenMP's maximum); items side by side, one thread each
  int threads_per_rank = 0;   ///< MPI workers: OpenMP threads each (0: the cores the launcher gave the rank)
  bool show_progress = true;  ///< items done / running / queued and an ETA on stderr when it is a terminal
  bool log_lines = false;     ///< a plain line on stdout per finished item (a batch job's log)
  std::string command_line;
  /// Local only: the first failed item stops the study (no new items; the items in flight finish) and its
  /// error is rethrown as it was (an input error stays one): `kerf-dem run --replicates`, where every item
  /// is the same scene and one failure means all would fail.
  bool stop_at_first_failure = false;
  /// Local only: false when the caller already holds OUT's parent directory (a run's OutputManifest).
  bool hold_output_directory = true;
  /// Items of kinds that write checkpoints (tension, compression, calibrate, cut): a checkpoint every this
  /// many seconds of wall time, continued by a rerun after a kill (0: none).
  double checkpoint_every_s = 600;
  ProgressCallback on_progress;  ///< local only: each item's progress reports (stage "NAME: stage")
};

struct StudyOutcome {
  int exit_status = 0;  ///< 0; kExitModelError when some item failed (the tables are written all the same)
  Json summary;
};

/// Runs the study on this machine and writes its outputs.
StudyOutcome run_study_local(const StudySpec& spec, const StudyOptions& options);

/// Writes DIR/items.csv, conditions.csv, summary.json and plots/ from the scheduler's finished tables.
Json write_study_outputs(const StudySpec& spec, const StudyScheduler& scheduler, const StudyOptions& options,
                         double wall_time_s, int workers);

/// Before any item runs: creates DIR/items, removes the partial item directories a killed run left there, and
/// moves each finished item whose scene is that of another item of this study to that item's name (a grid
/// that gained or lost a value renumbers its conditions; the finished cuts are reused all the same). Returns
/// how many items it moved.
std::size_t prepare_study_directory(const StudySpec& spec, const std::filesystem::path& out);
/// The study's end, on one machine or on MPI's rank 0: writes the outputs, prints the closing line, and gives
/// the exit status (kExitModelError when some item failed).
StudyOutcome finish_study(const StudySpec& spec, const StudyScheduler& scheduler, const StudyOptions& options,
                          double wall_time_s, int workers, const std::string& where);

/// The study's progress for a terminal (one line redrawn) or a log (a line per finished item).
class StudyProgress {
 public:
  StudyProgress(const StudyOptions& options, int workers);
  void item_done(const StudyItemResult& r, const StudyScheduler& s);
  void tick(const StudyScheduler& s);  ///< redraws the terminal line (at most a few times a second)
  void finish(const StudyScheduler& s);

 private:
  bool bar_, log_;
  int workers_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::string line(const StudyScheduler& s) const;
};

/// Reads the study file and runs it: under `mpirun -np N` (N > 1, built with MPI) over the ranks
/// (kerf/dem/study/study_mpi.hpp), else on this machine.
StudyOutcome run_study(const std::filesystem::path& study_file, const StudyOptions& options);

}  // namespace kerf::dem
