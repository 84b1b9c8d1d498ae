#include "io/output_path.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <sys/stat.h>

#include "numerics/error.hpp"

namespace tribolab::io {
namespace fs = std::filesystem;

OutputTarget resolve_output(const std::string& path) {
  if (path.empty()) throw InputError("output file name is empty");
  fs::path p(path);
  // Follow symbolic links one by one (as open() would), up to the kernel's own limit of 40.
  for (int hops = 0;; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0) {
      if (errno != ENOENT) throw InputError(path, std::string("cannot write: ") + std::strerror(errno));
      const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
      if (!fs::is_directory(dir)) throw InputError(path, "directory does not exist");
      return {OutputTarget::Kind::file, p.string()};
    }
    if (S_ISLNK(st.st_mode)) {
      if (hops == 40) throw InputError(path, "too many levels of symbolic links");
      std::error_code ec;
      const fs::path to = fs::read_symlink(p, ec);
      if (ec) throw InputError(path, "cannot read the symbolic link: " + ec.message());
      p = to.is_absolute() ? to : p.parent_path() / to;
      continue;
    }
    if (S_ISREG(st.st_mode)) return {OutputTarget::Kind::file, p.string()};
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) return {OutputTarget::Kind::stream, p.string()};
    if (S_ISDIR(st.st_mode)) throw InputError(path, "is a directory, expected a file name");
    throw InputError(path, S_ISBLK(st.st_mode) ? "is a block device; refusing to write to it"
                                               : "is not a regular file, device or FIFO");
  }
}

std::string resolve_file_output(const std::string& path, const std::string& why) {
  const OutputTarget t = resolve_output(path);
  if (t.kind != OutputTarget::Kind::file) {
    throw InputError(path, "is a device or FIFO, not a regular file (" + why + ")");
  }
  return t.path;
}

}  // namespace tribolab::io
