// The demo's input files, carried inside the binary (src/app/demo/embed_demo_data.cmake embeds
// data/demo/ at build time). Each study's files are made by its committed script
// data/demo/<study>/make.sh from tribolab's own simulators, so the data can be regenerated
// and checked (src/app/demo_data_test.cpp runs the scripts and compares byte for byte).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace tribolab::app {

/// One shipped file.
struct DemoFile {
  std::string name;          ///< path below data/demo/, e.g. "incline/run_20deg.txt"
  std::string_view content;  ///< exact bytes of the file
};

/// Every embedded file, sorted by name.
std::vector<DemoFile> demo_files();

/// The content of data/demo/<name>; throws std::logic_error when it was not embedded (a
/// build error, not a user error).
std::string_view demo_file(std::string_view name);

/// Writes data/demo/<name> to <dir>/<name> (creating folders; atomically) and returns the
/// path written, so the demo analyses real files that the user can re-run commands on.
std::string write_demo_file(std::string_view name, const std::string& dir);

namespace detail {
struct EmbeddedFile {
  const char* name;
  const char* begin;
  const char* end;
};
extern const EmbeddedFile kDemoFiles[];
}  // namespace detail

}  // namespace tribolab::app
