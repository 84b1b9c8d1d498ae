// The output files of a workflow, checked before any work (docs/cli.md#errors): every front
// end gets the same early error (the command line exit 2 or 1, Python ValueError), never a
// result computed and then lost because its file cannot be written.
#pragma once

#include <string>
#include <vector>

namespace tribolab::app {

/// One output file of a workflow: the option struct's field that names it and the path
/// (empty = not requested, skipped).
struct OutputPath {
  std::string field;  ///< snake_case field ("out", "report", "bounces_out"); "report" must end in .html
  std::string path;
};

/// Empty when `path` is a usable HTML report path, else why not: it does not end in .html or
/// .htm (`*malformed` set to true: a malformed command line), it is a folder or its folder
/// does not exist (`*malformed` false).
std::string report_path_problem(const std::string& path, bool* malformed = nullptr);

/// Empty when no two outputs name one file and no output names an input, else the problem,
/// its fields marked (numerics/error.hpp field()). `files` in the order given; an empty
/// field marks an input (inputs may repeat: a series may analyse one file twice).
std::string same_file_problem(const std::vector<OutputPath>& files);

/// Throws InputError naming the field, before any work: two outputs naming one file, an
/// output naming an input, a report not ending in .html, an output that is a folder or whose
/// folder does not exist.
void check_output_paths(const std::vector<std::string>& inputs, const std::vector<OutputPath>& outputs);

}  // namespace tribolab::app
