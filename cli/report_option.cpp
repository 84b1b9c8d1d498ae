#include "report_option.hpp"

#include "numerics/error.hpp"
#include "report/html.hpp"

#include <cctype>
#include <filesystem>

namespace tribolab::cli {

std::string check_report_path(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path p(path);
  std::string ext = p.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".html" && ext != ".htm") return "'" + path + "' must end in .html or .htm";
  std::error_code ec;
  if (fs::is_directory(p, ec)) return "'" + path + "' is a directory";
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) return "folder '" + dir.string() + "' does not exist";
  return {};
}

CLI::Option* add_report_option(CLI::App& cmd, std::string& path, report::PlotlyMode& plotly) {
  cmd.add_option_function<std::string>(
         "--plotly", [&plotly](const std::string& text) { plotly = report::parse_plotly_mode(text); },
         "How the --report page gets Plotly.js: embed (inside the page, offline), cdn (a link to the "
         "pinned version on jsDelivr; needs the network), file (plotly-VERSION.min.js written once "
         "beside the report and shared by every report in that folder)")
      ->type_name("MODE")
      ->check(CLI::IsMember({"embed", "cdn", "file"}))
      ->default_str(std::string(report::to_string(plotly)));
  return cmd
      .add_option("--report", path,
                  "Also write an interactive, offline HTML report to this file (.html)")
      ->type_name("FILE.html")
      ->check(CLI::Validator(
          [](std::string& value) {
            std::string problem = check_report_path(value);
            // A wrong extension is a malformed command line (exit 2); a folder that does not
            // exist is a file-system problem like a missing --out folder (exit 1).
            if (problem.find("folder") != std::string::npos || problem.find("directory") != std::string::npos) {
              throw InputError("--report", problem);
            }
            return problem;
          },
          "", "report path"));
}

bool write_report_if_requested(const std::string& path, report::PlotlyMode plotly,
                               const std::function<report::Report()>& build) {
  if (path.empty()) return false;
  report::write_html(build(), path, plotly);
  return true;
}

}  // namespace tribolab::cli
