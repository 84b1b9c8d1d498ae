// Report pages of the bounce analyses (`bounce analyze --report`, `bounce fit --report`) and
// the building blocks the demo's "bounce runs" case study shares with them: the figures of
// one analysed bounce (tips and centre, fits over the data, residuals, orientation and spin),
// its tables (values at the impact with uncertainties, restitution, energies), and the
// figures and tables of a contact-law fit (parity plots, residuals, parameters).
// docs/cli.md#bounce-analyze, docs/cli.md#bounce-fit.
#pragma once

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_fit.hpp"
#include "report/report.hpp"

#include <string>
#include <vector>

namespace tribolab::app {

/// Adds the figures of one analysed bounce to `s`, titled "<title>: x–t" etc.: x–t, y–t
/// (tips, centre, fitted line/parabolas, the impact time marked, unfitted frames in grey),
/// the trajectory, the x and y residuals, the orientation θ–t and the spin ω–t with the
/// fitted lines. Returns the number of figures added (6).
int add_bounce_analysis_figures(report::Section& s, const std::string& title,
                                const analysis::BounceAnalysis& r);

/// Before/after the impact: v_x, v_y, ω (at the impact time), a_y, R^2, points, apex height
/// and kinetic energies, each value with its standard uncertainty.
report::Table bounce_segments_table(const analysis::BounceAnalysis& r);

/// Impact time, e from velocities and from heights, θ and collision angle at the impact,
/// energy change, floor, mean normal force (when a contact duration was given).
report::Table bounce_restitution_table(const analysis::BounceAnalysis& r);

/// The equations of the analysis, citing seed 001 where it has them.
void add_bounce_analysis_equations(report::Section& s, const analysis::BounceAnalysis& r);

/// `bounce analyze --report`: `command` is the command line shown under the title.
report::Report bounce_analyze_report(const std::string& command, const bounce::Ball& ball,
                                     const analysis::BounceAnalysis& r);

/// Adds the figures of a contact-law fit to `s`: measured against predicted outgoing v_x,
/// v_y and ω (parity plots with the line y = x), and the residuals against the row and against
/// the orientation at touch. Returns the number of figures added (5).
int add_bounce_fit_figures(report::Section& s, const std::string& title,
                           const std::vector<analysis::BounceRow>& rows,
                           const analysis::BounceFitResult& r);

/// Fitted parameters with uncertainties, each marked fitted or fixed, and the rms.
report::Table bounce_fit_parameters_table(const analysis::BounceFitOptions& o,
                                          const analysis::BounceFitResult& r);

/// The contact law of a fit, with the fitted values, as add_contact_equations shows it (for a
/// restitution-based law, D at the rows' median incoming speed).
void add_bounce_fit_equations(report::Section& s, const std::vector<analysis::BounceRow>& rows,
                              const analysis::BounceFitOptions& o, const analysis::BounceFitResult& r);

/// `bounce fit --report`.
report::Report bounce_fit_report(const std::string& command, const std::vector<analysis::BounceRow>& rows,
                                 const analysis::BounceFitOptions& o, const analysis::BounceFitResult& r);

}  // namespace tribolab::app
