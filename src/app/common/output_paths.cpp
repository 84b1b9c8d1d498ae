#include "app/common/output_paths.hpp"

#include "numerics/error.hpp"

#include <cctype>
#include <filesystem>

namespace tribolab::app {
namespace {

namespace fs = std::filesystem;

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ea, eb;
  const fs::path pa = fs::weakly_canonical(a, ea), pb = fs::weakly_canonical(b, eb);
  return ea || eb ? a == b : pa == pb;
}

/// Empty when `path` can be written: not a folder, its folder exists.
std::string folder_problem(const std::string& path) {
  const fs::path p(path);
  std::error_code ec;
  if (fs::is_directory(p, ec)) return "'" + path + "' is a directory";
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) return "directory '" + dir.string() + "' does not exist";
  return {};
}

}  // namespace

std::string report_path_problem(const std::string& path, bool* malformed) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool bad_name = ext != ".html" && ext != ".htm";
  if (malformed) *malformed = bad_name;
  if (bad_name) return "'" + path + "' must end in .html or .htm";
  return folder_problem(path);
}

std::string same_file_problem(const std::vector<OutputPath>& files) {
  for (std::size_t i = 0; i < files.size(); ++i) {
    for (std::size_t j = i + 1; j < files.size(); ++j) {
      const OutputPath &a = files[i], &b = files[j];
      if (a.path.empty() || b.path.empty() || (a.field.empty() && b.field.empty())) continue;
      if (!same_file(a.path, b.path)) continue;
      if (a.field.empty() || b.field.empty())
        return field(a.field.empty() ? b.field : a.field) + ": '" + b.path + "' is also the input file; choose another name";
      return field(a.field) + " and " + field(b.field) + " name the same file '" + b.path + "'; choose two names";
    }
  }
  return {};
}

void check_output_paths(const std::vector<std::string>& inputs, const std::vector<OutputPath>& outputs) {
  std::vector<OutputPath> files;
  for (const auto& in : inputs) files.push_back({"", in});
  files.insert(files.end(), outputs.begin(), outputs.end());
  if (auto e = same_file_problem(files); !e.empty()) throw InputError(e);
  for (const auto& o : outputs) {
    if (o.path.empty()) continue;
    const std::string e = o.field == "report" ? report_path_problem(o.path) : folder_problem(o.path);
    if (!e.empty()) throw InputError(field(o.field), e);
  }
}

}  // namespace tribolab::app
