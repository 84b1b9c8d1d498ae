// The demo's case study "from film to numbers" (src/app/demo/demo_film.cpp): a simulated throw is
// filmed (video::plan_throw_film, video::write_video: what `bounce render` does), tracked back
// with the ellipse tracker (video::track_video: what `track video --ellipse` does), and the
// tips ball.A, ball.B analysed as `bounce analyze` does, beside the simulation's truth.
#pragma once

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_synth.hpp"
#include "report/report.hpp"
#include "video/render_throw.hpp"
#include "video/track_video.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace tribolab::app {

/// How far the tracks lie from the film's truth, over the frames both have.
struct FilmTrackingError {
  int frames = 0;                 ///< frames compared (tracked, not lost)
  double median_centre_px = 0;    ///< median distance of track "ball" from the true centre, px
  double max_centre_px = 0;       ///< px
  double median_tip_px = 0;       ///< median distance of ball.A and ball.B from the true tips, px
  double max_tip_px = 0;          ///< px
  double median_axis_deg = 0;     ///< median |error| of the major axis' direction (mod 180 deg), deg
  bool a_is_truth_a = true;       ///< the tracker's end A is the film's tip A (else its tip B)
};

/// Everything the case study computes, in the video's time (frame k at k / fps).
struct FilmCase {
  video::ThrowFilmOptions options;
  video::ThrowFilm film;
  video::TrackVideoOptions tracking;
  video::TrackVideoResult tracked;
  analysis::BounceAnalyzeOptions analyze;
  analysis::BounceAnalysis analysis;
  analysis::SynthVideoTruth truth;  ///< the throw's truth shifted to the video's time origin
  FilmTrackingError error;
  std::string video;                ///< the rendered video, <out>/data/film/throw.avi
  std::string csv;                  ///< the tracks, <out>/data/film/tracks.csv
  std::string tracking_report;      ///< <out>/film_tracking.html
};

/// The throw and the camera of the case study: the demo's "higher" bounce (the low-damping
/// law D = 6000, released at 0.8 m with topspin), 480 x 360 px at 240 fps, about 0.6 s, noise
/// and motion blur.
video::ThrowFilmOptions film_case_options();

/// Renders the film into <out_dir>/data/film/, tracks it, writes the tracks' CSV and the
/// tracking report (<out_dir>/film_tracking.html), and analyses the bounce.
FilmCase run_film_case(const std::string& out_dir, const video::ThrowFilmOptions& options = film_case_options());

/// The commands that repeat the tracking and the analysis from the demo folder: `track video`
/// (writes data/film/tracks.csv and film_tracking.html) and `bounce analyze`.
std::vector<std::string> film_commands(const FilmCase& c);

/// The case study's section of the demo report (the tracking report is already written).
void add_film_sections(report::Report& r, const FilmCase& c, std::ostream& log);

}  // namespace tribolab::app
