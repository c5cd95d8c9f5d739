#include "kerf/io.hpp"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "file_text.hpp"
#include "kerf/error.hpp"

namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("kerf-io-test-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}
std::size_t n_files(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++n;
  return n;
}
}  // namespace

TEST_CASE("io: a symbolic link is followed and stays a link", "[io]") {
  const fs::path dir = scratch("link");
  std::ofstream(dir / "target.csv") << "old";
  fs::create_symlink("target.csv", dir / "link.csv");
  kerf::write_file_atomically(dir / "link.csv", "new");
  CHECK(fs::is_symlink(dir / "link.csv"));
  CHECK(kerf::testing::file_text(dir / "target.csv") == "new");
  CHECK(n_files(dir) == 2);
  fs::remove_all(dir);
}

TEST_CASE("io: a FIFO is written through, not replaced", "[io]") {
  const fs::path dir = scratch("fifo");
  const fs::path fifo = dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const pid_t reader = ::fork();
  if (reader == 0) {  // the child reads what the parent writes, then exits with 0 when it was "abc"
    std::ifstream in(fifo);
    std::string got;
    std::getline(in, got);
    ::_exit(got == "abc" ? 0 : 1);
  }
  kerf::write_file_atomically(fifo, "abc\n");
  int status = 0;
  ::waitpid(reader, &status, 0);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(fs::is_fifo(fifo));
  CHECK(n_files(dir) == 1);
  fs::remove_all(dir);
}

TEST_CASE("io: an unwritable directory is an OutputError before any work", "[io]") {
  CHECK_THROWS_AS(kerf::check_writable_directory("/proc/kerf-cannot-write"), kerf::OutputError);
  CHECK_THROWS_AS(kerf::check_writable_file("/proc/kerf-cannot-write/x.csv"), kerf::OutputError);
  CHECK_THROWS_AS(kerf::check_writable_file(""), kerf::InputError);
  CHECK_NOTHROW(kerf::check_writable_file("-"));
  CHECK_NOTHROW(kerf::check_writable_file("/dev/null"));
  const fs::path dir = scratch("probe");
  CHECK_NOTHROW(kerf::check_writable_directory(dir / "sub"));
  CHECK(fs::is_directory(dir / "sub"));
  CHECK(n_files(dir / "sub") == 0);  // the probe is gone
  fs::remove_all(dir);
}

TEST_CASE("io: the temporary files of a killed writer are removed by SIGTERM and by the next run", "[io]") {
  const fs::path dir = scratch("signal");
  const pid_t child = ::fork();
  if (child == 0) {
    // Catch2 puts a handler of its own in place for each test case and restores the one it found afterwards (the
    // default, over kerf's, when an earlier test case had installed it): the program's state is the default.
    std::signal(SIGTERM, SIG_DFL);
    const fs::path temporary = kerf::TemporaryFile::reserve(dir / "big.csv");
    std::ofstream(temporary) << "partial";
    std::raise(SIGTERM);
    ::_exit(0);  // not reached: the handler removes the file and dies of the signal
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK(n_files(dir) == 0);
  // A kill -9 leaves them: the next run into the directory removes them (and nothing else).
  std::ofstream(dir / "forces.csv.tmp-0123abcd") << "partial";
  std::ofstream(dir / "forces.png.tmp-0123abcd.png") << "partial";
  std::ofstream(dir / "forces.csv") << "kept";
  std::ofstream(dir / "notes.tmp-draft") << "kept";
  // A report killed before its renames leaves its staging directory (and its finished files in it).
  fs::create_directory(dir / ".staging-89abcdef");
  std::ofstream(dir / ".staging-89abcdef" / "report.md") << "partial";
  fs::create_directory(dir / ".staging-user");  // not of kerf's pattern: kept
  CHECK(kerf::remove_stale_temporaries(dir) == 3);
  CHECK(!fs::exists(dir / ".staging-89abcdef"));
  CHECK(fs::exists(dir / ".staging-user"));
  CHECK(n_files(dir) == 3);
  fs::remove_all(dir);
}

TEST_CASE("io: a run marks its directory and a rerun removes the files of the run before", "[io]") {
  const fs::path dir = scratch("manifest");
  std::ofstream(dir / "user-notes.txt") << "mine";
  {
    kerf::OutputManifest hold(dir, /*fresh=*/true);
    CHECK(fs::exists(dir / kerf::OutputManifest::kRunningName));
    kerf::write_file_atomically(dir / "a.csv", "1");
    kerf::write_file_atomically(dir / "frames" / "frame_0001.vtp", "1");
  }
  CHECK_FALSE(fs::exists(dir / kerf::OutputManifest::kRunningName));
  {
    kerf::OutputManifest hold(dir, /*fresh=*/true);
    CHECK_FALSE(fs::exists(dir / "a.csv"));
    CHECK_FALSE(fs::exists(dir / "frames" / "frame_0001.vtp"));
    CHECK(fs::exists(dir / "user-notes.txt"));
    kerf::write_file_atomically(dir / "b.csv", "1");
  }
  {
    kerf::OutputManifest hold(dir, /*fresh=*/false);  // a resume keeps what the run wrote
    CHECK(fs::exists(dir / "b.csv"));
  }
  fs::remove_all(dir);
}
