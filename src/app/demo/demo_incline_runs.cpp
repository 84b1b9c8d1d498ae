// The "incline-runs" case study of the demo (seed 000, issue 7 item 3): the synthetic tracked
// runs shipped in data/demo/incline/ (made by its make.sh) are written to <out>/data/incline/
// and analysed by the same library calls as `incline analyze`, `normal-friction-test` and
// `mu-from-slide`, each shown with the command that repeats it from the demo folder and the
// truth the script used.
#include "app/demo/demo.hpp"
#include "app/demo/demo_data.hpp"
#include "app/incline/incline_analysis.hpp"
#include "app/incline/report_incline_analysis.hpp"

#include "analysis/incline_diagnostics.hpp"
#include "analysis/incline_fit.hpp"
#include "analysis/incline_slide.hpp"
#include "incline/params.hpp"
#include "io/text.hpp"
#include "io/track_import.hpp"
#include "report/format.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>

namespace tribolab::app {
namespace {

using report::format_uncertain;
using report::format_value;

/// One shipped run and the truth its line of data/demo/incline/make.sh used (synth's
/// defaults: t_launch = 0.1 s, launch point (0.05, 0) m).
struct DemoRun {
  const char* file;      ///< below data/demo/incline/
  const char* phi_deg;   ///< as written on the command lines
  double mu, v0, normal_accel;
  const char* synth;     ///< the options of its make.sh line, checked by demo_content_test
};

const DemoRun kRuns[] = {
    {"run_12deg.csv", "12", 0.634, 2.62, 0, "--mu 0.634 --phi-deg 12 --v0 2.62 --fps 120 --seed 12 --format csv"},
    {"run_16deg.txt", "16", 0.634, 2.62, 0, "--mu 0.634 --phi-deg 16 --v0 2.62 --fps 240 --seed 16"},
    {"run_20.96deg.txt", "20.96", 0.634, 2.62, 0, "--mu 0.634 --phi-deg 20.96 --v0 2.62 --fps 80 --seed 21"},
    {"run_25deg.txt", "25", 0.634, 2.3, 0, "--mu 0.634 --phi-deg 25 --v0 2.3 --fps 120 --seed 25"},
    {"run_28deg.txt", "28", 0.634, 2.0, 0, "--mu 0.634 --phi-deg 28 --v0 2 --fps 120 --seed 28"},
    {"run_20.96deg_normal.txt", "20.96", 0.634, 2.62, 0.3,
     "--mu 0.634 --phi-deg 20.96 --v0 2.62 --normal-accel 0.3 --fps 120 --seed 30"},
};
const DemoRun kSlide = {"slide_41.09deg.txt", "41.09", 0.634, 0, 0,
                        "--mu 0.634 --phi-deg 41.09 --v0 0 --fps 240 --duration 0.7 --seed 41"};
constexpr double kTLaunch = 0.1, kX0 = 0.05, kY0 = 0;

track::Track read_run(const std::string& path) { return io::read_tracks(path).tracks.front(); }

std::string data_path(const DemoRun& r) { return std::string("data/incline/") + r.file; }

bool holds(const analysis::Estimate& e, double v) { return e.ci_low <= v && v <= e.ci_high; }

}  // namespace

void add_incline_runs_case_study(report::Report& r, std::ostream& log, const std::string& data_dir) {
  auto& summary = r.add_section("Incline runs: tracked launches analysed (incline study, synthetic data)");
  summary.add_paragraph(
      "What a team films: the disc launched across the incline at five angles, one launch with a friction "
      "component normal to the path (model A), and a straight slide. The runs were made by tribolab's own "
      "simulators with 1 mm position noise at 80–240 fps (data/demo/incline/make.sh, shown in the 'made by' "
      "column) and are written next to this report in data/incline/; each analysis below is the library call "
      "the command in the 'repeat with' column makes, so running it from the report's folder prints the same "
      "numbers. The truth is known, so the table says whether each 95 % interval holds it.");
  report::Table made;
  made.caption = "Runs: how each was made and the command that repeats its analysis";
  made.header = {"file", "made by: tribolab incline synth ...", "repeat with"};
  report::Table t;
  t.caption = "Runs: the truth and what incline analyze recovers";
  t.header = {"file", "model (by the verdict)", "μ truth", "μ fit", "μ truth in 95 % interval", "v_0 truth (m/s)",
              "v_0 fit", "v_0 truth in 95 % interval", "f_N/m truth (m/s^2)", "f_N/m fit (model A)",
              "verdict: normal friction"};
  std::vector<analysis::InclineAnalysis> analyses;
  InclineNormalFrictionTestOptions nft;  // what `incline normal-friction-test` is given
  std::vector<std::string> nft_sources, nft_angle_text;  // as the demo folder's command line says
  log << "  runs: file  model  mu(fit +- sigma)  truth in CI  verdict\n";
  for (const DemoRun& run : kRuns) {
    const std::string path = write_demo_file(std::string("incline/") + run.file, data_dir);
    analysis::InclineFitOptions o;
    o.phi = to_rad(std::stod(run.phi_deg));
    const track::Track track = read_run(path);
    analysis::InclineAnalysis a = analysis::analyze_incline_run(track, o);
    // The parameters of the model the verdict accepts: A when normal friction is present.
    const bool use_a = a.verdict == analysis::Verdict::present && a.model_a;
    const analysis::Estimate& mu = use_a ? a.model_a->mu : a.model_b.mu;
    const analysis::Estimate& v0 = use_a ? a.model_a->v0 : a.model_b.v0;
    made.rows.push_back({data_path(run), run.synth,
                         "tribolab incline analyze " + data_path(run) + " --phi-deg " + run.phi_deg});
    t.rows.push_back({run.file, use_a ? "A" : "B", format_value(run.mu, 4), format_uncertain(mu.value, mu.sigma),
                      holds(mu, run.mu) ? "yes" : "no", format_value(run.v0, 4), format_uncertain(v0.value, v0.sigma),
                      holds(v0, run.v0) ? "yes" : "no", format_value(run.normal_accel, 3),
                      a.model_a ? format_uncertain(a.model_a->normal_accel.value, a.model_a->normal_accel.sigma) : "—",
                      to_string(a.verdict)});
    char line[160];
    std::snprintf(line, sizeof line, "    %-24s %s  %.4f +- %.4f  %s  %s\n", run.file, use_a ? "A" : "B", mu.value,
                  mu.sigma, holds(mu, run.mu) ? "yes" : "no", to_string(a.verdict));
    log << line;
    if (run.normal_accel == 0) {  // the model B runs go to the test across angles
      nft.files.push_back(path);
      nft.phi_deg.push_back(std::stod(run.phi_deg));
      nft_sources.push_back(data_path(run));
      nft_angle_text.push_back(run.phi_deg);
    }
    analyses.push_back(std::move(a));
  }
  summary.add_table(std::move(made));
  summary.add_table(std::move(t));
  int flagged = 0, model_b_runs = 0;
  for (std::size_t i = 0; i < analyses.size(); ++i)
    if (kRuns[i].normal_accel == 0) {
      ++model_b_runs;
      flagged += analyses[i].verdict == analysis::Verdict::present;
    }
  summary.add_paragraph("Decision rule for the verdict: " + incline_decision_rule() + " Of the " +
                        std::to_string(model_b_runs) + " runs made without normal friction, " + std::to_string(flagged) +
                        " " + (flagged == 1 ? "is" : "are") +
                        " flagged 'present': a test of size 5 % flags about one model B run in 20 (3.5 % over 200 "
                        "runs, docs/theory.md#incline-analysis), which is why the normal-friction test across "
                        "angles below is the study's second, independent check.");
  add_incline_analysis_equations(summary);

  // The seed's run and the model A run in full.
  const auto full = [&](std::size_t i, const std::string& heading, const std::string& what) {
    const DemoRun& run = kRuns[i];
    auto& s = r.add_section(heading);
    s.add_paragraph(what + " Repeat with: tribolab incline analyze " + data_path(run) + " --phi-deg " + run.phi_deg +
                    " --report analyze.html");
    add_incline_run_analysis(s, run.file, analyses[i],
                             InclineTruth{run.mu, run.v0, kTLaunch, kX0, kY0, run.normal_accel});
  };
  full(2, "Incline runs: the study's launch, φ = 20.96°",
       "The study's run (μ = 0.634, v_0 = 2.62 m/s) filmed at 80 fps: model B fits to the noise, model A's "
       "normal component is not significant, so the verdict is 'absent'.");
  full(5, "Incline runs: a launch with normal friction (model A)",
       "The same launch with a friction component f_N/m = 0.3 m/s^2 normal to the path (5 % of the friction "
       "deceleration): model B leaves structured residuals, model A's interval excludes 0 and the F-test is "
       "significant, so the verdict is 'present'.");

  std::string nft_files, nft_angles;
  for (std::size_t i = 0; i < nft_sources.size(); ++i) {
    nft_files += " " + nft_sources[i];
    nft_angles += (i ? "," : "") + nft_angle_text[i];
  }
  auto& ns = r.add_section("Incline runs: normal-friction test across angles (eq c)");
  ns.add_paragraph("θ_c of each model B run, located at its v_y extremum, against tan φ. Repeat with: "
                   "tribolab incline normal-friction-test" + nft_files + " --phi-deg " + nft_angles);
  // The command's own workflow; each point then named as from the demo folder.
  analysis::NormalFrictionTest test = incline_normal_friction_test(nft).test;
  for (std::size_t i = 0; i < test.points.size(); ++i) test.points[i].source = nft_sources[i];
  add_normal_friction_fit(ns, "Across angles", test, 0.634);
  log << "  normal-friction-test: mu = " << format_uncertain(test.mu, test.sigma_mu) << " (truth 0.634), verdict "
      << to_string(test.verdict) << '\n';

  auto& ss = r.add_section("Incline runs: straight slide, μ from eq a");
  const std::string slide_path = write_demo_file(std::string("incline/") + kSlide.file, data_dir);
  ss.add_paragraph("The disc released from rest at φ = 41.09° (the study's slide, section 5-1 (伍-一)) slides straight down the fall "
                   "line (made by tribolab incline synth " + std::string(kSlide.synth) + "). Repeat with: "
                   "tribolab incline mu-from-slide " + data_path(kSlide) + " --phi-deg " + kSlide.phi_deg);
  analysis::SlideOptions so;
  so.phi = to_rad(std::stod(kSlide.phi_deg));
  const analysis::SlideResult slide = analysis::mu_from_slide(read_run(slide_path), so);
  add_slide_analysis(ss, "Slide", slide, so, kSlide.mu);
  log << "  slide: mu = " << format_uncertain(*slide.mu, *slide.sigma_mu) << " (truth 0.634)\n";
}

}  // namespace tribolab::app
