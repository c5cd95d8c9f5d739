// The scene layer (dem/scene.cpp, dem/kinds/): the kind registry, the field tables of the scene sections and
// a small cut run end to end through run_scene against stored forces and crack counts.
#include "kerf/dem/scene.hpp"

#include <omp.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/dem/procedures/lab_test.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"

using namespace kerf::dem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using kerf::Json;

namespace {

// A scratch directory of this process's own (runs of the suite side by side, e.g. a sanitized one, do not collide).
std::filesystem::path scratch_dir(const std::string& name) {
  return std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
}
/// The same keys and texts, numbers equal to within an ulp or two: a unit conversion and its inverse
/// (mm -> m -> mm) are not exact inverses in floating point.
void check_same_json(const Json& a, const Json& b) {
  REQUIRE(a.type() == b.type());
  if (a.is_object()) {
    REQUIRE(a.size() == b.size());
    for (const auto& [key, value] : a.items()) {
      INFO(key);
      REQUIRE(b.contains(key));
      check_same_json(value, b.at(key));
    }
  } else if (a.is_number_float()) {
    CHECK_THAT(a.get<double>(), WithinRel(b.get<double>(), 1e-15));
  } else {
    CHECK(a == b);
  }
}
}  // namespace

TEST_CASE("scene: the registry constructs every registered kind, an unknown kind lists the valid ones", "[scene]") {
  const std::vector<std::string> names = scene_kind_names();
  CHECK(names == std::vector<std::string>{"specimen", "tension", "compression", "calibrate", "cut", "calibrate_cut",
                                          "toughness"});
  for (const auto& name : names) {
    const std::unique_ptr<SceneKind> kind = make_scene_kind(name);
    REQUIRE(kind != nullptr);
    CHECK(kind->name() == name);  // the registry's names are the kinds' own
  }
  // A program registers kinds of its own (tests/tools/kerf_dem_test_kinds.cpp), but none of a name already taken.
  CHECK_THROWS_WITH(register_scene_kind(+[] { return make_scene_kind("cut"); }),
                    "register_scene_kind: kind 'cut' is registered already");
  CHECK(scene_kind_names() == names);
  CHECK_THROWS_WITH(make_scene_kind("cutt"),
                    "kind = cutt: expected one of 'specimen', 'tension', 'compression', 'calibrate', 'cut', "
                    "'calibrate_cut', 'toughness' (did you mean 'cut'?)");
  CHECK_THROWS_WITH(read_scene(Json{{"kind", "tensoin"}}, "."),
                    Catch::Contains("kind = tensoin") && Catch::Contains("did you mean 'tension'?"));
}

TEST_CASE("scene: a scene is read and checked before any genesis", "[scene]") {
  const Json cut{{"kind", "cut"}, {"cut", {{"depth_of_cut_mm", 0.1}, {"length_mm", 0.3}}}};
  const Scene scene = read_scene(cut, ".");
  CHECK(scene.kind_name == "cut");
  CHECK(scene.common.output.frame_every_samples == 100);
  // Unknown keys, ranges and missing required keys name the JSON path.
  Json bad = cut;
  bad["cut"]["depth_of_cut_mn"] = 0.1;
  CHECK_THROWS_WITH(read_scene(bad, "."), Catch::Contains("cut.depth_of_cut_mn") && Catch::Contains("depth_of_cut_mm"));
  bad = cut;
  bad["cut"].erase("length_mm");
  CHECK_THROWS_WITH(read_scene(bad, "."), Catch::Contains("cut.length_mm"));
  bad = cut;
  bad["specimen"] = Json{{"radius_min_um", 10}, {"radius_max_um", 8}};
  CHECK_THROWS_WITH(read_scene(bad, "."),
                    Catch::StartsWith("specimen.radius_max_um = 8: expected a value >= radius_min_um"));
  bad = cut;
  bad["grooves"] = Json{{"shape", "trapezoid"}};
  CHECK_THROWS_WITH(read_scene(bad, "."),
                    Catch::Contains("grooves.shape = trapezoid") && Catch::Contains("did you mean 'trapezoidal'?"));
  bad = cut;
  bad["output"] = Json{{"frame_every_samples", -1}};
  CHECK_THROWS_AS(read_scene(bad, "."), kerf::InputError);
  // Options a kind does not support.
  RunOptions options;
  options.replicates = 3;
  CHECK_THROWS_WITH(read_scene(Json{{"kind", "tension"}}, ".").kind->check_options(options, {}),
                    Catch::Contains("--replicates = 3"));
  options.replicates = 1;
  options.checkpoint_every = 5;
  CHECK_THROWS_WITH(read_scene(Json{{"kind", "specimen"}}, ".").kind->check_options(options, {}),
                    Catch::Contains("--checkpoint-every = 5"));
}

TEST_CASE("scene: field tables read the struct's defaults, check ranges and round-trip through to_json", "[scene]") {
  // Defaults: an empty section gives the struct's initialisers.
  const Json empty = Json::object();
  kerf::ObjectReader none(empty, "specimen");
  const SpecimenSpec spec = read_specimen_spec(none);
  CHECK(kerf::fields_to_json(specimen_fields(), spec) == kerf::fields_to_json(specimen_fields(), SpecimenSpec{}));
  CHECK(spec.packing == Packing::random);
  // Round trip: to_json, then read, gives the same struct (to within an ulp: unit conversions round).
  SpecimenSpec s;
  s.packing = Packing::hexagonal;
  s.seed = 42;
  s.width_m = 0.4e-3;
  const Json j = specimen_spec_to_json(s);
  kerf::ObjectReader back(j, "specimen");
  check_same_json(specimen_spec_to_json(read_specimen_spec(back)), j);
  CHECK(j.at("packing") == "hexagonal");
  CutParams p;
  p.cut.depth_of_cut_m = 0.05e-3;
  p.grooves.shape = GrooveShape::trapezoidal;
  p.tool.friction_coefficient = 0.1;
  const Json cj = cut_params_to_json(p);
  kerf::ObjectReader root(cj, "");
  check_same_json(cut_params_to_json(read_cut_params(root)), cj);
  LoadingSpec l;
  l.quasi_static_check = false;
  const Json lj = kerf::fields_to_json(loading_fields(), l);
  kerf::ObjectReader lr(lj, "loading");
  check_same_json(kerf::fields_to_json(loading_fields(), read_loading_spec(lr, LabTest::compression)), lj);
  // Tension's own default of max_strain.
  kerf::ObjectReader t(empty, "loading");
  CHECK(read_loading_spec(t, LabTest::tension).max_strain == 0.005);
  // Ranges: a physics check names the key; the scene layer adds the path.
  s = SpecimenSpec{};
  s.packing_fraction = 0.95;
  CHECK_THROWS_WITH(check_specimen_spec(s), Catch::StartsWith("packing_fraction = 0.95: expected"));
  CHECK_THROWS_WITH(kerf::with_path("specimen", [&] { check_specimen_spec(s); }),
                    Catch::StartsWith("specimen.packing_fraction = 0.95"));
  p = CutParams{};
  p.tool.edge_segments = 0;
  CHECK_THROWS_WITH(validate_cut_params(p), Catch::StartsWith("tool.edge_segments = 0"));
  // Unknown key (the reader's finish) with a suggestion.
  const Json typo{{"seeed", 3}};
  kerf::ObjectReader r(typo, "specimen");
  read_specimen_spec(r);
  CHECK_THROWS_WITH(r.finish(), Catch::Contains("specimen.seeed") && Catch::Contains("did you mean 'seed'?"));
  // Every section has a key table; an unknown one lists them.
  for (const auto& section : scene_sections())
    CHECK(scene_keys_markdown(section).find("| key | unit |") != std::string::npos);
  CHECK_THROWS_WITH(scene_keys_markdown("tol"), Catch::Contains("SECTION = tol") && Catch::Contains("'tool'"));
}

TEST_CASE("scene: small cut regression through run_scene", "[scene][regression]") {
  // A miniature of the Yang et al. 2018 validation cut (2 s on one thread). Reference forces and crack counts with
  // their tolerance; regenerate with KERF_REGENERATE_REFERENCE=1 build/tests/kerf_dem_tests '[regression]'.
  const std::string file = std::string(KERF_SOURCE_DIR) + "/tests/dem/reference/cut_small.json";
  const Json scene = Json::parse(R"({"kind": "cut", "material": {"base": "soda_lime_glass_fj"},
    "specimen": {"width_mm": 0.4, "height_mm": 0.25, "radius_min_um": 10, "radius_max_um": 13, "seed": 1,
                 "growth_steps": 2000, "relax_steps": 500},
    "cut": {"depth_of_cut_mm": 0.05, "speed_m_per_s": 2, "length_mm": 0.1},
    "grooves": {"shape": "rectangular", "pitch_mm": 0.08, "width_mm": 0.03},
    "output": {"frame_every_samples": 0}})");
  RunOptions options;
  options.out = scratch_dir("kerf_scene_test_cut_small");
  options.show_progress = false;
  std::filesystem::remove_all(options.out);
  const SceneOutcome done = run_scene(scene, std::string(KERF_SOURCE_DIR) + "/data/scenes/scene.json", options);
  CHECK(done.exit_status == 0);
  CHECK(std::filesystem::exists(options.out / "forces.csv"));
  const Json& r = done.summary.at("results");
  Json now;
  for (const char* key : {"main_force_N", "thrust_force_N", "main_force_std_N", "thrust_force_std_N", "cracks_tensile",
                          "cracks_shear", "cracks_chip", "cracks_subsurface", "particles_removed_by_grooves"})
    now[key] = r.at(key);
  now["n_particles"] = done.summary.at("n_particles");
  std::filesystem::remove_all(options.out);
  if (const char* env = std::getenv("KERF_REGENERATE_REFERENCE"); env && std::string(env) == "1") {
    const Json out{{"description",
                    "tests/dem/scene_test.cpp 'small cut regression through run_scene'; regenerate with "
                    "KERF_REGENERATE_REFERENCE=1 build/tests/kerf_dem_tests '[regression]'"},
                   {"relative_tolerance", 0.02},
                   {"crack_count_tolerance", 3},
                   {"values", now}};
    kerf::write_file_atomically(file, out.dump(2) + "\n");
    WARN("reference regenerated: " << file);
    return;
  }
  const Json ref = kerf::read_json_file(file);
  const double tol = ref.at("relative_tolerance"), cracks = ref.at("crack_count_tolerance");
  CHECK(now.at("n_particles") == ref.at("values").at("n_particles"));
  CHECK(now.at("particles_removed_by_grooves") == ref.at("values").at("particles_removed_by_grooves"));
  for (const auto& [key, value] : ref.at("values").items()) {
    INFO(key);
    if (key.rfind("cracks_", 0) == 0)
      CHECK_THAT(now.at(key).get<double>(), WithinAbs(value.get<double>(), cracks));
    else
      CHECK_THAT(now.at(key).get<double>(), WithinRel(value.get<double>(), tol));
  }
}

namespace {
/// The small cut of the regression above, as a replicated scene the tests below vary.
Json small_cut_scene() {
  return Json::parse(R"({"kind": "cut", "material": {"base": "soda_lime_glass_fj"},
    "specimen": {"width_mm": 0.4, "height_mm": 0.25, "radius_min_um": 10, "radius_max_um": 13, "seed": 1,
                 "growth_steps": 2000, "relax_steps": 500},
    "cut": {"depth_of_cut_mm": 0.05, "speed_m_per_s": 2, "length_mm": 0.02},
    "output": {"frame_every_samples": 0}})");
}
}  // namespace

TEST_CASE("scene: progress reaches the caller's callback, every stage to its end", "[scene]") {
  RunOptions options;
  options.out = scratch_dir("kerf_scene_test_progress");
  options.show_progress = false;
  std::vector<ProgressUpdate> seen;
  options.on_progress = [&](const ProgressUpdate& u) { seen.push_back(u); };
  std::filesystem::remove_all(options.out);
  const SceneOutcome done =
      run_scene(small_cut_scene(), std::string(KERF_SOURCE_DIR) + "/data/scenes/scene.json", options);
  std::filesystem::remove_all(options.out);
  // Every cut's summary carries the standard errors of its mean forces and how they were found.
  const Json& r = done.summary.at("results");
  for (const char* force : {"main_force", "thrust_force"}) {
    const std::string method = r.at(std::string(force) + "_sem_method");
    CHECK((method == "batch_means" || method == "autocorrelation" || method == "none"));
    CHECK((method == "none") == r.at(std::string(force) + "_sem_N").is_null());
    CHECK(r.at(std::string(force) + "_inefficiency_samples").get<double>() >= 1);
  }
  std::vector<std::string> stages;
  for (std::size_t k = 0; k < seen.size(); ++k) {
    if (stages.empty() || stages.back() != seen[k].stage) stages.push_back(seen[k].stage);
    if (k > 0 && seen[k].stage == seen[k - 1].stage) CHECK(seen[k].done >= seen[k - 1].done);  // never backwards
    CHECK(seen[k].done <= seen[k].total * (1 + 1e-12));
  }
  REQUIRE(stages == std::vector<std::string>{"specimen genesis", "cut"});
  CHECK(seen.back().done == seen.back().total);  // the cut's stage ends at 100 %
  CHECK(seen.back().unit == "particle-steps");
}

TEST_CASE("scene: a cut the workpiece cannot hold is refused after the geneses in flight, not one per replicate",
          "[scene]") {
  // The tool speed bound needs the workpiece's time step: it is checked after each replicate's genesis, and
  // the first replicate that fails stops the others (the study's stop_at_first_failure) with its input error.
  // Items run side by side, one per thread: one thread sees one genesis, two threads at most two (in parallel).
  Json scene = small_cut_scene();
  scene["cut"]["speed_m_per_s"] = 1e6;
  const int threads_before = omp_get_max_threads();
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    RunOptions options;
    options.out = scratch_dir("kerf_scene_test_replicates_refused");
    options.show_progress = false;
    options.replicates = 4;
    std::set<std::string> genesis_stages;
    options.on_progress = [&](const ProgressUpdate& u) {
      if (u.stage.find("specimen genesis") != std::string::npos) genesis_stages.insert(u.stage);
    };
    std::filesystem::remove_all(options.out);
    try {
      run_scene(scene, std::string(KERF_SOURCE_DIR) + "/data/scenes/scene.json", options);
      FAIL("a tool speed of 1e6 m/s accepted");
    } catch (const kerf::InputError& e) {
      CHECK(e.field() == "cut.speed_m_per_s");
    }
    INFO(threads << " threads");
    CHECK(genesis_stages.count("condition_1_seed_1: specimen genesis") == 1);
    CHECK(static_cast<int>(genesis_stages.size()) <= threads);
    CHECK(std::filesystem::is_empty(options.out / "replicates" / "items"));  // no item kept
    CHECK_FALSE(std::filesystem::exists(options.out / "summary.json"));
    std::filesystem::remove_all(options.out);
  }
  omp_set_num_threads(threads_before);
}
