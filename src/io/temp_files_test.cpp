#include "io/temp_files.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include <sys/wait.h>
#include <unistd.h>

#include "io/atomic_file.hpp"

namespace tribolab::io {
namespace {

namespace fs = std::filesystem;

/// Runs `body` in a forked child that has install_temp_cleanup_on_signals(); returns its
/// wait status.
template <class Body>
int in_child(Body body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    install_temp_cleanup_on_signals();
    body();
    std::_Exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(TempFiles, ASignalRemovesRegisteredFilesAndStillEndsTheProcess) {
  // Issue 26: SIGINT/SIGTERM left the extracted video (3.7 GB seen) and `.OUT.tmpPID` files.
  const fs::path dir = fs::temp_directory_path() / ("tribolab_tempfiles_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string kept = (dir / "kept").string(), temp = (dir / "temp").string();
  for (int sig : {SIGINT, SIGTERM}) {
    const int status = in_child([&] {
      std::ofstream(kept) << "unregistered";
      std::ofstream(temp) << "registered";
      TempRegistration r(temp);
      {
        TempRegistration gone(kept);  // registered, then released: kept
      }
      ::raise(sig);
    });
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << status;
    EXPECT_FALSE(fs::exists(temp)) << sig;
    EXPECT_TRUE(fs::exists(kept)) << sig;
  }
  // AtomicFile's temporary file is registered.
  const std::string out = (dir / "out.csv").string();
  const int status = in_child([&] {
    AtomicFile f(out);
    f.stream() << "half" << std::flush;
    ::raise(SIGTERM);
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1) << "a .out.csv.tmpPID left";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tribolab::io
