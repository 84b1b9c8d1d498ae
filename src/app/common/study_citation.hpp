// The two studies tribolab was built from, cited in full once per document: in the README,
// in the demo report's About block and in a "Source" section at the end of each command's
// report (docs/theory.md names them seed 000 and seed 001).
#pragma once

#include "report/report.hpp"

#include <string>

namespace tribolab::app {

enum class Study { incline, rugby_ball };

/// Authors, Chinese title with its English translation, school, fair, year and entry.
std::string study_citation(Study study);

/// `r` with a last section "Source" that cites `study` (for a report of one command).
report::Report with_study_source(report::Report r, Study study);

}  // namespace tribolab::app
