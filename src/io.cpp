#include "kerf/io.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <mutex>
#include <random>
#include <stdexcept>
#include <system_error>

#include "kerf/error.hpp"

namespace kerf {

namespace {

namespace fs = std::filesystem;

// The temporary files in flight, for the SIGINT/SIGTERM handler: fixed slots that the handler reads
// without allocating or locking (unlink is async-signal-safe).
constexpr std::size_t kTemporarySlots = 64;
constexpr std::size_t kPathBytes = 4096;
struct TemporarySlot {
  std::atomic<bool> used{false};
  char path[kPathBytes];
};
TemporarySlot temporary_slots[kTemporarySlots];
std::mutex temporary_slots_mutex;

// The interrupt note (set_interrupt_note): fixed buffers the handler reads once `note_ready` says they are whole.
constexpr std::size_t kNoteBytes = 1024;
struct InterruptNote {
  std::atomic<bool> ready{false};
  char path[kPathBytes];
  char if_exists[kNoteBytes + 1], otherwise[kNoteBytes + 1];
  std::size_t if_exists_size = 0, otherwise_size = 0;
};
InterruptNote interrupt_note;

void write_all(int fd, const char* text, std::size_t size) {  // async-signal-safe
  while (size > 0) {
    const ssize_t n = ::write(fd, text, size);
    if (n <= 0) return;
    text += n, size -= static_cast<std::size_t>(n);
  }
}

extern "C" void remove_temporaries_and_die(int signal_number) {
  for (auto& slot : temporary_slots) {
    if (slot.used.load()) ::unlink(slot.path);
  }
  if (interrupt_note.ready.load()) {
    const bool exists = interrupt_note.path[0] != '\0' && ::access(interrupt_note.path, F_OK) == 0;
    if (exists)
      write_all(STDERR_FILENO, interrupt_note.if_exists, interrupt_note.if_exists_size);
    else
      write_all(STDERR_FILENO, interrupt_note.otherwise, interrupt_note.otherwise_size);
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

// The first time over any handler but SIG_IGN (nohup: stay ignored); after that again wherever the default has come
// back (a harness that restores the handlers it found, as Catch2 does after each test case), never over another.
void install_signal_cleanup() {
  static std::atomic<bool> first{true};
  const bool once = first.exchange(false);
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction previous {};
    ::sigaction(signal_number, nullptr, &previous);
    if (previous.sa_handler == SIG_IGN || previous.sa_handler == remove_temporaries_and_die) continue;
    if (once || previous.sa_handler == SIG_DFL) std::signal(signal_number, remove_temporaries_and_die);
  }
}

/// Copies `text` and a newline into `buffer` (at most kNoteBytes in all); returns the size.
std::size_t copy_note(char* buffer, std::string_view text) {
  if (text.empty()) return 0;
  const std::size_t n = std::min(text.size(), kNoteBytes - 1);
  std::memcpy(buffer, text.data(), n);
  buffer[n] = '\n';
  return n + 1;
}

bool is_temporary_name(const std::string& name) {
  const auto at = name.rfind(".tmp-");
  if (at == std::string::npos || at == 0) return false;
  const std::string tail = name.substr(at + 5);
  const std::string hex = tail.substr(0, 8);
  if (hex.size() != 8 || hex.find_first_not_of("0123456789abcdef") != std::string::npos) return false;
  return tail.size() == 8 || tail.substr(8) == ".png";
}

/// A report's staging directory (".staging-1a2b3c4d", kerf/report.hpp's write_report).
bool is_staging_name(const std::string& name) {
  return name.size() == 17 && name.rfind(".staging-", 0) == 0 &&
         name.find_first_not_of("0123456789abcdef", 9) == std::string::npos;
}

/// Writes through an existing file that is not a regular file (a device, a FIFO, "-" for stdout): there is
/// nothing to replace atomically, and replacing it would destroy it.
void write_through(const fs::path& path, std::string_view contents) {
  if (path == "-") {
    std::fwrite(contents.data(), 1, contents.size(), stdout);
    if (std::fflush(stdout) != 0) throw OutputError("-", std::strerror(errno));
    return;
  }
  std::ofstream out(path, std::ios::binary);
  if (!out) throw OutputError(path.string(), std::strerror(errno));
  out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
  out.flush();
  if (!out) throw OutputError(path.string(), "the write failed");
}

/// The file a write goes to: a symbolic link's target (the link stays), else the path itself.
fs::path write_target(const fs::path& path) {
  fs::path target = path;
  std::error_code error;
  for (int hop = 0; fs::is_symlink(target, error); ++hop) {  // a dangling link too: its file is created
    const fs::path next = fs::read_symlink(target, error);
    if (error || hop == 40) throw OutputError(path.string(), error ? error.message() : "too many levels of links");
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  return target;
}

bool is_special(const fs::path& path) {
  if (path == "-") return true;
  std::error_code error;
  const auto status = fs::status(path, error);
  return fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status);
}

// The run directory whose outputs are listed in its manifest (OutputManifest), if any.
std::mutex manifest_mutex;
fs::path manifest_dir;

void record_output(const fs::path& path) {
  const std::lock_guard<std::mutex> lock(manifest_mutex);
  if (manifest_dir.empty()) return;
  std::error_code error;
  const fs::path relative = fs::relative(fs::absolute(path, error), manifest_dir, error);
  if (error || relative.empty() || *relative.begin() == "..") return;
  std::ofstream(manifest_dir / OutputManifest::kFileName, std::ios::app) << relative.string() << '\n';
}

}  // namespace

OutputManifest::OutputManifest(const fs::path& dir, bool fresh) {
  check_writable_directory(dir);
  remove_stale_temporaries(dir);
  const fs::path absolute = fs::absolute(dir);
  // The files the previous run into this directory wrote (finished or killed): gone before this one writes;
  // not those under a directory of work in flight (kInFlightPrefix: a study's item, continued or removed by it).
  std::ifstream previous;
  if (fresh) previous.open(absolute / kFileName);
  for (std::string line; std::getline(previous, line);) {
    const fs::path relative(line);
    if (line.empty() || relative.is_absolute() || line.find("..") != std::string::npos) continue;
    if (std::any_of(relative.begin(), relative.end(), in_flight)) continue;
    std::error_code ignored;
    if (fs::is_regular_file(absolute / relative, ignored)) fs::remove(absolute / relative, ignored);
  }
  previous.close();
  std::ofstream(absolute / kFileName, fresh ? std::ios::trunc : std::ios::app).flush();
  write_file_atomically(absolute / kRunningName, "a run writes into this directory (or was killed)\n");
  const std::lock_guard<std::mutex> lock(manifest_mutex);
  manifest_dir = absolute;
  dir_ = absolute;
}

OutputManifest::~OutputManifest() {
  {
    const std::lock_guard<std::mutex> lock(manifest_mutex);
    manifest_dir.clear();
  }
  std::error_code ignored;
  fs::remove(dir_ / kRunningName, ignored);
}

fs::path TemporaryFile::reserve(const fs::path& path, std::string_view suffix) {
  install_signal_cleanup();
  std::random_device entropy;
  fs::path temporary = path.string() + fmt::format(".tmp-{:08x}{}", entropy(), suffix);
  const std::string text = temporary.string();
  const std::lock_guard<std::mutex> lock(temporary_slots_mutex);
  for (auto& slot : temporary_slots) {
    if (slot.used.load() || text.size() >= kPathBytes) continue;
    std::memcpy(slot.path, text.c_str(), text.size() + 1);
    slot.used.store(true);
    break;
  }
  return temporary;
}

void set_interrupt_note(const fs::path& path, std::string_view if_exists, std::string_view otherwise) {
  install_signal_cleanup();
  interrupt_note.ready.store(false);  // the handler reads no half-written note
  const std::string text = path.string();
  const std::size_t n = text.size() < kPathBytes ? text.size() : 0;  // too long: as if there were no file
  std::memcpy(interrupt_note.path, text.data(), n);
  interrupt_note.path[n] = '\0';
  interrupt_note.if_exists_size = copy_note(interrupt_note.if_exists, if_exists);
  interrupt_note.otherwise_size = copy_note(interrupt_note.otherwise, otherwise);
  interrupt_note.ready.store(true);
}

void TemporaryFile::release(const fs::path& temporary) {
  const std::string text = temporary.string();
  const std::lock_guard<std::mutex> lock(temporary_slots_mutex);
  for (auto& slot : temporary_slots) {
    if (slot.used.load() && text == slot.path) slot.used.store(false);
  }
}

void write_file_atomically(const fs::path& requested, std::string_view contents) {
  if (is_special(requested)) return write_through(requested, contents);
  const fs::path path = write_target(requested);
  if (is_special(path)) return write_through(path, contents);
  std::error_code error;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), error);
  if (error) throw OutputError(path.parent_path().string(), error.message());
  const fs::path temporary = TemporaryFile::reserve(path);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      TemporaryFile::release(temporary);
      throw OutputError(temporary.string(), std::strerror(errno));
    }
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.flush();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      TemporaryFile::release(temporary);
      throw OutputError(temporary.string(), "the write failed (is the disk full?)");
    }
  }
  move_into_place(temporary, path);
}

void move_into_place(const fs::path& temporary, const fs::path& path) {
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
  }
  TemporaryFile::release(temporary);
  if (error)
    throw OutputError(path.string(),
                      fmt::format("cannot rename '{}' onto it: {}", temporary.string(), error.message()));
  record_output(path);
}

void check_writable_directory(const fs::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw OutputError(dir.string(), error.message());
  if (!fs::is_directory(dir, error)) throw OutputError(dir.string(), "it is not a directory");
  const fs::path probe = TemporaryFile::reserve(dir / ".kerf-probe");
  std::ofstream out(probe, std::ios::binary);
  const bool ok = static_cast<bool>(out << 'k' << std::flush);
  const int probe_errno = errno;
  out.close();
  fs::remove(probe, error);
  TemporaryFile::release(probe);
  if (!ok)
    throw OutputError(dir.string(), fmt::format("the directory is not writable ({})", std::strerror(probe_errno)));
}

void check_writable_file(const fs::path& requested) {
  if (requested.empty()) throw InputError("output file", "\"\"", "a file name");
  if (is_special(requested)) return;
  const fs::path path = write_target(requested);
  if (is_special(path)) return;
  std::error_code error;
  if (fs::is_directory(path, error)) throw OutputError(path.string(), "it is a directory");
  // The file is replaced by a rename: its directory is what must be writable.
  check_writable_directory(path.has_parent_path() ? path.parent_path() : fs::path("."));
}

std::size_t remove_stale_temporaries(const fs::path& dir) {
  std::size_t n_removed = 0;
  std::error_code error;
  for (fs::recursive_directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    if (it.depth() > 2) it.disable_recursion_pending();
    const std::string name = it->path().filename().string();
    if (it->is_regular_file(error) && is_temporary_name(name)) {
      std::error_code ignored;
      if (fs::remove(it->path(), ignored)) ++n_removed;
    } else if (it->is_directory(error) && is_staging_name(name)) {  // a report's, killed before its renames
      it.disable_recursion_pending();
      std::error_code ignored;
      if (fs::remove_all(it->path(), ignored) > 0) ++n_removed;
    }
  }
  return n_removed;
}

std::string csv_escape(std::string_view field) {
  if (field.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(field);
  std::string quoted = "\"";
  for (char c : field) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  quoted += '"';
  return quoted;
}

std::string csv_number(double value) {
  if (!std::isfinite(value)) return "";
  return fmt::format("{}", value);  // shortest representation that round-trips
}

std::string csv_line(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) line += ',';
    line += fields[i];
  }
  line += '\n';
  return line;
}

bool is_terminal(std::FILE* stream) {
  return ::isatty(::fileno(stream)) == 1;
}

GrowingFile::GrowingFile(const fs::path& path, std::string_view head) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) throw OutputError(path.string(), fmt::format("cannot open it: {}", std::strerror(errno)));
  record_output(path);
  append(head);
}

GrowingFile::~GrowingFile() {
  if (fd_ >= 0) ::close(fd_);
}

void GrowingFile::append(std::string_view text) {
  while (!text.empty()) {  // one write() for a piece below the pipe/page size; a short write goes on from there
    const ::ssize_t n = ::write(fd_, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw OutputError(path_.string(), fmt::format("the write failed: {}", std::strerror(errno)));
    text.remove_prefix(static_cast<std::size_t>(n));
  }
}

double eta_seconds(double done_before, double done, double total, double elapsed_s) {
  const double rate = elapsed_s > 0 ? (done - done_before) / elapsed_s : 0.0;  // this process's
  if (!(rate > 0) || !std::isfinite(rate)) return std::nan("");
  return std::max(0.0, total - std::min(done, total)) / rate;
}

std::string eta_text(double seconds) {
  if (!std::isfinite(seconds)) return "";
  if (seconds < 120) return fmt::format("ETA {:.0f} s", seconds);
  if (seconds < 7200) return fmt::format("ETA {:.0f} min", seconds / 60);
  return fmt::format("ETA {:.1f} h", seconds / 3600);
}

Progress::Progress(std::string label, std::size_t total, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      enabled_(is_terminal(stderr)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

Progress::~Progress() {
  finish();
}

void Progress::advance(std::size_t count) {
  done_ += count;
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ >= std::chrono::milliseconds(200)) {
    last_draw_ = now;
    draw(false);
  }
}

void Progress::resume_at(std::size_t done) {
  done_ = done_before_ = done;
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (enabled_) draw(true);
}

void Progress::draw(bool final_line) {
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = total_ ? static_cast<double>(done_) / static_cast<double>(total_) : 1.0;
  const double rate = elapsed_s > 0 ? static_cast<double>(done_ - done_before_) / elapsed_s : 0.0;  // this process's
  const std::string eta = eta_text(eta_seconds(static_cast<double>(done_before_), static_cast<double>(done_),
                                               static_cast<double>(total_), elapsed_s));
  fmt::print(stderr, "\r{}: {:5.1f}%  {}/{} {}  {:.3g} {}/s  {}   {}", label_, 100.0 * fraction, done_, total_, unit_,
             rate, unit_, eta.empty() ? "ETA ?" : eta, final_line ? "\n" : "");
  std::fflush(stderr);
}

}  // namespace kerf
