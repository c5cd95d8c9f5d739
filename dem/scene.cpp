// A kerf-dem scene: the shared sections, the run options, running and resuming (kerf/dem/scene.hpp).
#include "kerf/dem/scene.hpp"

#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/version.hpp"

namespace kerf::dem {

namespace fs = std::filesystem;

const FieldTable<OutputSpec>& output_fields() {
  static const FieldTable<OutputSpec> table{
      int_field("frame_every_samples", 0, 100000000,
                "VTK frames (particles, joints, walls, cracks) every N samples and of the final state; 0: none",
                &OutputSpec::frame_every_samples),
      bool_field("frame_png", "also a picture with each VTK frame, as specimen.png: frame_K.png (and its PDF)",
                 &OutputSpec::frame_png)};
  return table;
}

void SceneKind::check_options(const RunOptions& options, const SceneCommon&) const {
  if (options.replicates > 1)
    throw InputError("--replicates", std::to_string(options.replicates),
                     "replicates only for cut and toughness scenes (calibrate_cut: calibration.replicates)");
}

SceneOutcome SceneKind::resume(const SceneCommon&, const SceneRun&, const Checkpoint&) {
  throw ModelError("kerf-dem", "a checkpoint of a scene kind that writes none");
}

Scene read_scene(const Json& doc, const fs::path& scene_dir) {
  ObjectReader root(doc, "");
  Scene s;
  if (!root.has("kind") && doc.contains("models") && doc.contains("cut")) {
    // A scene of the analytic models (no kind, a "models" section): the other program's.
    throw InputError("kind", "(missing)",
                     "one of the kerf-dem kinds: this is a kerf-forces scene (analytic models, no kind); run it with "
                     "kerf-forces predict");
  }
  s.kind_name = root.get_string("kind");
  s.kind = make_scene_kind(s.kind_name, root.key_path("kind"));
  root.ignore("description");
  s.common.material = read_scene_material(root);
  if (auto spec = root.find_object("specimen")) {
    if (spec->has("file")) {
      fs::path file = spec->get_string("file");
      if (file.is_relative()) file = scene_dir / file;
      if (!fs::exists(file)) throw InputError("specimen.file", file.string(), "an existing specimen file");
      s.common.specimen_file = file.string();
    } else {
      s.common.specimen = read_specimen_spec(*spec);
    }
    spec->finish();
  }
  s.common.engine = read_engine_settings(root);
  s.kind->read(root, s.common);
  if (auto output = root.find_object("output")) {
    s.common.output = read_fields(*output, output_fields(), OutputSpec{});
    output->finish();
  }
  root.finish();
  return s;
}

namespace {

/// The outcome's summary with the provenance block its OUT/summary.json got (write_summary).
SceneOutcome with_provenance(SceneOutcome outcome, const RunOptions& options, const Json& scene) {
  outcome.summary["provenance"] = summary_provenance(options, scene);
  return outcome;
}

}  // namespace

Json summary_provenance(const RunOptions& options, const Json& scene) {
  if (!options.provenance.is_object()) return Json();
  Json provenance = options.provenance;
  provenance["scene_as_run"] = scene;
  return provenance;
}

SceneOutcome run_scene(const Json& doc, const fs::path& scene_file, const RunOptions& options) {
  const Scene scene = read_scene(doc, scene_file.parent_path());
  scene.kind->check_options(options, scene.common);
  if (options.checkpoint_every > 0 && options.replicates > 1)
    throw InputError("--checkpoint-every", std::to_string(options.checkpoint_every),
                     "no checkpoints with --replicates");
  const OutputManifest hold(options.out, /*fresh=*/true);  // writable? then the old outputs go, before any work
  RunOptions with_provenance_kept = options;               // the checkpoints keep it for a resume
  with_provenance_kept.provenance = run_provenance(options.command_line, scene_file.string(), options.overrides);
  const SceneRun run{doc, fs::absolute(scene_file).parent_path().string(), with_provenance_kept};
  return with_provenance(scene.kind->run(scene.common, run), with_provenance_kept, doc);
}

SceneOutcome resume_scene(const fs::path& dir, bool show_progress, const ProgressCallback& on_progress,
                          const std::string& command_line) {
  const Checkpoint c = read_checkpoint(dir);
  const Scene scene = read_scene(c.scene, c.scene_dir);
  RunOptions options;
  options.out = dir;
  options.checkpoint_every = c.checkpoint_every;
  options.show_progress = show_progress;
  options.on_progress = on_progress;
  const OutputManifest hold(dir, /*fresh=*/false);
  // The original run's provenance (a checkpoint of a kerf before it kept none: its command line is unknown),
  // and this resume appended: a checkpoint written from here on keeps both for the next one.
  options.provenance = c.provenance.is_object()
                           ? c.provenance
                           : run_provenance("(unknown: the checkpoint predates provenance in checkpoints)", "", {});
  const Json now = run_provenance(command_line, "", {});
  Json resume{{"from_sample", c.sample_index}, {"checkpoint", (dir / "checkpoint.bin").string()}};
  for (const char* key : {"date", "command_line", "version", "git_commit", "host", "threads"})
    resume[key] = now.at(key);
  options.provenance["resumes"].push_back(std::move(resume));
  return with_provenance(scene.kind->resume(scene.common, SceneRun{c.scene, c.scene_dir, options}, c), options,
                         c.scene);
}

}  // namespace kerf::dem
