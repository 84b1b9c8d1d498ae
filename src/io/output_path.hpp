// What an output path may be, and how each kind is written (docs/cli.md, "Output files").
// A regular file (or nothing) is replaced atomically: written beside it and renamed over it.
// A symbolic link is followed: its final target is what gets written, the link stays. A
// character device (/dev/null, /dev/stdout) or a FIFO is written through, in place, never
// replaced. Anything else (a directory, a block device, a socket) is refused.
#pragma once

#include <string>

namespace tribolab::io {

struct OutputTarget {
  enum class Kind {
    file,    ///< a regular file or none yet: write a temporary file beside it, rename it over
    stream,  ///< a character device or FIFO: open and write it in place
  };
  Kind kind = Kind::file;
  std::string path;  ///< where to write: the given path with every symbolic link followed
};

/// Classifies `path` as above; throws InputError naming `path` for an empty name, a
/// directory, a missing directory, a block device, a socket or a symlink loop.
OutputTarget resolve_output(const std::string& path);

/// The same, for outputs that must be renamed into place (a sweep's checkpoint, a video):
/// a device or FIFO is refused with `why` ("a sweep output is checkpointed and renamed").
std::string resolve_file_output(const std::string& path, const std::string& why);

}  // namespace tribolab::io
