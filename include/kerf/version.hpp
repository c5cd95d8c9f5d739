#pragma once
// What built kerf and what a run was: the version, the git commit captured when CMake configured the build,
// and the provenance block a run's summary.json carries.
//
//   fmt::print("{}\n", kerf::version_line("kerf-dem"));   // "kerf-dem 0.2.0 (git d6d883e)"
//   summary["provenance"] = kerf::run_provenance("kerf-dem run s.json", "s.json", {"cut.length_mm=0.2"});
#include <string>
#include <string_view>
#include <vector>

#include "kerf/json_reader.hpp"

namespace kerf {

/// The project version, CMakeLists.txt's project() VERSION ("0.2.0").
std::string_view version();
/// `git describe --always --dirty` of the source tree when the build was configured; empty outside git.
std::string_view git_commit();
/// "PROGRAM VERSION (git COMMIT)", the --version line of the programs.
std::string version_line(std::string_view program);

/// Arguments joined into one shell line, quoting those that need it.
std::string command_line(int argc, const char* const* argv);

/// 64-bit FNV-1a of a text's bytes as 16 hex digits.
std::string text_hash_fnv1a64(std::string_view text);
/// 64-bit FNV-1a of a file's bytes as 16 hex digits; empty when it cannot be read.
std::string file_hash_fnv1a64(const std::string& path);

/// version, git_commit, command_line, scene (path), scene_fnv1a64 (its hash), overrides, date (UTC, ISO 8601),
/// host and threads (OpenMP's maximum).
Json run_provenance(const std::string& command, const std::string& scene_path,
                    const std::vector<std::string>& overrides);

}  // namespace kerf
