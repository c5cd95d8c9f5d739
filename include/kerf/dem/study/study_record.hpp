#pragma once
// A study's record: one CSV row per finished item, written as each item finishes, that a rerun of the study
// on any machine reuses, so that a study of many sessions' compute keeps its results when its output
// directory does not survive (issue 41; data/studies/results/).
//
//   "record": {"file": "results/seed000_steady.csv", "results": ["main_force_N", "thrust_force_N"]}
//
// Columns: condition, the conditions' tags (e.g. domain, surface), seed, the named results, cpu_time_s,
// wall_time_s, threads, host, kerf_version, git_commit, date, scene_fnv1a64. A row stands for the item whose
// scene has its scene_fnv1a64 (study_item_scene_key): the condition's number and tags only label it, so a
// study whose conditions were reordered still finds its rows, and a row of a changed scene is not reused.
//
//   StudyRecord record(spec);                      // reads the file if it exists (InputError if not a record)
//   if (auto r = record.find(item)) ...            // a recorded item: its results, reused = true
//   record.add(result, item_summary);              // rewrites the file whole with the new row
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "kerf/dem/study/study.hpp"

namespace kerf::dem {

class StudyRecord {
 public:
  /// Reads spec.record's file when it exists; an empty record otherwise (spec.record must be set).
  explicit StudyRecord(const StudySpec& spec);
  /// The item's recorded result (reused = true; its results are the recorded ones), if a row has its scene.
  std::optional<StudyItemResult> find(const StudyItem& item) const;
  /// Adds the row of a finished item (once: a row with its scene already there is left as it is) and rewrites
  /// the file whole. `summary` is the item's summary.json (its provenance and study_item); a failed item is
  /// not recorded.
  void add(const StudyItemResult& result, const Json& summary);
  std::size_t size() const;

 private:
  const StudySpec& spec_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;  ///< cells in header_'s order
  mutable std::mutex mutex_;
  std::size_t column(const std::string& name) const;
  void write() const;
};

}  // namespace kerf::dem

namespace kerf::dem {

/// The study's record, or none when the study has no "record" (the coordinator's, local or MPI).
std::unique_ptr<StudyRecord> open_study_record(const StudySpec& spec);
/// The coordinator's next item to run (local or MPI): the scheduler's next items that the record holds are
/// completed from it (and logged as reused), unless DIR/items holds the same item finished (reused there, with
/// every result of its summary). None: nothing to run now (StudyScheduler::next).
std::optional<StudyItem> next_item_to_run(StudyScheduler& scheduler, const StudyRecord* record,
                                          const std::filesystem::path& out, StudyProgress& progress);
/// Adds a finished item to the record (if there is one), with its DIR/items summary's provenance.
void record_finished_item(StudyRecord* record, const StudyItemResult& result, const std::filesystem::path& out);

}  // namespace kerf::dem
