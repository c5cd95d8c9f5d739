#include "kerf/version.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <ctime>
#include <fstream>
#include <iterator>

#include "kerf/openmp_env.hpp"

namespace kerf {

std::string_view version() {
  return KERF_VERSION;
}

std::string_view git_commit() {
  return
#include "git_commit.inc"
      ;
}

std::string version_line(std::string_view program) {
  return git_commit().empty() ? fmt::format("{} {}", program, version())
                              : fmt::format("{} {} (git {})", program, version(), git_commit());
}

std::string command_line(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const bool plain = !arg.empty() && arg.find_first_not_of(
                                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                           "0123456789-_./=:,+@%") == std::string_view::npos;
    if (i) line += ' ';
    if (plain) {
      line += arg;
    } else {
      line += '\'';
      for (char c : arg) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
      line += '\'';
    }
  }
  return line;
}

std::string text_hash_fnv1a64(std::string_view text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return fmt::format("{:016x}", hash);
}

std::string file_hash_fnv1a64(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return text_hash_fnv1a64(bytes);
}

Json run_provenance(const std::string& command, const std::string& scene_path,
                    const std::vector<std::string>& overrides) {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::array<char, 32> date{};
  std::strftime(date.data(), date.size(), "%Y-%m-%dT%H:%M:%SZ", &utc);
  std::array<char, 256> host{};
  if (gethostname(host.data(), host.size() - 1) != 0) host[0] = '\0';
  return Json{{"version", std::string(version())},
              {"git_commit", std::string(git_commit())},
              {"command_line", command},
              {"scene", scene_path},
              {"scene_fnv1a64", file_hash_fnv1a64(scene_path)},
              {"overrides", overrides},
              {"date", std::string(date.data())},
              {"host", std::string(host.data())},
              {"threads", omp_get_max_threads()},
              {"openmp_wait_policy", openmp_wait_policy()}};
}

}  // namespace kerf
