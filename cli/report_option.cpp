#include "report_option.hpp"

#include "app/output_paths.hpp"
#include "numerics/error.hpp"
#include "report/html.hpp"


namespace tribolab::cli {

std::string check_report_path(const std::string& path) { return app::report_path_problem(path); }

CLI::Option* add_report_option(CLI::App& cmd, std::string& path) {
  return cmd
      .add_option("--report", path,
                  "Also write an interactive, offline HTML report to this file (.html)")
      ->type_name("FILE.html")
      ->check(CLI::Validator(
          [](std::string& value) {
            bool malformed = false;
            std::string problem = app::report_path_problem(value, &malformed);
            // A wrong extension is a malformed command line (exit 2); a folder that does not
            // exist is a file-system problem like a missing --out folder (exit 1).
            if (!problem.empty() && !malformed) throw InputError("--report", problem);
            return problem;
          },
          "", "report path"));
}

bool write_report_if_requested(const std::string& path,
                               const std::function<report::Report()>& build) {
  if (path.empty()) return false;
  report::write_html(build(), path);
  return true;
}

bool write_report_if_requested(const std::string& path, const report::Report& report) {
  if (path.empty()) return false;
  report::write_html(report, path);
  return true;
}

}  // namespace tribolab::cli
