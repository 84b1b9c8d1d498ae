#include "app/common/series_files.hpp"

#include "report/html.hpp"

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

std::string encode_link(const std::string& path) {
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) || c == '.' || c == '_' || c == '-' || c == '/') {
      out += static_cast<char>(c);
    } else {
      static const char* hex = "0123456789ABCDEF";
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

std::vector<std::string> write_run_reports(const std::vector<std::string>& sources, const std::string& report_path,
                                           report::PlotlyMode plotly,
                                           const std::function<std::optional<report::Report>(std::size_t)>& report_of) {
  std::vector<std::string> links(sources.size());
  if (report_path.empty()) return links;
  const std::string folder = series_runs_folder(report_path);
  fs::create_directories(folder);
  const std::string folder_name = fs::path(folder).filename().string();
  const std::string report_dir = fs::absolute(report_path).parent_path().string();
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const std::optional<report::Report> r = report_of(i);
    if (!r) continue;
    const std::string file = series_run_file(i, sources[i], sources.size());
    report::write_html(*r, (fs::path(folder) / file).string(), plotly, report_dir);
    links[i] = encode_link(folder_name + "/" + file);
  }
  return links;
}

}  // namespace tribolab::app
