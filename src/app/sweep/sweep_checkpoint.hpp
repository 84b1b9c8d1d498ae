// The output file of a running sweep: FILE.partial, opened fresh or resumed, appended to in
// cell order, renamed to FILE when complete (docs/theory.md#sweeps, "Checkpoint and
// resume"). Shared by the single-process and the MPI sweep.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "io/sweep_file.hpp"

namespace tribolab::app {

struct SweepCommandOptions;

/// Which parts of two sweep headers differ ("grid, physical options"), for messages; the
/// shard index is compared only when with_shard_index.
std::string header_difference(const io::SweepHeader& a, const io::SweepHeader& b, bool with_shard_index);

class SweepCheckpoint {
 public:
  /// Deletes FILE and FILE.partial first when options.restart. Then: a FILE holding this
  /// complete sweep -> reused(); a FILE holding anything else -> InputError. Else opens
  /// FILE.partial (exclusively locked): a checkpoint of this sweep is verified and resumed
  /// (a torn last line dropped), one of another sweep -> InputError, none (or one cut
  /// inside its first two lines) -> created with header and column lines.
  SweepCheckpoint(const SweepCommandOptions& options, const io::SweepHeader& header);
  SweepCheckpoint(const SweepCheckpoint&) = delete;
  SweepCheckpoint& operator=(const SweepCheckpoint&) = delete;
  ~SweepCheckpoint();

  bool reused() const { return reused_; }
  /// Cells of the shard already in the file; computation resumes at this local index.
  std::int64_t first_local() const { return first_local_; }
  const std::string& partial_path() const { return partial_; }

  /// Appends complete lines (in cell order) with write(); fsync every fsync_interval_s.
  void append(const std::string& lines);
  /// fsync and close; when `complete`, rename FILE.partial to FILE (and fsync the directory).
  void finish(bool complete);

 private:
  std::string out_, partial_;
  int fd_ = -1;
  bool reused_ = false;
  std::int64_t first_local_ = 0;
  double fsync_interval_s_ = 5;
  std::chrono::steady_clock::time_point last_sync_;
};

}  // namespace tribolab::app
