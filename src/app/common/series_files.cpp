#include "app/common/series_files.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace tribolab::app {

namespace fs = std::filesystem;

std::string series_runs_folder(const std::string& report_path) {
  const fs::path p(report_path);
  return (p.parent_path() / (p.stem().string() + "_runs")).string();
}

std::string series_run_file(std::size_t index, const std::string& source, std::size_t n_runs) {
  const std::size_t width = std::to_string(n_runs).size();
  std::string number = std::to_string(index + 1);
  number.insert(0, width - std::min(width, number.size()), '0');
  std::string stem = fs::path(source).stem().string();
  for (char& c : stem)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')) c = '_';
  return number + "_" + (stem.empty() ? "run" : stem) + ".html";
}

}  // namespace tribolab::app
