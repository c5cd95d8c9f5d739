#include "kerf/install.hpp"

#include <dlfcn.h>

#include <cerrno>
#include <string>
#include <system_error>

namespace kerf {

namespace {

/// The file of the program or shared object that holds this function: the Python module when kerf is loaded
/// into Python, else the program (dladdr names the program by its argv[0], which may be a bare name on PATH, so
/// the program's own file comes from /proc/self/exe).
std::filesystem::path own_binary() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&own_binary), &info) != 0 && info.dli_fname && *info.dli_fname &&
      std::string(info.dli_fname) != program_invocation_name) {
    return info.dli_fname;
  }
  std::error_code error;
  return std::filesystem::read_symlink("/proc/self/exe", error);
}

}  // namespace

std::filesystem::path installed_data_directory() {
  std::error_code error;
  const std::filesystem::path binary = std::filesystem::weakly_canonical(own_binary(), error);
  if (error || binary.empty()) return {};
  const std::filesystem::path dir = binary.parent_path();
  // PREFIX/bin/kerf-forces, or PREFIX/lib/pythonX.Y/site-packages/kerf.*.so.
  std::filesystem::path prefix = dir.parent_path();
  const std::string name = dir.filename().string();
  if (name == "site-packages" || name == "dist-packages") prefix = dir.parent_path().parent_path().parent_path();
  const std::filesystem::path data = prefix / "share" / "kerf" / "data";
  return std::filesystem::is_directory(data / "materials", error) ? data : std::filesystem::path{};
}

}  // namespace kerf
