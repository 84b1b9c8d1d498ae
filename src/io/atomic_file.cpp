#include "io/atomic_file.hpp"

#include "numerics/error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <unistd.h>

namespace tribolab::io {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  if (path_.empty()) throw InputError("output file name is empty");
  namespace fs = std::filesystem;
  const fs::path target(path_);
  if (fs::is_directory(target)) throw InputError(path_, "is a directory, expected a file name");
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir)) throw InputError(path_, "directory does not exist");
  tmp_ = (dir / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()))).string();
  out_.open(tmp_, std::ios::binary | std::ios::trunc);
  if (!out_) throw InputError(path_, std::string("cannot write: ") + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(tmp_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok) throw InputError(path_, "write failed (disk full?)");
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    throw InputError(path_, std::string("cannot write: ") + std::strerror(errno));
  }
  committed_ = true;
}

}  // namespace tribolab::io
