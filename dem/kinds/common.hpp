#pragma once
// What the scene kinds share (internal to dem/kinds/): the specimen (genesis or file), the summary's head,
// VTK frames, the material a calibration writes, and the factories the kind registry calls.
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/procedures/calibration.hpp"
#include "kerf/dem/procedures/cut_calibration.hpp"
#include "kerf/dem/procedures/cut_window.hpp"
#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/dem/procedures/lab_test.hpp"
#include "kerf/dem/procedures/toughness.hpp"
#include "kerf/dem/scene.hpp"
#include "kerf/io.hpp"
#include "kerf/result_table.hpp"

namespace kerf::dem::kinds {

namespace fs = std::filesystem;

/// Where a run's progress goes: the terminal bar and the caller's callback (RunOptions).
struct ProgressTarget {
  bool bar = true;            ///< false for replicates run side by side (one bar each would garble the terminal)
  ProgressCallback callback;  ///< empty: none
  std::string prefix;         ///< before the stage's name ("replicate 2: ")
};
ProgressTarget progress_target(const RunOptions& options);

/// One stage's progress: advances its bar and reports to the callback (serialised across threads).
class StageProgress {
 public:
  /// Reports the start (done = 0) to the callback.
  StageProgress(const ProgressTarget& target, const std::string& stage, double total, const std::string& unit);
  /// Adds `count` units done; `sample` is what the stage measured last (kept for later reports).
  void advance(double count, std::optional<SampleState> sample = std::nullopt);
  /// A stage resumed from a checkpoint: `done` units and `sample` were done before (reported as `resumed`,
  /// left out of the rates). Call it before the first advance.
  void resume_at(double done, std::optional<SampleState> sample);
  /// Ends the stage at 100 %; `sample`: its last one, when advance has not reported it.
  void finish(std::optional<SampleState> sample = std::nullopt);

 private:
  std::optional<Progress> bar_;
  ProgressCallback callback_;
  ProgressUpdate update_;
};

/// The specimen of a scene: loaded from specimen.file or made by genesis (its progress shown), the engine
/// settings applied; `spec`, `report` and the wall time are filled in.
Simulation obtain_specimen(const SceneCommon& scene, SpecimenSpec& spec, SpecimenReport& report, double& wall_s,
                           const ProgressTarget& progress);

/// The summary's "specimen" object: the spec, the report and the genesis wall time.
Json specimen_json(const SpecimenSpec& spec, const SpecimenReport& report, double wall_s);

/// {"kind", "material", "threads"}: how every summary begins.
Json summary_head(const std::string& kind, const Material& material);

/// A scene's specimen with the head of its summary: what every kind that starts from one specimen does first.
struct StartedRun {
  Simulation specimen;
  SpecimenSpec spec;
  SpecimenReport report;
  Json summary;  ///< summary_head, "specimen" (specimen_json) and "time_step_s"
};
StartedRun start_from_specimen(const SceneCommon& scene, const std::string& kind, const ProgressTarget& progress);

/// What a calibration builds its candidates' specimens from, with the head of its summary. From a genesis: the
/// compacted packings of seeds specimen.seed + 0..packings-1 (the summary's "specimen" has the first
/// compaction's report, no joints yet, and "packings"); from specimen.file: the saved specimen, one packing (as
/// start_from_specimen; more is an input error naming calibration.packings).
struct StartedSources {
  std::vector<SpecimenSource> sources;
  Json summary;
};
StartedSources start_specimen_sources(const SceneCommon& scene, const std::string& kind, int packings,
                                      const ProgressTarget& progress);

/// Writes options.out/summary.json, with the run's provenance block (summary_provenance) when it has one: the
/// summary is written once, by its kind, never read back to be completed.
void write_summary(const RunOptions& options, const Json& scene, Json summary);

/// A cut's results under kerf-forces' names (issue 55 item 5): every `main_force...` key copied as
/// `cutting_force...` (the old name is kept, deprecated, until 0.3.0), and `cutting_force_N_per_mm`,
/// `thrust_force_N_per_mm`: the forces divided by the cut's width `width_mm` (the specimen's thickness), per mm of
/// width at any thickness. The `travel_windows` rows too, by the results' width.
void name_cut_forces(Json& results);

/// When a run writes its next checkpoint (RunOptions): every checkpoint_every samples, and at the first
/// sample after checkpoint_every_s of wall time since the last one (or the start).
class CheckpointSchedule {
 public:
  explicit CheckpointSchedule(const RunOptions& options);
  /// Whether to write one after sample `sample_index`; true restarts the wall-time interval.
  bool due(int sample_index);

 private:
  int every_samples_;
  std::chrono::duration<double> every_;
  std::chrono::steady_clock::time_point last_;
};

/// Where a run stands between checkpoints: frames written, samples done.
struct RunProgress {
  FrameList frames;
  int sample_index = 0;
  std::string scene_dir;
  ProgressTarget progress;
  /// The disks' positions at the run's first frame [m], x and y per disk of the workpiece (empty until the
  /// first frame is written or, on a resume, read back from OUT/frame_reference.bin).
  std::vector<double> frame_reference_m;
};

/// What a frame shows: the running simulation, and for a cut its window (null without one: the disks'
/// workpiece indices and the whole workpiece at the first frame), its cut line (the cracks' place) and the
/// region of its PNG pictures.
struct FrameSource {
  const Simulation& sim;
  const CutWindow* window = nullptr;
  std::optional<double> y_cut_m;
  std::optional<std::array<double, 4>> view_m;
  std::string title;  ///< the PNG's title before ", t = ..."
};

/// Writes the next VTK frame (particles and joints, walls, cracks: parts 0, 1, 2) and records it for the .pvd
/// series; with output.frame_png, frame_K.png too. The first frame also writes OUT/frame_reference.bin (the
/// disks' positions in metres, bit for bit: the displacements' reference, read back by a resumed run, so that
/// its frames are those of an uninterrupted one).
void write_frame_files(const fs::path& out, const FrameSource& frame, const OutputSpec& output, RunProgress& progress);

/// calibration.material_name (a file name) and calibration.install_material of calibrate and calibrate_cut.
struct MaterialOutput {
  std::string name;
  bool install = false;  ///< also write data/materials/<name>.json (the data directory in use)
};
const FieldTable<MaterialOutput>& material_output_fields();
/// Reads material_name (default `fallback`) and install_material.
MaterialOutput read_material_output(ObjectReader& calibration, const std::string& fallback);
/// Writes the fitted material to OUT/<name>.json and, with install, to the data directory (summary notes it).
void write_material_output(const MaterialOutput& output, const Json& material, const fs::path& out, Json& summary);

/// Yang et al. 2018, Section 4 repeats each cut on `replicates` packings: replicate k uses packing seed specimen.seed +
/// k. They run as a study of one condition (`cut_scene`, a scene of kind cut, with replicates) into
/// OUT/replicates (items/condition_1_seed_S/ each; finished ones reused on a rerun); OUT/summary.json has the
/// per-replicate results and their mean and (sample) standard deviation. `summary` is the head every summary
/// starts with (kind, material, threads).
SceneOutcome run_cut_replicates(const Json& cut_scene, const std::string& scene_dir, const CutParams& cut,
                                int replicates, Json summary, const RunOptions& options);

// The kinds (one file each under dem/kinds/; each names itself, SceneKind::name), constructed by the registry.
std::unique_ptr<SceneKind> make_specimen_kind();
std::unique_ptr<SceneKind> make_tension_kind();
std::unique_ptr<SceneKind> make_compression_kind();
std::unique_ptr<SceneKind> make_calibrate_kind();
std::unique_ptr<SceneKind> make_cut_kind();
std::unique_ptr<SceneKind> make_calibrate_cut_kind();
std::unique_ptr<SceneKind> make_toughness_kind();

}  // namespace kerf::dem::kinds

namespace kerf::dem::kinds {
/// The key tables of the kinds' own "calibration" sections (Markdown, for kerf-dem keys).
std::string calibrate_keys_markdown();
std::string calibrate_targets_keys_markdown();
std::string calibrate_toughness_keys_markdown();
std::string calibrate_cut_keys_markdown();
}  // namespace kerf::dem::kinds
