// The "incline-series" case study of the demo (seed 000 launched many discs: table 1, figures
// 五A-八): the synthetic series shipped in data/demo/incline_series/ (made by its make.sh) is
// written to <out>/data/incline_series/ and analysed as `incline analyze` over several files
// does (analysis::run_series, summarize_incline_series), with the truth the script used beside
// every result: first the seven discs at one angle (figure 八's stop-point scaling), then all
// ten discs at four angles (the cos(theta_c)-tan(phi) test).
#include "numerics/units.hpp"
#include "app/common/report_util.hpp"
#include "app/demo/demo.hpp"
#include "app/demo/demo_data.hpp"
#include "app/incline/report_incline_series.hpp"

#include "analysis/incline_fit.hpp"
#include "analysis/incline_series.hpp"
#include "analysis/series.hpp"
#include "incline/params.hpp"
#include "io/track_import.hpp"
#include "report/format.hpp"

#include <cmath>
#include <ostream>

namespace tribolab::app {
namespace {

using report::format_uncertain;
using report::format_value;

/// One shipped disc and the truth its line of data/demo/incline_series/make.sh used.
struct SeriesDisc {
  const char* file;     ///< below data/demo/incline_series/
  const char* phi_deg;  ///< as on the command line
  double v0;            ///< m/s
  const char* synth;    ///< the options of its make.sh line (checked by demo_incline_series_test)
};

constexpr double kMuTruth = 0.585;  // the seed's figure-八 value
const SeriesDisc kDiscs[] = {
    {"disc01_10.37deg.txt", "10.37", 1.2, "--mu 0.585 --phi-deg 10.37 --v0 1.2 --fps 120 --seed 101"},
    {"disc02_10.37deg.txt", "10.37", 1.4, "--mu 0.585 --phi-deg 10.37 --v0 1.4 --fps 120 --seed 102"},
    {"disc03_10.37deg.txt", "10.37", 1.6, "--mu 0.585 --phi-deg 10.37 --v0 1.6 --fps 120 --seed 103"},
    {"disc04_10.37deg.txt", "10.37", 1.8, "--mu 0.585 --phi-deg 10.37 --v0 1.8 --fps 120 --seed 104"},
    {"disc05_10.37deg.txt", "10.37", 2.0, "--mu 0.585 --phi-deg 10.37 --v0 2 --fps 120 --seed 105"},
    {"disc06_10.37deg.txt", "10.37", 2.2, "--mu 0.585 --phi-deg 10.37 --v0 2.2 --fps 120 --seed 106"},
    {"disc07_10.37deg.txt", "10.37", 2.4, "--mu 0.585 --phi-deg 10.37 --v0 2.4 --fps 120 --seed 107"},
    {"disc08_6deg.txt", "6", 2.0, "--mu 0.585 --phi-deg 6 --v0 2 --fps 120 --seed 108"},
    {"disc09_14deg.txt", "14", 2.0, "--mu 0.585 --phi-deg 14 --v0 2 --fps 120 --seed 109"},
    {"disc10_18deg.txt", "18", 2.0, "--mu 0.585 --phi-deg 18 --v0 2 --fps 120 --seed 110"},
};
constexpr std::size_t kOneAngle = 7;  // the first seven share 10.37 deg

std::string data_path(const SeriesDisc& d) { return std::string("data/incline_series/") + d.file; }
/// The series of discs [0, n) analysed as `incline analyze` over several files does.
struct Analysed {
  std::vector<analysis::RunOutcome<analysis::InclineAnalysis>> runs;
  analysis::InclineSeriesSummary summary;
  std::vector<InclineSeriesRun> report_runs;
};

Analysed analyse(const std::vector<std::string>& paths, std::size_t n) {
  Analysed a;
  const std::vector<std::string> files(paths.begin(), paths.begin() + static_cast<std::ptrdiff_t>(n));
  a.runs = analysis::run_series<analysis::InclineAnalysis>(files, [](std::size_t i, const std::string& f) {
    analysis::InclineFitOptions o;
    o.phi = to_rad(std::stod(kDiscs[i].phi_deg));
    return analysis::analyze_incline_run(io::read_tracks(f).tracks.front(), o);
  });
  std::vector<analysis::InclineRunPoint> points;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& r = a.runs[i];
    if (r.ok()) points.push_back(analysis::incline_run_point(*r.result, data_path(kDiscs[i])));
    a.report_runs.push_back({data_path(kDiscs[i]), r.ok() ? &*r.result : nullptr,
                             to_rad(std::stod(kDiscs[i].phi_deg)), r.located_error()});
  }
  a.summary = analysis::summarize_incline_series(points);
  return a;
}

std::string interval_of(const std::optional<double>& lo, const std::optional<double>& hi) {
  return "[" + (lo ? format_value(*lo, 5) : std::string("—")) + ", " + (hi ? format_value(*hi, 5) : std::string("—")) + "]";
}

bool holds(const std::optional<double>& lo, const std::optional<double>& hi, double v) {
  return (!lo || *lo <= v) && (!hi || v <= *hi);
}

}  // namespace

void add_incline_series_case_study(report::Report& r, std::ostream& log, const std::string& data_dir) {
  std::vector<std::string> paths;
  for (const auto& d : kDiscs) paths.push_back(write_demo_file(std::string("incline_series/") + d.file, data_dir));

  auto& intro = r.add_section("Incline series: many discs (incline study, synthetic data)");
  intro.add_paragraph(
      "The incline study launched many discs and drew them together (table 1, figures 5A–8 (五A–八)). This series was made by "
      "tribolab's own simulator (data/demo/incline_series/make.sh): seven discs at the study's figure 8 (八) angle, "
      "10.37°, launched at 1.2 to 2.4 m/s, and three more at 6°, 14° and 18°, all with μ = 0.585 (the study's "
      "figure 8 (八) value), 1 mm noise at 120 fps. The files are written next to this report in data/incline_series/; "
      "the analyses below are what incline analyze over several files computes, so the commands shown print the "
      "same numbers.");
  report::Table made;
  made.caption = "Discs: how each was made (tribolab incline synth ...)";
  made.header = {"file", "φ (deg)", "v_0 truth (m/s)", "made by: tribolab incline synth ..."};
  for (const auto& d : kDiscs) made.rows.push_back({data_path(d), d.phi_deg, format_value(d.v0, 3), d.synth});
  intro.add_table(std::move(made));

  // Seven discs at one angle: weighted mu and figure 八's slopes, against the truth.
  const Analysed one = analyse(paths, kOneAngle);
  const double phi = to_rad(10.37);
  auto& t1 = r.add_section("Incline series: seven discs at 10.37°, truth beside the result");
  std::string files;
  for (std::size_t i = 0; i < kOneAngle; ++i) files += " " + data_path(kDiscs[i]);
  t1.add_paragraph("Repeat with: tribolab incline analyze" + files + " --phi-deg 10.37 --report series.html");
  report::Table truth;
  truth.caption = "Seven discs: what the series recovers against the truth (μ = 0.585)";
  truth.header = {"quantity", "truth", "result", "95 % interval", "truth in interval"};
  const auto& m = *one.summary.mu;
  truth.rows.push_back({"weighted μ of the runs", format_value(kMuTruth, 4), format_uncertain(m.mean, m.sigma),
                        "[" + format_value(m.mean - 1.96 * m.sigma, 5) + ", " + format_value(m.mean + 1.96 * m.sigma, 5) + "]",
                        yes_no(std::abs(m.mean - kMuTruth) <= 1.96 * m.sigma)});
  for (const auto& sc : one.summary.scaling) {
    const double slope_truth = *analysis::stop_slope(sc.relation, kMuTruth, phi, kDefaultG);
    truth.rows.push_back({"slope " + analysis::stop_relation_key(sc.relation), format_value(slope_truth, 5),
                          format_uncertain(sc.fit.slope, sc.fit.sigma),
                          "[" + format_value(sc.fit.ci_low, 5) + ", " + format_value(sc.fit.ci_high, 5) + "]",
                          yes_no(sc.fit.ci_low <= slope_truth && slope_truth <= sc.fit.ci_high)});
    truth.rows.push_back({"μ from " + analysis::stop_relation_key(sc.relation), format_value(kMuTruth, 4),
                          sc.mu ? format_value(*sc.mu, 5) : "—", interval_of(sc.mu_ci_low, sc.mu_ci_high),
                          yes_no(holds(sc.mu_ci_low, sc.mu_ci_high, kMuTruth))});
  }
  t1.add_table(std::move(truth));
  t1.add_paragraph("χ^2 = " + format_value(m.chi2, 4) + " with " + std::to_string(m.dof) + " dof (p = " +
                   format_value(m.p_value, 3) + "): the discs agree within their errors, as discs of one μ should.");
  add_incline_series(r, "Seven discs at 10.37°", one.report_runs, one.summary, {});
  log << "  seven discs at 10.37 deg: mu = " << format_uncertain(m.mean, m.sigma) << " (truth 0.585), chi2 "
      << format_value(m.chi2, 4) << "/" << m.dof << ", p " << format_value(m.p_value, 3) << '\n';
  for (const auto& sc : one.summary.scaling)
    log << "    " << analysis::stop_relation_key(sc.relation) << ": mu " << (sc.mu ? format_value(*sc.mu, 5) : "-") << " "
        << interval_of(sc.mu_ci_low, sc.mu_ci_high) << '\n';

  // All ten discs at four angles: cos(theta_c) against tan(phi).
  const Analysed all = analyse(paths, std::size(kDiscs));
  auto& t2 = r.add_section("Incline series: all ten discs at four angles");
  std::string all_files, angles;
  for (const auto& d : kDiscs) {
    all_files += " " + data_path(d);
    angles += std::string(angles.empty() ? "" : ",") + d.phi_deg;
  }
  t2.add_paragraph("Repeat with: tribolab incline analyze" + all_files + " --phi-deg " + angles +
                   " --report all.html. With several angles the stop-point slopes are not fitted (each depends on "
                   "φ); the angles give instead the study's cos θ_c–tan φ test (eq c').");
  report::Table truth2;
  truth2.caption = "Ten discs: what the series recovers against the truth (μ = 0.585)";
  truth2.header = {"quantity", "truth", "result", "truth within 2σ"};
  const auto& m2 = *all.summary.mu;
  truth2.rows.push_back({"weighted μ of the runs", format_value(kMuTruth, 4), format_uncertain(m2.mean, m2.sigma),
                         yes_no(std::abs(m2.mean - kMuTruth) <= 2 * m2.sigma)});
  if (all.summary.theta_c_test) {
    const auto& tc = *all.summary.theta_c_test;
    truth2.rows.push_back({"μ = 1/slope of cos θ_c against tan φ", format_value(kMuTruth, 4),
                           format_uncertain(tc.mu, tc.sigma_mu), yes_no(std::abs(tc.mu - kMuTruth) <= 2 * tc.sigma_mu)});
    truth2.rows.push_back({"normal friction (eq c' intercept)", "absent", to_string(tc.verdict), yes_no(tc.verdict == analysis::Verdict::absent)});
    log << "  ten discs, four angles: cos(theta_c)-tan(phi) mu = " << format_uncertain(tc.mu, tc.sigma_mu) << '\n';
  }
  if (all.summary.normal_friction)
    truth2.rows.push_back({"normal friction pooled (model A)", "absent", to_string(all.summary.normal_friction->verdict),
                           yes_no(all.summary.normal_friction->verdict == analysis::Verdict::absent)});
  t2.add_table(std::move(truth2));
  add_incline_series(r, "Ten discs", all.report_runs, all.summary, {});
}

}  // namespace tribolab::app
