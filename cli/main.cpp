#include "app.hpp"

#include <glog/logging.h>

int main(int argc, char** argv) {
  // Ceres logs through glog to stderr (e.g. "covariance matrix is near rank deficient"): the
  // CLI reports every failure itself in one line, so only fatal glog messages may pass.
  FLAGS_minloglevel = google::GLOG_FATAL;
  return tribolab::cli::run(argc, argv);
}
