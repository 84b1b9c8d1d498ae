// Output files that appear whole or not at all: data is written to a temporary file next
// to the target and renamed over it only by commit(). A command that fails half-way leaves
// no partial output (SPEC section 5). A symbolic link is followed (its target is replaced,
// the link kept); a device or FIFO is written in place (io/output_path.hpp). SIGINT/SIGTERM
// remove the temporary file too (io/temp_files.hpp).
#pragma once

#include <fstream>
#include <memory>
#include <string>

#include "io/temp_files.hpp"

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
  std::string path_;   // as given, for messages
  std::string final_;  // the regular file to rename over (symbolic links followed)
  std::string tmp_;    // the temporary file beside final_; empty when writing a device in place
  std::unique_ptr<TempRegistration> cleanup_;  // removes tmp_ if a signal ends the process
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace tribolab::io
