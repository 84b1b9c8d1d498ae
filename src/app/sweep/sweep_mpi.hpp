// One sweep over many MPI ranks (`mpirun -np N tribolab bounce sweep ...`), available when
// built with -DTRIBOLAB_MPI=ON (Debian: libopenmpi-dev openmpi-bin). Rank 0 owns the files;
// every rank computes; the output is byte-identical to a single-process run.
// See docs/theory.md#sweeps.
#pragma once

#include <atomic>
#include <ostream>

#include "app/sweep/sweep_command.hpp"

namespace tribolab::app {

/// True when the process was started by an MPI launcher (mpirun/mpiexec/srun sets
/// OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK) - whether or not this build has MPI.
bool launched_by_mpi_launcher();

/// True when this build links MPI (cmake -DTRIBOLAB_MPI=ON, the default of `make build`).
/// Only sweep_mpi.cpp sees MPI; without it, MpiSession and run_sweep_command_mpi throw
/// InputError saying the build has no MPI.
bool built_with_mpi();

/// MPI_Init_thread (funneled: only the calling thread uses MPI) on construction unless MPI
/// is already initialised; MPI_Finalize on destruction if it initialised it.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
  bool owner_ = false;
};

/// Runs a sweep over all ranks of MPI_COMM_WORLD. Every rank calls it with the same options
/// and model. The shard's remaining cells are processed in rounds: each round of
/// size x block cells is split into `size` contiguous sub-blocks, rank r computes sub-block
/// r on its threads, rank 0 gathers the CSV text in rank order (= cell order) and appends it
/// to the checkpoint, then broadcasts continue / stop (cancel, checked on rank 0 only) /
/// error. Checkpoint, resume, rename and derived maps are rank 0's, exactly as in
/// run_sweep_command, so the file is byte-identical to a one-process run. Returns the
/// result on rank 0; other ranks get SweepStatus::worker. An error on any rank is rethrown on
/// every rank.
SweepCommandResult run_sweep_command_mpi(const SweepCommandOptions& options,
                                         const sweep::CellModel& model,
                                         const SweepProgressCallback& progress,
                                         const std::atomic<bool>* cancel = nullptr);

}  // namespace tribolab::app
