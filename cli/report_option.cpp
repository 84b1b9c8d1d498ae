#include "report_option.hpp"

#include "app/common/output_paths.hpp"
#include "numerics/error.hpp"
#include "report/html.hpp"


namespace tribolab::cli {

std::string check_report_path(const std::string& path) { return app::report_path_problem(path); }

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
            bool malformed = false;
            std::string problem = app::report_path_problem(value, &malformed);
            // A wrong extension is a malformed command line (exit 2); a folder that does not
            // exist is a file-system problem like a missing --out folder (exit 1).
            if (!problem.empty() && !malformed) throw InputError("--report", problem);
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
