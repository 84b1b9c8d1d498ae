#include "studio/upload.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

namespace tribolab::studio {

namespace fs = std::filesystem;

const std::vector<std::string>& openable_extensions() {
  static const std::vector<std::string> kExtensions = {".mp4", ".mov", ".avi", ".mkv", ".webm", ".m4v", ".trk", ".trz"};
  return kExtensions;
}

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool openable_extension(const std::string& ext) {
  const auto& all = openable_extensions();
  return std::find(all.begin(), all.end(), lower(ext)) != all.end();
}

/// The code point of the UTF-8 sequence at s[i] and its length; length 0 when invalid
/// (overlong, surrogate, beyond U+10FFFF, truncated).
std::pair<char32_t, std::size_t> utf8_at(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (n == 0 || i + n > s.size()) return {0, 0};
  char32_t cp = n == 1 ? c : n == 2 ? (c & 0x1f) : n == 3 ? (c & 0x0f) : (c & 0x07);
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) >> 6) != 0x2) return {0, 0};
    cp = (cp << 6) | (byte(i + k) & 0x3f);
  }
  static constexpr char32_t kMin[] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < kMin[n] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return {0, 0};
  return {cp, n};
}

/// Characters kept in a saved name: ASCII letters, digits and `.-_+,()[]`, and non-ASCII
/// letters and signs but the invisible ones (C1 controls, no-break and soft hyphen, zero-width
/// and bidi controls that make a name read as another, the byte order mark, specials).
bool kept(char32_t c) {
  if (c < 0x80) return std::isalnum(static_cast<int>(c)) || (c != 0 && std::strchr(".-_+,()[]", static_cast<int>(c)) != nullptr);
  if (c <= 0xa0 || c == 0xad || c == 0x34f || c == 0x61c || c == 0x180e) return false;
  if ((c >= 0x2000 && c <= 0x200f) || (c >= 0x2028 && c <= 0x202f) || (c >= 0x205f && c <= 0x206f)) return false;
  if (c == 0x3000 || c == 0xfeff || (c >= 0xfff0 && c <= 0xffff) || (c >= 0xe0000 && c <= 0xe007f)) return false;
  return true;
}

/// Cuts `s` to at most `bytes` bytes without splitting a UTF-8 sequence.
std::string cut(std::string s, std::size_t bytes) {
  if (s.size() <= bytes) return s;
  std::size_t n = bytes;
  while (n > 0 && (static_cast<unsigned char>(s[n]) >> 6) == 0x2) --n;
  return s.substr(0, n);
}

[[noreturn]] void storage_error(const std::string& what, int error) {
  const bool full = error == ENOSPC || error == EDQUOT || error == EFBIG;
  throw UploadError(507, what + ": " + std::strerror(error) +
                             (full ? " (the disk is full: free some space, or track the file with `track video`)"
                                   : " (start the studio on a folder you can write, or copy the file into it)"));
}

}  // namespace

bool studio_can_open(const fs::path& file) { return openable_extension(file.extension().string()); }

std::string upload_name(std::string_view given) {
  if (given.empty()) throw UploadError(400, "the upload has no file name ('name')");
  const std::size_t slash = given.find_last_of("/\\");
  const std::string_view last = slash == std::string_view::npos ? given : given.substr(slash + 1);
  std::string safe;
  for (std::size_t i = 0; i < last.size();) {
    const auto [cp, n] = utf8_at(last, i);
    const bool keep = n > 0 && kept(cp);
    if (keep)
      safe.append(last.substr(i, n));
    else if (safe.empty() || safe.back() != '_')
      safe += '_';
    i += n > 0 ? n : 1;
  }
  // No trailing dot (Windows drops it too); the extension is what follows the last dot.
  while (!safe.empty() && (safe.back() == '.' || safe.back() == '_')) safe.pop_back();
  const std::size_t dot = safe.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : safe.substr(dot);
  if (!openable_extension(ext)) {
    std::string list;
    for (const auto& e : openable_extensions()) list += (list.empty() ? "" : " ") + e;
    throw UploadError(415, "'" + std::string(given) + "' is not a file the studio opens: a video or a Tracker project (" +
                               list + ")");
  }
  // No hidden file, no name read as an option: leading dots, dashes and '_' go.
  std::string stem = safe.substr(0, dot);
  stem.erase(0, std::min(stem.find_first_not_of(".-_"), stem.size()));
  stem = cut(stem, 100);
  while (!stem.empty() && (stem.back() == '.' || stem.back() == '_')) stem.pop_back();
  return (stem.empty() ? "upload" : stem) + ext;
}

UploadFile::UploadFile(const fs::path& root) : root_(root) {
  const std::string folder(kUploadFolder);
  if (::mkdir((root_ / folder).c_str(), 0755) != 0 && errno != EEXIST)
    storage_error("the folder " + folder + "/ cannot be created", errno);
  // O_NOFOLLOW: an uploads/ that is a symlink (out of the folder, perhaps) is not written through.
  dir_ = ::open((root_ / folder).c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (dir_ < 0) storage_error(folder + "/ cannot be opened as a folder (is it a file, or a symlink?)", errno);
  std::random_device random;
  for (int attempt = 0; attempt < 16 && fd_ < 0; ++attempt) {
    char name[40];
    std::snprintf(name, sizeof name, ".upload-%08x%08x.part", random(), random());
    fd_ = ::openat(dir_, name, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd_ >= 0)
      temp_ = name;
    else if (errno != EEXIST)
      storage_error("a file cannot be created in " + folder + "/", errno);
  }
  if (fd_ < 0) storage_error("a file cannot be created in " + folder + "/", EEXIST);
}

UploadFile::~UploadFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temp_.empty()) ::unlinkat(dir_, temp_.c_str(), 0);
  if (dir_ >= 0) ::close(dir_);
}

std::uint64_t UploadFile::available_bytes() const {
  struct statvfs s {};
  if (::fstatvfs(dir_, &s) != 0) return UINT64_MAX;  // unknown: the writes will tell
  return static_cast<std::uint64_t>(s.f_bavail) * s.f_frsize;
}

void UploadFile::write(std::string_view piece) {
  while (!piece.empty()) {
    const ssize_t n = ::write(fd_, piece.data(), piece.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) storage_error("the upload cannot be written after " + std::to_string(size_) + " bytes", n < 0 ? errno : ENOSPC);
    piece.remove_prefix(static_cast<std::size_t>(n));
    size_ += static_cast<std::uint64_t>(n);
  }
}

std::string UploadFile::commit(const std::string& name) {
  if (::fsync(fd_) != 0) storage_error("the upload cannot be written to disk", errno);
  if (::close(fd_) != 0) {
    fd_ = -1;
    storage_error("the upload cannot be written to disk", errno);
  }
  fd_ = -1;
  const fs::path p(name);
  const std::string stem = p.stem().string(), ext = p.extension().string();
  for (int n = 1; n <= 10000; ++n) {
    const std::string candidate = n == 1 ? name : stem + "-" + std::to_string(n) + ext;
    struct stat st {};
    // A name whose autosave is left from a deleted file would restore that file's tracks.
    if (::fstatat(dir_, (candidate + ".studio.json").c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0) continue;
    if (::renameat2(dir_, temp_.c_str(), dir_, candidate.c_str(), RENAME_NOREPLACE) == 0) {
      committed_ = true;
      return std::string(kUploadFolder) + "/" + candidate;
    }
    if (errno == EEXIST) continue;
    if (errno == EINVAL || errno == ENOSYS) {
      // A file system without RENAME_NOREPLACE: a hard link never replaces either.
      if (::linkat(dir_, temp_.c_str(), dir_, candidate.c_str(), 0) == 0) {
        ::unlinkat(dir_, temp_.c_str(), 0);
        committed_ = true;
        return std::string(kUploadFolder) + "/" + candidate;
      }
      if (errno == EEXIST) continue;
    }
    storage_error("the upload cannot be named " + std::string(kUploadFolder) + "/" + candidate, errno);
  }
  throw UploadError(507, "every name from " + name + " to " + stem + "-10000" + ext + " is taken in " +
                             std::string(kUploadFolder) + "/: rename the file");
}

}  // namespace tribolab::studio
