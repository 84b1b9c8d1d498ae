// EllipseTracker (docs/theory.md#ellipse-tracking): predict, segment by colour distance,
// refine the edge to sub-pixel, label the ends of the major axis continuously.
#include "video/ellipse_tracker.hpp"

#include "numerics/error.hpp"
#include "video/ellipse_fit.hpp"
#include "video/frame_time.hpp"
#include "numerics/units.hpp"
#include "numerics/polyfit.hpp"
#include "numerics/statistics.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <optional>
#include <sstream>

namespace tribolab::video {
namespace {

constexpr std::size_t kMotionPoints = 8;  ///< centres in the parabola fit
constexpr std::size_t kSpinPoints = 6;    ///< orientations in the spin fit
constexpr double kRoundRatio = 0.05;      ///< (a - b) / a below this: no orientation
constexpr double kRoundPx = 0.5;          ///< nor with the axes closer than this, px
constexpr double kConfidentScore = 0.9;   ///< a fit from the prediction this good needs no search
/// Exposures tried, as fractions of the frame period, when a fit scores below min_score:
/// a full-period shutter first (the widest edge windows), then shorter ones. A phone's or a
/// messenger's 30 fps video of a short exposure (or 120 fps footage re-encoded to 30 fps)
/// blurs an object by a fraction of its travel between frames; edge windows sized for the
/// whole travel then hold tens of pixels of background texture and lose most edge points
/// (docs/theory.md#ellipse-tracking, item 8).
constexpr double kExposures[] = {1.0, 0.5, 0.25, 0.125};
// The least share of the outline's normals a score is taken over: those that ran off the image
// are not counted against a fit, up to a quarter of them (docs/theory.md#ellipse-tracking).
constexpr double kLeastInView = 0.75;

/// Distance of every pixel of `roi` to `colour` (per channel, grey levels): low inside the
/// object, |background - object| outside, linear in the mixing fraction across an edge.
cv::Mat colour_distance(const Frame& frame, const cv::Rect& roi, const cv::Vec3d& colour) {
  const cv::Mat& img = frame.bgr.empty() ? frame.gray : frame.bgr;
  cv::Mat out(roi.height, roi.width, CV_32F);
  const int ch = img.channels();
  const float c0 = static_cast<float>(colour[0]), c1 = static_cast<float>(colour[1]), c2 = static_cast<float>(colour[2]);
  for (int r = 0; r < roi.height; ++r) {
    const unsigned char* p = img.ptr<unsigned char>(roi.y + r) + static_cast<std::ptrdiff_t>(roi.x) * ch;
    float* o = out.ptr<float>(r);
    if (ch == 3) {
      for (int c = 0; c < roi.width; ++c) {
        const float d0 = p[3 * c] - c0, d1 = p[3 * c + 1] - c1, d2 = p[3 * c + 2] - c2;
        o[c] = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
      }
    } else {
      for (int c = 0; c < roi.width; ++c) o[c] = std::abs(p[c * ch] - c0);
    }
  }
  return out;
}

/// Least-squares polynomial (degree <= 2) through (s, v), evaluated at s = x.
double poly_predict(const std::vector<double>& s, const std::vector<double>& v, int degree, double x) {
  const std::vector<double> c = numerics::least_squares_polynomial(s, v, degree);
  double y = 0;
  for (std::size_t j = c.size(); j-- > 0;) y = y * x + c[j];
  return y;
}

/// Per-channel median of the pixels of `img` where `mask` is set.
cv::Vec3d median_colour(const cv::Mat& img, const cv::Mat& mask) {
  cv::Vec3d out;
  std::vector<std::vector<unsigned char>> v(static_cast<std::size_t>(img.channels()));
  for (int r = 0; r < img.rows; ++r) {
    const unsigned char* p = img.ptr<unsigned char>(r);
    const unsigned char* m = mask.ptr<unsigned char>(r);
    for (int c = 0; c < img.cols; ++c) {
      if (!m[c]) continue;
      for (int k = 0; k < img.channels(); ++k) v[static_cast<std::size_t>(k)].push_back(p[c * img.channels() + k]);
    }
  }
  for (int k = 0; k < img.channels(); ++k) {
    auto& w = v[static_cast<std::size_t>(k)];
    if (!w.empty()) out[k] = upper_median(std::move(w));
  }
  return out;
}

/// Sensor noise sd of a grey image, robust to edges: 1.4826 MAD of horizontal neighbour
/// differences over sqrt(2).
double noise_sd(const cv::Mat& img) {
  std::vector<int> d;
  const int ch = img.channels();
  for (int r = 0; r < img.rows; ++r) {
    const unsigned char* p = img.ptr<unsigned char>(r);
    for (int c = 0; c + 1 < img.cols; ++c) d.push_back(std::abs(p[(c + 1) * ch] - p[c * ch]));
  }
  if (d.empty()) return 0;
  return kMadToSd * upper_median(std::move(d)) / std::sqrt(2.0);
}

std::string fmt_point(double x, double y) {
  std::ostringstream os;
  os.precision(6);
  os << "(" << x << ", " << y << ")";
  return os.str();
}

// The motion update() assumes for a frame: steps since the last good centre, whether a
// velocity is known, the velocity (px per frame) and the spin (rad per frame).
struct Motion {
  int steps = 1;
  bool moving = false;
  cv::Point2d velocity;
  double omega = 0;
};

// The best edge fit of one frame so far (EllipseTracker::update): fits must lie within `gate`
// px of the prediction `pred`; the score is that of score_of.
struct FrameFit {
  cv::Rect image_rect;
  cv::Point2d pred;           // px
  double gate = 0;            // px
  double a_ref = 0, b_ref = 0;  // the running semi-axes, px
  double score = 0, rms = 0;
  Ellipse found;
  std::vector<EdgePoint> edges;  // the found ellipse's inlier edge points
  // The square reaching `pad` px from the prediction each way, clipped to the image.
  cv::Rect window(double pad) const;
  // Score: fraction of normals giving a kept edge point, times agreement of the axes with the
  // running ones (a merged or partly hidden object changes shape).
  double score_of(const EdgeFit& fit) const;
  // Keeps the fit from `init` when it scores better (or as well, with `ties`).
  void try_fit(const cv::Mat& dist, cv::Point origin, const Ellipse& init, const EdgeFitOptions& opt,
               bool ties = false);
};

}  // namespace

std::string EllipseTrackerOptions::validate() const {
  if (!(min_score >= 0 && min_score <= 1)) return "ellipse min_score must be in [0, 1]";
  if (max_gap_frames < 0 || max_gap_frames > 10000) return "ellipse max_gap_frames must be in [0, 10000]";
  return "";
}

struct EllipseTracker::Impl {
  EllipseTrackerOptions options;
  std::string name;
  cv::Vec3d colour;            ///< object colour (BGR or grey), learned in the first frame
  double contrast = 0;         ///< |background - object| in the first frame, grey levels
  double a_ref = 0, b_ref = 0; ///< running semi-axes, px
  struct Centre { int index; double x, y; };
  struct Turn { int index; double phi; };
  std::deque<Centre> centres;  ///< last good centres (motion model)
  std::deque<Turn> turns;      ///< last good orientations, unwrapped (spin model)
  double phi_last = 0;         ///< last orientation (screen, counter-clockwise), rad
  int index_last = 0;          ///< last good frame index
  double speed_hint = 0;       ///< px per frame to allow for when the motion model is short
  int lost_run = 0;            ///< consecutive lost frames
  bool gave_up = false;
  double exposure = 1;         ///< exposure as a fraction of the frame period (learned, sticky)
  int short_exposure_frames = 0;  ///< accepted frames whose best fit assumed exposure < 1
  int weak_frames = 0;         ///< lost frames with an ellipse found in the gate but a weak fit
  int empty_frames = 0;        ///< lost frames with nothing of the object's outline found
  int given_up_frames = 0;     ///< frames after more than max_gap_frames lost in a row
  /// Every accepted frame goes to the pass that puts the frames at their time (at_frame_time),
  /// with the motion model's piece it belongs to (counted up at each restart: a bounce, a mark
  /// off the model) and the edge points its fit was made from.
  FrameTimePass pass;
  int piece = 0;
  /// The start frame, held back from the pass until the next accepted frame gives the motion:
  /// it was fitted with edge windows for a sharp edge, and is refitted once (refit_start) from
  /// `start_contrast` (the colour distance around it, pixel (0, 0) at `start_origin`) with
  /// windows as long as its blur.
  std::optional<FittedFrame> start_frame;
  cv::Mat start_contrast;
  cv::Point start_origin;

  cv::Point2d predict_centre(int index) const {
    const Centre& last = centres.back();
    if (centres.size() == 1) return {last.x, last.y};
    std::vector<double> s, x, y;
    for (const auto& c : centres) {
      s.push_back(c.index - last.index);
      x.push_back(c.x);
      y.push_back(c.y);
    }
    const int degree = centres.size() >= 3 ? 2 : 1;  // flight is a parabola
    const double at = index - last.index;
    return {poly_predict(s, x, degree, at), poly_predict(s, y, degree, at)};
  }

  double spin_per_frame() const {
    if (turns.size() < 2) return 0;
    std::vector<double> s, p;
    for (const auto& t : turns) {
      s.push_back(t.index - turns.back().index);
      p.push_back(t.phi);
    }
    const double p1 = poly_predict(s, p, 1, 1), p0 = poly_predict(s, p, 1, 0);
    return p1 - p0;
  }

  EllipseObservation observe(int index, const Ellipse& e, double phi, double score, bool lost,
                             bool round, double rms) const {
    EllipseObservation o;
    o.centre.frame = index;
    o.centre.x_px = e.cx;
    o.centre.y_px = e.cy;
    o.centre.score = score;
    o.centre.lost = lost;
    o.centre.angle_rad = phi;
    o.centre.major_px = e.a;
    o.centre.minor_px = e.b;
    // screen counter-clockwise angle phi: direction (cos phi, -sin phi) in image coordinates
    const double ux = std::cos(phi) * e.a, uy = -std::sin(phi) * e.a;
    o.ax_px = e.cx + ux, o.ay_px = e.cy + uy;
    o.bx_px = e.cx - ux, o.by_px = e.cy - uy;
    o.round = round;
    o.rms_px = rms;
    return o;
  }

  /// Edge-fit settings for an object moving by `velocity` (px per frame) and turning by
  /// `spin_per_frame` (screen, rad); `blur_px`: motion of unknown direction (no velocity
  /// measured yet), px per frame. The edge ramp of a blurred object is as wide as its travel
  /// during the exposure (at most one frame's travel): profiles reach past half of it.
  /// `exposure`: the shutter's fraction of the frame period; the blur along a normal is that
  /// fraction of the boundary point's travel (the reach, which must hold the prediction's
  /// error, is not scaled).
  EdgeFitOptions edge_options(cv::Point2d velocity, double spin_per_frame, double blur_px = 0,
                              double exposure_fraction = 1) const {
    EdgeFitOptions eo;
    eo.known_a = a_ref, eo.known_b = b_ref;
    eo.vx_px = exposure_fraction * velocity.x, eo.vy_px = exposure_fraction * velocity.y;
    eo.dpsi_rad = -exposure_fraction * spin_per_frame;  // screen counter-clockwise is clockwise in image axes
    eo.blur_px = exposure_fraction * blur_px;
    // Blur beyond about the minor axis leaves no ellipse to fit (docs/theory.md#ellipse-tracking),
    // and a short exposure leaves a fast object sharp: the reach stops at 2 b of travel.
    const double travel = std::hypot(velocity.x, velocity.y) + a_ref * std::abs(spin_per_frame) + blur_px;
    eo.reach_px = 4 + 0.6 * std::min(travel, 2 * b_ref);
    eo.max_blur_px = b_ref;
    eo.min_contrast = 0.4 * contrast;
    eo.max_inside = 0.35 * contrast;
    eo.iterations = 2;
    return eo;
  }

  // update()'s steps.
  // A fit from the region of the object's colour nearest the prediction, unless the fit is clearly good.
  void fit_from_segment(FrameFit& fit, const Frame& frame, const EdgeFitOptions& eo) const;
  // Refits from the ellipse found (the measured motion, other exposures); the exposure of the fit kept.
  double refit(FrameFit& fit, const Frame& frame, const Motion& m) const;
  // The start frame refitted with the motion from it to the frame accepted at `index` (`found`,
  // orientation `phi`), and handed to the pass (start_frame).
  void refit_start(int index, const Ellipse& found, double phi, double exposure_used);
  // Takes an accepted fit into the motion and spin models and the running axes.
  EllipseObservation accept(int index, const FrameFit& fit, double phi_pred, double speed, double exposure_used);
};

EllipseTracker::EllipseTracker(const EllipseTrackerOptions& options) : impl_(std::make_unique<Impl>()) {
  if (const std::string err = options.validate(); !err.empty()) throw InputError(err);
  impl_->options = options;
}
EllipseTracker::~EllipseTracker() = default;
EllipseTracker::EllipseTracker(EllipseTracker&&) noexcept = default;
EllipseTracker& EllipseTracker::operator=(EllipseTracker&&) noexcept = default;

EllipseObservation EllipseTracker::start(const Frame& first, double x_px, double y_px,
                                         const std::string& name) {
  Impl& s = *impl_;
  {
    Impl fresh;
    fresh.options = s.options;
    fresh.name = name;
    s = std::move(fresh);
  }
  const cv::Mat& img = first.bgr.empty() ? first.gray : first.bgr;
  const std::string where = "ellipse " + name;
  if (img.empty() || img.depth() != CV_8U) throw InputError(where, "the start frame is empty");
  if (!(x_px >= 0 && y_px >= 0 && x_px <= img.cols - 1 && y_px <= img.rows - 1)) {
    throw InputError(where, "start point " + fmt_point(x_px, y_px) + " is outside the " +
                                std::to_string(img.cols) + "x" + std::to_string(img.rows) + " image");
  }
  const int sx = static_cast<int>(std::lround(x_px)), sy = static_cast<int>(std::lround(y_px));
  // Object colour: per-channel median of the 5x5 pixels around the start point.
  {
    const cv::Rect box = cv::Rect(sx - 2, sy - 2, 5, 5) & cv::Rect(0, 0, img.cols, img.rows);
    std::vector<cv::Mat> planes;
    cv::split(img(box).clone(), planes);
    for (int k = 0; k < img.channels(); ++k) {
      s.colour[k] = upper_median(std::vector<unsigned char>(planes[static_cast<std::size_t>(k)].begin<unsigned char>(),
                                                            planes[static_cast<std::size_t>(k)].end<unsigned char>()));
    }
  }
  const std::string no_object = "no contrasting object around the start point " + fmt_point(x_px, y_px) +
                                " (it must lie inside a ball or disc, fully in view, that differs "
                                "from its surroundings)";
  // Segment: Otsu threshold of the colour distance in a window around the start point,
  // grown until the object containing the start point lies inside it.
  const cv::Rect image_rect(0, 0, img.cols, img.rows);
  cv::Mat object;  // CV_8U mask of the object in `roi`
  cv::Rect roi;
  for (int half = 24;; half *= 2) {
    roi = cv::Rect(sx - half, sy - half, 2 * half + 1, 2 * half + 1) & image_rect;
    const bool whole = roi == image_rect;
    const cv::Mat dist = colour_distance(first, roi, s.colour);
    cv::Mat dist8, mask, labels;
    dist.convertTo(dist8, CV_8U);
    cv::threshold(dist8, mask, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
    cv::connectedComponents(mask, labels, 8, CV_32S);
    const int label = labels.at<int>(sy - roi.y, sx - roi.x);
    bool usable = label > 0;
    if (usable) {
      object = labels == label;
      cv::Rect bb = cv::boundingRect(object);
      const bool touches_window = bb.x == 0 || bb.y == 0 || bb.x + bb.width == roi.width ||
                                  bb.y + bb.height == roi.height;
      const bool touches_image = (bb.x == 0 && roi.x == 0) || (bb.y == 0 && roi.y == 0) ||
                                 (bb.x + bb.width == roi.width && roi.x + roi.width == img.cols) ||
                                 (bb.y + bb.height == roi.height && roi.y + roi.height == img.rows);
      if (touches_image) throw InputError(where, no_object);
      if (!touches_window) {
        // Contrast: the object's median colour against that of a ring 4..8 px outside it.
        cv::Mat grown4, grown8, core;
        cv::dilate(object, grown4, cv::getStructuringElement(cv::MORPH_ELLIPSE, {9, 9}));
        cv::dilate(object, grown8, cv::getStructuringElement(cv::MORPH_ELLIPSE, {17, 17}));
        cv::erode(object, core, cv::getStructuringElement(cv::MORPH_ELLIPSE, {3, 3}));
        if (cv::countNonZero(core) < 4) core = object;
        const cv::Vec3d obj = median_colour(img(roi), core), bg = median_colour(img(roi), grown8 & ~grown4);
        double c2 = 0;
        for (int k = 0; k < img.channels(); ++k) c2 += (bg[k] - obj[k]) * (bg[k] - obj[k]);
        s.colour = obj;
        s.contrast = std::sqrt(c2);
        cv::Mat buf;
        const double noise = noise_sd(gray_region(first, roi, buf));
        if (s.contrast < 20 || s.contrast < 8 * noise || cv::countNonZero(object) < 12) {
          if (whole) throw InputError(where, no_object);
        } else {
          break;
        }
      }
    }
    if (whole) throw InputError(where, no_object);
  }
  Ellipse init = ellipse_from_moments(object, cv::Point2d(roi.x, roi.y));
  s.a_ref = init.a, s.b_ref = init.b;
  const cv::Rect fit_roi =
      cv::Rect(static_cast<int>(init.cx - init.a - 10), static_cast<int>(init.cy - init.a - 10),
               static_cast<int>(2 * init.a + 21), static_cast<int>(2 * init.a + 21)) & image_rect;
  EdgeFitOptions eo = s.edge_options({0, 0}, 0);
  eo.known_a = eo.known_b = 0;  // the shape is what the first frame measures
  const auto edge_score = [](const EdgeFit& f) { return f.ok ? static_cast<double>(f.inliers) / f.profiles : 0.0; };
  EdgeFit fit = fit_ellipse_edges(colour_distance(first, fit_roi, s.colour), fit_roi.tl(), init, eo);
  double score = edge_score(fit);
  // A start frame taken in motion (a disc launched fast, filmed at 30 fps) has edges blurred
  // wider than a sharp edge's profiles reach: fitted again allowing a quarter, half and all of
  // the minor semi-axis of blur of unknown direction (as the first step after a start does), in
  // a window that holds the longer profiles; the best score, judged by the same bar, is kept.
  for (int k = 2; k >= 0 && score < s.options.min_score; --k) {
    EdgeFitOptions blurred = s.edge_options({0, 0}, 0, s.b_ref / (1 << k));
    blurred.known_a = blurred.known_b = 0;
    const int half = static_cast<int>(std::ceil(init.a + blurred.reach_px + 3));
    const cv::Rect roi = cv::Rect(static_cast<int>(init.cx) - half, static_cast<int>(init.cy) - half, 2 * half + 1,
                                  2 * half + 1) & image_rect;
    const EdgeFit again = fit_ellipse_edges(colour_distance(first, roi, s.colour), roi.tl(), init, blurred);
    if (edge_score(again) > score) {
      fit = again;
      score = edge_score(again);
    }
  }
  if (!fit.ok || score < s.options.min_score || fit.ellipse.b < 2) {
    throw InputError(where, "the object around the start point " + fmt_point(x_px, y_px) +
                                " is not an ellipse with a clear edge (edge score " +
                                std::to_string(score) + ")");
  }
  const Ellipse& e = fit.ellipse;
  s.a_ref = e.a, s.b_ref = e.b;
  const bool round = e.a - e.b < std::max(kRoundRatio * e.a, kRoundPx);
  // End A: the end of the major axis pointing right (screen angle in (-90, 90] degrees).
  double phi = round ? 0 : -e.psi;
  phi = std::remainder(phi, kPi);
  if (phi <= -kPi / 2) phi += kPi;
  s.phi_last = phi;
  s.index_last = first.index;
  s.centres.push_back({first.index, e.cx, e.cy});
  if (!round) s.turns.push_back({first.index, phi});
  s.start_frame = FittedFrame{first.index, 0, e, e.a, e.b, phi, score, fit.rms_px, round, fit.points};
  {
    // Room for the profiles of the longest blur the tracker fits (a travel of 2 b).
    const int half = static_cast<int>(std::ceil(e.a + 4 + 1.2 * e.b + 3));
    const cv::Rect roi = cv::Rect(static_cast<int>(e.cx) - half, static_cast<int>(e.cy) - half, 2 * half + 1,
                                  2 * half + 1) & image_rect;
    s.start_contrast = colour_distance(first, roi, s.colour);
    s.start_origin = roi.tl();
  }
  // First step: no velocity is known yet, so allow a fast throw: a tenth of the image diagonal
  // per frame (a 15 fps video of a toss moves the ball 70 px per frame at 640x480).
  s.speed_hint = std::max(15 + 0.5 * e.a, 0.1 * std::hypot(img.cols, img.rows));
  return s.observe(first.index, e, phi, score, false, round, fit.rms_px);
}

namespace {

cv::Rect FrameFit::window(double pad) const {
  // Clamped before the conversion to int: a prediction far outside the image stays defined.
  const auto clamp_px = [](double v) { return static_cast<int>(std::clamp(v, -1e6, 1e6)); };
  const int size = clamp_px(2 * pad + 2);
  return cv::Rect(clamp_px(std::floor(pred.x - pad)), clamp_px(std::floor(pred.y - pad)), size, size) & image_rect;
}

double FrameFit::score_of(const EdgeFit& fit) const {
  const double shape = std::max(std::abs(fit.ellipse.a / a_ref - 1), std::abs(fit.ellipse.b / b_ref - 1));
  // Normals that ran off the image are no evidence against the fit: not counted, as long as
  // kLeastInView of the outline's are (a ball leaving the view, a throw's top above it).
  const double in_view = std::max<double>(fit.profiles - fit.off_image, kLeastInView * fit.profiles);
  return std::min(1.0, fit.inliers / in_view) * std::clamp(1 - 3 * shape, 0.0, 1.0);
}

void FrameFit::try_fit(const cv::Mat& dist, cv::Point origin, const Ellipse& init, const EdgeFitOptions& opt,
                       bool ties) {
  const EdgeFit fit = fit_ellipse_edges(dist, origin, init, opt);
  if (!fit.ok || std::hypot(fit.ellipse.cx - pred.x, fit.ellipse.cy - pred.y) > gate) return;
  const double sc = score_of(fit);
  if (sc > score || (ties && sc >= score)) score = sc, found = fit.ellipse, rms = fit.rms_px, edges = fit.points;
}

}  // namespace

void EllipseTracker::Impl::fit_from_segment(FrameFit& fit, const Frame& frame, const EdgeFitOptions& eo) const {
  const cv::Rect roi = fit.window(a_ref + fit.gate + eo.reach_px + 3);
  if (!(fit.score < kConfidentScore && roi.width >= 3 && roi.height >= 3)) return;
  const cv::Mat dist = colour_distance(frame, roi, colour);
  cv::Mat mask = dist < 0.5 * contrast, labels, stats, cents;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, cents, 8, CV_32S);
  const double area = kPi * a_ref * b_ref;
  int best = -1;
  double best_d = fit.gate;
  for (int k = 1; k < n; ++k) {
    const double ak = stats.at<int>(k, cv::CC_STAT_AREA);
    if (ak < 0.4 * area || ak > 2.5 * area) continue;  // not the object (or merged with another)
    const double d = std::hypot(cents.at<double>(k, 0) + roi.x - fit.pred.x,
                                cents.at<double>(k, 1) + roi.y - fit.pred.y);
    if (d < best_d) best_d = d, best = k;
  }
  if (best > 0) {
    const Ellipse seg = ellipse_from_moments(labels == best, cv::Point2d(roi.x, roi.y));
    if (seg.a > 1 && seg.b > 1) fit.try_fit(dist, roi.tl(), seg, eo);
  }
}

double EllipseTracker::Impl::refit(FrameFit& fit, const Frame& frame, const Motion& m) const {
  double exposure_used = exposure;
  if (!(fit.score > 0)) return exposure_used;
  const cv::Point2d last(centres.back().x, centres.back().y);
  const cv::Point2d v = m.moving ? m.velocity : (cv::Point2d(fit.found.cx, fit.found.cy) - last) / m.steps;
  const Ellipse from = fit.found;
  const double d_found = std::hypot(fit.found.cx - fit.pred.x, fit.found.cy - fit.pred.y);
  bool decided = false, weak = false;
  for (const double fraction : kExposures) {
    if (m.moving && fraction == exposure) continue;  // the fits above assumed this one
    const bool motion_refit = !m.moving && fraction == 1.0;
    if (!motion_refit) {
      // Once a short exposure has been learned, every fit short of clearly good is retried.
      if (!decided) {
        weak = fit.score < options.min_score || (exposure < 1 && fit.score < kConfidentScore);
        decided = true;
      }
      if (!weak) break;
    }
    const EdgeFitOptions eo2 = edge_options(v, m.omega, 0, fraction);
    if (const cv::Rect roi = fit.window(a_ref + d_found + eo2.reach_px + 3); roi.width >= 3 && roi.height >= 3) {
      const double before = fit.score;
      fit.try_fit(colour_distance(frame, roi, colour), roi.tl(), from, eo2, motion_refit);
      if (fit.score > before || motion_refit) exposure_used = fraction;
    }
  }
  return exposure_used;
}

void EllipseTracker::Impl::refit_start(int index, const Ellipse& found, double phi, double exposure_used) {
  FittedFrame f = std::move(*start_frame);
  start_frame.reset();
  const double steps = std::max(1, index - f.index);
  const cv::Point2d v((found.cx - f.found.cx) / steps, (found.cy - f.found.cy) / steps);
  EdgeFitOptions eo = edge_options(v, (phi - f.phi) / steps, 0, exposure_used);
  eo.known_a = f.found.a, eo.known_b = f.found.b;
  const EdgeFit again = fit_ellipse_edges(start_contrast, start_origin, f.found, eo);
  start_contrast.release();
  // Kept when it holds as well as the start's own fit did (the same score), and stays on it.
  const double score = again.ok ? static_cast<double>(again.inliers) / again.profiles : 0.0;
  if (score >= std::min(f.score, options.min_score) &&
      std::hypot(again.ellipse.cx - f.found.cx, again.ellipse.cy - f.found.cy) <= 0.5 * f.found.b) {
    f.found = again.ellipse;
    f.phi = f.phi + std::remainder(-again.ellipse.psi - f.phi, kPi);
    f.rms = again.rms_px;
    f.edges = again.points;
  }
  pass.add(std::move(f));
}

EllipseObservation EllipseTracker::Impl::accept(int index, const FrameFit& fit, double phi_pred, double speed,
                                                double exposure_used) {
  const Ellipse& found = fit.found;
  const bool round = found.a - found.b < std::max(kRoundRatio * found.a, kRoundPx);
  const double phi = round ? phi_pred : phi_pred + std::remainder(-found.psi - phi_pred, kPi);
  // Motion model: a centre far off the prediction (a bounce) restarts the parabola, and the
  // spin model with it: a bounce changes the spin too (a rugby ball's from 45 to -19 rad/s), and
  // each next frame's turn, taken nearest the old spin's prediction, was read half a turn per
  // frame off (+75 rad/s, docs/theory.md#ellipse-tracking, item 7). From this frame on the
  // spin is learned afresh, the next turn taken as the smaller one, as at the start.
  const double innovation = std::hypot(found.cx - fit.pred.x, found.cy - fit.pred.y);
  if (centres.size() >= 2 && innovation > 3 + 0.25 * speed) {
    speed_hint = std::max(speed, 1.0);
    centres.clear();
    turns.clear();
    ++piece;
  }
  if (start_frame) refit_start(index, found, phi, exposure_used);
  pass.add({index, piece, found, a_ref, b_ref, phi, fit.score, fit.rms, round, fit.edges});
  centres.push_back({index, found.cx, found.cy});
  while (centres.size() > kMotionPoints) centres.pop_front();
  if (!round) {
    turns.push_back({index, phi});
    while (turns.size() > kSpinPoints) turns.pop_front();
  }
  phi_last = phi;
  index_last = index;
  a_ref = 0.8 * a_ref + 0.2 * found.a;
  b_ref = 0.8 * b_ref + 0.2 * found.b;
  lost_run = 0;
  exposure = exposure_used;
  if (exposure_used < 1) ++short_exposure_frames;
  return observe(index, found, phi, fit.score, false, round, fit.rms);
}

EllipseObservation EllipseTracker::update(const Frame& frame) {
  Impl& s = *impl_;
  TRIBOLAB_ASSERT(!s.centres.empty(), std::string("EllipseTracker::update before start"));
  const cv::Mat& img = frame.bgr.empty() ? frame.gray : frame.bgr;
  const int index = frame.index;
  cv::Point2d pred = s.predict_centre(index);
  if (!std::isfinite(pred.x) || !std::isfinite(pred.y)) pred = {s.centres.back().x, s.centres.back().y};
  Motion m;
  m.omega = s.spin_per_frame();  // rad per frame
  if (!std::isfinite(m.omega)) m.omega = 0;
  const double phi_pred = s.phi_last + m.omega * (index - s.index_last);
  Ellipse pred_e{pred.x, pred.y, s.a_ref, s.b_ref, -phi_pred};
  if (s.gave_up || img.empty()) {
    ++s.given_up_frames;
    return s.observe(index, pred_e, phi_pred, 0, true, false, 0);
  }
  m.steps = std::max(1, index - s.centres.back().index);
  m.moving = s.centres.size() >= 2;  // a velocity is known
  m.velocity = m.moving ? (pred - cv::Point2d(s.centres.back().x, s.centres.back().y)) / m.steps : cv::Point2d(0, 0);
  const double speed = m.moving ? std::hypot(m.velocity.x, m.velocity.y) : s.speed_hint;
  // Gate: how far the object may lie from the prediction. A bounce reverses the velocity
  // within a frame (error up to 2 |v| dt); lost frames widen the search.
  const double gate = 4 + 0.5 * s.b_ref + 2.2 * speed + 3.0 * s.lost_run;
  // Without a velocity, allow for blur up to the minor semi-axis (a longer smear is no ellipse
  // any more); the fit is redone below with the motion measured.
  const EdgeFitOptions eo =
      s.edge_options(m.velocity, m.omega, m.moving ? 0 : std::min(s.speed_hint, s.b_ref), m.moving ? s.exposure : 1);
  FrameFit fit;
  fit.image_rect = cv::Rect(0, 0, img.cols, img.rows);
  fit.pred = pred;
  fit.gate = gate;
  fit.a_ref = s.a_ref, fit.b_ref = s.b_ref;
  // 1. From the prediction (right in flight, also with part of the object hidden), in a window
  //    just holding the predicted outline and its profiles.
  if (const cv::Rect roi = fit.window(s.a_ref + eo.reach_px + 3); roi.width >= 3 && roi.height >= 3) {
    fit.try_fit(colour_distance(frame, roi, s.colour), roi.tl(), pred_e, eo);
  }
  // 2. Unless that fit is clearly good: segment the whole gate and start from the region of
  //    the object's colour nearest the prediction (right after a bounce); the better score wins.
  s.fit_from_segment(fit, frame, eo);
  // Refit from the ellipse found: with the motion just measured when none was known (every
  // edge window then allowed for a fast throw's blur; ties kept, as its windows fit the
  // motion), and, when the fit would be lost (below min_score; below kConfidentScore once a
  // short exposure has been learned), with every other exposure:
  // each a sharper edge window, less of the background in it. The same score decides;
  // nothing outside the gate is considered. A fit that holds is left as it is.
  const double exposure_used = s.refit(fit, frame, m);
  if (fit.score < s.options.min_score) {
    (fit.score > 0 ? s.weak_frames : s.empty_frames) += 1;
    ++s.lost_run;
    if (s.lost_run > s.options.max_gap_frames) s.gave_up = true;
    return s.observe(index, pred_e, phi_pred, fit.score, true, false, 0);
  }
  // Accepted. Orientation: the end of the major axis nearest the predicted A direction.
  return s.accept(index, fit, phi_pred, speed, exposure_used);
}

std::string EllipseTracker::loss_hint() const {
  const Impl& s = *impl_;
  std::string hint;
  if (s.weak_frames == 0 && s.empty_frames == 0) return hint;
  if (s.weak_frames >= s.empty_frames) {
    hint = "in " + std::to_string(s.weak_frames) +
           " frame(s) the ball's outline was found near its predicted place but fitted poorly (blur, a lossy "
           "video's blocks and colour smearing, a partly hidden ball, a background of the ball's colour): a lower " +
           field("ellipse_min_score") + " (e.g. 0.4) keeps such frames; check them in the report";
  } else {
    hint = "in " + std::to_string(s.empty_frames) +
           " frame(s) nothing of the ball's outline was found near its predicted place (hidden, out of view, or "
           "a bounce faster than the motion model): a larger " + field("max_gap") + " bridges a hidden ball";
  }
  if (s.given_up_frames > 0) {
    hint += "; given up after more than " + field("max_gap") + " (" + std::to_string(s.options.max_gap_frames) +
            ") lost frames in a row, so the last " + std::to_string(s.given_up_frames) + " frame(s) were not searched";
  }
  return hint;
}

EllipseTracker::AtFrameTime EllipseTracker::at_frame_time() const {
  const Impl& s = *impl_;
  FrameTimePass::Result r;
  if (s.start_frame) {  // no frame accepted after the start
    FrameTimePass with_start = s.pass;
    with_start.add(*s.start_frame);
    r = with_start.result();
  } else {
    r = s.pass.result();
  }
  AtFrameTime out;
  out.exposure = r.exposure;
  for (const RetimedFrame& f : r.frames) {
    out.poses.push_back(s.observe(f.frame.index, f.at, f.phi, f.frame.score, false, false, f.frame.rms));
  }
  return out;
}

EllipseObservation EllipseTracker::mark(const Frame& frame, double x_px, double y_px) {
  Impl& s = *impl_;
  TRIBOLAB_ASSERT(!s.centres.empty(), std::string("EllipseTracker::mark before start"));
  const cv::Mat& img = frame.bgr.empty() ? frame.gray : frame.bgr;
  if (!(x_px >= 0 && y_px >= 0 && x_px <= img.cols - 1 && y_px <= img.rows - 1)) {
    throw InputError("ellipse " + s.name, "the mark " + fmt_point(x_px, y_px) + " of frame " +
                                              std::to_string(frame.index) + " is outside the image");
  }
  double omega = s.spin_per_frame();
  if (!std::isfinite(omega)) omega = 0;
  const double phi = s.phi_last + omega * (frame.index - s.index_last);
  // A mark where the motion model predicts the ball (as an accepted centre would be, within
  // 3 px + a quarter of a frame's travel) continues it; elsewhere the motion restarts from the
  // mark: the frames before it may have followed something else.
  const int steps = std::max(1, frame.index - s.centres.back().index);
  const cv::Point2d pred = s.predict_centre(frame.index);
  const double speed = s.centres.size() >= 2
                           ? std::hypot(pred.x - s.centres.back().x, pred.y - s.centres.back().y) / steps
                           : s.speed_hint;
  const bool continues = s.centres.size() >= 2 && !s.gave_up && s.lost_run == 0 &&
                         std::hypot(x_px - pred.x, y_px - pred.y) <= 3 + 0.25 * speed;
  s.speed_hint = std::max({s.speed_hint, speed, 1.0});
  if (s.start_frame) {  // no frame accepted since the start: no motion to refit it with
    s.pass.add(std::move(*s.start_frame));
    s.start_frame.reset();
  }
  if (!continues) {
    s.centres.clear();
    ++s.piece;
  }
  s.centres.push_back({frame.index, x_px, y_px});
  while (s.centres.size() > kMotionPoints) s.centres.pop_front();
  s.phi_last = phi;
  s.index_last = frame.index;
  s.lost_run = 0;
  s.gave_up = false;
  const bool round = s.a_ref - s.b_ref < std::max(kRoundRatio * s.a_ref, kRoundPx);
  EllipseObservation o = s.observe(frame.index, Ellipse{x_px, y_px, s.a_ref, s.b_ref, -phi}, phi, 1, false, round, 0);
  o.centre.manual = true;
  return o;
}

}  // namespace tribolab::video
