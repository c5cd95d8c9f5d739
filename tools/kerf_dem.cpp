// kerf-dem: the 2D bonded-particle DEM with flat joints (issue 4), a thin front end to the library
// (kerf/dem/scene.hpp: the scene kinds, replicates, checkpoints).
//
//   kerf-dem run SCENE.json [--set key.path=value]... [--out DIR] [--threads N] [--checkpoint-every N] [--replicates N]
//   kerf-dem resume DIR [--threads N]
//   kerf-dem keys [SECTION]      the Markdown key table of every scene section (docs/dem.md), or of one
//
// Exit status 2 for bad input (the message names the field, the value and what was expected), 3 when the
// model fails (e.g. an unstable run, a calibration that does not converge, a damaged checkpoint), 4 when an
// output cannot be written (the directory is checked before any work).
#include <fmt/format.h>
#include <omp.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "kerf/dem/scene.hpp"
#include "kerf/error.hpp"
#include "kerf/json_reader.hpp"

namespace {

constexpr const char* kProgram = "kerf-dem";

int run_command(const std::string& scene_path, const std::vector<std::string>& sets, kerf::dem::RunOptions options) {
  kerf::Json doc = kerf::read_json_file(scene_path);
  for (const auto& s : sets) kerf::apply_override(doc, s);
  return kerf::dem::run_scene(doc, scene_path, options).exit_status;
}

int keys_command(const std::string& section) {
  std::cout << kerf::dem::scene_keys_markdown(section);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"kerf-dem: 2D bonded-particle DEM with Potyondy's flat joint"};
  app.require_subcommand(1);
  std::string scene_path, resume_dir, section;
  std::vector<std::string> sets;
  std::string out_dir = "out";
  kerf::dem::RunOptions options;
  int threads = 0;
  const std::string kinds = fmt::format("{}", fmt::join(kerf::dem::scene_kind_names(), ", "));
  auto* run = app.add_subcommand("run", "run a scene (kind: " + kinds + ")");
  run->add_option("scene", scene_path, "scene JSON file")->required();
  run->add_option("--set", sets, "override a scene value: key.path=value (repeatable)");
  run->add_option("--out", out_dir, "output directory (default: out)");
  run->add_option("--threads", threads, "OpenMP threads (default: all)")->check(CLI::Range(1, 1024));
  run->add_option("--checkpoint-every", options.checkpoint_every,
                  "write DIR/checkpoint.bin every N samples (tension, compression, cut; calibrate: after every evaluation)")
      ->check(CLI::Range(1, 100000000));
  run->add_option("--replicates", options.replicates, "cut scenes: repeat on N packings (seeds specimen.seed + 0..N-1)")
      ->check(CLI::Range(1, 1000));
  auto* resume = app.add_subcommand("resume", "continue a killed test, cut or calibration from DIR/checkpoint.bin");
  resume->add_option("dir", resume_dir, "output directory of the killed run")->required();
  resume->add_option("--threads", threads, "OpenMP threads (default: all)")->check(CLI::Range(1, 1024));
  auto* keys = app.add_subcommand("keys", "print the Markdown key table of the scene sections (docs/dem.md)");
  keys->add_option("section", section, "one section (" + fmt::format("{}", fmt::join(kerf::dem::scene_sections(), ", ")) +
                                            "; default: all)");
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
    if (resume->parsed()) return kerf::dem::resume_scene(resume_dir).exit_status;
    if (out_dir.empty()) throw kerf::InputError("--out", "\"\"", "a directory name");
    options.out = out_dir;
    return run_command(scene_path, sets, options);
  } catch (const kerf::InputError& e) {
    return error(e.what(), kerf::kExitInputError);
  } catch (const kerf::ModelError& e) {
    return error(e.what(), kerf::kExitModelError);
  } catch (const kerf::OutputError& e) {
    return error(e.what(), kerf::kExitOutputError);
  } catch (const std::exception& e) {
    return error(e.what(), 1);
  }
}
