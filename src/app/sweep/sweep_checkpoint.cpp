#include "app/sweep/sweep_checkpoint.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app/sweep/sweep_command.hpp"
#include "io/output_path.hpp"
#include "numerics/error.hpp"

namespace tribolab::app {
using namespace ::tribolab::io;
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// Which parts of two sweep headers differ, for error messages (the shard index is
/// compared only when `with_shard_index`).
std::string difference_impl(const SweepHeader& a, const SweepHeader& b, bool with_shard_index) {
  std::vector<std::string> parts;
  if (a.grid.axes != b.grid.axes) {
    parts.push_back("grid");
  } else if (header_identity(SweepHeader{a.grid, {}, {}, {}}) !=
             header_identity(SweepHeader{b.grid, {}, {}, {}})) {
    parts.push_back("fixed speed/mu");
  }
  if (a.outputs != b.outputs) parts.push_back("outputs");
  if (a.model != b.model) parts.push_back("physical options");
  if (a.shard.count != b.shard.count || (with_shard_index && a.shard.index != b.shard.index)) {
    parts.push_back("shard");
  }
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? ", " : "") + parts[i];
  return s.empty() ? "header" : s;
}

/// An open file descriptor, closed on scope exit.
class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }
  void close(const std::string& path) {
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw InputError(path, std::string("close failed: ") + std::strerror(errno));
  }

 private:
  int fd_;
};

void write_all(int fd, const std::string& data, const std::string& path) {
  const char* p = data.data();
  std::size_t left = data.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(path, std::string("write failed: ") + std::strerror(errno));
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

void sync_fd(int fd, const std::string& path) {
  if (::fsync(fd) != 0) throw InputError(path, std::string("fsync failed: ") + std::strerror(errno));
}

void sync_directory_of(const std::string& path) {
  const fs::path p(path);
  const std::string dir = p.has_parent_path() ? p.parent_path().string() : ".";
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd >= 0) {
    ::fsync(fd);  // best effort: makes the rename durable
    ::close(fd);
  }
}

/// Opens FILE.partial (creating it if missing) and takes its exclusive lock, so that no
/// other sweep writes it or renames it while we hold it. `created` tells whether we made it.
/// The lock is held on an inode: if another run renamed or removed the name between our
/// open() and flock(), the lock is on a stray file and the name is opened again.
int open_locked(const std::string& partial, bool& created) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    created = true;
    int raw = ::open(partial.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (raw < 0 && errno == EEXIST) {
      created = false;
      raw = ::open(partial.c_str(), O_WRONLY | O_CLOEXEC);
      if (raw < 0 && errno == ENOENT) continue;  // removed meanwhile: create it
    }
    Fd fd(raw);
    if (fd.get() < 0) throw InputError(partial, std::string("cannot write: ") + std::strerror(errno));
    if (::flock(fd.get(), LOCK_EX | LOCK_NB) != 0) {
      throw InputError(partial, "is being written by another running sweep on the same " + field("out") +
                                    "; wait for it to finish or stop it (a second writer would "
                                    "mix the two runs' rows)");
    }
    struct stat held {}, named {};
    if (::fstat(fd.get(), &held) == 0 && ::stat(partial.c_str(), &named) == 0 &&
        held.st_dev == named.st_dev && held.st_ino == named.st_ino) {
      return fd.release();
    }
  }
  throw InputError(partial, "keeps being replaced by another process; is a second sweep running?");
}

}  // namespace

std::string header_difference(const SweepHeader& a, const SweepHeader& b, bool with_shard_index) {
  return difference_impl(a, b, with_shard_index);
}

SweepCheckpoint::SweepCheckpoint(const SweepCommandOptions& o, const SweepHeader& header)
    : out_(resolve_file_output(o.out, "a sweep is checkpointed in FILE.partial, then renamed to FILE")),
      partial_(out_ + ".partial"),
      fsync_interval_s_(o.fsync_interval_s) {
  // 0. The lock first: nothing below (not even --restart's deletions) may touch the files
  // of a sweep that another process is running.
  bool created = false;
  Fd fd(open_locked(partial_, created));
  // A checkpoint we made only to hold the lock goes again if we do not write it.
  struct RemoveIfUnused {
    const std::string& path;
    bool armed;
    ~RemoveIfUnused() {
      if (armed) ::unlink(path.c_str());
    }
  } unused{partial_, created};
  std::error_code ec;
  bool resume = !created;
  if (o.restart) {
    fs::remove(out_, ec);
    resume = false;
  }
  // 1. A finished output of this very sweep is reused; any other file there is kept.
  if (fs::exists(out_)) {
    SweepFileScan scan;
    try {
      scan = scan_sweep_file(out_);
    } catch (const InputError& e) {
      throw InputError(marked_message(e) + " (" + field("out") + " exists and is not this sweep's output; "
                                               "pass " + field("restart") + " to overwrite it)");
    }
    if (format_header(scan.header) != format_header(header)) {
      throw InputError(out_, "exists and holds a different sweep (differs in " +
                                 difference_impl(scan.header, header, true) +
                                 "); pass " + field("restart") + " to overwrite it");
    }
    if (scan.complete_cells != scan.expected_cells || scan.torn_tail) {
      throw InputError(out_, "exists but is incomplete; pass " + field("restart") + " to recompute it");
    }
    reused_ = true;
    return;
  }

  // 2. Resume or create the checkpoint.
  unused.armed = false;
  // A checkpoint killed while its first two lines were being written holds a prefix of
  // them: start it afresh.
  const std::string preamble = format_header(header) + format_columns(header);
  bool fresh = !resume;
  if (resume) {
    const auto size = fs::file_size(partial_);
    if (size < preamble.size()) {
      std::ifstream in(partial_, std::ios::binary);
      std::string head(size, '\0');
      in.read(head.data(), static_cast<std::streamsize>(size));
      fresh = preamble.compare(0, size, head) == 0;
    }
  }
  if (!fresh) {
    SweepFileScan scan;
    try {
      scan = scan_sweep_file(partial_);
    } catch (const InputError& e) {
      throw InputError(marked_message(e) +
                       " (the checkpoint is damaged; delete it or pass " + field("restart") + ")");
    }
    if (format_header(scan.header) != format_header(header)) {
      throw InputError(partial_, "is the checkpoint of a different sweep (differs in " +
                                     difference_impl(scan.header, header, true) +
                                     "); delete it or pass " + field("restart"));
    }
    // Drop a torn last line (the process was killed in the middle of a write).
    if (::ftruncate(fd.get(), static_cast<off_t>(scan.valid_bytes)) != 0) {
      throw InputError(partial_, std::string("cannot truncate: ") + std::strerror(errno));
    }
    first_local_ = scan.complete_cells;
  } else {
    if (::ftruncate(fd.get(), 0) != 0) {
      throw InputError(partial_, std::string("cannot truncate: ") + std::strerror(errno));
    }
    write_all(fd.get(), preamble, partial_);
    sync_fd(fd.get(), partial_);
  }
  if (::lseek(fd.get(), 0, SEEK_END) < 0) throw InputError(partial_, "cannot seek");
  fd_ = fd.release();
  last_sync_ = Clock::now();
}

SweepCheckpoint::~SweepCheckpoint() {
  if (fd_ >= 0) ::close(fd_);  // after an error: what was written stays as the checkpoint
}

void SweepCheckpoint::append(const std::string& lines) {
  TRIBOLAB_ASSERT(fd_ >= 0, "append to a closed checkpoint");
  write_all(fd_, lines, partial_);
  if (std::chrono::duration<double>(Clock::now() - last_sync_).count() >= fsync_interval_s_) {
    sync_fd(fd_, partial_);
    last_sync_ = Clock::now();
  }
}

void SweepCheckpoint::finish(bool complete) {
  if (fd_ < 0) return;
  Fd fd(fd_);
  fd_ = -1;
  sync_fd(fd.get(), partial_);
  // Renamed while still locked: no other run can take the checkpoint over in between.
  if (complete && std::rename(partial_.c_str(), out_.c_str()) != 0) {
    throw InputError(out_, std::string("cannot rename the finished checkpoint: ") + std::strerror(errno));
  }
  fd.close(complete ? out_ : partial_);
  if (complete) sync_directory_of(out_);
}

}  // namespace tribolab::app
