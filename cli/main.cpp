#include "app.hpp"
#include "io/temp_files.hpp"

#include <glog/logging.h>

int main(int argc, char** argv) {
  // Ceres logs through glog to stderr (e.g. "covariance matrix is near rank deficient"): the
  // CLI reports every failure itself in one line, so only fatal glog messages may pass.
  FLAGS_minloglevel = google::GLOG_FATAL;
  // Ctrl-C or kill leaves no temporary file behind (an extracted video, `.OUT.tmpPID`).
  tribolab::io::install_temp_cleanup_on_signals();
  return tribolab::cli::run(argc, argv);
}
