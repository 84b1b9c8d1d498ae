#include "app/track/report_track_video.hpp"
#include "app/common/report_util.hpp"

#include "report/format.hpp"
#include "numerics/units.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

namespace tribolab::app {
namespace {

using report::Figure;
using report::format_value;
using report::Series;
using report::Table;
using video::TrackedRow;
using video::TrackedSeries;
using video::TrackVideoResult;



/// "m" when the video is calibrated, else "px" (world positions in pixels, y up).
std::string world_unit(const TrackVideoResult& r) { return r.input.calibration.calibrated ? "m" : "px"; }

/// "12", "12–15": lost frame ranges as text ("none" when empty).
std::string ranges_text(const std::vector<std::pair<int, int>>& ranges) {
  if (ranges.empty()) return "none";
  std::string s;
  for (const auto& [a, b] : ranges) {
    if (!s.empty()) s += ", ";
    s += a == b ? std::to_string(a) : std::to_string(a) + "–" + std::to_string(b);
  }
  return s;
}

/// An ellipse gives three tracks (NAME, NAME.A, NAME.B) of one object: its ends share the
/// centre's orientation and score, which are drawn once, with the centre.
bool is_ellipse_end(const TrackVideoResult& r, const TrackedSeries& s) {
  if (s.kind != video::Target::Kind::ellipse || s.name.size() < 3) return false;
  const std::string tail = s.name.substr(s.name.size() - 2);
  if (tail != ".A" && tail != ".B") return false;
  const std::string base = s.name.substr(0, s.name.size() - 2);
  return std::any_of(r.series.begin(), r.series.end(), [&](const TrackedSeries& o) { return o.name == base; });
}

std::string kind_text(const TrackVideoResult& r, const TrackedSeries& s) {
  if (s.kind == video::Target::Kind::point) return "point";
  return is_ellipse_end(r, s) ? "ellipse: end " + s.name.substr(s.name.size() - 1) + " of the major axis"
                              : "ellipse: centre";
}

/// Angles (rad) unwrapped to a continuous curve and converted to degrees: each step is taken
/// as the one of size at most 180 deg (period 360 deg); NaN (lost frames) is kept as a gap and
/// the next finite angle continues from the last finite one.
std::vector<double> unwrap_deg(const std::vector<double>& rad) {
  std::vector<double> out(rad.size(), kNaN);
  double last = kNaN, offset = 0;
  for (std::size_t i = 0; i < rad.size(); ++i) {
    if (!std::isfinite(rad[i])) continue;
    double a = rad[i] * kDegPerRad + offset;
    if (std::isfinite(last)) {
      const double turns = std::round((a - last) / 360.0);
      offset -= 360.0 * turns;
      a -= 360.0 * turns;
    }
    out[i] = last = a;
  }
  return out;
}

Table video_table(const TrackVideoResult& r) {
  const auto& in = r.input;
  const auto& c = in.calibration;
  Table t;
  t.caption = "The video, its time base and its calibration";
  t.header = {"quantity", "value"};
  t.rows.push_back({"input", in.input});
  if (!in.project_video.empty()) t.rows.push_back({"video named by the project", in.project_video});
  t.rows.push_back({"codec", in.info.codec.empty() ? "—" : in.info.codec});
  t.rows.push_back({"image size (px)", std::to_string(in.info.width) + " × " + std::to_string(in.info.height)});
  t.rows.push_back({"frames in the container", std::to_string(in.info.frame_count)});
  t.rows.push_back({"frames decoded (the clip's steps)", std::to_string(r.frames)});
  t.rows.push_back({"clip", "start frame " + std::to_string(in.clip.start_frame) + ", step " +
                                std::to_string(in.clip.step_size) + ", " +
                                (in.clip.step_count > 0 ? std::to_string(in.clip.step_count) + " steps" : "to the end")});
  t.rows.push_back({"frame rate in the container (1/s)", in.info.fps > 0 ? format_value(in.info.fps) : "unknown"});
  t.rows.push_back({"frame duration Δt (s)", format_value(in.time.frame_duration_s, 6)});
  t.rows.push_back({"time of the start frame t_0 (s)", format_value(in.time.start_time_s, 6)});
  t.rows.push_back({"time scale (real s per video s)", format_value(in.time.time_scale, 6)});
  if (c.calibrated) {
    const auto& k = c.coords.front();
    const std::string per = c.metres_per_unit == 1 ? " px per m" : " px per unit";
    t.rows.push_back({"calibration", format_value(k.xscale, 6) + per + " along x, " + format_value(k.yscale, 6) +
                                         " along y (from frame " + std::to_string(k.frame) + "; " +
                                         std::to_string(c.coords.size()) + " key frame(s))"});
    if (c.metres_per_unit != 1)
      t.rows.push_back({"length unit", format_value(c.metres_per_unit, 6) + " m per unit; positions below in m"});
    // One quantity per row, its unit last: "origin (px), axes (deg)" put "deg" under both.
    t.rows.push_back({"origin x, y (px)", format_value(k.origin_x) + ", " + format_value(k.origin_y)});
    t.rows.push_back({"axes' angle (deg)", format_value(k.angle_deg)});
  } else {
    t.rows.push_back({"calibration", "none: positions in pixels, y up (no scale given)"});
  }
  return t;
}

Table tracks_table(const TrackVideoResult& r) {
  Table t;
  t.caption = "Tracks";
  t.header = {"track", "kind", "frames", "tracked", "lost frames", "median score", "from the human marks (px)"};
  for (const TrackedSeries& s : r.series) {
    std::string human = "—";
    if (s.vs_human && s.vs_human->frames == 0) {
      human = "no marked frame tracked (" + std::to_string(s.vs_human->marks) + " marks)";
    } else if (s.vs_human) {
      human = "median " + format_value(s.vs_human->median_px, 3) + ", largest " + format_value(s.vs_human->max_px, 3) +
              " over " + std::to_string(s.vs_human->frames) + " frames";
    }
    const std::string first = s.rows.empty() ? "—" : std::to_string(s.rows.front().frame);
    const std::string last = s.rows.empty() ? "—" : std::to_string(s.rows.back().frame);
    t.rows.push_back({s.name, kind_text(r, s), std::to_string(s.rows.size()) + " (" + first + "–" + last + ")",
                      std::to_string(s.tracked), ranges_text(s.lost_ranges), format_value(s.median_score, 3), human});
  }
  return t;
}

/// One series per track of `value(row)` against t (NaN for lost rows: a gap in the line).
Figure time_figure(const TrackVideoResult& r, const std::string& title, const std::string& y_title,
                   const std::function<double(const TrackedRow&)>& value) {
  Figure f = make_figure(title, "t (s)", y_title, 380);
  for (const TrackedSeries& s : r.series) {
    Series d = named(s.name, report::Mode::LinesMarkers);
    for (const TrackedRow& row : s.rows) {
      d.x.push_back(row.t);
      d.y.push_back(row.lost ? kNaN : value(row));
    }
    f.series.push_back(std::move(d));
  }
  return f;
}

/// The project's human marks of the tracks compared with them (Tracker's marks on the same
/// frames), in world units, as black markers.
void add_human_marks(Figure& f, const TrackVideoResult& r, bool y) {
  for (const TrackedSeries& s : r.series) {
    if (!s.vs_human) continue;
    for (const track::Track& m : r.input.marks_px) {
      if (m.name != s.name) continue;
      Series h = named(s.name + ": human marks");
      h.color = "black";
      for (const track::TrackPoint& p : m.points) {
        const auto [wx, wy] = r.input.calibration.to_world(p.frame, p.x, p.y);
        h.x.push_back(r.input.time.t(p.frame));
        h.y.push_back(y ? wy : wx);
      }
      f.series.push_back(std::move(h));
    }
  }
}

Figure orientation_figure(const TrackVideoResult& r) {
  Figure f = make_figure("Orientation against time", "t (s)", "θ (deg, unwrapped)", 380);
  for (const TrackedSeries& s : r.series) {
    if (is_ellipse_end(r, s) || s.angle_rad.size() != s.rows.size()) continue;
    std::vector<double> rad = s.angle_rad;
    for (std::size_t i = 0; i < rad.size(); ++i)
      if (s.rows[i].lost) rad[i] = kNaN;
    if (std::none_of(rad.begin(), rad.end(), [](double a) { return std::isfinite(a); })) continue;
    Series d = named(s.name, report::Mode::LinesMarkers);
    for (const TrackedRow& row : s.rows) d.x.push_back(row.t);
    d.y = unwrap_deg(rad);
    f.series.push_back(std::move(d));
  }
  f.caption = "A point's pattern rotation since its first frame, or an ellipse's orientation (the direction from its "
              "centre to end A), counter-clockwise as seen on the screen, unwrapped to a continuous curve: each step "
              "between frames is taken as the one of at most 180°. Its slope is the spin.";
  return f;
}

Figure score_figure(const TrackVideoResult& r) {
  Figure f = make_figure("Score against time", "t (s)", "score (0 to 1)", 340);
  for (const TrackedSeries& s : r.series) {
    if (is_ellipse_end(r, s)) continue;
    Series d = named(s.name, report::Mode::LinesMarkers);
    Series lost = named(s.name + ": lost");
    lost.color = "#d62728";
    for (const TrackedRow& row : s.rows) {
      d.x.push_back(row.t);
      d.y.push_back(row.lost ? kNaN : row.score);
      if (row.lost) {
        lost.x.push_back(row.t);
        lost.y.push_back(std::isfinite(row.score) ? row.score : 0.0);
      }
    }
    f.series.push_back(std::move(d));
    if (!lost.x.empty()) f.series.push_back(std::move(lost));
  }
  f.caption = "How well each frame matched (a point: the pattern's correlation; an ellipse: the edge fit). Lost "
              "frames are the red markers (at their score, or 0 when none), and gaps in the line; their rows in the "
              "CSV have no position.";
  return f;
}

}  // namespace

int add_track_video_sections(report::Report& rep, const TrackVideoResult& r, const std::string& prefix) {
  const std::string unit = world_unit(r);
  auto& s = rep.add_section(prefix + "Video and tracks");
  s.add_table(video_table(r));
  s.add_equation("t = (t_0 + (n − n_0) Δt) × scale", "docs/theory.md#video-tracking",
                 "the time of frame n, n_0 = the clip's start frame " + std::to_string(r.input.time.start_frame) +
                     "; x, y in " + unit + " with y up, the image's x_px, y_px in pixels with y down");
  s.add_table(tracks_table(r));
  std::vector<std::string> warnings = r.input.warnings;
  for (const auto& w : r.warnings)
    if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
  if (warnings.empty()) {
    s.add_paragraph("No warnings.");
  } else {
    s.add_subheading("Warnings");
    s.add_list(warnings);
  }

  if (!r.thumbnails.empty()) {
    auto& g = rep.add_section(prefix + "Frames with the tracks drawn");
    report::Gallery gallery;
    gallery.caption = std::to_string(r.thumbnails.size()) + " frames of the clip, reduced, with every track drawn as "
                      "the tracker saw it.";
    for (const auto& th : r.thumbnails)
      gallery.images.push_back({th.jpeg, "frame " + std::to_string(th.frame) + ", t = " + format_value(th.t, 5) + " s", ""});
    g.add_gallery(std::move(gallery));
  }

  auto& p = rep.add_section(prefix + "Tracks against time");
  Figure x = time_figure(r, "x against time", "x (" + unit + ")", [](const TrackedRow& w) { return w.x; });
  add_human_marks(x, r, false);
  x.caption = "Horizontal position of every track; gaps are lost frames.";
  if (std::any_of(r.series.begin(), r.series.end(), [](const TrackedSeries& s) { return s.vs_human.has_value(); }))
    x.caption += " Black markers: the Tracker project's own (human) marks of the tracks compared with them.";
  Figure y = time_figure(r, "y against time", "y (" + unit + ")", [](const TrackedRow& w) { return w.y; });
  add_human_marks(y, r, true);
  y.caption = "Vertical position (up) of every track; gaps are lost frames.";
  p.add_figure(std::move(x));
  p.add_figure(std::move(y));
  int figures = 2;
  Figure o = orientation_figure(r);
  if (!o.series.empty()) {
    p.add_figure(std::move(o));
    ++figures;
  }
  p.add_figure(score_figure(r));
  return figures + 1;
}

report::Report track_video_report(const TrackVideoResult& result) {
  report::Report r;
  r.title = "tribolab track video";
  r.subtitle = result.input.input + ": " + std::to_string(result.series.size()) + " tracks over " +
               std::to_string(result.frames) + " frames";
  add_track_video_sections(r, result);
  return r;
}

}  // namespace tribolab::app
