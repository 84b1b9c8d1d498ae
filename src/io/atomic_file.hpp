// Output files that appear whole or not at all: data is written to a temporary file next
// to the target and renamed over it only by commit(). A command that fails half-way leaves
// no partial output (SPEC section 5).
#pragma once

#include <fstream>
#include <string>

namespace tribolab::io {

class AtomicFile {
 public:
  /// Opens a temporary file beside `path`; throws InputError naming `path` if impossible.
  explicit AtomicFile(std::string path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();

  std::ostream& stream() { return out_; }
  /// Flushes, closes and renames the temporary file to the target; throws on failure.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_, tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace tribolab::io
