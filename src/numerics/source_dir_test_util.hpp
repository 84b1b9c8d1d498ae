// The repository's root for tests that read its files (data/demo/, ../shared/data/): the
// environment variable TRIBOLAB_SOURCE_DIR when set (ctest sets it), else the source directory
// the test was compiled from (CMakeLists.txt defines the macro TRIBOLAB_SOURCE_DIR for every
// area's test program), so a test program run directly finds the files too.
#pragma once

#include <cstdlib>
#include <string>

namespace tribolab {

inline std::string test_source_dir() {
  if (const char* env = std::getenv("TRIBOLAB_SOURCE_DIR"); env && *env) return env;
#ifdef TRIBOLAB_SOURCE_DIR
  return TRIBOLAB_SOURCE_DIR;
#else
  return ".";
#endif
}

}  // namespace tribolab
