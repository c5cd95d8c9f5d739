#include "kerf/dem/study/study_record.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <initializer_list>

#include "kerf/csv_table.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"

namespace kerf::dem {

namespace fs = std::filesystem;

namespace {

constexpr const char* kKeyColumn = "scene_fnv1a64";
// After the condition, its tags, the seed and the named results.
constexpr std::array<const char*, 8> kRunColumns{"cpu_time_s",   "wall_time_s", "threads", "host",
                                                 "kerf_version", "git_commit",  "date",    kKeyColumn};

std::string cell_text(const Json& value) {
  return value.is_string() ? value.get<std::string>() : value.dump();
}

/// The value at `path` (dotted) of `j` as a cell: a number as csv_number, a text as it is, else empty.
std::string summary_cell(const Json& j, std::initializer_list<const char*> path) {
  const Json* at = &j;
  for (const char* key : path) {
    if (!at->is_object() || !at->contains(key)) return "";
    at = &at->at(key);
  }
  if (at->is_number()) return csv_number(at->get<double>());
  return at->is_string() ? at->get<std::string>() : "";
}

}  // namespace

StudyRecord::StudyRecord(const StudySpec& spec) : spec_(spec) {
  header_.emplace_back("condition");
  for (const std::string& t : spec.tag_names) header_.push_back(t);
  header_.emplace_back("seed");
  for (const std::string& r : spec.record->results) header_.push_back(r);
  for (const char* c : kRunColumns) header_.emplace_back(c);
  std::error_code error;
  if (!fs::exists(spec.record->file, error)) return;
  const CsvTable t = read_csv_file(spec.record->file);
  for (const char* required : {"condition", "seed", kKeyColumn})
    if (!t.has_column(required))
      throw InputError("record.file", spec.record->file.string(),
                       fmt::format("a study record (a CSV with the columns condition, seed, ..., {})", kKeyColumn));
  // The file's other columns are kept, after this study's.
  for (const std::string& h : t.header)
    if (std::find(header_.begin(), header_.end(), h) == header_.end()) header_.push_back(h);
  for (const auto& row : t.rows) {
    std::vector<std::string> cells(header_.size());
    for (std::size_t k = 0; k < t.header.size(); ++k) cells[column(t.header[k])] = row[k];
    rows_.push_back(std::move(cells));
  }
}

std::size_t StudyRecord::column(const std::string& name) const {
  return static_cast<std::size_t>(std::find(header_.begin(), header_.end(), name) - header_.begin());
}

std::size_t StudyRecord::size() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return rows_.size();
}

std::optional<StudyItemResult> StudyRecord::find(const StudyItem& item) const {
  const std::string key = study_item_scene_key(spec_, item);
  const std::lock_guard<std::mutex> lock(mutex_);
  const std::size_t k = column(kKeyColumn);
  for (const auto& row : rows_) {
    if (row[k] != key) continue;
    StudyItemResult r;
    r.item = item;
    r.ok = true;
    r.reused = true;
    for (const std::string& name : spec_.record->results) {
      double v = 0;
      if (parse_number(row[column(name)], v)) r.results.emplace_back(name, v);
    }
    parse_number(row[column("wall_time_s")], r.wall_time_s);
    r.host = row[column("host")];
    return r;
  }
  return std::nullopt;
}

void StudyRecord::add(const StudyItemResult& result, const Json& summary) {
  if (!result.ok) return;
  const std::string key = study_item_scene_key(spec_, result.item);
  const std::lock_guard<std::mutex> lock(mutex_);
  const std::size_t k = column(kKeyColumn);
  if (std::any_of(rows_.begin(), rows_.end(), [&](const auto& row) { return row[k] == key; })) return;
  std::vector<std::string> row(header_.size());
  row[column("condition")] = std::to_string(result.item.condition + 1);
  for (const auto& [name, value] : spec_.conditions[static_cast<std::size_t>(result.item.condition)].tags)
    row[column(name)] = cell_text(value);
  row[column("seed")] = std::to_string(result.item.seed);
  for (const auto& [name, v] : result.results)
    if (std::find(spec_.record->results.begin(), spec_.record->results.end(), name) != spec_.record->results.end())
      row[column(name)] = csv_number(v);
  row[column("cpu_time_s")] = summary_cell(summary, {"study_item", "cpu_time_s"});
  row[column("wall_time_s")] = csv_number(result.wall_time_s);
  row[column("threads")] = summary_cell(summary, {"study_item", "threads"});
  row[column("host")] = result.host;
  row[column("kerf_version")] = summary_cell(summary, {"provenance", "version"});
  row[column("git_commit")] = summary_cell(summary, {"provenance", "git_commit"});
  row[column("date")] = summary_cell(summary, {"provenance", "date"});
  row[k] = key;
  rows_.push_back(std::move(row));
  // Condition by condition, seeds in order (numbers compared as numbers).
  const std::size_t c = column("condition"), s = column("seed");
  std::stable_sort(rows_.begin(), rows_.end(), [&](const auto& a, const auto& b) {
    double ca = 0, cb = 0, sa = 0, sb = 0;
    parse_number(a[c], ca), parse_number(b[c], cb), parse_number(a[s], sa), parse_number(b[s], sb);
    return ca != cb ? ca < cb : sa < sb;
  });
  write();
}

void StudyRecord::write() const {
  std::vector<std::string> escaped;
  for (const std::string& h : header_) escaped.push_back(csv_escape(h));
  std::string text = csv_line(escaped);
  for (const auto& row : rows_) {
    std::vector<std::string> cells;
    for (const std::string& cell : row) cells.push_back(csv_escape(cell));
    text += csv_line(cells);
  }
  fs::create_directories(spec_.record->file.parent_path());
  write_file_atomically(spec_.record->file, text);
}

}  // namespace kerf::dem

namespace kerf::dem {

std::unique_ptr<StudyRecord> open_study_record(const StudySpec& spec) {
  return spec.record ? std::make_unique<StudyRecord>(spec) : nullptr;
}

std::optional<StudyItem> next_item_to_run(StudyScheduler& scheduler, const StudyRecord* record,
                                          const std::filesystem::path& out, StudyProgress& progress) {
  while (std::optional<StudyItem> item = scheduler.next()) {
    if (record == nullptr) return item;
    std::optional<StudyItemResult> recorded = record->find(*item);
    if (!recorded) return item;
    try {  // the same item finished in DIR/items: run_study_item reuses it with all its results
      const Json old = read_study_item_summary(out, *item);
      if (study_scene_key(old.at("study_item").at("scene")) == study_item_scene_key(scheduler.spec(), *item))
        return item;
    } catch (const std::exception&) {
      // None there (or not of this scene): the record's row stands for it.
    }
    scheduler.complete(*recorded);
    progress.item_done(*recorded, scheduler);
  }
  return std::nullopt;
}

void record_finished_item(StudyRecord* record, const StudyItemResult& result, const std::filesystem::path& out) {
  if (record == nullptr || !result.ok) return;
  Json summary = Json::object();
  try {
    summary = read_study_item_summary(out, result.item);
  } catch (const std::exception&) {
    // Reused from the record itself (no directory): add() finds its row and leaves it.
  }
  record->add(result, summary);
}

}  // namespace kerf::dem
