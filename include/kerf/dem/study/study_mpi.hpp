#pragma once
// A study over MPI ranks (kerf/dem/study/study.hpp): rank 0 is the coordinator (the scheduler, the progress, the
// outputs; it runs no item), every other rank a worker that asks for an item, runs it with its own OpenMP
// threads into DIR/items (a file system all ranks share) and sends back its result. Messages are JSON text;
// waiting ranks poll with short sleeps rather than spin in MPI_Recv, so a rank waiting for work leaves its
// core to the ones computing. Built only with MPI (CMake option KERF_WITH_MPI); otherwise the functions say so.
#include <filesystem>

#include "kerf/dem/study/study.hpp"

namespace kerf::dem {

/// True when kerf was built with MPI.
bool study_mpi_built();
/// True when this process was started by an MPI launcher (mpirun, srun) with more than one rank.
bool study_mpi_launched();

/// Every rank calls it: reads the study (each rank), runs it over the ranks and, on rank 0, writes the outputs.
/// Rank 0 throws the errors (the CLI prints them); other ranks return the exit status quietly.
StudyOutcome run_study_mpi(const std::filesystem::path& study_file, const StudyOptions& options);

}  // namespace kerf::dem
