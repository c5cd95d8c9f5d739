// A study over MPI ranks (kerf/dem/study/study_mpi.hpp): rank 0 coordinates, the others run items.
//
// Messages (JSON text, MPI_CHAR): a worker sends kRequest with the result of its last item (empty the first
// time); the coordinator answers kItem (the item) or kStop. A worker with no answer yet waits in a loop of
// MPI_Iprobe and short sleeps (20 us doubling up to 0.5 ms), not in a blocking receive (Open MPI's spins a core).
#include "kerf/dem/study/study_mpi.hpp"

#include <cstdlib>

#include "kerf/dem/study/study_record.hpp"
#include "kerf/error.hpp"

#if KERF_HAVE_MPI

#include <fmt/format.h>
#include <mpi.h>
#include <omp.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <iostream>
#include <string>
#include <thread>

#include "kerf/error.hpp"
#include "kerf/io.hpp"

namespace kerf::dem {

namespace fs = std::filesystem;

namespace {

constexpr int kRequest = 1, kItem = 2, kStop = 3;

/// MPI_Init_thread on construction, MPI_Finalize on destruction (once per process).
class MpiSession {
 public:
  MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiSession() { MPI_Finalize(); }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

void send_text(const std::string& text, int to, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

/// Waits (polling, with short sleeps) for a message from `from` (MPI_ANY_SOURCE: anyone) and receives it;
/// `idle` is called between polls.
std::string receive_text(int from, MPI_Status& status, const std::function<void()>& idle = {}) {
  int flag = 0;
  // Sleeps from 20 us, doubling up to 0.5 ms: an answer costs at most ~3 ms (measured: 2 ms naps cost 7 ms an
  // item on this VM, 0.2 ms naps 5 % of a core per waiting rank), a long wait ~2 % of a core.
  std::chrono::microseconds nap(20);
  while (true) {
    MPI_Iprobe(from, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (flag) break;
    if (idle) idle();
    std::this_thread::sleep_for(nap);
    nap = std::min(2 * nap, std::chrono::microseconds(500));
  }
  int length = 0;
  MPI_Get_count(&status, MPI_CHAR, &length);
  std::string text(static_cast<std::size_t>(length), '\0');
  MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}

/// The exit status of the exception being handled (what report_error would return), without printing.
int status_of_current_exception() {
  try {
    throw;
  } catch (const InputError&) {
    return kExitInputError;
  } catch (const ModelError&) {
    return kExitModelError;
  } catch (const OutputError&) {
    return kExitOutputError;
  } catch (...) {
    return 1;
  }
}

/// A worker's OpenMP threads by default: the cores the launcher bound the rank to, or, when it did not bind
/// it (all of the node's cores), the node's cores shared among the node's workers (the coordinator, which
/// mostly sleeps, not counted). Never more threads than cores on a node.
int default_threads_per_rank(int rank) {
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node);
  int node_size = 1;
  MPI_Comm_size(node, &node_size);
  int coordinator_here = rank == 0 ? 1 : 0, coordinators = 0;
  MPI_Allreduce(&coordinator_here, &coordinators, 1, MPI_INT, MPI_SUM, node);
  MPI_Comm_free(&node);
  cpu_set_t set;
  CPU_ZERO(&set);
  const int mine = sched_getaffinity(0, sizeof(set), &set) == 0 ? CPU_COUNT(&set) : omp_get_num_procs();
  const int online = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (mine < online) return std::max(1, mine);  // the launcher gave this rank these cores
  return std::max(1, online / std::max(1, node_size - coordinators));
}

StudyOutcome coordinate(const StudySpec& spec, const StudyOptions& options, int size) {
  const auto start = std::chrono::steady_clock::now();
  StudyScheduler scheduler(spec);
  StudyProgress progress(options, size - 1);
  const std::unique_ptr<StudyRecord> record = open_study_record(spec);
  StudyRecord* const recorded = record.get();
  std::deque<int> waiting;  // workers with nothing to do until a result decides an adaptive condition
  int stopped = 0;
  const auto answer = [&](int worker) {
    if (const auto item = next_item_to_run(scheduler, recorded, options.out, progress)) {
      send_text(Json{{"condition", item->condition}, {"replicate", item->replicate}, {"seed", item->seed}}.dump(),
                worker, kItem);
    } else if (scheduler.finished()) {
      send_text("", worker, kStop);
      ++stopped;
    } else {
      waiting.push_back(worker);
    }
  };
  while (stopped < size - 1) {
    MPI_Status status;
    const std::string text = receive_text(MPI_ANY_SOURCE, status, [&] { progress.tick(scheduler); });
    if (!text.empty()) {
      const StudyItemResult r = study_item_result_from_json(Json::parse(text));
      record_finished_item(recorded, r, options.out);
      scheduler.complete(r);
      progress.item_done(r, scheduler);
    }
    answer(status.MPI_SOURCE);
    for (std::size_t n = waiting.size(); n > 0; --n) {  // a result may give the waiting workers something
      const int w = waiting.front();
      waiting.pop_front();
      answer(w);
    }
  }
  progress.finish(scheduler);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return finish_study(spec, scheduler, options, wall, size - 1, fmt::format(" on {} worker ranks", size - 1));
}

void work(const StudySpec& spec, const StudyOptions& options, int rank, int threads) {
  std::string last;  // the last item's result, sent with the next request
  while (true) {
    send_text(last, 0, kRequest);
    MPI_Status status;
    const std::string text = receive_text(0, status);
    if (status.MPI_TAG == kStop) return;
    const Json j = Json::parse(text);
    const StudyItem item{j.at("condition").get<int>(), j.at("replicate").get<int>(), j.at("seed").get<std::uint64_t>()};
    last = study_item_result_to_json(run_study_item(spec, item, options.out, threads, rank, options.checkpoint_every_s))
               .dump();
  }
}

}  // namespace

bool study_mpi_built() {
  return true;
}

StudyOutcome run_study_mpi(const fs::path& study_file, const StudyOptions& options) {
  MpiSession mpi;
  const int rank = mpi.rank();
  if (mpi.size() == 1)  // a launcher's environment, but one rank (each task its own singleton): no one to coordinate
    return run_study_local(read_study(read_json_file(study_file.string()), study_file), options);
  // Every rank reads the study; rank 0 also holds the output directory. A failure on rank 0 stops every rank
  // (the status is broadcast) and is thrown there; the others return it quietly.
  int status = 0;
  std::exception_ptr error;
  std::optional<StudySpec> spec;
  std::optional<OutputManifest> hold;
  try {
    spec.emplace(read_study(read_json_file(study_file.string()), study_file));
    if (rank == 0) {
      hold.emplace(options.out, /*fresh=*/true);
      prepare_study_directory(*spec, options.out);
    }
  } catch (...) {
    status = status_of_current_exception();
    error = std::current_exception();
  }
  int worst = 0;
  MPI_Allreduce(&status, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  if (worst != 0) {
    if (rank == 0 && error) std::rethrow_exception(error);
    return {worst, {}};
  }
  const int threads = options.threads_per_rank > 0 ? options.threads_per_rank : default_threads_per_rank(rank);
  if (rank == 0) {
    std::cout << fmt::format("study: {} conditions over {} worker ranks, {} threads each (rank 0 coordinates)\n",
                             spec->conditions.size(), mpi.size() - 1, threads);
    // Open MPI gives a rank's stdout a pseudo-terminal and forwards it: plain lines, never a redrawn one.
    StudyOptions logged = options;
    logged.log_lines = true;
    logged.show_progress = false;
    return coordinate(*spec, logged, mpi.size());
  }
  try {
    work(*spec, options, rank, threads);
  } catch (const std::exception& e) {  // not an item's failure (run_study_item keeps those): a bug, no memory
    std::cerr << "kerf-dem: error: rank " << rank << ": " << printable(e.what()) << "\n";
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  return {0, {}};
}

bool study_mpi_launched() {
  // Open MPI's mpirun, PMI-1/2 launchers (MPICH's, srun --mpi=pmi2), srun's steps (srun --mpi=pmix).
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "MPI_LOCALNRANKS", "SLURM_STEP_NUM_TASKS"}) {
    const char* value = std::getenv(name);
    if (value && std::atoi(value) > 1) return true;
  }
  return false;
}

}  // namespace kerf::dem

#else  // built without MPI

namespace kerf::dem {

bool study_mpi_built() {
  return false;
}
bool study_mpi_launched() {
  return false;
}
StudyOutcome run_study_mpi(const std::filesystem::path&, const StudyOptions&) {
  throw InputError("mpirun", "(launched)", "kerf built with MPI (CMake option KERF_WITH_MPI)");
}

}  // namespace kerf::dem

#endif
