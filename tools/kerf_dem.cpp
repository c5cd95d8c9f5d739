// kerf-dem: the 2D bonded-particle DEM with flat joints (issue 4), a thin front end to the library
// (kerf/dem/scene.hpp: the scene kinds, replicates, checkpoints). Its command line is a function, kerf_dem_main
// (kerf_dem.hpp), which kerf-dem's main (kerf_dem_main.cpp) and the test suite's twin with its own kinds call.
//
//   kerf-dem run SCENE.json [--set key.path=value]... [--out DIR] [--threads N] [--checkpoint-every N] [--replicates N]
//                [--log-every N]   (log lines on stdout when it is not a terminal)
//   kerf-dem resume DIR [--threads N]
//   kerf-dem keys [SECTION]      the Markdown key table of every scene section (docs/dem-keys.md), or of one
//   kerf-dem results [--python]  the Markdown table of the results each kind writes (docs/dem-keys.md), or the
//                Python module of their keys (python/kerf/result_keys.py)
//   kerf-dem study STUDY.json --out DIR [--threads N] [--threads-per-rank N] [--checkpoint-minutes M] [--log-every N]
//                a study (kerf/dem/study/study.hpp); under `mpirun -np N` across ranks (built with MPI)
//
// Exit status 2 for bad input (the message names the field, the value and what was expected), 3 when the
// model fails (e.g. an unstable run, a calibration that does not converge, a damaged checkpoint), 4 when an
// output cannot be written (the directory is checked before any work).
#include "kerf_dem.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>

#include "kerf/dem/output/run_log.hpp"
#include "kerf/dem/scene.hpp"
#include "kerf/dem/study/study.hpp"
#include "kerf/dem/study/study_mpi.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/json_reader.hpp"
#include "kerf/version.hpp"

namespace {

constexpr const char* kProgram = "kerf-dem";

/// Runs `body(on_progress)`; when standard output is not a terminal (a log file, a batch job) and `log_every`
/// > 0, with a log line every `log_every` samples of each stage and the performance lines
/// (kerf/dem/output/run_log.hpp), which on_progress feeds; without the run's last one for a study (`performance_line`
/// false: the study's last line sums it up).
int with_log(int log_every, const std::function<int(const kerf::dem::ProgressCallback&)>& body,
             bool performance_line = true) {
  std::optional<kerf::dem::RunLog> log;
  kerf::dem::ProgressCallback on_progress;
  if (log_every > 0 && !isatty(STDOUT_FILENO)) {
    log.emplace(std::cout, log_every);
    on_progress = [&log](const kerf::dem::ProgressUpdate& u) { log->report(u); };
  }
  const int status = body(on_progress);
  if (log && performance_line) log->finish(omp_get_max_threads());
  return status;
}

int run_command(const std::string& scene_path, const std::vector<std::string>& sets, kerf::dem::RunOptions options,
                int log_every) {
  kerf::Json doc = kerf::read_json_file(scene_path);
  for (const auto& s : sets) kerf::apply_override(doc, s);
  options.overrides = sets;
  return with_log(log_every, [&](const kerf::dem::ProgressCallback& on_progress) {
    options.on_progress = on_progress;
    try {
      return kerf::dem::run_scene(doc, scene_path, options).exit_status;
    } catch (const kerf::InputError& e) {
      kerf::blame_the_key_set(e, sets);
    }
  });
}

/// What a SIGINT/SIGTERM/SIGHUP prints before the run dies (kerf/io.hpp): how to continue it from its checkpoint
/// in `out`, if it has written one by then.
void note_how_to_continue(const std::filesystem::path& out, const kerf::dem::RunOptions& options) {
  const std::string dir = out.string();
  const char* resume[] = {kProgram, "resume", dir.c_str()};
  if (options.replicates > 1) {
    kerf::set_interrupt_note({}, "",
                             fmt::format("{}: interrupted; the same command continues it (finished replicates "
                                         "are reused, from {})",
                                         kProgram, (out / "replicates").string()));
    return;
  }
  kerf::set_interrupt_note(out / "checkpoint.bin",
                           fmt::format("{}: interrupted; continue with: {}", kProgram, kerf::command_line(3, resume)),
                           fmt::format("{}: interrupted before its first checkpoint (none in {}; --checkpoint-every N "
                                       "writes them): nothing to resume, run it again",
                                       kProgram, dir));
}

int keys_command(const std::string& section) {
  std::cout << kerf::dem::scene_keys_markdown(section);
  return 0;
}

}  // namespace

// Long (~115 lines) for a reason: the CLI's option table, one block per subcommand, then one dispatch to the library
// call each makes (as kerf-forces' main).
int kerf::dem::kerf_dem_main(int argc, char** argv) {
  CLI::App app{"kerf-dem: 2D bonded-particle DEM with Potyondy's flat joint"};
  app.require_subcommand(1);
  app.set_version_flag("--version", kerf::version_line(kProgram));
  std::string scene_path, resume_dir, section;
  std::vector<std::string> sets;
  std::string out_dir = "out";
  kerf::dem::RunOptions options;
  int threads = 0, log_every = 100;
  const std::string kinds = fmt::format("{}", fmt::join(kerf::dem::scene_kind_names(), ", "));
  auto* run = app.add_subcommand("run", "run a scene (kind: " + kinds + ")");
  run->add_option("scene", scene_path, "scene JSON file")->required();
  run->add_option("--set", sets, "override a scene value: key.path=value (repeatable)");
  run->add_option("--out", out_dir, "output directory (default: out)");
  run->add_option("--threads", threads, "OpenMP threads (default: all)")->check(CLI::Range(1, 1024));
  run->add_option(
         "--checkpoint-every", options.checkpoint_every,
         "write DIR/checkpoint.bin every N samples (tension, compression, cut; calibrate: after every evaluation)")
      ->check(CLI::Range(1, 100000000));
  run->add_option("--log-every", log_every,
                  "when standard output is not a terminal: a log line every N samples of each stage (0: none; "
                  "default: 100)")
      ->check(CLI::Range(0, 100000000));
  run->add_option("--replicates", options.replicates, "cut scenes: repeat on N packings (seeds specimen.seed + 0..N-1)")
      ->check(CLI::Range(1, 1000));
  auto* resume = app.add_subcommand("resume", "continue a killed test, cut or calibration from DIR/checkpoint.bin");
  resume->add_option("dir", resume_dir, "output directory of the killed run")->required();
  resume->add_option("--threads", threads, "OpenMP threads (default: all)")->check(CLI::Range(1, 1024));
  resume->add_option("--log-every", log_every, "as for run: a log line every N samples when stdout is not a terminal")
      ->check(CLI::Range(0, 100000000));
  auto* keys = app.add_subcommand("keys", "print the Markdown key table of the scene sections (docs/dem-keys.md)");
  keys->add_option(
      "section", section,
      "one section (" + fmt::format("{}", fmt::join(kerf::dem::scene_sections(), ", ")) + "; default: all)");
  bool results_python = false;
  auto* results = app.add_subcommand(
      "results", "print the Markdown table of the results each kind writes into summary.json (docs/dem-keys.md)");
  results->add_flag("--python", results_python,
                    "print them as the Python module kerf.result_keys instead (python/kerf/result_keys.py)");
  std::string study_path;
  kerf::dem::StudyOptions study_options;
  auto* study = app.add_subcommand(
      "study",
      std::string("run a study: a scene under several conditions, each on several packings (") +
          (kerf::dem::study_mpi_built() ? "under mpirun -np N: across ranks" : "built without MPI: this machine") +
          ")");
  study->add_option("study", study_path, "study JSON file (keys: kerf-dem keys study)")->required();
  study->add_option("--out", out_dir, "output directory (default: out); items are reused from it on a rerun");
  study->add_option("--threads", threads, "on one machine: threads in all, items side by side (default: all)")
      ->check(CLI::Range(1, 1024));
  study
      ->add_option("--threads-per-rank", study_options.threads_per_rank,
                   "under mpirun: OpenMP threads of each worker rank (default: the cores the launcher gives it)")
      ->check(CLI::Range(1, 1024));
  double checkpoint_minutes = study_options.checkpoint_every_s / 60;
  study
      ->add_option("--checkpoint-minutes", checkpoint_minutes,
                   "items of tension, compression, calibrate and cut scenes: a checkpoint every M minutes in "
                   "OUT/items/.partial-NAME, from which a rerun continues a killed item (default: 10; 0: none)")
      ->check(CLI::Range(0.0, 1e6));
  int study_log_every = 10000;
  study
      ->add_option("--log-every", study_log_every,
                   "on one machine, when standard output is not a terminal: besides a line per finished item, a "
                   "log line every N samples of each item's stages (0: none; default: 10000)")
      ->check(CLI::Range(0, 100000000));
  const auto error = [](const std::string& what, int status) {
    std::cerr << kProgram << ": error: " << kerf::printable(what) << "\n";
    return status;
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    return error(e.what(), kerf::kExitInputError);
  }
  try {
    if (threads > 0) omp_set_num_threads(threads);
    if (keys->parsed()) return keys_command(section);
    if (results->parsed()) {
      std::cout << (results_python ? kerf::dem::result_keys_python() : kerf::dem::scene_results_markdown());
      return 0;
    }
    if (resume->parsed()) {
      note_how_to_continue(resume_dir, options);
      return with_log(log_every, [&](const kerf::dem::ProgressCallback& on_progress) {
        return kerf::dem::resume_scene(resume_dir, true, on_progress, kerf::command_line(argc, argv)).exit_status;
      });
    }
    if (out_dir.empty()) throw kerf::InputError("--out", "\"\"", "a directory name");
    if (study->parsed()) {
      study_options.out = out_dir;
      study_options.threads = threads;
      study_options.checkpoint_every_s = 60 * checkpoint_minutes;
      study_options.log_lines = !isatty(STDOUT_FILENO);
      study_options.command_line = kerf::command_line(argc, argv);
      // The items' stage lines (on_progress: local runs only).
      return with_log(
          study_log_every,
          [&](const kerf::dem::ProgressCallback& on_progress) {
            study_options.on_progress = on_progress;
            return kerf::dem::run_study(study_path, study_options).exit_status;
          },
          /*performance_line=*/false);
    }
    options.out = out_dir;
    options.command_line = kerf::command_line(argc, argv);
    note_how_to_continue(options.out, options);
    return run_command(scene_path, sets, options, log_every);
  } catch (const std::exception&) {
    return kerf::report_error(kProgram);
  }
}
