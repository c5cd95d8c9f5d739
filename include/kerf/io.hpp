#pragma once
// Output that is written completely or not at all, CSV formatting, and terminal progress.
//
//   kerf::write_file_atomically("out/result.csv", text);  // writes out/result.csv.tmp-XXXX, then renames
//   kerf::Progress progress("sweep", n_points);            // draws only when stderr is a terminal
//   progress.advance(1);
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace kerf {

/// Writes `contents` to a temporary file beside `path`, flushes it, then renames it over `path`, so
/// readers see the old file or the whole new one, never a partial one. Throws std::runtime_error.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

/// Renames a finished temporary file over `path` (atomic on one file system); on failure removes the
/// temporary and throws std::runtime_error. The last step of every all-or-nothing write.
void move_into_place(const std::filesystem::path& temporary, const std::filesystem::path& path);

/// Quotes a CSV field when it holds a comma, quote or newline (RFC 4180).
std::string csv_escape(std::string_view field);
/// Formats a number for CSV with round-trip precision ("1.5", "2.5e-07"); non-finite values become "".
std::string csv_number(double value);
/// Joins fields (already escaped) with commas and a trailing newline.
std::string csv_line(const std::vector<std::string>& fields);

/// Progress (percent, rate, ETA) on stderr, redrawn at most a few times a second, and only when stderr
/// is a terminal: quiet in pipes, files and CI.
class Progress {
 public:
  Progress(std::string label, std::size_t total, std::string unit = "points");
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(std::size_t count);
  void finish();
  bool enabled() const { return enabled_; }

 private:
  void draw(bool final_line);

  std::string label_, unit_;
  std::size_t total_, done_ = 0;
  bool enabled_, finished_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

/// True when the stream (stdout or stderr) is a terminal.
bool is_terminal(std::FILE* stream);

}  // namespace kerf
