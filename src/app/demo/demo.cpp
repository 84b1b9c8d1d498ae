// `tribolab demo`: the case studies in report order and the whole demo run (src/app/demo/demo.hpp).
#include "app/demo/demo.hpp"
#include "app/common/result_keys.hpp"

#include "numerics/error.hpp"
#include "report/embedded.hpp"
#include "report/html.hpp"

#include <filesystem>

namespace tribolab::app {
namespace {

/// Creates `dir` (and its parents); InputError naming the field `out` when that is impossible.
void make_output_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  if (dir.empty()) throw InputError(field("out"), "folder name is empty");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw InputError(field("out"), "cannot create folder '" + dir + "'" +
                                  (ec ? ": " + ec.message() : ": a file has that name"));
  }
}

}  // namespace

std::vector<CaseStudy> demo_case_studies(const DemoContext& context) {
  return {
      {"about", add_about_section},
      {"incline", add_incline_case_study},
      {"incline-runs",
       [context](report::Report& r, std::ostream& log) {
         add_incline_runs_case_study(r, log, (std::filesystem::path(context.out) / "data").string());
       }},
      {"incline-series",
       [context](report::Report& r, std::ostream& log) {
         add_incline_series_case_study(r, log, (std::filesystem::path(context.out) / "data").string());
       }},
      {"bounce", add_bounce_case_study},
      {"bounce-runs", [context](report::Report& r, std::ostream& log) { add_bounce_runs_case_study(r, log, context); }},
      {"bounce-series", [context](report::Report& r, std::ostream& log) { add_bounce_series_case_study(r, log, context); }},
      {"film", [context](report::Report& r, std::ostream& log) { add_film_case_study(r, log, context); }},
      {"errata", add_errata_section},
  };
}

DemoSummary run_demo(const std::string& out, std::ostream& log) {
  make_output_folder(out);
  report::Report r;
  r.title = "tribolab: friction and impact, two studies reproduced";
  r.subtitle = "Written by “tribolab demo” (tribolab " + std::string(report::tribolab_version()) +
               ") from data shipped with the project.";
  DemoSummary summary;
  for (const CaseStudy& c : demo_case_studies(DemoContext{out})) {
    log << "demo: " << c.name << '\n' << std::flush;
    c.build(r, log);
    summary.case_studies.push_back(c.name);
  }
  summary.report = (std::filesystem::path(out) / "report.html").string();
  // The demo writes several reports into one folder: they share one plotly-<version>.min.js
  // beside them (--plotly file) instead of 1.5 MB of Plotly.js each (README.md says so).
  report::write_html(r, summary.report, report::PlotlyMode::file);
  summary.sections = r.sections.size();
  summary.figures = r.figure_count();
  return summary;
}


const ResultKeys& demo_result_keys() {
  static const ResultKeys k = {
      {"report", "", "path of report.html"}, {"case_studies", "", ""}, {"sections", "", ""}, {"figures", "", ""},
  };
  return k;
}
}  // namespace tribolab::app
