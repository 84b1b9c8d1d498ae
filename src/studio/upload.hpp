// Files sent to the studio by the page (docs/design.md#studio, "Uploads"): which files the
// studio opens, the safe name an upload is saved under, and the file written as the bytes
// arrive (never held whole in memory), inside the folder's `uploads/` and never over a file
// that exists.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tribolab::studio {

/// The extensions of the files the studio opens: videos OpenCV decodes and Tracker projects.
const std::vector<std::string>& openable_extensions();  // ".mp4", ..., ".trk", ".trz"
/// True when `file`'s extension (in any case) is one of openable_extensions().
bool studio_can_open(const std::filesystem::path& file);

/// An upload refused or failed, with the HTTP status it is answered with (400 bad name, 413
/// too large, 415 not a file the studio opens, 507 the folder cannot hold it) and the reason.
struct UploadError : std::runtime_error {
  UploadError(int status_, const std::string& message) : std::runtime_error(message), status(status_) {}
  int status;
};

/// The sub-folder of the studio's folder that uploads are written to.
inline constexpr std::string_view kUploadFolder = "uploads";

/// The name a file called `given` (as the browser names it; any bytes) is saved under: its last
/// path component (after '/' or '\'), every control, format (bidi, zero-width) or other
/// character a shell or file system treats specially (`"*:<>?|` and whitespace) replaced by
/// '_' (runs of them by one), invalid UTF-8 likewise, leading dots and dashes removed (no hidden
/// file, nothing read as an option), the stem cut to 100 bytes; an empty stem becomes
/// "upload". Throws UploadError 400 when nothing is given, 415 when the extension is not one
/// the studio opens (the extension is kept as given).
std::string upload_name(std::string_view given);

/// A file being uploaded into `root`/uploads/: created as a hidden temporary file there
/// (`.upload-RANDOM.part`, O_EXCL, the folder opened without following a symlink), written
/// piece by piece, and renamed to a free name by commit() (renameat2 RENAME_NOREPLACE, so an
/// existing file is never replaced, even one created meanwhile). Destroyed uncommitted (an
/// interrupted or refused upload), the temporary file is removed. Every failure is an
/// UploadError 507 naming the cause (disk full, folder not writable).
class UploadFile {
 public:
  /// `root`: the studio's folder (canonical). Creates `uploads/` when missing.
  explicit UploadFile(const std::filesystem::path& root);
  ~UploadFile();
  UploadFile(const UploadFile&) = delete;
  UploadFile& operator=(const UploadFile&) = delete;

  /// Bytes free on the folder's file system (statvfs), for refusing a declared size at once.
  std::uint64_t available_bytes() const;
  /// Appends `piece`.
  void write(std::string_view piece);
  std::uint64_t size() const { return size_; }
  /// Flushes the file to disk and gives it the name `name` (from upload_name()) or, when that
  /// name or its autosave `NAME.studio.json` exists, the first free `STEM-2.EXT`, `STEM-3.EXT`,
  /// ...; returns the path relative to the root ("uploads/clip-2.mp4").
  std::string commit(const std::string& name);

 private:
  std::filesystem::path root_;
  int dir_ = -1;          ///< the uploads folder, opened O_DIRECTORY | O_NOFOLLOW
  int fd_ = -1;           ///< the temporary file
  std::string temp_;      ///< its name in the folder
  std::uint64_t size_ = 0;
  bool committed_ = false;
};

}  // namespace tribolab::studio
