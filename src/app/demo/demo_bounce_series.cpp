// The demo's series of shipped filmed bounces (seed 001 experiment 2, figure 32, in small):
// twelve synthetic throws (data/demo/bounce_series/, made by its make.sh) analysed as
// `bounce analyze throw*.txt` does, the series summary and figures, and every run's result
// beside the truth of the simulation that made it. The files are written to
// <out>/data/bounce_series/ so the command shown can be re-run from the demo folder.
#include "app/demo/demo.hpp"
#include "app/demo/demo_data.hpp"
#include "app/bounce/report_bounce_series.hpp"
#include "app/common/report_util.hpp"

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_series.hpp"
#include "analysis/bounce_synth.hpp"
#include "bounce/geometry.hpp"
#include "io/text.hpp"
#include "io/track_import.hpp"
#include "io/tracker_export.hpp"
#include "numerics/error.hpp"
#include "report/format.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <ostream>

namespace tribolab::app {
namespace {

using report::format_uncertain;
using report::format_value;



/// The throws of data/demo/bounce_series/make.sh, option for option (checked byte for byte).
std::vector<analysis::SynthVideoOptions> throws() {
  std::vector<analysis::SynthVideoOptions> out;
  int i = 0;
  for (double theta : {-50, -30, -10, 10, 30, 50})
    for (double omega : {-45, 45}) {
      ++i;
      analysis::SynthVideoOptions o;
      o.law.D = 6000;
      o.height = 0.8;
      o.theta_deg = theta;
      o.omega = omega;
      o.vx = 1.5;
      o.fps = 240;
      o.noise = 0.001;
      o.time_factor = 8;
      o.seed = static_cast<std::uint64_t>(100 + i);
      out.push_back(o);
    }
  return out;
}

std::string throw_name(std::size_t i) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "bounce_series/throw%02zu.txt", i + 1);
  return buf;
}

}  // namespace

void add_bounce_series_case_study(report::Report& rep, std::ostream& log, const DemoContext& context) {
  const std::string data_dir = (std::filesystem::path(context.out) / "data").string();
  const auto opts = throws();
  std::vector<analysis::BounceAnalysis> analyses;
  std::vector<analysis::SynthVideoTruth> truths;
  std::vector<std::string> files;
  std::string durations;  // --contact-duration, one per file
  for (std::size_t i = 0; i < opts.size(); ++i) {
    const std::string name = throw_name(i);
    const auto synth = analysis::synth_video(opts[i]);
    TRIBOLAB_ASSERT(demo_file(name) == io::write_export_text({synth.tip_a, synth.tip_b}),
                    "data/demo/" + name + " is not what the demo's copy of its make.sh line makes");
    const std::string path = write_demo_file(name, data_dir);
    io::ImportOptions io;
    io.time_scale = 0.125;
    io.tracks = {"A", "B"};
    const auto set = io::read_tracks(path, io);
    analysis::BounceAnalyzeOptions o;
    o.floor_y = 0.0;
    // A team counts the frames in contact: the contact duration to the nearest frame.
    const double frame = 1 / opts[i].fps;
    o.contact_duration =
        std::max(1.0, std::round((synth.truth.t_separation - synth.truth.t_touch) / frame)) * frame;
    durations += (durations.empty() ? "" : ",") + io::format_number(*o.contact_duration);
    analyses.push_back(analysis::analyze_bounce(set.find("A"), set.find("B"), o));
    truths.push_back(synth.truth);
    files.push_back("data/" + name);
  }
  const bounce::Ball ball;
  std::vector<analysis::BounceSeriesPoint> points;
  std::vector<BounceSeriesRun> runs;
  for (std::size_t i = 0; i < analyses.size(); ++i) {
    points.push_back(analysis::point_of(analyses[i]));
    runs.push_back({files[i], &analyses[i], {}});
  }
  const analysis::BounceSeriesOptions so;
  const auto summary = analysis::summarize_bounce_series(points, so);

  auto& intro = rep.add_section("Bounce series: twelve throws (rugby-ball study, experiment 2)");
  intro.add_paragraph(
      "The rugby-ball study threw the ball 120 times and plotted e against the collision angle (its figure 32). Here twelve "
      "synthetic filmed throws made by tribolab's own simulator (the low-damping law of the bounce section, "
      "D = 6000; released at 0.8 m, 1.5 m/s, orientations −50 to 50°, spin ±45 rad/s; 240 fps played at 30, "
      "1 mm noise) are analysed together. The files are in data/bounce_series/ (made by the commands of "
      "data/demo/bounce_series/make.sh, checked identical here). Reproduce from the demo folder with:");
  intro.add_list({"tribolab bounce analyze data/bounce_series/throw*.txt --track-a A --track-b B --time-scale 0.125 "
                  "--floor-y 0 --contact-duration " + durations + " --bounces-out bounces.csv --report series.html"});
  intro.add_paragraph("The contact durations are the frames in contact counted on each film (one value per file, "
                      "in the order the shell lists them).");
  {
    report::Table t;
    t.caption = "Every throw: analysed (± 1 s.u.) beside the simulation's truth";
    t.header = {"file", "release θ (deg)", "release ω (rad/s)", "collision angle (deg)", "truth at touch (deg)",
                "e_v", "truth e", "e_h", "truth sqrt(H'/H)"};
    for (std::size_t i = 0; i < analyses.size(); ++i) {
      const auto& r = analyses[i];
      const auto& tr = truths[i];
      const double angle_true = bounce::collision_angle_deg(ball, tr.touch.theta, tr.touch.vx >= 0 ? 1 : -1);
      t.rows.push_back({std::filesystem::path(files[i]).filename().string(), format_value(opts[i].theta_deg), format_value(opts[i].omega),
                        format_uncertain(r.collision_angle_deg, r.sigma_collision_angle_deg), format_value(angle_true),
                        format_uncertain(r.e_velocity, r.sigma_e_velocity),
                        format_value(-tr.separation.vy / tr.touch.vy), format_uncertain(r.e_height, r.sigma_e_height),
                        format_value(std::sqrt(tr.post_apex / tr.release_apex))});
    }
    intro.add_table(std::move(t));
  }
  intro.add_paragraph(
      "How to read it: the truth's e is the model's, −v_y at separation over v_y at first touch, and its angle is "
      "at first touch. The analysis reports both at the same instants: it locates the first touch and the "
      "separation where each fitted flight's lowest point meets the floor, and evaluates the angle at the touch "
      "and the velocities at touch and separation (docs/theory.md#bounce-analysis), with uncertainties that "
      "include those instants'. e from apex heights needs no instant.");
  {
    report::Figure f;
    f.title = "e against the collision angle: analysed and true";
    f.x_axis.title = "collision angle θ (deg)";
    f.y_axis.title = "restitution e";
    f.height_px = 420;
    report::Series an = named("analysed e_v (± 1 s.e.)"), tr = named("truth (at touch)");
    for (std::size_t i = 0; i < points.size(); ++i) {
      an.x.push_back(points[i].collision_angle_deg);
      an.y.push_back(points[i].e_velocity);
      an.y_error.push_back(points[i].sigma_e_velocity);
      tr.x.push_back(bounce::collision_angle_deg(ball, truths[i].touch.theta, truths[i].touch.vx >= 0 ? 1 : -1));
      tr.y.push_back(-truths[i].separation.vy / truths[i].touch.vy);
    }
    tr.color = "black";
    f.series.push_back(std::move(an));
    f.series.push_back(std::move(tr));
    report::Series one = named("e = 1", report::Mode::Lines);
    one.dash = report::Dash::Dash;
    one.color = "gray";
    one.x = {0, 180};
    one.y = {1, 1};
    f.series.push_back(std::move(one));
    f.caption = "Each throw twice: where the analysis puts it and where the simulation's truth is.";
    intro.add_figure(std::move(f));
  }
  add_bounce_series(rep, "Bounce series: ", runs, points, summary, so, std::vector<std::string>(runs.size()));
  log << "  bounce series: " << points.size() << " throws, " << analysis::e_velocity_headline(summary) << ", e_v > 1 in "
      << summary.above_one_velocity.above << " (" << summary.above_one_velocity.significant << " significantly)\n";
}

}  // namespace tribolab::app
