#include "app/sweep/sweep_mpi.hpp"

#include <cstdlib>

#include "numerics/error.hpp"

// The one file of tribolab that sees MPI: CMakeLists.txt defines TRIBOLAB_WITH_MPI for it
// (and its test) alone when configured with -DTRIBOLAB_MPI=ON.
#if TRIBOLAB_WITH_MPI
#include <mpi.h>

#include <chrono>
#include <memory>
#include <vector>

#include "app/sweep/sweep_checkpoint.hpp"
#include "io/sweep_file.hpp"
#endif

namespace tribolab::app {

bool launched_by_mpi_launcher() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr ||
         std::getenv("PMIX_RANK") != nullptr;
}

#if TRIBOLAB_WITH_MPI

bool built_with_mpi() { return true; }

using namespace ::tribolab::io;

namespace {

/// Rank 0's decision after each step, broadcast to all ranks.
enum Decision : long long { kContinue = 0, kStop = 1, kError = 2, kReused = 3 };

void broadcast_string(std::string& s, int root) {
  long long n = static_cast<long long>(s.size());
  MPI_Bcast(&n, 1, MPI_LONG_LONG, root, MPI_COMM_WORLD);
  s.resize(static_cast<std::size_t>(n));
  if (n > 0) MPI_Bcast(s.data(), static_cast<int>(n), MPI_CHAR, root, MPI_COMM_WORLD);
}

/// Broadcasts rank 0's decision (and message); throws InputError(message) on kError.
long long agree(long long decision, std::string message) {
  MPI_Bcast(&decision, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  if (decision == kError) {
    broadcast_string(message, 0);
    throw InputError(message);
  }
  return decision;
}

}  // namespace

MpiSession::MpiSession() {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    owner_ = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (owner_ && !finalised) MPI_Finalize();
}

SweepCommandResult run_sweep_command_mpi(const SweepCommandOptions& o, const sweep::CellModel& model,
                                         const SweepProgressCallback& progress, const std::atomic<bool>* cancel) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  // Validation is deterministic: every rank throws the same error, no communication needed.
  SweepCommandResult r = checked_sweep_start(o, model);
  const SweepHeader header{o.grid, o.shard, model.output_names, model.description};

  // 1. Rank 0 opens (or resumes, or reuses) the output; everyone learns where to start.
  std::unique_ptr<SweepCheckpoint> file;
  long long first = 0;
  long long decision = kContinue;
  std::string message;
  if (rank == 0) {
    try {
      if ((!o.contour_out.empty() || !o.threshold_out.empty() || o.keep_derived) &&
          model.output_index(o.contour.output) < 0) {
        throw InputError(field("contour") + ": the cell model has no output '" + o.contour.output + "'");
      }
      file = std::make_unique<SweepCheckpoint>(o, header);
      decision = file->reused() ? kReused : kContinue;
      first = file->reused() ? 0 : file->first_local();
    } catch (const std::exception& e) {
      decision = kError;
      message = marked_message(e);
    }
  }
  if (agree(decision, message) == kReused) {
    if (rank != 0) {
      r.status = SweepStatus::worker;
      return r;
    }
    r.status = SweepStatus::reused;
    r.cells_resumed = r.cells_shard;
    write_derived_maps(o, model, r);
    return r;
  }
  MPI_Bcast(&first, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  r.cells_resumed = first;

  // 2. Rounds: rank r computes [lo_r, hi_r) of [a, b); rank 0 appends in rank order.
  const auto t0 = std::chrono::steady_clock::now();
  const long long n_local = r.cells_shard;
  const long long block = o.chunk_cells > 0 ? o.chunk_cells * 4LL * r.threads : 256LL * r.threads;
  sweep::RunOptions ro;
  ro.threads = o.threads;
  ro.chunk_cells = o.chunk_cells;
  std::string mine;
  sweep::ResultSink sink;
  sink.encode = [&](const sweep::ChunkView& c, std::string& buf) { append_cell_lines(buf, o.grid, c); };
  sink.commit = [&](const sweep::ChunkView&, const std::string& buf) { mine += buf; };
  std::vector<int> lengths(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size));
  std::vector<int> infos(2 * static_cast<std::size_t>(size));
  std::vector<char> all;
  long long a = first;
  bool stopped = false;
  while (a < n_local) {
    const long long b = std::min(n_local, a + block * size);
    const long long lo = a + (b - a) * rank / size, hi = a + (b - a) * (rank + 1) / size;
    mine.clear();
    std::string error;
    bool failed = false;
    try {
      sweep::run_cells(o.grid, model, o.shard, lo, ro, sink, hi);
    } catch (const std::exception& e) {
      error = marked_message(e);
      failed = true;
    }
    // A failed rank sends its error message instead of its lines.
    const std::string& payload = failed ? error : mine;
    TRIBOLAB_ASSERT(payload.size() < (1u << 30), "MPI round too large");
    int info[2] = {static_cast<int>(payload.size()), failed ? 1 : 0};
    MPI_Gather(info, 2, MPI_INT, infos.data(), 2, MPI_INT, 0, MPI_COMM_WORLD);
    if (rank == 0) {
      int total = 0;
      for (std::size_t k = 0; k < static_cast<std::size_t>(size); ++k) {
        lengths[k] = infos[2 * k];
        offsets[k] = total;
        total += lengths[k];
      }
      all.resize(static_cast<std::size_t>(total));
    }
    MPI_Gatherv(payload.data(), info[0], MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                MPI_CHAR, 0, MPI_COMM_WORLD);
    decision = kContinue;
    message.clear();
    if (rank == 0) {
      for (std::size_t k = 0; k < static_cast<std::size_t>(size) && decision == kContinue; ++k) {
        if (infos[2 * k + 1] != 0) {
          decision = kError;
          message = std::string(all.data() + offsets[k], static_cast<std::size_t>(lengths[k]));
        }
      }
      try {
        if (decision == kContinue) {
          file->append(std::string(all.begin(), all.end()));
          if (b < n_local && cancel != nullptr && cancel->load()) decision = kStop;
        }
      } catch (const std::exception& e) {
        decision = kError;
        message = marked_message(e);
      }
      if (progress) {
        sweep::Progress p;
        p.done = b;
        p.total = n_local;
        p.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        p.rate = p.elapsed_s > 0 ? static_cast<double>(b - first) / p.elapsed_s : 0;
        progress(p);
      }
    }
    try {
      decision = agree(decision, message);
    } catch (...) {
      if (file) file->finish(false);
      throw;
    }
    a = b;
    if (decision == kStop) {
      stopped = true;
      break;
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (rank != 0) {
    r.status = SweepStatus::worker;
    return r;
  }
  r.cells_computed = a - first;
  file->finish(!stopped);
  if (stopped) {
    r.status = SweepStatus::cancelled;
    r.out = file->partial_path();
    return r;
  }
  write_derived_maps(o, model, r);
  return r;
}

#else  // built without MPI

namespace {
[[noreturn]] void no_mpi() {
  throw InputError("this tribolab was built without MPI (cmake -DTRIBOLAB_MPI=ON)");
}
}  // namespace

bool built_with_mpi() { return false; }
MpiSession::MpiSession() { no_mpi(); }
MpiSession::~MpiSession() = default;
SweepCommandResult run_sweep_command_mpi(const SweepCommandOptions&, const sweep::CellModel&,
                                         const SweepProgressCallback&, const std::atomic<bool>*) {
  no_mpi();
}

#endif

}  // namespace tribolab::app
