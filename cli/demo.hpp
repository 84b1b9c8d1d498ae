// `tribolab demo`: the report is assembled from case studies, each of which appends its
// sections to the report (and may print progress to `log`). To add one, write a function
//
//   void add_incline_case_study(report::Report& r, std::ostream& log);
//
// in its own cli/demo_<name>.cpp and list it in demo_case_studies() (cli/demo_cmd.cpp).
#pragma once

#include "report/report.hpp"

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace tribolab::cli {

/// One part of the demo report.
struct CaseStudy {
  std::string name;  ///< short name shown in the progress log, e.g. "incline"
  std::function<void(report::Report&, std::ostream& log)> build;
};

/// The case studies of `tribolab demo`, in report order.
std::vector<CaseStudy> demo_case_studies();

/// "About this report": what tribolab is, the two seeds, conventions and units, how to read
/// the report. Text only; no computed numbers.
void add_about_section(report::Report& r, std::ostream& log);

}  // namespace tribolab::cli
