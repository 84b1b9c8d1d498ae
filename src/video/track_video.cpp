// The `track video` workflow (track_video.hpp): one pass over the clip, every target
// followed by its own tracker from its own start frame.
#include "video/track_video.hpp"

#include "track/rigid_body.hpp"

#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/units.hpp"
#include "numerics/statistics.hpp"
#include "video/codec.hpp"

#include <opencv2/imgcodecs.hpp>  // the cv::IMWRITE_* names; encoding is codec.hpp's
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <numbers>
#include <cstdio>
#include <cmath>
#include <deque>
#include <limits>
#include <optional>
#include <set>
#include <type_traits>
#include <variant>

namespace tribolab::video {

namespace {

/// Thumbnails are at most this wide, px (a report shows several side by side).
constexpr int kThumbWidth = 320;
/// Most thumbnails a run keeps (memory: each is at most 320 px wide).
constexpr int kMaxThumbnails = 100;

std::vector<std::string> output_names(const Target& t) {
  if (t.kind == Target::Kind::ellipse) return {t.name, t.name + ".A", t.name + ".B"};
  return {t.name};
}

}  // namespace

std::string TrackVideoOptions::validate() const {
  if (auto e = source.validate(); !e.empty()) return e;
  if (auto e = point.validate(); !e.empty()) return e;
  if (auto e = path.validate(); !e.empty()) return e;
  if (auto e = ellipse.validate(); !e.empty()) return e;
  if (targets.empty()) return "nothing to track: give " + field("start") + ", " + field("ellipse") + " or " + field("from_track");
  if (thumbnails < 0 || thumbnails > kMaxThumbnails) return "thumbnails must be from 0 to 100";
  std::set<std::string> names;
  for (const Target& t : targets) {
    const std::string opt = field(!t.from_track.empty()                 ? "from_track"
                                  : t.kind == Target::Kind::ellipse ? "ellipse"
                                                                    : "start");
    if (t.name.empty()) return opt + ": the track needs a name";
    if (t.name.find_first_of("\n\r\"") != std::string::npos) {
      return opt + " " + t.name + ": a track name may not hold quotes or line breaks";
    }
    if (t.from_track.empty()) {
      if (!std::isfinite(t.x_px) || !std::isfinite(t.y_px)) return opt + " " + t.name + ": position must be finite";
      if (t.frame < -1) return opt + " " + t.name + ": the start frame must not be negative";
    }
    std::set<int> marked;
    for (const ManualMark& m : t.marks) {
      const std::string where = field("mark") + " " + t.name + "@" + std::to_string(m.frame);
      if (!std::isfinite(m.x_px) || !std::isfinite(m.y_px)) return where + ": the position must be finite";
      if (m.frame < 0) return where + ": the frame must not be negative";
      if (!marked.insert(m.frame).second) return where + ": two marks on one frame";
    }
    for (const std::string& n : output_names(t)) {
      if (!names.insert(n).second) return opt + ": the track name '" + n + "' is used twice";
    }
  }
  return "";
}

// Named, not anonymous: TrackSession::Impl, a member of a class of the header, holds them.
namespace detail {

/// One target being followed: its tracker, where it starts, and the series it fills.
struct Follower {
  Target target;
  int start_frame = 0;
  double start_x = 0, start_y = 0;
  std::variant<PointTracker, EllipseTracker, PathTracker> tracker;
  bool started = false;
  std::vector<Frame> pending;  // PathTracker: the frames (index, t; no image) it answers at the end
  std::vector<std::size_t> series;  // indices into the result's series
  // Frame and ellipse trackers with marks: the frames just before the next mark (copies),
  // re-tracked backward from it when it is reached; and the last frame they may reach back to.
  std::deque<Frame> recent;
  int reach_back_to = 0;
  std::set<int> retracked;  // frames whose rows a backward tracking from a mark replaced
  // PathTracker with marks: the grey image around each mark (PathTracker::look_crop) and the
  // mark in it, read before the tracking (read_mark_looks) and given at the start (add_look).
  std::vector<std::pair<ManualMark, cv::Mat>> looks;
};

}  // namespace detail

namespace {

using detail::Follower;

/// Frames before a mark that a frame or ellipse tracker re-tracks backward from it (copies of
/// them are held while the mark approaches: 16 frames of 1080p are 130 MB).
constexpr std::size_t kBackwardFrames = 16;
/// A backward and a forward position this close (px) agree: the forward track is kept from there.
constexpr double kAgreePx = 2;

TrackedRow make_row(const Frame& f, const VideoInput& in, double x_px, double y_px, double score,
                    bool lost, bool manual = false) {
  TrackedRow r;
  r.frame = f.index;
  r.t = f.t;
  r.lost = lost;
  r.manual = manual && !lost;
  if (lost || !std::isfinite(x_px) || !std::isfinite(y_px)) {
    r.lost = true;
    r.x = r.y = r.x_px = r.y_px = kNaN;
    r.score = 0;
    return r;
  }
  r.x_px = x_px;
  r.y_px = y_px;
  r.score = std::isfinite(score) ? std::clamp(score, 0.0, 1.0) : 0;
  const auto [x, y] = in.calibration.to_world(f.index, x_px, y_px);
  r.x = x;
  r.y = y;
  return r;
}

void record(Follower& w, const Frame& f, const VideoInput& in, std::vector<TrackedSeries>& out,
            const Observation& o) {
  out[w.series[0]].rows.push_back(make_row(f, in, o.x_px, o.y_px, o.score, o.lost, o.manual));
  out[w.series[0]].angle_rad.push_back(o.angle_rad);
  if (o.refound && !o.lost) out[w.series[0]].refound_frames.push_back(f.index);
  if (o.manual) out[w.series[0]].manual_frames.push_back(f.index);
}

void record(Follower& w, const Frame& f, const VideoInput& in, std::vector<TrackedSeries>& out,
            const EllipseObservation& e) {
  const Observation& c = e.centre;
  const double pos[3][2] = {{c.x_px, c.y_px}, {e.ax_px, e.ay_px}, {e.bx_px, e.by_px}};
  for (int k = 0; k < 3; ++k) {
    // The mark is of the centre; the ends follow from the running axes and orientation.
    out[w.series[k]].rows.push_back(make_row(f, in, pos[k][0], pos[k][1], c.score, c.lost, c.manual && k == 0));
    out[w.series[k]].angle_rad.push_back(c.angle_rad);
    if (c.manual && k == 0) out[w.series[k]].manual_frames.push_back(f.index);
  }
}

void check_marks(const Target& target, int start_frame, const VideoInput& in) {
  for (const ManualMark& m : target.marks) {
    const std::string where = field("mark") + " " + target.name + "@" + std::to_string(m.frame);
    if (!in.clip.contains(m.frame)) {
      throw InputError(where, "frame " + std::to_string(m.frame) + " is not one of the clip's frames (from " +
                                  std::to_string(in.clip.start_frame) + " every " + std::to_string(in.clip.step_size) +
                                  ")");
    }
    if (m.frame <= start_frame) {
      throw InputError(where, "the track starts at frame " + std::to_string(start_frame) +
                                  ": a mark must come after its start (to move the start, start the track there)");
    }
    if (m.x_px < 0 || m.y_px < 0 || m.x_px > in.info.width - 1 || m.y_px > in.info.height - 1) {
      throw InputError(where, "the mark (" + io::format_number(m.x_px) + ", " + io::format_number(m.y_px) +
                                  ") px is outside the " + std::to_string(in.info.width) + "x" +
                                  std::to_string(in.info.height) + " image");
    }
  }
}

void resolve_start(Follower& w, const VideoInput& in) {
  Target& t = w.target;
  if (!t.from_track.empty()) {
    if (in.marks_px.empty()) {
      throw InputError(field("from_track") + " " + t.from_track,
                       "only a Tracker project (.trk or .trz) has tracks to start from");
    }
    const auto it = std::find_if(in.marks_px.begin(), in.marks_px.end(),
                                 [&](const track::Track& m) { return m.name == t.from_track; });
    if (it == in.marks_px.end()) {
      std::string names;
      for (const auto& m : in.marks_px) names += (names.empty() ? "'" : ", '") + m.name + "'";
      throw InputError(field("from_track") + " " + t.from_track,
                       "no such track in " + in.input + "; its tracks: " + names);
    }
    if (it->points.empty()) {
      throw InputError(field("from_track") + " " + t.from_track, "the track has no mark on the clip's frames");
    }
    w.start_frame = it->points.front().frame;
    w.start_x = it->points.front().x;
    w.start_y = it->points.front().y;
    return;
  }
  const std::string opt = field(t.kind == Target::Kind::ellipse ? "ellipse" : "start") + " " + t.name;
  w.start_frame = t.frame < 0 ? in.clip.start_frame : t.frame;
  w.start_x = t.x_px;
  w.start_y = t.y_px;
  if (!in.clip.contains(w.start_frame)) {
    throw InputError(opt, "frame " + std::to_string(w.start_frame) + " is not one of the clip's frames (from " +
                              std::to_string(in.clip.start_frame) + " every " +
                              std::to_string(in.clip.step_size) + ")");
  }
  if (w.start_x < 0 || w.start_y < 0 || w.start_x > in.info.width - 1 || w.start_y > in.info.height - 1) {
    throw InputError(opt, "the start point (" + io::format_number(w.start_x) + ", " +
                              io::format_number(w.start_y) + ") px is outside the " +
                              std::to_string(in.info.width) + "x" + std::to_string(in.info.height) +
                              " image");
  }
}

/// Which clip steps get a thumbnail: n evenly spaced over the expected steps.
std::set<int> thumbnail_steps(int n, int expected) {
  std::set<int> s;
  if (n <= 0) return s;
  if (expected <= 0) expected = n;
  for (int i = 0; i < n; ++i) {
    s.insert(n == 1 ? 0 : static_cast<int>(std::lround(double(i) * (expected - 1) / (n - 1))));
  }
  return s;
}

const cv::Scalar kColours[] = {{40, 40, 230}, {230, 120, 30}, {40, 180, 40}, {200, 40, 200},
                               {30, 200, 220}, {160, 100, 40}, {120, 120, 120}, {200, 200, 40}};

/// Draws every series' trail up to the thumbnail's frame and its current position.
void draw_tracks(cv::Mat& img, double scale, int frame, const std::vector<TrackedSeries>& series) {
  for (std::size_t k = 0; k < series.size(); ++k) {
    const cv::Scalar colour = kColours[k % std::size(kColours)];
    std::vector<cv::Point> trail;
    const TrackedRow* now = nullptr;
    for (const TrackedRow& r : series[k].rows) {
      if (r.frame > frame) break;
      if (r.frame == frame) now = &r;
      if (r.lost) continue;
      trail.emplace_back(static_cast<int>(std::lround(r.x_px * scale)),
                         static_cast<int>(std::lround(r.y_px * scale)));
    }
    if (trail.size() > 1) cv::polylines(img, trail, false, colour, 1, cv::LINE_AA);
    if (now != nullptr && !now->lost) {
      const cv::Point p(static_cast<int>(std::lround(now->x_px * scale)),
                        static_cast<int>(std::lround(now->y_px * scale)));
      cv::circle(img, p, 4, colour, 1, cv::LINE_AA);
    }
  }
}

void summarise(TrackedSeries& s) {
  std::vector<double> scores;
  int lost_from = -1, lost_to = -1;
  for (const TrackedRow& r : s.rows) {
    if (r.lost) {
      if (lost_from < 0) lost_from = r.frame;
      lost_to = r.frame;
      continue;
    }
    if (lost_from >= 0) s.lost_ranges.emplace_back(lost_from, lost_to);
    lost_from = -1;
    ++s.tracked;
    scores.push_back(r.score);
  }
  if (lost_from >= 0) s.lost_ranges.emplace_back(lost_from, lost_to);
  if (!scores.empty()) s.median_score = median(std::move(scores));
}

}  // namespace

HumanComparison compare_with_human(const TrackedSeries& s, const track::Track& human, int start_frame,
                                   int image_width_px) {
  // A user corrects a point farther than 4 px from the mark per 640 px of image width
  // (12 px at 1080p, issue 24); farther than 10 px with a score is a confident wrong answer.
  constexpr double kCorrectPxPer640 = 4, kConfidentlyWrongPx = 10;
  HumanComparison c;
  c.correct_px = kCorrectPxPer640 * image_width_px / 640.0;
  std::vector<double> d;
  std::size_t j = 0;
  for (const track::TrackPoint& p : human.points) {
    if (p.frame == start_frame) continue;
    while (j < s.rows.size() && s.rows[j].frame < p.frame) ++j;
    if (j == s.rows.size() || s.rows[j].frame != p.frame) continue;
    ++c.marks;
    if (s.rows[j].lost) {
      ++c.to_correct;
      continue;
    }
    const double dist = std::hypot(s.rows[j].x_px - p.x, s.rows[j].y_px - p.y);
    d.push_back(dist);
    if (dist > c.correct_px) ++c.to_correct;
    if (dist > kConfidentlyWrongPx) ++c.confidently_wrong;
  }
  c.frames = static_cast<int>(d.size());
  if (!d.empty()) {
    c.max_px = *std::max_element(d.begin(), d.end());
    c.median_px = median(d);
    std::sort(d.begin(), d.end());
    c.p90_px = d[static_cast<std::size_t>(std::ceil(0.9 * static_cast<double>(d.size()))) - 1];
  }
  return c;
}

/// What the frame loop leaves for the end of the tracking (and for a re-tracking).
struct TrackSession::Impl {
  std::string input;
  TrackVideoResult streamed;       // input, frames, and the rows recorded while streaming
  std::vector<Follower> followers;
  std::vector<std::pair<Frame, cv::Mat>> thumbs;  // frame facts and its downscaled image
  double scale = 1;                // thumbnails' scale
  std::vector<std::string> reader_warnings;
};

TrackSession::TrackSession() = default;
TrackSession::~TrackSession() = default;
bool TrackSession::empty() const { return !impl; }

namespace {

/// The real time between two tracked frames, s (a slow-motion clip's time scale included; 0 when
/// the time base is unknown): the path tracker's reach is a speed, and both point trackers keep
/// earlier frames at least 1/30 s apart.
double step_s(const VideoInput& in) { return in.clip.step_size * in.time.real_frame_s(); }

/// The frame tracker's options, given the clip's time base unless set.
PointTrackerOptions point_options(const TrackVideoOptions& options, const VideoInput& in) {
  PointTrackerOptions point = options.point;
  if (point.step_s == 0) point.step_s = step_s(in);
  return point;
}

/// The rows of `w` from frame `m`'s mark backward: a fresh tracker of the follower's kind started
/// at the mark runs over the held frames in reverse (their indices mirrored, 2 m - k, so that
/// they increase as the trackers expect), and replaces the forward rows until the two agree
/// (within kAgreePx) or the backward one is lost; never at or before `w.reach_back_to`.
void track_backward(Follower& w, const Frame& marked, const ManualMark& mk, const VideoInput& in,
                    std::vector<TrackedSeries>& out, const TrackVideoOptions& options) {
  const auto mirrored = [&](const Frame& f) {
    Frame g = f;  // shares the images
    g.index = 2 * marked.index - f.index;
    return g;
  };
  const bool ellipse = std::holds_alternative<EllipseTracker>(w.tracker);
  std::vector<EllipseObservation> back;  // per frame from the mark backward (a point's in .centre)
  try {
    if (ellipse) {
      EllipseTracker t(options.ellipse);
      back.push_back(t.start(mirrored(marked), mk.x_px, mk.y_px, w.target.name));
      for (auto it = w.recent.rbegin(); it != w.recent.rend() && it->index > w.reach_back_to; ++it) {
        back.push_back(t.update(mirrored(*it)));
        if (back.back().centre.lost) break;
      }
    } else {
      PointTracker t(point_options(options, in));
      EllipseObservation e;
      e.centre = t.start(mirrored(marked), mk.x_px, mk.y_px, w.target.name);
      back.push_back(e);
      for (auto it = w.recent.rbegin(); it != w.recent.rend() && it->index > w.reach_back_to; ++it) {
        e.centre = t.update(mirrored(*it));
        back.push_back(e);
        if (e.centre.lost) break;
      }
    }
  } catch (const InputError&) {
    return;  // no object to start on at the mark (too little texture, no contrasting ball): forward only
  }
  TrackedSeries& centre = out[w.series[0]];
  const std::size_t at_mark = centre.rows.size() - 1;  // the mark's row, just recorded
  // An ellipse's ends: the backward tracker labels them afresh; A is the end nearest the
  // forward A at the mark, and the orientation continues the forward one.
  bool swap = false;
  double turn = 0;
  if (ellipse) {
    const TrackedRow& fa = out[w.series[1]].rows[at_mark];
    const EllipseObservation& b0 = back.front();
    swap = std::hypot(b0.ax_px - fa.x_px, b0.ay_px - fa.y_px) > std::hypot(b0.bx_px - fa.x_px, b0.by_px - fa.y_px);
    const double a0 = b0.centre.angle_rad + (swap ? kPi : 0);
    turn = 2 * kPi * std::round((centre.angle_rad[at_mark] - a0) / (2 * kPi)) + (swap ? kPi : 0);
  } else {
    turn = centre.angle_rad[at_mark];  // the backward pattern's angle is relative to the mark's
  }
  for (std::size_t k = 1; k < back.size() && k <= at_mark; ++k) {
    const Observation& b = back[k].centre;
    const std::size_t row = at_mark - k;
    TrackedRow& f = centre.rows[row];
    if (b.lost) break;
    if (!f.lost && std::hypot(f.x_px - b.x_px, f.y_px - b.y_px) <= kAgreePx) break;
    w.retracked.insert(f.frame);
    Frame meta;
    meta.index = f.frame;
    meta.t = f.t;
    const double pos[3][2] = {{b.x_px, b.y_px},
                              {swap ? back[k].bx_px : back[k].ax_px, swap ? back[k].by_px : back[k].ay_px},
                              {swap ? back[k].ax_px : back[k].bx_px, swap ? back[k].ay_px : back[k].by_px}};
    for (std::size_t s = 0; s < w.series.size(); ++s) {
      out[w.series[s]].rows[row] = make_row(meta, in, pos[s][0], pos[s][1], b.score, false);
      out[w.series[s]].angle_rad[row] = b.angle_rad + turn;
      auto& refound = out[w.series[s]].refound_frames;
      refound.erase(std::remove(refound.begin(), refound.end(), f.frame), refound.end());
    }
  }
}

/// The ellipse tracker's poses at each frame's time (EllipseTracker::at_frame_time) in place of
/// the rows its frames reported: not where a mark or a backward tracking from one wrote the row.
void retime(const Follower& w, const EllipseTracker::AtFrameTime& at, const VideoInput& in,
            std::vector<TrackedSeries>& out) {
  if (at.exposure > 0) {
    for (const std::size_t s : w.series) out[s].exposure = at.exposure;
  }
  const std::vector<TrackedRow>& rows = out[w.series[0]].rows;
  for (const EllipseObservation& e : at.poses) {
    const auto it = std::lower_bound(rows.begin(), rows.end(), e.centre.frame,
                                     [](const TrackedRow& r, int frame) { return r.frame < frame; });
    if (it == rows.end() || it->frame != e.centre.frame || it->lost || it->manual ||
        w.retracked.count(e.centre.frame) != 0) {
      continue;
    }
    const auto row = static_cast<std::size_t>(it - rows.begin());
    Frame meta;
    meta.index = it->frame;
    meta.t = it->t;
    const double score = it->score;
    const double pos[3][2] = {{e.centre.x_px, e.centre.y_px}, {e.ax_px, e.ay_px}, {e.bx_px, e.by_px}};
    for (std::size_t s = 0; s < w.series.size() && s < 3; ++s) {
      out[w.series[s]].rows[row] = make_row(meta, in, pos[s][0], pos[s][1], score, false);
      out[w.series[s]].angle_rad[row] = e.centre.angle_rad;
    }
  }
}

/// The path trackers' marks are read first (a decoding up to the last of them), so that each
/// mark shows its tracker the object's look there in the frames before it as well as after
/// (PathTracker::add_look): kept is the part of the marked frame's grey image around the mark.
void read_mark_looks(std::vector<Follower>& followers, const VideoInput& in) {
  int last = -1;
  for (const Follower& w : followers) {
    if (!std::holds_alternative<PathTracker>(w.tracker)) continue;
    for (const ManualMark& m : w.target.marks) last = std::max(last, m.frame);
  }
  if (last < 0) return;
  FrameReader reader(in);
  Frame f;
  while (reader.next(f) && f.index <= last) {
    for (Follower& w : followers) {
      if (!std::holds_alternative<PathTracker>(w.tracker)) continue;
      for (const ManualMark& m : w.target.marks) {
        if (m.frame != f.index) continue;
        const cv::Rect r = PathTracker::look_crop(frame_size(f), m.x_px, m.y_px);
        if (r.area() == 0) continue;  // outside the image: check_marks' error comes at the start
        ManualMark in_crop = m;
        in_crop.x_px -= r.x;
        in_crop.y_px -= r.y;
        cv::Mat buf;
        w.looks.emplace_back(in_crop, gray_region(f, r, buf).clone());
      }
    }
  }
}

/// Starts every target and streams the clip through its tracker (the rows of the frame
/// trackers; the path trackers collect candidates).
void stream(TrackSession::Impl& session, const std::string& input, const TrackVideoOptions& options) {
  TrackVideoResult result;
  result.input = open_input(input, options.source);
  const VideoInput& in = result.input;
  std::vector<Follower> followers;
  for (const Target& t : options.targets) {
    Follower w{t, 0, 0, 0, PointTracker(point_options(options, in)), false, {}, {}, {}, 0, {}, {}};
    if (w.target.kind == Target::Kind::ellipse) {
      w.tracker = EllipseTracker(options.ellipse);
    } else if (options.offline_points) {
      PathTrackerOptions path = options.path;
      if (path.step_s == 0) path.step_s = step_s(in);
      w.tracker = PathTracker(path);
    }
    resolve_start(w, in);
    check_marks(w.target, w.start_frame, in);
    w.reach_back_to = w.start_frame;
    for (const std::string& n : output_names(t)) {
      w.series.push_back(result.series.size());
      TrackedSeries s;
      s.name = n;
      s.kind = t.kind;
      result.series.push_back(std::move(s));
    }
    followers.push_back(std::move(w));
  }

  read_mark_looks(followers, in);
  FrameReader reader(in);
  const int expected = reader.expected_steps();
  const std::set<int> thumb_steps = thumbnail_steps(options.thumbnails, expected);
  const double scale = std::min(1.0, double(kThumbWidth) / std::max(1, in.info.width));
  session.scale = scale;
  std::vector<std::pair<Frame, cv::Mat>>& thumbs = session.thumbs;
  Frame f;
  while (reader.next(f)) {
    for (Follower& w : followers) {
      if (!w.started && f.index != w.start_frame) continue;
      std::visit(
          [&](auto& tracker) {
            using Tracker = std::decay_t<decltype(tracker)>;
            const auto mark = std::find_if(w.target.marks.begin(), w.target.marks.end(),
                                           [&](const ManualMark& m) { return m.frame == f.index; });
            if (!w.started) {
              record(w, f, in, result.series, tracker.start(f, w.start_x, w.start_y, w.target.name));
              if constexpr (std::is_same_v<Tracker, PathTracker>) {
                tracker.set_marks(w.target.marks);
                for (const auto& [mk, crop] : w.looks) tracker.add_look(mk.frame, crop, mk.x_px, mk.y_px);
                w.looks.clear();
              }
              w.started = true;
            } else if constexpr (std::is_same_v<Tracker, PathTracker>) {
              tracker.update(f);  // answers in finish(), after the last frame
              Frame meta;
              meta.index = f.index;
              meta.t = f.t;
              w.pending.push_back(std::move(meta));
            } else if (mark != w.target.marks.end()) {
              record(w, f, in, result.series, tracker.mark(f, mark->x_px, mark->y_px));
              track_backward(w, f, *mark, in, result.series, options);
              w.recent.clear();
              w.reach_back_to = f.index;
            } else {
              record(w, f, in, result.series, tracker.update(f));
            }
            if constexpr (!std::is_same_v<Tracker, PathTracker>) {
              // Hold this frame when a mark follows within kBackwardFrames frames.
              const bool near_mark = std::any_of(w.target.marks.begin(), w.target.marks.end(), [&](const ManualMark& m) {
                return m.frame > f.index && m.frame - f.index <= static_cast<int>(kBackwardFrames) * std::max(1, in.clip.step_size);
              });
              if (near_mark && mark == w.target.marks.end()) {
                Frame copy;
                copy.index = f.index;
                copy.t = f.t;
                copy.bgr = f.bgr.clone();
                copy.gray = f.gray.clone();
                w.recent.push_back(std::move(copy));
                if (w.recent.size() > kBackwardFrames) w.recent.pop_front();
              }
            }
          },
          w.tracker);
    }
    if (thumb_steps.count(result.frames) != 0) {
      Frame meta;
      meta.index = f.index;
      meta.t = f.t;
      cv::Mat small;
      cv::resize(f.bgr, small, cv::Size(), scale, scale, cv::INTER_AREA);
      thumbs.emplace_back(std::move(meta), std::move(small));
    }
    ++result.frames;
    if (options.progress) options.progress(result.frames, std::max(expected, result.frames));
  }
  for (const Follower& w : followers) {
    if (!w.started) {
      throw InputError(w.target.from_track.empty() ? w.target.name : field("from_track") + " " + w.target.from_track,
                       "the start frame " + std::to_string(w.start_frame) + " is beyond the end of the clip (" +
                           std::to_string(result.frames) + " frames decoded)");
    }
  }
  session.reader_warnings = reader.warnings();
  session.input = input;
  session.streamed = std::move(result);
  session.followers = std::move(followers);
}

/// The end of a tracking: the path trackers' answers, summaries, checks, thumbnails, warnings.
TrackVideoResult conclude(TrackSession::Impl& session) {
  TrackVideoResult result;
  result.input = session.streamed.input;
  result.series = session.streamed.series;
  result.frames = session.streamed.frames;
  const VideoInput& in = result.input;
  std::vector<Follower>& followers = session.followers;
  const std::string& input = session.input;
  std::vector<std::string> hints;  // per follower: why its track lost frames
  for (Follower& w : followers) {
    std::string hint;
    if (auto* path = std::get_if<PathTracker>(&w.tracker)) {
      const std::vector<Observation> obs = path->finish();
      for (std::size_t i = 0; i < obs.size() && i < w.pending.size(); ++i) record(w, w.pending[i], in, result.series, obs[i]);
      hint = path->loss_hint();
    } else if (const auto* ellipse = std::get_if<EllipseTracker>(&w.tracker)) {
      retime(w, ellipse->at_frame_time(), in, result.series);
      hint = ellipse->loss_hint();
    } else if (const auto* point = std::get_if<PointTracker>(&w.tracker)) {
      hint = point->loss_hint();
    }
    hints.push_back(hint);
  }
  for (TrackedSeries& s : result.series) summarise(s);
  for (const Follower& w : followers) {
    const std::vector<int>& done = result.series[w.series[0]].manual_frames;
    for (const ManualMark& m : w.target.marks) {
      if (std::find(done.begin(), done.end(), m.frame) == done.end()) {
        throw InputError(field("mark") + " " + w.target.name + "@" + std::to_string(m.frame),
                         "frame " + std::to_string(m.frame) + " is beyond the end of the clip (" +
                             std::to_string(result.frames) + " frames decoded)");
      }
    }
  }
  for (const Follower& w : followers) {
    if (w.target.from_track.empty()) continue;
    for (const auto& m : in.marks_px) {
      if (m.name == w.target.from_track) {
        result.series[w.series[0]].vs_human = compare_with_human(result.series[w.series[0]], m, w.start_frame, in.info.width);
      }
    }
  }
  for (const auto& [meta, small] : session.thumbs) {
    cv::Mat img = small.clone();  // drawn again at every re-tracking
    draw_tracks(img, session.scale, meta.index, result.series);
    Thumbnail t;
    t.frame = meta.index;
    t.t = meta.t;
    t.jpeg = encode_image(".jpg", img, {cv::IMWRITE_JPEG_QUALITY, 85});
    if (t.jpeg.empty()) {
      throw InputError(input, "cannot encode a thumbnail as JPEG");
    }
    result.thumbnails.push_back(std::move(t));
  }
  result.warnings = in.warnings;
  for (const auto& w : session.reader_warnings) result.warnings.push_back(w);
  for (std::size_t wi = 0; wi < followers.size(); ++wi) {  // an ellipse's ends are lost with its centre
    const Follower& w = followers[wi];
    const TrackedSeries& s = result.series[w.series[0]];
    if (s.lost_ranges.empty()) continue;
    std::string frames;
    for (const auto& [a, b] : s.lost_ranges) {
      frames += (frames.empty() ? "" : ", ") + std::to_string(a) + (a == b ? "" : "-" + std::to_string(b));
    }
    std::string refound;
    for (int k : s.refound_frames) refound += (refound.empty() ? "" : ", ") + std::to_string(k);
    result.warnings.push_back("track '" + s.name + "': lost at frame(s) " + frames + " (rows with empty positions)" +
                              (refound.empty() ? "" : "; found again at frame(s) " + refound) +
                              (hints[wi].empty() ? "" : "; " + hints[wi]));
  }
  // A ball seen as an ellipse looks the same after half a turn: a turn near 90 degrees per
  // frame cannot be told from the other way round (the tracker takes the smaller one, across a
  // bounce the one nearest the turn before): warned above track::kAmbiguousTurnDeg
  // (docs/theory.md#plausibility-checks, "Spin near half a turn per frame").
  for (const Follower& w : followers) {
    if (w.target.kind != Target::Kind::ellipse) continue;
    const TrackedSeries& s = result.series[w.series[0]];
    const int step = std::max(1, result.input.clip.step_size);
    double most = 0;
    int at = 0;
    for (std::size_t i = 1; i < s.rows.size(); ++i) {
      if (s.rows[i].lost || s.rows[i - 1].lost || s.rows[i].frame - s.rows[i - 1].frame != step) continue;
      const double turn = std::abs(s.angle_rad[i] - s.angle_rad[i - 1]) * 180 / std::numbers::pi;
      if (turn > most) most = turn, at = s.rows[i].frame;
    }
    if (!(most > track::kAmbiguousTurnDeg)) continue;
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "track '%s' turns up to %.0f degrees per frame (frame %d): a ball seen as an ellipse looks the "
                  "same after half a turn, so %.0f degrees the other way fits as well and the ends A, B may be "
                  "swapped from frame to frame; if the ball may spin that fast, film at a higher frame rate or put "
                  "a mark on the ball",
                  s.name.c_str(), most, at, 180 - most);
    result.warnings.push_back(buf);
  }
  // The project's own marks are an independent check: a track far from them has followed
  // something else (an edge sliding along itself, a look-alike) even where its score held.
  // Human marks scatter ~1 px at the zoom they are clicked at; 3x that is not scatter. A wide
  // image is clicked zoomed out (jmoljana's marks, 1920 px wide, lie on a 2.8 px grid: one
  // screen pixel per 2.8 image pixels), so the bar grows with the width past 640 px, as the
  // correction distance does (compare_with_human).
  constexpr double kHumanDisagreementPxPer640 = 3;
  const double disagreement_px = kHumanDisagreementPxPer640 * std::max(1.0, result.input.info.width / 640.0);
  for (const TrackedSeries& s : result.series) {
    if (!s.vs_human || s.vs_human->frames == 0 || !(s.vs_human->median_px > disagreement_px)) continue;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.1f px (median over %d frames)", s.vs_human->median_px, s.vs_human->frames);
    result.warnings.push_back("track '" + s.name + "' lies " + buf +
                              " from the project's own marks: it has followed something else; check the report, "
                              "start on a textured mark or use " + field("ellipse") + " for a ball");
  }
  return result;
}

}  // namespace

TrackVideoResult track_video(const std::string& input, const TrackVideoOptions& options, TrackSession* keep) {
  if (const auto err = options.validate(); !err.empty()) throw InputError(err);
  auto session = std::make_unique<TrackSession::Impl>();
  stream(*session, input, options);
  TrackVideoResult result = conclude(*session);
  if (keep != nullptr) keep->impl = std::move(session);
  return result;
}

std::optional<TrackVideoResult> retrack(TrackSession& session, const std::vector<Target>& targets) {
  if (!session.impl || targets.size() != session.impl->followers.size()) return std::nullopt;
  TrackSession::Impl& s = *session.impl;
  std::vector<std::size_t> changed;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const Target& a = targets[i];
    const Follower& w = s.followers[i];
    const Target& b = w.target;
    if (a.kind != b.kind || a.name != b.name || a.x_px != b.x_px || a.y_px != b.y_px || a.frame != b.frame ||
        a.from_track != b.from_track) {
      return std::nullopt;
    }
    const bool same = a.marks.size() == b.marks.size() &&
                      std::equal(a.marks.begin(), a.marks.end(), b.marks.begin(), [](const ManualMark& x, const ManualMark& y) {
                        return x.frame == y.frame && x.x_px == y.x_px && x.y_px == y.y_px;
                      });
    if (same) continue;
    if (!std::holds_alternative<PathTracker>(w.tracker)) return std::nullopt;  // streams forward: decode again
    changed.push_back(i);
  }
  for (std::size_t i : changed) check_marks(targets[i], s.followers[i].start_frame, s.streamed.input);  // before any change
  for (std::size_t i : changed) {
    Follower& w = s.followers[i];
    std::get<PathTracker>(w.tracker).set_marks(targets[i].marks);
    w.target.marks = targets[i].marks;
  }
  return conclude(s);
}



track::TrackSet to_track_set(const TrackVideoResult& result) {
  track::TrackSet set;
  set.source = result.input.input;
  set.format = "video";
  set.file_length_unit = result.input.calibration.calibrated ? "m" : "px";
  set.time_scale = result.input.time.time_scale;
  set.warnings = result.warnings;
  for (const TrackedSeries& s : result.series) {
    track::Track t;
    t.name = s.name;
    for (const TrackedRow& r : s.rows) {
      if (!r.lost) t.points.push_back({r.frame, r.t, r.x, r.y});
    }
    set.tracks.push_back(std::move(t));
  }
  return set;
}

}  // namespace tribolab::video
