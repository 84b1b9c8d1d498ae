#include "io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include "io/output_path.hpp"
#include "numerics/error.hpp"

namespace tribolab::io {
namespace {

namespace fs = std::filesystem;

std::string temp_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("tribolab_atomic_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const std::string& path, const std::string& text) {
  AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(AtomicFile, ReplacesARegularFileWhole) {
  const std::string dir = temp_dir("regular");
  write(dir + "/a.txt", "old\n");
  write(dir + "/a.txt", "new\n");
  EXPECT_EQ(slurp(dir + "/a.txt"), "new\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);  // no temp left
}

TEST(AtomicFile, WritesASymlinksTargetAndKeepsTheLink) {
  // Issue 26: the rename swapped the link for a plain file and left its target unchanged.
  const std::string dir = temp_dir("symlink");
  fs::create_directories(dir + "/real");
  write(dir + "/real/data.csv", "old\n");
  fs::create_symlink("real/data.csv", dir + "/link.csv");  // relative, as `ln -s` makes them
  fs::create_symlink(dir + "/link.csv", dir + "/link2.csv");  // a chain of two
  write(dir + "/link2.csv", "new\n");
  EXPECT_TRUE(fs::is_symlink(dir + "/link.csv"));
  EXPECT_TRUE(fs::is_symlink(dir + "/link2.csv"));
  EXPECT_EQ(slurp(dir + "/real/data.csv"), "new\n");
  // A dangling link creates its target.
  fs::create_symlink("real/fresh.csv", dir + "/dangling.csv");
  write(dir + "/dangling.csv", "fresh\n");
  EXPECT_TRUE(fs::is_symlink(dir + "/dangling.csv"));
  EXPECT_EQ(slurp(dir + "/real/fresh.csv"), "fresh\n");
}

TEST(AtomicFile, WritesAFifoInPlace) {
  // Issue 26: the FIFO was replaced by a regular file and its reader got nothing.
  const std::string dir = temp_dir("fifo");
  const std::string fifo = dir + "/pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A non-blocking reader lets the writer's open() return at once; the text (far below
  // the 64 KiB pipe buffer) waits in the pipe.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  write(fifo, "through the pipe\n");
  char buf[64] = {};
  const ssize_t n = ::read(reader, buf, sizeof buf);
  ::close(reader);
  EXPECT_EQ(std::string(buf, n > 0 ? static_cast<std::size_t>(n) : 0), "through the pipe\n");
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST(AtomicFile, WritesACharacterDeviceInPlaceAndReportsItsErrorOnce) {
  // Issue 26: `--out d/mynull` (a copy of /dev/null) became a 15 KB regular file, and as
  // root `--out /dev/full` replaced /dev/full. Devices made here, never the real ones.
  const std::string dir = temp_dir("device");
  const std::string null = dir + "/mynull", full = dir + "/myfull";
  if (::mknod(null.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0 ||
      ::mknod(full.c_str(), S_IFCHR | 0666, ::makedev(1, 7)) != 0) {
    GTEST_SKIP() << "mknod needs CAP_MKNOD";
  }
  write(null, std::string(15000, 'x'));
  struct stat st {};
  ASSERT_EQ(::lstat(null.c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_EQ(message_of([&] { write(full, std::string(1 << 20, 'x')); }),
            full + ": write failed (disk full?)");
  ASSERT_EQ(::lstat(full.c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST(OutputPath, RefusesWhatCannotBeWritten) {
  const std::string dir = temp_dir("refused");
  EXPECT_EQ(message_of([&] { resolve_output(dir); }), dir + ": is a directory, expected a file name");
  EXPECT_EQ(message_of([&] { resolve_output(dir + "/no/such.csv"); }),
            dir + "/no/such.csv: directory does not exist");
  fs::create_symlink("loop", dir + "/loop");
  EXPECT_EQ(message_of([&] { resolve_output(dir + "/loop"); }),
            dir + "/loop: too many levels of symbolic links");
  ASSERT_EQ(::mkfifo((dir + "/pipe").c_str(), 0600), 0);
  EXPECT_EQ(message_of([&] { resolve_file_output(dir + "/pipe", "a video is renamed into place"); }),
            dir + "/pipe: is a device or FIFO, not a regular file (a video is renamed into place)");
}

}  // namespace
}  // namespace tribolab::io
