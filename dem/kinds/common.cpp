// What the scene kinds share (dem/kinds/common.hpp).
#include "common.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <optional>

#include "kerf/dem/output/output.hpp"
#include "kerf/dem/output/png.hpp"
#include "kerf/dem/procedures/cut_results.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "kerf/material.hpp"

namespace kerf::dem::kinds {

void name_cut_forces(Json& results) {
  namespace k = cut_keys;
  const Json width = results.value(k::width_mm, Json());
  const auto name = [&](Json& r) {
    std::vector<std::pair<std::string, Json>> canonical;
    for (const auto& [key, value] : r.items())
      if (std::string current = cutting_force_name(key); !current.empty()) canonical.emplace_back(current, value);
    for (auto& [key, value] : canonical) r[key] = std::move(value);
    if (!width.is_number() || !(width.get<double>() > 0)) return;
    for (const auto& [force, per_mm] : {std::pair{k::cutting_force_N, k::cutting_force_N_per_mm},
                                        std::pair{k::thrust_force_N, k::thrust_force_N_per_mm}})
      if (r.contains(force) && r[force].is_number()) r[per_mm] = r[force].get<double>() / width.get<double>();
  };
  name(results);
  if (results.contains(k::travel_windows) && results[k::travel_windows].is_array())
    for (auto& w : results[k::travel_windows]) name(w);
}

ProgressTarget progress_target(const RunOptions& options) {
  return {options.show_progress, options.on_progress, ""};
}

CheckpointSchedule::CheckpointSchedule(const RunOptions& options)
    : every_samples_(options.checkpoint_every),
      every_(options.checkpoint_every_s),
      last_(std::chrono::steady_clock::now()) {}

bool CheckpointSchedule::due(int sample_index) {
  const bool by_samples = every_samples_ > 0 && sample_index % every_samples_ == 0;
  if (every_.count() <= 0) return by_samples;  // no clock read per sample without a wall-time interval
  const auto now = std::chrono::steady_clock::now();
  if (!by_samples && now - last_ < every_) return false;
  last_ = now;
  return true;
}

namespace {
/// One callback at a time across threads (replicates side by side); a mutex, not an OpenMP critical section,
/// so that an exception the callback throws (a Python KeyboardInterrupt) leaves it unlocked.
std::mutex progress_callback_mutex;
}  // namespace

StageProgress::StageProgress(const ProgressTarget& target, const std::string& stage, double total,
                             const std::string& unit)
    : callback_(target.callback), update_{target.prefix + stage, 0, total, unit, std::nullopt} {
  if (target.bar) bar_.emplace(update_.stage, static_cast<std::size_t>(total), unit);
  if (callback_) {
    const std::lock_guard<std::mutex> lock(progress_callback_mutex);
    callback_(update_);
  }
}

void StageProgress::advance(double count, std::optional<SampleState> sample) {
  update_.done += count;
  if (sample) update_.sample = std::move(sample);
  if (bar_) bar_->advance(static_cast<std::size_t>(count));
  if (callback_) {
    const std::lock_guard<std::mutex> lock(progress_callback_mutex);
    callback_(update_);
  }
}

void StageProgress::resume_at(double done, std::optional<SampleState> sample) {
  update_.done = done;
  update_.sample = std::move(sample);
  if (bar_) bar_->resume_at(static_cast<std::size_t>(done));
  if (callback_) {
    ProgressUpdate start = update_;
    start.resumed = true;
    const std::lock_guard<std::mutex> lock(progress_callback_mutex);
    callback_(start);
  }
}

void StageProgress::finish(std::optional<SampleState> sample) {
  if (bar_) bar_->finish();
  if (callback_ && (update_.done != update_.total || sample)) {
    update_.done = update_.total;
    if (sample) update_.sample = std::move(sample);
    const std::lock_guard<std::mutex> lock(progress_callback_mutex);
    callback_(update_);
  }
}

namespace {
/// A genesis's progress: the stage "specimen genesis", begun at the first report (its total known then).
class GenesisStage {
 public:
  explicit GenesisStage(const ProgressTarget& target) : target_(target) {}
  GenesisProgress callback() {
    return [this](std::int64_t done, std::int64_t total) {
      if (!stage_) stage_.emplace(target_, "specimen genesis", static_cast<double>(total), "steps");
      stage_->advance(static_cast<double>(done - shown_));
      shown_ = done;
    };
  }
  /// Ends the stage with the genesis's own steps, for the log's performance lines (its total is an upper bound).
  void finish(std::size_t n_disks) {
    if (stage_) stage_->finish(SampleState{shown_, 0, n_disks, 0, {}, {}, {}, {}, {}});
  }

 private:
  const ProgressTarget& target_;
  std::optional<StageProgress> stage_;
  std::int64_t shown_ = 0;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

Simulation obtain_specimen(const SceneCommon& scene, SpecimenSpec& spec, SpecimenReport& report, double& wall_s,
                           const ProgressTarget& target) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<Simulation> sim;
  if (scene.specimen_file) {
    sim.emplace(load_specimen(*scene.specimen_file, scene.material, spec, report));
  } else {
    spec = scene.specimen;
    GenesisStage stage(target);
    sim.emplace(make_specimen(scene.material, spec, report, stage.callback()));
    stage.finish(sim->particles().size());
  }
  scene.engine.apply_to(*sim);
  wall_s = seconds_since(start);
  return std::move(*sim);
}

Json specimen_json(const SpecimenSpec& spec, const SpecimenReport& report, double wall_s) {
  Json j = specimen_spec_to_json(spec);
  j.update(specimen_report_to_json(report));
  j["genesis_wall_time_s"] = wall_s;
  return j;
}

Json summary_head(const std::string& kind, const Material& material) {
  return Json{{"kind", kind}, {"material", material_to_json(material)}, {"threads", omp_get_max_threads()}};
}

StartedRun start_from_specimen(const SceneCommon& scene, const std::string& kind, const ProgressTarget& progress) {
  SpecimenSpec spec;
  SpecimenReport report;
  double genesis_s = 0;
  Simulation specimen = obtain_specimen(scene, spec, report, genesis_s, progress);
  Json summary = summary_head(kind, scene.material);
  summary["specimen"] = specimen_json(spec, report, genesis_s);
  summary["time_step_s"] = specimen.time_step();
  return {std::move(specimen), spec, report, std::move(summary)};
}

StartedSources start_specimen_sources(const SceneCommon& scene, const std::string& kind, int packings,
                                      const ProgressTarget& progress) {
  if (scene.specimen_file) {
    if (packings != 1)
      throw InputError("calibration.packings", std::to_string(packings), "1 with specimen.file (one saved packing)");
    StartedRun started = start_from_specimen(scene, kind, progress);
    std::vector<SpecimenSource> sources;
    sources.push_back(SpecimenSource::saved(std::move(started.specimen), scene.engine));
    return {std::move(sources), std::move(started.summary)};
  }
  const auto start = std::chrono::steady_clock::now();
  StartedSources out{{}, summary_head(kind, scene.material)};
  for (int k = 0; k < packings; ++k) {
    SpecimenSpec spec = scene.specimen;
    spec.seed += static_cast<std::uint64_t>(k);
    ProgressTarget target = progress;
    if (packings > 1) target.prefix += fmt::format("packing {}: ", k + 1);
    GenesisStage stage(target);
    CompactedPacking packing = compact_packing(spec, stage.callback());
    stage.finish(packing.disks.particles().size());
    if (k == 0) out.summary["specimen"] = specimen_json(spec, packing.report, 0);
    out.sources.push_back(SpecimenSource::genesis(std::move(packing), spec, scene.engine));
  }
  out.summary["specimen"]["genesis_wall_time_s"] = seconds_since(start);
  out.summary["specimen"]["packings"] = packings;
  return out;
}

void write_summary(const RunOptions& options, const Json& scene, Json summary) {
  if (Json provenance = summary_provenance(options, scene); !provenance.is_null())
    summary["provenance"] = std::move(provenance);
  write_file_atomically(options.out / "summary.json", summary.dump(2) + "\n");
}

namespace {
/// OUT/frame_reference.bin: "KERFREF1", the count of values (UInt64), the values (x, y per disk, metres, Float64
/// in the machine's byte order: a resumed run on the same machine reads them back bit for bit).
constexpr std::string_view kReferenceMagic = "KERFREF1";
constexpr const char* kReferenceFile = "frame_reference.bin";

void write_frame_reference(const fs::path& out, const std::vector<double>& reference_m) {
  std::string bytes(kReferenceMagic);
  const std::uint64_t n = reference_m.size();
  bytes.append(reinterpret_cast<const char*>(&n), sizeof n);
  bytes.append(reinterpret_cast<const char*>(reference_m.data()), n * sizeof(double));
  write_file_atomically(out / kReferenceFile, bytes);
}

/// The reference a run wrote with its first frame; empty when there is none to read (a run begun by a kerf
/// before the displacements: its frames get NaN displacements).
std::vector<double> read_frame_reference(const fs::path& out) {
  std::ifstream in(out / kReferenceFile, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t head = kReferenceMagic.size() + sizeof(std::uint64_t);
  std::uint64_t n = 0;
  if (bytes.size() >= head) std::memcpy(&n, bytes.data() + kReferenceMagic.size(), sizeof n);
  // The count read against the bytes that follow (not head + n * 8, which a corrupt count could wrap).
  if (bytes.size() < head || bytes.compare(0, kReferenceMagic.size(), kReferenceMagic) != 0 ||
      (bytes.size() - head) % sizeof(double) != 0 || n != (bytes.size() - head) / sizeof(double))
    return {};
  std::vector<double> reference(n);
  std::memcpy(reference.data(), bytes.data() + head, n * sizeof(double));
  return reference;
}
}  // namespace

void write_frame_files(const fs::path& out, const FrameSource& frame, const OutputSpec& output, RunProgress& progress) {
  const Simulation& sim = frame.sim;
  const std::size_t k = progress.frames.size();
  if (progress.frame_reference_m.empty()) {
    if (k == 0) {
      // The first frame: every disk of the workpiece where it is now (a windowed cut's reservoir: the disks
      // outside the first window have not moved either).
      const Particles& p = frame.window ? frame.window->workpiece().particles() : sim.particles();
      progress.frame_reference_m.resize(2 * p.size());
      for (std::size_t i = 0; i < p.size(); ++i) {
        progress.frame_reference_m[2 * i] = p.x[i];
        progress.frame_reference_m[2 * i + 1] = p.y[i];
      }
      write_frame_reference(out, progress.frame_reference_m);
    } else {
      progress.frame_reference_m = read_frame_reference(out);
      if (progress.frame_reference_m.empty())
        std::cerr << fmt::format(
            "kerf-dem: no {} in {} (a run begun by an earlier kerf): the frames' "
            "displacement_m is NaN\n",
            kReferenceFile, out.string());
    }
  }
  const Particles& p = sim.particles();
  FrameDiskArrays extra;
  extra.id.resize(p.size());
  extra.displacement_m.resize(2 * p.size());
  const std::vector<double>& ref = progress.frame_reference_m;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::int64_t id = frame.window ? frame.window->workpiece_index(i) : static_cast<std::int64_t>(i);
    extra.id[i] = id;
    const auto at = 2 * static_cast<std::size_t>(id);
    const bool known = at + 1 < ref.size();
    extra.displacement_m[2 * i] = known ? p.x[i] - ref[at] : std::nan("");
    extra.displacement_m[2 * i + 1] = known ? p.y[i] - ref[at + 1] : std::nan("");
  }
  const std::string name = fmt::format("frame_{:04d}.vtp", k);
  const std::string walls = fmt::format("walls_{:04d}.vtp", k);
  const std::string cracks = fmt::format("cracks_{:04d}.vtp", k);
  write_vtp_frame(out / name, sim, extra);
  write_walls_vtp(out / walls, sim.walls());
  write_cracks_vtp(out / cracks, sim.cracks(), frame.y_cut_m);
  if (output.frame_png)
    write_specimen_png(out / fmt::format("frame_{:04d}.png", k), sim, fmt::format("{}, frame {}", frame.title, k),
                       frame.view_m);
  progress.frames.push_back({sim.time(), {name, walls, cracks}});
}

const FieldTable<MaterialOutput>& material_output_fields() {
  static const FieldTable<MaterialOutput> table{
      text_field("material_name", "the fitted material: OUT/<name>.json", &MaterialOutput::name,
                 [](const std::string& name) {
                   return name.empty() || name.find_first_of("/\\. ") != std::string::npos
                              ? std::string("a file name without '/', '.', spaces")
                              : std::string();
                 }),
      bool_field("install_material", "also write data/materials/<name>.json", &MaterialOutput::install)};
  return table;
}

MaterialOutput read_material_output(ObjectReader& cal, const std::string& fallback) {
  return read_fields(cal, material_output_fields(), MaterialOutput{fallback, false});
}

void write_material_output(const MaterialOutput& output, const Json& material, const fs::path& out, Json& summary) {
  write_file_atomically(out / (output.name + ".json"), material.dump(2) + "\n");
  if (output.install) {
    const fs::path installed = kerf::data_directory() / "materials" / (output.name + ".json");
    write_file_atomically(installed, material.dump(2) + "\n");
    summary["installed_material"] = installed.string();
  }
}

}  // namespace kerf::dem::kinds
