// Writing a report: figures, report.md, comparison.csv and summary.json staged, then moved into place together.
#include <fmt/format.h>

#include <random>
#include <system_error>

#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "report_internal.hpp"

namespace kerf {

using namespace report_detail;

std::vector<std::filesystem::path> write_report(const Comparison& c, const std::filesystem::path& out_dir,
                                                const ReportOptions& options) {
  namespace fs = std::filesystem;
  fs::create_directories(out_dir);
  remove_stale_temporaries(out_dir);  // a killed report's staging directory and temporaries
  std::random_device entropy;
  const fs::path staging = out_dir / fmt::format(".staging-{:08x}", entropy());
  std::vector<std::string> names;
  try {
    fs::create_directory(staging);
    std::vector<std::string> plot_files;
    if (options.plots) {
      for (const auto& f : plan_figures(c)) {
        render_png(f.figure, staging / f.file);
        plot_files.push_back(f.file);
      }
    }
    Json summary = summary_json(c, options);
    summary["files"] = plot_files;
    write_file_atomically(staging / "report.md", report_markdown(c, options, plot_files));
    write_file_atomically(staging / "comparison.csv", comparison_csv(c));
    write_file_atomically(staging / "summary.json", summary.dump(2) + "\n");
    names = {"report.md", "comparison.csv", "summary.json"};
    names.insert(names.end(), plot_files.begin(), plot_files.end());
    // Check every target before replacing any, so that a blocked target leaves the old report whole.
    for (const auto& name : names) {
      const fs::path target = out_dir / name;
      if (fs::exists(target) && !fs::is_regular_file(target)) {
        throw InputError(target.string(), "(not a regular file)", "a path the report can write a file to");
      }
    }
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    throw;
  }
  std::vector<fs::path> written;
  for (const auto& name : names) {
    std::error_code error;
    fs::rename(staging / name, out_dir / name, error);
    if (error) {
      std::error_code ignored;
      fs::remove_all(staging, ignored);
      throw OutputError((out_dir / name).string(), fmt::format("cannot move it into place: {}", error.message()));
    }
    written.push_back(out_dir / name);
  }
  std::error_code ignored;
  fs::remove_all(staging, ignored);
  return written;
}

}  // namespace kerf
