// The demo's analysis of shipped bounce data (seed 001, experiments 1 and 4): three synthetic
// filmed bounces (data/demo/bounce/*.txt, 240 fps slow motion, 1 mm noise) analysed as
// `bounce analyze` does, and a table of 40 bounces fitted as `bounce fit` does, each next to
// the truth of the simulation that made it. The files are written to <out>/data/bounce/ so the
// commands shown can be re-run from the demo folder.
#include "app/demo/demo.hpp"
#include "app/demo/demo_bounce_truth.hpp"
#include "app/demo/demo_data.hpp"
#include "app/bounce/report_bounce.hpp"
#include "app/bounce/report_bounce_analysis.hpp"

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_fit.hpp"
#include "analysis/bounce_synth.hpp"
#include "bounce/geometry.hpp"
#include "io/bounce_table.hpp"
#include "io/text.hpp"
#include "io/track_import.hpp"
#include "io/tracker_export.hpp"
#include "numerics/error.hpp"
#include "report/format.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>
#include <ostream>

namespace tribolab::app {
namespace {

using report::format_uncertain;
using report::format_value;

constexpr double kTimeScale = 0.125;  ///< 240 fps played at 30 fps (make.sh: --time-factor 8)

/// One shipped video: its file and the synth-video options of its line in make.sh.
struct Run {
  std::string file;   ///< below data/demo/
  std::string title;  ///< section heading after "Bounce runs: "
  std::string story;  ///< what the run shows
  analysis::SynthVideoOptions options;
};

/// The runs of data/demo/bounce/make.sh, option for option (checked byte for byte below).
std::vector<Run> runs() {
  analysis::SynthVideoOptions base;  // height 0.8, theta 20 deg, vx 1.5, 240 fps, 1 mm, x8
  base.height = 0.8;
  base.theta_deg = 20;
  base.vx = 1.5;
  base.fps = 240;
  base.noise = 0.001;
  base.time_factor = 8;
  Run higher{"bounce/higher.txt", "a bounce higher than the drop",
             "Released at 0.8 m with clockwise spin (topspin for a ball moving to +x), with the "
             "low-damping law of the bounce section (D = 6000): the spin's energy lifts the ball "
             "above its release height, the study's headline (its experiment 1: e = 1.20).",
             base};
  higher.options.law.D = 6000;
  higher.options.omega = -45;
  higher.options.seed = 1;
  Run ordinary{"bounce/ordinary.txt", "an ordinary bounce (the study's law)",
               "The same throw with anticlockwise spin and the study's fitted law (D = 60423): an "
               "ordinary bounce that loses most of its energy and turns back.",
               base};
  ordinary.options.omega = 45;
  ordinary.options.seed = 2;
  Run backspin{"bounce/backspin.txt", "the same low-damping ball, spin reversed",
               "The throw of the first run with the spin reversed: the same law no longer lifts "
               "the ball above its release height. The sense of the spin decides.",
               base};
  backspin.options.law.D = 6000;
  backspin.options.omega = 45;
  backspin.options.seed = 3;
  return {higher, ordinary, backspin};
}

/// The synth-table options of make.sh (the seed's fitted law, 40 rows, seed 1).
analysis::SynthTableOptions table_options() {
  analysis::SynthTableOptions o;
  o.rows = 40;
  o.noise_v = 0.02;
  o.noise_omega = 0.5;
  o.seed = 1;
  return o;
}


std::vector<std::string> truth_row(const std::string& name, double value, double sigma, double truth) {
  const TruthCheck c{name, value, sigma, truth};
  const bool defined = std::isfinite(value) && std::isfinite(sigma);
  return {name, format_uncertain(value, sigma), format_value(truth), defined ? (c.covered() ? "yes" : "no") : "—"};
}

std::string check_same(std::string_view shipped, const std::string& regenerated, const std::string& name) {
  TRIBOLAB_ASSERT(shipped == regenerated,
                  "data/demo/" + name + " is not what the demo's copy of its make.sh line makes");
  return "regenerated from its make.sh line: identical";
}

void add_run(report::Report& rep, const Run& run, const std::string& data_dir, std::ostream& log) {
  const auto synth = analysis::synth_video(run.options);
  const std::string note = check_same(demo_file(run.file), io::write_export_text({synth.tip_a, synth.tip_b}), run.file);
  const std::string path = write_demo_file(run.file, data_dir);
  const auto& truth = synth.truth;
  // A team counts the frames in contact: the contact duration to the nearest frame.
  const double frame = 1 / run.options.fps;
  const double contact = std::max(1.0, std::round((truth.t_separation - truth.t_touch) / frame)) * frame;

  io::ImportOptions io;
  io.time_scale = kTimeScale;
  io.tracks = {"A", "B"};
  const auto set = io::read_tracks(path, io);
  analysis::BounceAnalyzeOptions o;
  o.floor_y = 0.0;
  o.contact_duration = contact;
  const auto r = analysis::analyze_bounce(set.find("A"), set.find("B"), o);

  const std::string command = "tribolab bounce analyze data/" + run.file +
                              " --track-a A --track-b B --time-scale 0.125 --floor-y 0 --contact-duration " +
                              io::format_number(contact) + " --report " +
                              std::filesystem::path(run.file).stem().string() + ".html";
  auto& s = rep.add_section("Bounce runs: " + run.title);
  s.add_paragraph(run.story);
  s.add_paragraph("File data/" + run.file + " (" + note + "). Reproduce this analysis from the demo folder with:");
  s.add_list({command});
  s.add_paragraph("The floor is y = 0 in the file, as the study sets it in Tracker; the contact duration is the "
                  "number of frames in contact (" + format_value(contact * 1e3) + " ms; truth " +
                  format_value(1e3 * (truth.t_separation - truth.t_touch)) + " ms).");
  s.add_table(bounce_truth_table(r, truth, run.options.ball));
  s.add_table(bounce_segments_table(r));
  s.add_table(bounce_restitution_table(r));
  add_bounce_analysis_figures(s, run.title, r);
  log << "  " << run.file << ": e_velocity " << format_uncertain(r.e_velocity, r.sigma_e_velocity) << " (truth "
      << format_value(-truth.separation.vy / truth.touch.vy) << "), collision angle "
      << format_uncertain(r.collision_angle_deg, r.sigma_collision_angle_deg) << " deg (truth "
      << format_value(bounce::collision_angle_deg(run.options.ball, truth.touch.theta, truth.touch.vx < 0 ? -1 : 1)) << "), e_height "
      << format_uncertain(r.e_height, r.sigma_e_height) << " (truth " << format_value(std::sqrt(truth.post_apex / truth.release_apex))
      << ")\n";
}

void add_fit(report::Report& rep, const std::string& data_dir, std::ostream& log) {
  const std::string name = "bounce/table.csv";
  const auto to = table_options();
  const std::string note = check_same(demo_file(name), io::write_bounce_table(analysis::synth_table(to)), name);
  const std::string path = write_demo_file(name, data_dir);
  const auto rows = io::read_bounce_table(path);
  analysis::BounceFitOptions o;  // every parameter free, Huber loss, as `bounce fit` by default
  const auto r = analysis::fit_bounces(rows, o);

  auto& s = rep.add_section("Bounce runs: fitting the contact law to 40 bounces");
  s.add_paragraph("A table of 40 measured bounces (incoming and outgoing v_x, v_y, ω and the orientation at "
                  "touch), made with the study's fitted law (K = 101054 N/m^1.51, n = 1.51, D = 60423, μ = 0.5) "
                  "and noise of 0.02 m/s and 0.5 rad/s on the outgoing state. File data/" + name + " (" + note +
                  "). Reproduce from the demo folder with:");
  s.add_list({"tribolab bounce fit data/" + name + " --report fit.html"});
  const auto& law = to.law;
  // log(D/K) = log D - log K: its variance from the solver's covariance (parameters 0 and 2).
  const auto& C = r.fit.covariance;
  const double sd_log_ratio = std::sqrt(std::max(0.0, C(0, 0) + C(2, 2) - 2 * C(0, 2)));
  const double ratio = r.D / r.K;
  report::Table t;
  t.caption = "Fitted vs the law that made the table";
  t.header = {"parameter", "fitted (± 1 s.u.)", "truth", "truth in the 95% interval"};
  t.rows = {truth_row("K (N/m^n)", r.K, r.sigma_K, law.K), truth_row("n", r.n, r.sigma_n, law.n),
            truth_row("D (N s/m^(n+1))", r.D, r.sigma_D, law.D), truth_row("μ", r.mu, r.sigma_mu, to.friction.mu),
            truth_row("D/K (s/m)", ratio, ratio * sd_log_ratio, law.D / law.K)};
  s.add_table(t);
  s.add_paragraph("K and n are weakly determined by outgoing velocities alone (a central Hunt–Crossley impact's "
                  "restitution depends only on χ = D/K), so their intervals are wide; D/K and μ are sharp. "
                  "rms of the residuals " + format_value(r.rms) + " m/s against a noise of 0.02 m/s.");
  s.add_table(bounce_fit_parameters_table(o, r));
  add_bounce_fit_figures(s, "Table fit", rows, r);
  add_bounce_fit_equations(s, rows, o, r);
  log << "  table fit: K " << format_uncertain(r.K, r.sigma_K) << ", n " << format_uncertain(r.n, r.sigma_n) << ", D "
      << format_uncertain(r.D, r.sigma_D) << ", mu " << format_uncertain(r.mu, r.sigma_mu) << " (truth 101054, 1.51, 60423, 0.5)\n";
}

}  // namespace

void add_bounce_runs_case_study(report::Report& r, std::ostream& log, const DemoContext& context) {
  const std::string data_dir = (std::filesystem::path(context.out) / "data").string();
  for (const Run& run : runs()) add_run(r, run, data_dir, log);
  add_fit(r, data_dir, log);
}

}  // namespace tribolab::app
