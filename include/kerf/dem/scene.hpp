#pragma once
// A kerf-dem scene and its kinds, as a library: what the kerf-dem program runs and what other programs (the
// Yang et al. 2018 validation) call directly.
//
// A scene is a JSON document: "kind" names a scene kind; the sections every kind shares (material,
// specimen, engine, output) are read here; the kind reads its own (loading, cut/tool/grooves, calibration).
// A kind is a module with read (its sections, and every check that needs no simulation), check_options
// (the run options it supports), run and resume (from a checkpoint). The kind registry
// (dem/kinds/registry.cpp, one line per kind) constructs a kind by name; an unknown name lists the valid ones.
//
//   const Json doc = read_json_file("scene.json");
//   RunOptions options;
//   options.out = "out";
//   SceneOutcome done = run_scene(doc, "scene.json", options);  // writes out/summary.json and the rest
//   SceneOutcome again = resume_scene("out");                    // a run killed after a checkpoint
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/dem/engine/checkpoint.hpp"
#include "kerf/dem/laws/material.hpp"
#include "kerf/dem/procedures/specimen.hpp"
#include "kerf/field_table.hpp"
#include "kerf/json_reader.hpp"

namespace kerf::dem {

/// The scene's "output" section.
struct OutputSpec {
  int frame_every_samples = 100;  ///< VTK frames every N samples (and the final state); 0: none
  bool frame_png = false;         ///< a PNG picture (frame_K.png) with each VTK frame
};
const FieldTable<OutputSpec>& output_fields();

/// The sections every scene shares.
struct SceneCommon {
  Material material;
  std::optional<std::string> specimen_file;  ///< specimen.file: a saved specimen instead of a genesis
  SpecimenSpec specimen;
  EngineSettings engine;
  OutputSpec output;
};

/// What the latest sample of a stage measured (for log lines). Only the fields of the stage's kind are set:
/// a cut has travel and forces, a tension or compression test strain and stress.
struct SampleState {
  std::int64_t step = 0;  ///< time steps done in the stage
  double time_s = 0;      ///< simulated time since the stage began; 0: not measured (a genesis)
  std::size_t n_particles = 0;
  int cracks = 0;  ///< broken flat-joint elements so far (tension + shear)
  std::optional<double> travel_mm, main_force_N, thrust_force_N;  ///< cut: forces averaged over this sample
  std::optional<double> strain, stress_MPa;                       ///< tension, compression: axial
};

/// One report of a running stage: "specimen genesis", "cut", "tension", "replicate 2: cut", ... The first
/// report of a stage has done = 0 (its start), the last done = total. A stage resumed from a checkpoint starts
/// with a report marked `resumed` whose done and sample are where the checkpoint left it (not work of this
/// process: rates count from there).
struct ProgressUpdate {
  std::string stage;
  double done = 0, total = 0;         ///< in `unit`; done reaches total when the stage finishes
  std::string unit;                   ///< "steps", "particle-steps"
  std::optional<SampleState> sample;  ///< the latest sample (none before the first, nor in a genesis)
  bool resumed = false;               ///< the start of a stage resumed from a checkpoint
};
/// Called as a run advances (every sample; a genesis as it reports). Replicates run side by side report from
/// several threads, never two calls at once.
using ProgressCallback = std::function<void(const ProgressUpdate&)>;

/// How to run a scene (the kerf-dem command line's options).
struct RunOptions {
  std::filesystem::path out = "out";
  int checkpoint_every = 0;  ///< samples between checkpoints (a calibration: one per evaluation); 0: none
  /// Besides: a checkpoint at the first sample after this much wall time since the last one (a study's
  /// items; a calibration: one per evaluation); 0: none.
  double checkpoint_every_s = 0;
  bool checkpoints() const { return checkpoint_every > 0 || checkpoint_every_s > 0; }
  int replicates = 1;                  ///< cut scenes: packings specimen.seed + 0 .. replicates - 1
  bool show_progress = true;           ///< progress bars on stderr (drawn only when it is a terminal)
  ProgressCallback on_progress;        ///< besides the bars (a notebook, a log); empty: none
  std::string command_line;            ///< what started the run, for summary.json's provenance
  std::vector<std::string> overrides;  ///< the --set assignments already applied to the scene, for the same
  /// The run's provenance block (run_scene and resume_scene set it), kept in its checkpoints so that a resume
  /// reports the run it continues; null: none (a study's items).
  Json provenance;
};

/// What a run produced: its exit status (0; kExitModelError for a calibration that did not converge), the
/// summary written to OUT/summary.json, and for replicated cuts each replicate's own summary.
struct SceneOutcome {
  int exit_status = 0;
  Json summary;
  std::vector<Json> replicate_summaries;
};

/// The context of one run: the scene as run (what a checkpoint stores), its directory, the options.
struct SceneRun {
  Json doc;
  std::string scene_dir;  ///< absolute: specimen.file is found relative to it on resume
  RunOptions options;
};

/// One scene kind (see the top of this header).
class SceneKind {
 public:
  virtual ~SceneKind() = default;
  /// The kind's name, as a scene's "kind" gives it: written once, in the kind's own file (the registry lists these).
  virtual std::string name() const = 0;
  /// Reads and validates the kind's own sections of the scene root; the shared ones are already in `common`.
  virtual void read(ObjectReader& root, const SceneCommon& common) = 0;
  /// Rejects options the kind does not support (InputError naming the option). The default allows
  /// checkpoints and rejects replicates.
  virtual void check_options(const RunOptions& options, const SceneCommon& common) const;
  virtual SceneOutcome run(const SceneCommon& common, const SceneRun& run) = 0;
  /// Continues a run from its checkpoint (only kinds that write checkpoints get one).
  virtual SceneOutcome resume(const SceneCommon& common, const SceneRun& run, const Checkpoint& checkpoint);
  /// Whether the kind writes checkpoints when RunOptions asks for them (a study then checkpoints its items).
  virtual bool writes_checkpoints() const { return false; }
};

/// Makes a new kind object: what the registry holds of each kind.
using SceneKindFactory = std::unique_ptr<SceneKind> (*)();
/// The registered kinds' names, in the registry's order: the library's (dem/kinds/registry.cpp), then those a
/// program registered.
std::vector<std::string> scene_kind_names();
/// A new kind object for `name`; InputError on `path` listing the valid names otherwise.
std::unique_ptr<SceneKind> make_scene_kind(const std::string& name, const std::string& path = "kind");
/// Adds a kind to the registry, after the library's: a program's own (the test suite's kerf-dem-test-kinds,
/// tests/tools/kerf_dem_test_kinds.cpp, registers its test kind before it runs kerf-dem's main). Call it before any
/// scene is read (not thread-safe); std::logic_error when a kind of that name is registered already.
void register_scene_kind(SceneKindFactory make);

/// The scene sections with a key table: specimen, engine, loading, cut, tool, grooves, calibration,
/// calibration.targets, output ("material" is kerf/dem/laws/material.hpp's).
std::vector<std::string> scene_sections();
/// The Markdown key table of one section (all of them when `section` is empty), as docs/dem-keys.md holds them;
/// InputError listing the sections for an unknown one.
std::string scene_keys_markdown(const std::string& section = "");
/// The result tables of the kinds (kerf/result_table.hpp) as Markdown, as docs/dem-keys.md holds them: what each
/// writes into summary.json (kerf-dem results).
std::string scene_results_markdown();
/// The result keys as the Python module kerf.result_keys (python/kerf/result_keys.py; kerf-dem results --python).
std::string result_keys_python();

struct Scene {
  std::string kind_name;
  SceneCommon common;
  std::unique_ptr<SceneKind> kind;
};

/// Reads and validates a scene (unknown keys are rejected); `scene_dir` resolves a relative specimen.file.
Scene read_scene(const Json& doc, const std::filesystem::path& scene_dir);

/// The "provenance" block of a run's summary: the run's provenance (RunOptions::provenance) with the scene as
/// run; null when the run has none (a study's item, whose summary the study completes, or a run inside another).
Json summary_provenance(const RunOptions& options, const Json& scene);

/// Reads the scene, checks the options, creates options.out and runs it. `scene_file` is where the scene
/// came from (specimen.file is relative to its directory). OUT/summary.json (and the outcome's summary) get a
/// "provenance" block: version, git commit, command line, scene path and hash, overrides, the scene as run, date,
/// host, threads (kerf/version.hpp).
SceneOutcome run_scene(const Json& doc, const std::filesystem::path& scene_file, const RunOptions& options);

/// Continues the run killed in `dir` from dir/checkpoint.bin (options.out is `dir`). The summary's provenance is
/// the original run's (command line, scene path and hash, overrides, date: kept in the checkpoint), with a
/// "resumes" list: per resume its date, `command_line`, the sample it continued from, version, host, threads.
SceneOutcome resume_scene(const std::filesystem::path& dir, bool show_progress = true,
                          const ProgressCallback& on_progress = {}, const std::string& command_line = "");

}  // namespace kerf::dem
