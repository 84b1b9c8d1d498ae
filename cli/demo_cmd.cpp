// `tribolab demo --out DIR`: runs the case studies and writes DIR/report.html.
#include "app.hpp"
#include "demo.hpp"
#include "numerics/error.hpp"
#include "report/embedded.hpp"
#include "report/html.hpp"

#include <filesystem>
#include <iostream>
#include <sstream>

namespace tribolab::cli {
namespace {

struct DemoOptions {
  std::string out = "demo-out";  ///< folder for report.html (created if needed)
  bool json = false;
};

/// Creates `dir` (and its parents); InputError naming --out when that is impossible.
void make_output_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  if (dir.empty()) throw InputError("--out", "folder name is empty");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw InputError("--out", "cannot create folder '" + dir + "'" +
                                  (ec ? ": " + ec.message() : ": a file has that name"));
  }
}

void run_demo(const DemoOptions& opt) {
  make_output_folder(opt.out);
  std::ostringstream quiet;
  std::ostream& log = opt.json ? static_cast<std::ostream&>(quiet) : std::cout;

  report::Report r;
  r.title = "tribolab: friction and impact, two studies reproduced";
  r.subtitle = "Written by “tribolab demo” (tribolab " + std::string(report::tribolab_version()) +
               ") from data shipped with the project.";
  nlohmann::json studies = nlohmann::json::array();
  for (const CaseStudy& c : demo_case_studies(DemoContext{opt.out})) {
    log << "demo: " << c.name << '\n' << std::flush;
    c.build(r, log);
    studies.push_back(c.name);
  }
  const std::string path = (std::filesystem::path(opt.out) / "report.html").string();
  report::write_html(r, path);
  print_result({{"report", path},
                {"case_studies", studies},
                {"sections", r.sections.size()},
                {"figures", r.figure_count()}},
               opt.json);
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

void register_demo(CLI::App& root) {
  auto opt = std::make_shared<DemoOptions>();
  auto* cmd = root.add_subcommand(
      "demo",
      "Run both studies end to end on shipped data and write an offline HTML report "
      "(DIR/report.html)");
  cmd->add_option("--out", opt->out, "Folder for report.html, created if needed")
      ->type_name("DIR")
      ->capture_default_str();
  add_json_flag(*cmd, opt->json);
  cmd->callback([opt] { run_demo(*opt); });
}

}  // namespace tribolab::cli
