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
/// readers see the old file or the whole new one, never a partial one. A symbolic link is followed (the
/// link stays, its target is replaced); a device, a FIFO or "-" (stdout) is written through, never
/// replaced. Throws OutputError (the CLIs exit 4).
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

/// Renames a finished temporary file over `path` (atomic on one file system); on failure removes the
/// temporary and throws OutputError. The last step of every all-or-nothing write.
void move_into_place(const std::filesystem::path& temporary, const std::filesystem::path& path);

/// The name of a temporary file beside `path` ("PATH.tmp-1a2b3c4d" + suffix), removed by the process's
/// SIGINT/SIGTERM/SIGHUP handler (installed on first use) until move_into_place() or release() lets it go.
struct TemporaryFile {
  static std::filesystem::path reserve(const std::filesystem::path& path, std::string_view suffix = "");
  static void release(const std::filesystem::path& temporary);
};

/// A line for the same handler to write to standard error before the process dies (then killed by the signal
/// as before: exit status 128 + its number): `if_exists` when the file `path` exists at that moment, else
/// `otherwise` (an empty `path`: always `otherwise`). Newlines are added. One note per process, a later call
/// replaces it; longer than 1 KiB each is cut.
///
///   kerf::set_interrupt_note("out/checkpoint.bin", "kerf-dem: interrupted; continue with: kerf-dem resume out",
///                            "kerf-dem: interrupted before its first checkpoint: run it again");
void set_interrupt_note(const std::filesystem::path& path, std::string_view if_exists, std::string_view otherwise);

/// Creates `dir` if needed and writes and removes a probe file in it: throws OutputError before any work
/// when the output could not be written at the end.
void check_writable_directory(const std::filesystem::path& dir);
/// The same for one output file (its directory; a device, FIFO or "-" passes). An empty name is an
/// InputError.
void check_writable_file(const std::filesystem::path& path);
/// Removes the temporary files ("*.tmp-XXXXXXXX") and report staging directories (".staging-XXXXXXXX") a
/// killed run left in `dir` and two levels below; returns how many.
std::size_t remove_stale_temporaries(const std::filesystem::path& dir);

/// A run's hold on its output directory, from its start to its end. On construction: the directory is
/// checked writable, the temporary files of a killed run are removed, and so are the files the previous run
/// into it listed in its manifest (DIR/.kerf-outputs; `fresh` false, for a resumed run, keeps them;
/// a study's items are moved into place whole from a directory the manifest lists, so they stay, and its
/// items in flight, under a directory .partial-NAME, are the study's to continue or remove); DIR/kerf.running
/// marks the run in progress. Every file written into DIR while
/// it lives is listed in the manifest. The destructor removes the marker (a killed run leaves it).
class OutputManifest {
 public:
  static constexpr const char* kFileName = ".kerf-outputs";
  static constexpr const char* kRunningName = "kerf.running";
  /// A directory whose name starts so holds work in flight (a study's item): its owner continues or removes it.
  static constexpr std::string_view kInFlightPrefix = ".partial-";
  static bool in_flight(const std::filesystem::path& name) { return name.string().starts_with(kInFlightPrefix); }
  OutputManifest(const std::filesystem::path& dir, bool fresh);
  ~OutputManifest();
  OutputManifest(const OutputManifest&) = delete;
  OutputManifest& operator=(const OutputManifest&) = delete;

 private:
  std::filesystem::path dir_;
};

/// Quotes a CSV field when it holds a comma, quote or newline (RFC 4180).
std::string csv_escape(std::string_view field);
/// Formats a number for CSV with round-trip precision ("1.5", "2.5e-07"); non-finite values become "".
std::string csv_number(double value);
/// Joins fields (already escaped) with commas and a trailing newline.
std::string csv_line(const std::vector<std::string>& fields);

/// A file that readers may watch grow (a running cut's forces.csv): created, or emptied, with its head, then
/// appended to in whole pieces, each by one write() straight to the operating system, so that a reader sees whole
/// rows only. Listed in the run's manifest like every output. Not all-or-nothing: the finished run replaces it
/// whole (write_file_atomically), with the same bytes. Throws OutputError.
class GrowingFile {
 public:
  GrowingFile(const std::filesystem::path& path, std::string_view head);
  ~GrowingFile();
  GrowingFile(const GrowingFile&) = delete;
  GrowingFile& operator=(const GrowingFile&) = delete;
  void append(std::string_view text);

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

/// Seconds left at this process's rate (one rule for the terminal's progress and the log lines): `done` of
/// `total` units done, `done_before` of them before this process began (a resume), `elapsed_s` since it began;
/// NaN while no rate is known.
double eta_seconds(double done_before, double done, double total, double elapsed_s);
/// "ETA 42 s", "ETA 12 min", "ETA 3.4 h" (whole seconds below 2 minutes, whole minutes below 2 hours); "" for NaN.
std::string eta_text(double seconds);

/// Progress (percent, rate, ETA) on stderr, redrawn at most a few times a second, and only when stderr
/// is a terminal: quiet in pipes, files and CI.
class Progress {
 public:
  Progress(std::string label, std::size_t total, std::string unit = "points");
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(std::size_t count);
  /// Counts `done` as done before this process began (a run resumed from a checkpoint): shown in the bar, left
  /// out of the rate and the ETA. Call it before the first advance.
  void resume_at(std::size_t done);
  void finish();
  bool enabled() const { return enabled_; }

 private:
  void draw(bool final_line);

  std::string label_, unit_;
  std::size_t total_, done_ = 0, done_before_ = 0;
  bool enabled_, finished_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

/// True when the stream (stdout or stderr) is a terminal.
bool is_terminal(std::FILE* stream);

}  // namespace kerf
