// `tribolab demo`: the report is assembled from case studies, each of which appends its
// sections to the report (and may print progress to `log`). To add one, write a function
//
//   void add_incline_case_study(report::Report& r, std::ostream& log);
//
// in its own src/app/demo_<name>.cpp and list it in demo_case_studies() (src/app/demo/demo.cpp). A case
// study that writes files (e.g. the shipped data it analyses) also takes the DemoContext and is
// listed through a lambda that binds it.
#pragma once

#include "report/report.hpp"

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace tribolab::app {

/// One part of the demo report.
struct CaseStudy {
  std::string name;  ///< short name shown in the progress log, e.g. "incline"
  std::function<void(report::Report&, std::ostream& log)> build;
};

/// What a case study may need besides the report and the log.
struct DemoContext {
  std::string out;  ///< the demo's --out folder; shipped data files go to <out>/data/
};

/// The case studies of `tribolab demo`, in report order; those that write files get `context`.
std::vector<CaseStudy> demo_case_studies(const DemoContext& context);

/// What `tribolab demo` wrote.
struct DemoSummary {
  std::string report;                      ///< path of report.html
  std::vector<std::string> case_studies;   ///< names, in report order
  std::size_t sections = 0, figures = 0;   ///< counts in the report
};

/// Runs every case study (progress lines to `log`), writes <out>/report.html (creating `out`)
/// and the shipped data files under <out>/data/. InputError naming --out when the folder
/// cannot be made.
DemoSummary run_demo(const std::string& out, std::ostream& log);

/// An erratum found in a seed, with the independent check that shows it.
struct Erratum {
  std::string where;  ///< in the seed, e.g. "seed 001, table 4"
  std::string text;   ///< what is wrong and the corrected value
  std::string check;  ///< the figure/table of the report or the test that shows it
};

/// Seed 001's errata (bounce and sweep) as data; seed 000's are incline::CaseStudy::errata.
std::vector<Erratum> seed001_errata();

/// Seed 000: table 1, figures 二, 四-八 and the printed-number checks (src/app/demo/demo_incline.cpp).
void add_incline_case_study(report::Report& r, std::ostream& log);

/// Seed 000's shipped tracked runs (data/demo/incline/), written to `data_dir` and analysed
/// as `incline analyze`, `normal-friction-test` and `mu-from-slide` do (src/app/demo/demo_incline_runs.cpp).
void add_incline_runs_case_study(report::Report& r, std::ostream& log, const std::string& data_dir);

/// Seed 000's shipped series of discs (data/demo/incline_series/), written to `data_dir` and
/// analysed as `incline analyze` over several files does (src/app/demo/demo_incline_series.cpp).
void add_incline_series_case_study(report::Report& r, std::ostream& log, const std::string& data_dir);

/// Seed 001: geometry, table 4, figures 45-48, a drop, heat maps 53-56 (src/app/demo/demo_bounce.cpp).
void add_bounce_case_study(report::Report& r, std::ostream& log);

/// Seed 001 on shipped data: three filmed bounces analysed as `bounce analyze` does and a
/// table fitted as `bounce fit` does, against the truth (src/app/demo/demo_bounce_runs.cpp); writes the
/// files to <context.out>/data/bounce/.
void add_bounce_runs_case_study(report::Report& r, std::ostream& log, const DemoContext& context);

/// Seed 001 experiment 2 on shipped data: twelve filmed throws analysed as a series, as
/// `bounce analyze FILE...` does, beside the truth (src/app/demo/demo_bounce_series.cpp); writes the
/// files to <context.out>/data/bounce_series/.
void add_bounce_series_case_study(report::Report& r, std::ostream& log, const DemoContext& context);

/// From film to numbers: a simulated throw rendered to <context.out>/data/film/throw.avi,
/// tracked with the ellipse tracker (report <context.out>/film_tracking.html, linked) and
/// analysed as `bounce analyze` does, beside the truth (src/app/demo/demo_film.cpp).
void add_film_case_study(report::Report& r, std::ostream& log, const DemoContext& context);

/// The errata of both seeds (src/app/demo/demo_errata.cpp).
void add_errata_section(report::Report& r, std::ostream& log);

/// "About this report": what tribolab is, the two seeds, conventions and units, how to read
/// the report. Text only; no computed numbers.
void add_about_section(report::Report& r, std::ostream& log);

}  // namespace tribolab::app
