#include "io/atomic_file.hpp"

#include "io/output_path.hpp"
#include "numerics/error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <unistd.h>

namespace tribolab::io {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  namespace fs = std::filesystem;
  const OutputTarget target = resolve_output(path_);
  if (target.kind == OutputTarget::Kind::stream) {
    // A device or FIFO is written in place: renaming a file over it would replace it.
    out_.open(target.path, std::ios::binary);
    if (!out_) throw InputError(path_, std::string("cannot write: ") + std::strerror(errno));
    return;
  }
  const fs::path file(target.path);
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  final_ = file.string();
  tmp_ = (dir / ("." + file.filename().string() + ".tmp" + std::to_string(::getpid()))).string();
  cleanup_ = std::make_unique<TempRegistration>(tmp_);  // before the file exists
  out_.open(tmp_, std::ios::binary | std::ios::trunc);
  if (!out_) throw InputError(path_, std::string("cannot write: ") + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    if (!tmp_.empty()) std::remove(tmp_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  bool ok = static_cast<bool>(out_);
  out_.close();
  ok = ok && !out_.fail();
  if (!ok) throw InputError(path_, "write failed (disk full?)");
  if (!tmp_.empty() && std::rename(tmp_.c_str(), final_.c_str()) != 0) {
    throw InputError(path_, std::string("cannot write: ") + std::strerror(errno));
  }
  committed_ = true;
}

}  // namespace tribolab::io
