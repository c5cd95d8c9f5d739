// A study: a base scene under several conditions, each on several packings, one table of results
// (kerf/dem/study/study.hpp): run on this machine (items side by side) or over MPI (study_mpi.cpp). Its other rooms:
// study_file.cpp (the study file), study_item.cpp (one item), study_scheduler.cpp (what runs next, the progress),
// study_outputs.cpp (tables and plots), study_record.cpp (the record of finished items).
#include "kerf/dem/study/study.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "kerf/dem/study/study_mpi.hpp"
#include "kerf/dem/study/study_record.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"

namespace kerf::dem {

namespace fs = std::filesystem;

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
  std::exception_ptr failure;  // a bug or no memory: rethrown
  std::exception_ptr stopped;  // stop_at_first_failure: the first failed item's error, rethrown
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

StudyOutcome finish_study(const StudySpec& spec, const StudyScheduler& scheduler, const StudyOptions& options,
                          double wall_time_s, int workers, const std::string& where) {
  StudyOutcome outcome{0, write_study_outputs(spec, scheduler, options, wall_time_s, workers)};
  const std::size_t failed = outcome.summary["items_failed"].get<std::size_t>();
  std::cout << fmt::format(
      "study: {} items ({} failed, {} reused){} in {:.1f} s -> {}\n", outcome.summary["items"].get<std::size_t>(),
      failed, outcome.summary["items_reused"].get<std::size_t>(), where, wall_time_s, options.out.string());
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
