// The demo's case study "from film to numbers": a throw simulated with the low-damping law is
// rendered to a video at demo time (no video in git), tracked back with the ellipse tracker,
// and its tips analysed as `bounce analyze` does; the truth of the simulation stands beside
// every number, and the tracking report is written beside the demo's report and linked.
#include "app/demo/demo.hpp"
#include "app/demo/demo_bounce_truth.hpp"
#include "app/demo/demo_film.hpp"
#include "app/bounce/report_bounce_analysis.hpp"
#include "app/track/report_track_video.hpp"
#include "app/common/report_util.hpp"

#include "io/atomic_file.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "report/format.hpp"
#include "report/html.hpp"
#include "video/render.hpp"
#include "numerics/units.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <ostream>

namespace tribolab::app {
namespace {

namespace fs = std::filesystem;
using report::format_uncertain;
using report::format_value;


double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

const video::TrackedSeries& series(const video::TrackVideoResult& r, const std::string& name) {
  for (const auto& s : r.series)
    if (s.name == name) return s;
  throw InputError("track video", "no track '" + name + "' in the result");
}

/// Distances of the tracked centre and tips from the film's truth at the same frames, px.
FilmTrackingError tracking_error(const FilmCase& c) {
  FilmTrackingError e;
  const double px_per_m = 1 / c.film.view.scale_m_per_px;
  const auto& truth_c = c.film.truth.find("ball").points;
  const auto& truth_a = c.film.truth.find("ball.A").points;
  const auto& truth_b = c.film.truth.find("ball.B").points;
  const auto& centre = series(c.tracked, "ball");
  const auto& a = series(c.tracked, "ball.A");
  const auto& b = series(c.tracked, "ball.B");
  auto dist = [px_per_m](const video::TrackedRow& row, const track::TrackPoint& p) {
    return std::hypot(row.x - p.x, row.y - p.y) * px_per_m;
  };
  // Which of the film's tips the tracker called A: the nearer one on the first tracked frame.
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    const int k = a.rows[i].frame;
    if (a.rows[i].lost || k < 0 || k >= static_cast<int>(truth_a.size())) continue;
    e.a_is_truth_a = dist(a.rows[i], truth_a[k]) <= dist(a.rows[i], truth_b[k]);
    break;
  }
  std::vector<double> dc, dt, da;
  for (std::size_t i = 0; i < centre.rows.size(); ++i) {
    const int k = centre.rows[i].frame;
    if (centre.rows[i].lost || k < 0 || k >= static_cast<int>(truth_c.size())) continue;
    dc.push_back(dist(centre.rows[i], truth_c[k]));
    dt.push_back(dist(a.rows[i], e.a_is_truth_a ? truth_a[k] : truth_b[k]));
    dt.push_back(dist(b.rows[i], e.a_is_truth_a ? truth_b[k] : truth_a[k]));
    // The major axis' direction on screen (counter-clockwise, as in the world: the film has
    // no axes rotation) against the truth's theta, modulo 180 deg.
    const double theta = std::atan2(truth_b[k].y - truth_a[k].y, truth_b[k].x - truth_a[k].x);
    da.push_back(to_deg(std::abs(std::remainder(centre.angle_rad[i] - theta, std::numbers::pi))));
  }
  e.frames = static_cast<int>(dc.size());
  e.median_centre_px = median(dc);
  e.max_centre_px = dc.empty() ? 0 : *std::max_element(dc.begin(), dc.end());
  e.median_tip_px = median(dt);
  e.max_tip_px = dt.empty() ? 0 : *std::max_element(dt.begin(), dt.end());
  e.median_axis_deg = median(da);
  return e;
}

std::string throw_text(const video::ThrowFilmOptions& o) {
  const auto& m = o.motion;
  return "released at " + format_value(m.height) + " m, " + format_value(m.vx) + " m/s, orientation " + format_value(m.theta_deg) + "°, spin " +
         format_value(m.omega) + " rad/s (clockwise: topspin for a ball moving to +x), the low-damping law D = " + format_value(m.law.D);
}

}  // namespace

video::ThrowFilmOptions film_case_options() {
  video::ThrowFilmOptions o;
  o.motion.law.D = 6000;  // the low-damping law of the bounce section: the spin lifts the ball
  o.motion.height = 0.8;
  o.motion.theta_deg = 20;
  o.motion.omega = -45;
  o.motion.vx = 1.5;
  o.motion.after = 0.15;  // s filmed after the separation (36 frames of the second flight)
  o.motion.seed = 3;      // the phase of the first frame
  o.render.width = 480;
  o.render.height = 360;
  o.render.fps = 240;
  o.render.shutter_fraction = 0.5;  // 1/480 s exposure: the ball blurs by up to 10 mm (4 px)
  o.render.noise_sigma = 2;
  o.render.seed = 3;
  return o;
}

FilmCase run_film_case(const std::string& out_dir, const video::ThrowFilmOptions& options) {
  FilmCase c;
  c.options = options;
  c.film = video::plan_throw_film(c.options);
  TRIBOLAB_ASSERT(c.film.ball_in_view, "the demo's throw leaves the picture");
  const fs::path data = fs::path(out_dir) / "data" / "film";
  fs::create_directories(data);
  c.video = (data / "throw.avi").string();
  c.csv = (data / "tracks.csv").string();
  c.tracking_report = (fs::path(out_dir) / "film_tracking.html").string();
  video::write_video(c.video, c.film.scene, c.film.frames, c.film.render);

  // Track as `track video throw.avi --ellipse ball=X,Y --scale S --origin OX,OY` would: the
  // camera's scale and floor line are the calibration a team measures with a stick.
  const auto& view = c.film.view;
  c.tracking.source.scale_m_per_px = view.scale_m_per_px;
  c.tracking.source.origin_px = cv::Point2d(view.origin_x_px, view.origin_y_px);
  const auto s0 = c.film.motion.state(c.film.t0);
  const cv::Point2d start = view.to_px(s0.x, s0.y);
  video::Target ball;
  ball.kind = video::Target::Kind::ellipse;
  ball.name = "ball";
  ball.x_px = std::round(start.x);  // a click lands on a whole pixel
  ball.y_px = std::round(start.y);
  ball.frame = 0;
  c.tracking.targets = {ball};
  c.tracked = video::track_video(c.video, c.tracking);
  {
    io::AtomicFile f(c.csv);
    video::write_csv(f.stream(), c.tracked);
    f.commit();
  }
  report::write_html(track_video_report(c.tracked), c.tracking_report, report::PlotlyMode::file);  // as report.html

  // The truth in the video's time: frame k is at k / fps, t0 after the release.
  c.truth = c.film.motion.truth;
  c.truth.t_touch -= c.film.t0;
  c.truth.t_separation -= c.film.t0;
  c.error = tracking_error(c);
  if (!c.error.a_is_truth_a) {
    // The tracker named the film's tip B "A": its direction A -> B is the truth's theta + pi
    // (the same pose of a symmetric ball). Express the truth in the tracker's labels.
    c.truth.touch.theta += std::numbers::pi;
    c.truth.separation.theta += std::numbers::pi;
  }

  // Analyse as `bounce analyze tracks.csv --track-a ball.A --track-b ball.B --floor-y 0
  // --sigma-floor-y S --contact-duration D`: the floor is the calibration's origin line, the
  // contact duration the frames in contact counted on the film.
  const auto set = video::to_track_set(c.tracked);
  const double frame = 1 / c.options.render.fps;
  c.analyze.floor_y = 0.0;
  // The floor line is located in the image to a pixel (a uniform error over one pixel).
  c.analyze.sigma_floor_y = c.film.view.scale_m_per_px / std::sqrt(12.0);
  c.analyze.contact_duration =
      std::max(1.0, std::round((c.truth.t_separation - c.truth.t_touch) / frame)) * frame;
  c.analysis = analysis::analyze_bounce(set.find("ball.A"), set.find("ball.B"), c.analyze);
  return c;
}

std::vector<std::string> film_commands(const FilmCase& c) {
  const auto& view = c.film.view;
  const auto& start = c.tracking.targets.front();
  return {"tribolab track video data/film/throw.avi --ellipse ball=" + io::format_number(start.x_px) + "," +
              io::format_number(start.y_px) + " --scale " + io::format_number(view.scale_m_per_px) + " --origin " +
              io::format_number(view.origin_x_px) + "," + io::format_number(view.origin_y_px) +
              " --out data/film/tracks.csv --report film_tracking.html",
          "tribolab bounce analyze data/film/tracks.csv --track-a ball.A --track-b ball.B --floor-y 0 --sigma-floor-y " +
              io::format_number(c.analyze.sigma_floor_y) + " --contact-duration " +
              io::format_number(*c.analyze.contact_duration) + " --report film_bounce.html"};
}

void add_film_case_study(report::Report& rep, std::ostream& log, const DemoContext& context) {
  add_film_sections(rep, run_film_case(context.out), log);
}

void add_film_sections(report::Report& rep, const FilmCase& c, std::ostream& log) {
  const auto& r = c.analysis;
  const auto& e = c.error;
  const auto& view = c.film.view;
  const auto& ro = c.film.render;

  auto& s = rep.add_section("From film to numbers: a rendered throw tracked and analysed");
  s.add_paragraph(
      "The step both studies spent most of their time on is clicking points in video. Here tribolab films a throw "
      "it simulated itself (" + throw_text(c.options) + "), tracks the ball in that film with its ellipse tracker, "
      "and analyses the two tracked tips as a team would, so every number below can be checked against the "
      "simulation's truth. The film: " + std::to_string(ro.width) + " × " + std::to_string(ro.height) + " px, " +
      format_value(ro.fps) + " fps, " + std::to_string(c.film.frames) + " frames, exposure " + format_value(ro.shutter_fraction) +
      " of a frame (motion blur), sensor noise σ = " + format_value(ro.noise_sigma) + " grey levels, MJPG; " +
      format_value(1e3 * view.scale_m_per_px) + " mm per px, the ball " + format_value(c.options.motion.ball.a / view.scale_m_per_px) +
      " × " + format_value(c.options.motion.ball.b / view.scale_m_per_px) + " px (semi-axes). It is rendered when the demo "
      "runs (no video is shipped). Reproduce the tracking and the analysis from the demo folder with:");
  s.add_list(film_commands(c));
  {
    report::Table files;
    files.caption = "Files written beside this report";
    files.header = {"file", "what"};
    files.rows = {{"film_tracking.html", "the tracking report: the video, every track, thumbnails with the tracks "
                                         "drawn, x, y, orientation and score against time"},
                  {"data/film/throw.avi", "the rendered film"},
                  {"data/film/tracks.csv", "the tracks ball, ball.A, ball.B (track,frame,t,x,y,x_px,y_px,score)"}};
    files.links = {"film_tracking.html", "data/film/throw.avi", "data/film/tracks.csv"};
    s.add_table(std::move(files));
  }
  if (!c.tracked.thumbnails.empty()) {
    report::Gallery g;
    g.caption = "Frames of the film as the tracker saw them, with the tracks drawn.";
    for (const auto& th : c.tracked.thumbnails)
      g.images.push_back({th.jpeg, "frame " + std::to_string(th.frame) + ", t = " + format_value(th.t, 4) + " s", ""});
    s.add_gallery(std::move(g));
  }
  {
    const auto& bs = series(c.tracked, "ball");
    report::Table t;
    t.caption = "Tracking against the film's truth (over " + std::to_string(e.frames) + " frames)";
    t.header = {"quantity", "median", "largest"};
    t.rows = {{"centre (px)", format_value(e.median_centre_px, 3), format_value(e.max_centre_px, 3)},
              {"tips A and B (px)", format_value(e.median_tip_px, 3), format_value(e.max_tip_px, 3)},
              {"direction of the major axis (deg)", format_value(e.median_axis_deg, 3), "—"}};
    s.add_table(std::move(t));
    s.add_paragraph("Frames tracked " + std::to_string(bs.tracked) + " of " + std::to_string(bs.rows.size()) +
                    " (lost " + std::to_string(bs.rows.size() - bs.tracked) + "); median score " + format_value(bs.median_score, 3) + ". The tracker's end A is the film's tip " +
                    (e.a_is_truth_a ? "A" : "B") + " (the labels only need to stay continuous: the analysis takes "
                    "the direction A → B, and the collision angle does not depend on which end is called A).");
  }
  s.add_table(bounce_truth_table(r, c.truth, c.options.motion.ball));
  {
    std::string outside;
    for (const TruthCheck& k : bounce_truth_checks(r, c.truth, c.options.motion.ball)) {
      if (k.covered() || !std::isfinite(k.sigma) || k.sigma <= 0) continue;
      outside += (outside.empty() ? "" : "; ") + k.quantity + " " + format_uncertain(k.value, k.sigma) + " against " +
                 format_value(k.truth) + " (" + format_value(std::abs(k.value - k.truth) / k.sigma, 2) + " σ, " +
                 format_value(100 * std::abs(k.value - k.truth) / std::abs(k.truth), 2) + " %)";
    }
    s.add_paragraph(
        "How to read it: the uncertainties come from the scatter of the tracked points about the fitted flights "
        "(and a floor line located to one pixel: σ = " + format_value(1e3 * c.analyze.sigma_floor_y) + " mm). They do not "
        "include systematic errors of the tracking. " +
        (outside.empty() ? std::string("Every truth lies inside its 95 % interval.")
                         : "Outside its 95 % interval: " + outside + ". The tracking is good to a few hundredths "
                           "of a pixel (table above), so the intervals are narrow; but its small errors change slowly "
                           "from frame to frame (the ball's blur and its pixels change smoothly along the path) rather "
                           "than scattering like noise, and the fits' uncertainties count only the scatter. An error "
                           "of a few σ that is a fraction of a percent is what that leaves."));
  }
  s.add_paragraph("Times are the video's: frame k at k / " + format_value(ro.fps) + " s (the release happened " +
                  format_value(1e3 * c.film.t0) + " ms before frame 0). The contact duration given to the analysis is the "
                  "frames in contact counted on the film (" + format_value(1e3 * *c.analyze.contact_duration) + " ms; truth " +
                  format_value(1e3 * (c.truth.t_separation - c.truth.t_touch)) + " ms).");
  s.add_table(bounce_segments_table(r));
  s.add_table(bounce_restitution_table(r));
  add_bounce_analysis_figures(s, "Film", r);
  log << "  film: " << c.film.frames << " frames tracked to " << format_value(e.median_centre_px, 2)
      << " px (median centre), e_velocity " << format_uncertain(r.e_velocity, r.sigma_e_velocity) << " (truth "
      << format_value(-c.truth.separation.vy / c.truth.touch.vy) << "), tracking report " << c.tracking_report << "\n";
}

}  // namespace tribolab::app
