// Point tracking by rotating-template correlation with a motion model
// (docs/theory.md#point-tracking). A wide window (the first step, a long gap) is searched
// coarse to fine; after max_gap_frames lost frames the point is searched for afresh around
// the prediction and taken again only where the match is unambiguous.
#include "video/point_tracker.hpp"

#include "numerics/error.hpp"
#include "numerics/message_number.hpp"
#include "video/correlation.hpp"
#include "video/correlation_peak.hpp"
#include "numerics/units.hpp"
#include "video/motion_model.hpp"
#include "video/scene_memory.hpp"
#include "numerics/statistics.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <vector>

namespace tribolab::video {
namespace {

// Largest drop of the score below the median of the last five accepted ones (a junk match
// of a 21 px patch on a real video scored 0.69 where the ball scored 0.99).
constexpr double kMaxScoreDrop = 0.3;
// Least score of the first match after the start (measured 0.97-0.99 on rendered scenes,
// 0.994 on Tracker's BallToss).
constexpr double kFirstMatchScore = 0.9;
// The refinement's (patch + 4) px squares lie within the window and h + kRefineSlackPx px
// around it: the first centre within a pixel of a window position (sub-pixel offset), then
// two moves of at most 3 px each (the 5x5 map's peak, +-2, and its sub-pixel offset), half a
// square h + 2 and a pixel for the bilinear sampling (1 + 6 + 2 + 1 = 10, and 2 to spare).
constexpr int kRefineSlackPx = 12;
// A search half-width above this many patch sides goes coarse to fine (the first step's
// quarter of the image, a long gap); below it the direct correlation is cheap enough.
constexpr int kCoarseFromPatches = 2;
// Coarse to fine: candidate places kept from the half-resolution envelope, how far below
// its best (and below min_score) a candidate may score there, and the full-resolution
// half-width searched around each, px. The half-resolution score of the object itself was
// measured 0.02-0.15 below its full-resolution one on the rendered scenes and BallToss.
constexpr int kCoarseCandidates = 6;
constexpr double kCoarseSlack = 0.25;
constexpr int kFineRadius = 4;
// A match whose patch differs from its place in an earlier frame, when the object was a patch
// or more away, by less than this (mean absolute difference, grey levels, each patch's mean
// taken away) is the still background. Measured (docs/benchmarks.md): the frame tracker's
// matches on still texture 0.7-1.2 on the 36-throw grid (GRID_FRAME=1) and 0.7-2.7 on
// CarInLoop's image sequence (--patch 31); its matches within the correction distance 4.7 and
// more on the grid (0.5 % below 7.1), 34 and more on BallToss. Between the two.
constexpr double kStillGrey = 3.5;

// Smallest eigenvalue of the mean structure tensor of `patch` (CV_32F), (grey level/px)^2:
// the squared rms intensity gradient in the patch's weakest direction. Near zero for a flat
// patch (no texture) and for a straight edge or stripes (the autocorrelation is flat along
// them): such a patch cannot fix a position in two dimensions.
double weakest_gradient_energy(const cv::Mat& patch) {
  cv::Mat gx, gy;
  cv::Sobel(patch, gx, CV_32F, 1, 0, 3, 1.0 / 8);  // 1/8: grey levels per px
  cv::Sobel(patch, gy, CV_32F, 0, 1, 3, 1.0 / 8);
  // Interior only: the Sobel border is extrapolated.
  const cv::Rect in(1, 1, patch.cols - 2, patch.rows - 2);
  const double sxx = gx(in).dot(gx(in)), syy = gy(in).dot(gy(in)), sxy = gx(in).dot(gy(in));
  const double n = in.area();
  const double tr = (sxx + syy) / n, det = (sxx * syy - sxy * sxy) / (n * n);
  return tr / 2 - std::sqrt(std::max(0.0, tr * tr / 4 - det));
}

// Where the maximum of f over [-1, 1] lies, from f(-1), f(0), f(1): the parabola's vertex
// when it has one, else the best of the three samples. (A parabola without a maximum, as the
// peak correlations of a sharp object at exposures 0, 1/4, 1/2 decreasing ever faster, gave
// the middle sample: BallToss's sharp ball was then matched with a 17 px smear, scored 0.76
// and was lost five frames later.)
double best_vertex(double fm, double f0, double fp) {
  if (fm - 2 * f0 + fp < 0) return parabola_vertex(fm, f0, fp);
  return fm > f0 && fm >= fp ? -1.0 : fp > f0 && fp > fm ? 1.0 : 0.0;
}

}  // namespace

// Vertex of the parabola through (-1, fm), (0, f0), (1, fp), clamped to [-1, 1].
double parabola_vertex(double fm, double f0, double fp) {
  const double curv = fm - 2 * f0 + fp;
  if (curv >= 0) return 0;
  return std::clamp(0.5 * (fm - fp) / curv, -1.0, 1.0);
}

// Sub-pixel offset of the maximum of `r` near integer peak p: least-squares quadratic
// f = a + b x + c y + d x^2 + e x y + g y^2 over the 3x3 neighbourhood, stationary point;
// `value` (if given) receives the fitted maximum. Falls back to a parabola per axis when
// that surface has no maximum within a pixel, and to 0 on the border of r.
cv::Point2d subpixel_peak(const cv::Mat& r, cv::Point p, double* value) {
  if (value) *value = r.at<float>(p);
  if (p.x < 1 || p.y < 1 || p.x > r.cols - 2 || p.y > r.rows - 2) return {0, 0};
  double a = 0, b = 0, c = 0, d = 0, e = 0, g = 0;
  for (int j = -1; j <= 1; ++j) {
    for (int i = -1; i <= 1; ++i) {
      const double f = r.at<float>(p.y + j, p.x + i);
      a += f / 9;
      b += i * f / 6;
      c += j * f / 6;
      e += i * j * f / 4;
      d += (i * i - 2.0 / 3) * f / 2;  // x^2 - 2/3 is orthogonal to 1 and to y^2 - 2/3
      g += (j * j - 2.0 / 3) * f / 2;
    }
  }
  // Gradient zero: [2d e; e 2g] [x y]^T = -[b c]^T; a maximum needs a negative-definite Hessian.
  const double det = 4 * d * g - e * e;
  if (d < 0 && g < 0 && det > 0) {
    const double x = (-b * 2 * g + c * e) / det, y = (-c * 2 * d + b * e) / det;
    if (std::abs(x) <= 1 && std::abs(y) <= 1) {
      if (value) {
        *value = a + b * x + c * y + d * (x * x - 2.0 / 3) + e * x * y + g * (y * y - 2.0 / 3);
      }
      return {x, y};
    }
  }
  // Otherwise one parabola per axis through the peak row and column.
  const auto at = [&](int dx, int dy) { return static_cast<double>(r.at<float>(p.y + dy, p.x + dx)); };
  return {parabola_vertex(at(-1, 0), at(0, 0), at(1, 0)), parabola_vertex(at(0, -1), at(0, 0), at(0, 1))};
}

std::string PointTrackerOptions::validate() const {
  if (patch_px < 7 || patch_px % 2 == 0) {
    return "patch_px must be odd and >= 7, got " + std::to_string(patch_px);
  }
  if (search_px < 0) return "search_px must be >= 0, got " + std::to_string(search_px);
  if (!(min_score > 0 && min_score < 1)) {
    return "min_score must lie in (0, 1), got " + message_number(min_score);
  }
  if (!(max_turn_deg >= 0 && max_turn_deg <= 90)) {
    return "max_turn_deg must lie in [0, 90], got " + message_number(max_turn_deg);
  }
  if (max_gap_frames < 0) {
    return "max_gap_frames must be >= 0, got " + std::to_string(max_gap_frames);
  }
  if (!(step_s >= 0 && std::isfinite(step_s))) return "step_s must be >= 0 (0: unknown), got " + message_number(step_s);
  return {};
}

struct PointTracker::Impl {
  PointTrackerOptions opt;
  std::string name;
  cv::Size image_size;
  cv::Mat big;        // CV_32F reference patch around the start, side sqrt(2) * patch + margin
  MotionModel model{5, 3};
  int last_frame = 0;
  int start_frame = 0;
  int gap = 0;        // consecutive lost frames
  bool gave_up = false;
  bool restarted = false;  // found again after giving up: the start's velocity is not measured
  std::deque<double> innovation_px;   // |measured - predicted| of the last accepted frames
  std::deque<double> innovation_rad;  // same for the angle
  std::deque<double> recent_scores;   // scores of the last accepted frames
  SceneMemory scene;                  // earlier frames, and where the object was in them
  // Buffers reused from frame to frame.
  cv::Mat window, templ, region_gray;
  std::vector<cv::Mat> results;
  cv::Mat best_map, scratch, local, small_result, smeared, kernel;
  cv::Mat window_coarse, coarse_templ, coarse_scratch, coarse_best, part;
  std::vector<cv::Mat> coarse_results;
  // Motion blur: the start's velocity (px/frame, known once three positions are), the
  // estimated exposure as a fraction of the frame period, and the template's extra smear.
  cv::Point2d v0;
  bool have_v0 = false;
  double shutter = 0;
  cv::Point2d blur{0, 0};

  bool turns = true;   // false: the pattern looks the same turned (a plain ball), no angle search
  int half() const { return opt.patch_px / 2; }
  // Angle step: turns the patch's corner by at most ~1.5 px (8 degrees for a 21 px patch).
  double angle_step() const { return std::min(to_rad(8), 1.5 / (std::sqrt(2.0) * half())); }

  // Template for a pattern turned by `angle` (counter-clockwise on screen) since the start,
  // smeared along `blur` (px, image frame) when that is at least half a pixel long; side
  // 2 * half_side + 1 (default: patch_px).
  const cv::Mat& make_template(double angle, int half_side = -1) {
    if (half_side < 0) half_side = half();
    const double c = std::cos(angle), s = std::sin(angle);
    const double cb = (big.cols - 1) / 2.0;
    const double len = std::hypot(blur.x, blur.y);
    const int margin = len >= 0.5 ? static_cast<int>(std::ceil(len / 2)) + 1 : 0;
    const double h = half_side + margin;
    // dst(x, y) = big(M (x, y, 1)): body offset = R(-angle) * image offset (y down).
    const cv::Matx23d m(c, -s, cb - c * h + s * h,  //
                        s, c, cb - s * h - c * h);
    const int out = 2 * half_side + 1, side = out + 2 * margin;
    cv::warpAffine(big, margin ? smeared : templ, m, cv::Size(side, side),
                   cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_REPLICATE);
    if (margin) {
      // Line kernel: the segment [-blur/2, blur/2] sampled every quarter pixel, splatted
      // bilinearly (the exposure's uniform motion, docs/theory.md#point-tracking).
      const int k = 2 * margin + 1;
      kernel.create(k, k, CV_32F);
      kernel.setTo(0);
      const int n = std::max(2, static_cast<int>(std::ceil(4 * len)));
      for (int i = 0; i < n; ++i) {
        const double f = (i + 0.5) / n - 0.5;
        const double x = margin + f * blur.x, y = margin + f * blur.y;
        const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
        const double fx = x - x0, fy = y - y0;
        kernel.at<float>(y0, x0) += static_cast<float>((1 - fx) * (1 - fy));
        kernel.at<float>(y0, x0 + 1) += static_cast<float>(fx * (1 - fy));
        kernel.at<float>(y0 + 1, x0) += static_cast<float>((1 - fx) * fy);
        kernel.at<float>(y0 + 1, x0 + 1) += static_cast<float>(fx * fy);
      }
      kernel /= n;
      // filter2D correlates; the kernel is point-symmetric, so this is the convolution.
      cv::filter2D(smeared, smeared, -1, kernel, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
      smeared(cv::Rect(margin, margin, out, out)).copyTo(templ);
    }
    return templ;
  }

  // Half side of the half-resolution template (half_resolution of the window and template).
  int coarse_half() const { return (half() + 1) / 2; }
  // The template at half resolution: a full-resolution template two px wider than twice the
  // coarse one, halved (coarse pixel i at full pixel 2i, both centred), cropped so that no
  // coarse pixel depends on the pyramid's border rule.
  const cv::Mat& make_coarse_template(double angle) {
    const int hc = coarse_half();
    half_resolution(make_template(angle, 2 * hc + 2), coarse_scratch);
    coarse_scratch(cv::Rect(1, 1, 2 * hc + 1, 2 * hc + 1)).copyTo(coarse_templ);
    return coarse_templ;
  }

  // Correlation maps (`results`, per angle, and their envelope `best_map`, each of the full
  // resolution size for `window`) by a coarse-to-fine search for a wide window: the window
  // and the templates at half resolution (every other angle, twice the step) give the
  // candidate places, and only around the best few is the full resolution correlated, for
  // the angles next to each candidate's coarse angle. Elsewhere the maps hold -1.
  void coarse_to_fine(const std::vector<double>& angles, double min_score);

  // The extra smear, at most two patches long (the reference patch holds no more).
  double max_blur() const { return 2.0 * opt.patch_px; }
  void set_blur(cv::Point2d b) {
    const double len = std::hypot(b.x, b.y), cap = max_blur();
    blur = len > cap ? b * (cap / len) : b;
  }

  // Why frames were lost (loss_hint()): the predicted place out of the image, nothing like the
  // pattern within the gate, look-alikes near the prediction, a score far below the object's
  // recent ones, the first match after the start below its bar, the still background; and the
  // frames searched afresh.
  enum class Loss { view, none, rival, score, first, still };
  static constexpr int kLosses = 6;
  int lost_by[kLosses] = {};
  int searched_afresh = 0;

  Observation lost_observation(int frame, const MotionState& pred, double score, Loss why) {
    ++lost_by[static_cast<int>(why)];
    if (gave_up) ++searched_afresh;
    Observation o;
    o.frame = frame;
    o.x_px = pred.x_px;
    o.y_px = pred.y_px;
    o.angle_rad = pred.angle_rad;
    o.score = std::clamp(score, 0.0, 1.0);
    o.lost = true;
    ++gap;
    if (gap > opt.max_gap_frames) gave_up = true;
    return o;
  }

  // The next frame's observation (follow()); the frame is then kept in `scene` where due, with
  // where the object was in it.
  Observation update(const Frame& frame);
  Observation follow(const Frame& frame);

  // update()'s steps, with their results.
  struct SearchReach {
    int first_search = 0;  // the first step's search half-width, px
    int half_width = 0;    // this frame's search half-width (the gate), px
  };
  struct AngleSearch {
    bool search = false;          // the angle is searched (max_turn_deg > 0, a pattern that turns)
    std::vector<double> angles;   // the angles correlated, rad
    double spacing = 0;           // between them, rad
  };
  struct PeakChoice {
    bool found = false;  // false: lost (no peak, rivals, or beyond the gate on re-acquisition)
    bool rival = false;  // lost for rivals
    cv::Point at;        // the chosen peak in the correlation maps
    double score = 0;    // its score (lost: the score to report)
  };
  struct Refined {
    cv::Point2d centre;  // px
    double angle = 0;    // rad
    double score = 0;    // the peak value at the refined angle and position
  };
  // The template's extra smear per unit of exposure: v - R(theta) v0, px per frame.
  cv::Point2d blur_change(const MotionState& pred) const;
  // The search half-width around the prediction (and the first step's).
  SearchReach search_reach(const MotionState& pred, bool reacquire) const;
  // The angles to correlate around the predicted one.
  AngleSearch angle_search(const MotionState& pred) const;
  // The correlation maps of `window` for every angle (`results`) and their envelope (`best_map`).
  void correlate(const std::vector<double>& angles, int half_width);
  // The peak nearest the prediction, unless a rival makes it doubtful.
  PeakChoice choose_peak(const MotionState& pred, const cv::Rect& win, bool reacquire, int first_search);
  // Sub-pixel position and angle (and the exposure fraction, learned) around peak `at` of window
  // `win`; `gray` is the grey image of a rectangle at `origin` holding the window and
  // h + kRefineSlackPx px around it (or sharing its border with the image).
  Refined refine(const cv::Mat& gray, cv::Point origin, const cv::Rect& win, cv::Point at, const AngleSearch& as,
                 cv::Point2d dv);
  // The patch at `centre` (in `gray`, a grey image at `origin`) differs by less than
  // kStillGrey from the same place in a kept frame where the object was a patch or more away.
  bool still(const cv::Mat& gray, cv::Point origin, cv::Point2d centre) const {
    cv::Mat here;
    cv::getRectSubPix(gray, cv::Size(opt.patch_px, opt.patch_px), cv::Point2f(centre) - cv::Point2f(origin), here,
                      CV_32F);
    const std::optional<double> d = scene.least_difference(here, centre, opt.patch_px);
    return d && *d < kStillGrey;
  }
  // The score passes min_score, the first match's bar and the drop check (kept among the recent scores).
  bool score_accepted(double score);
  // Takes the accepted observation into the motion model (o.refound set on re-acquisition).
  void accept(Observation& o, const MotionState& pred, bool reacquire);
};

void PointTracker::Impl::coarse_to_fine(const std::vector<double>& angles, double min_score) {
  const int p = opt.patch_px, h = half(), hc = coarse_half();
  const cv::Size full(window.cols - p + 1, window.rows - p + 1);
  for (cv::Mat& r : results) {
    r.create(full, CV_32F);
    r.setTo(-1);
  }
  best_map.create(full, CV_32F);
  best_map.setTo(-1);
  half_resolution(window, window_coarse);
  // Coarse angles: every other one (each angle within one step of a coarse one).
  std::vector<std::size_t> coarse_of;  // index into angles
  for (std::size_t i = 0; i < angles.size(); i += 2) coarse_of.push_back(i);
  if (angles.size() % 2 == 0 && angles.size() > 1) coarse_of.push_back(angles.size() - 1);
  coarse_results.resize(coarse_of.size());
  const int tc = 2 * hc + 1;
  if (window_coarse.cols < tc || window_coarse.rows < tc) return;
  for (std::size_t j = 0; j < coarse_of.size(); ++j) {
    normed_correlation(window_coarse, make_coarse_template(angles[coarse_of[j]]), coarse_results[j]);
    if (j == 0) {
      coarse_results[0].copyTo(coarse_best);
    } else {
      cv::max(coarse_best, coarse_results[j], coarse_best);
    }
  }
  // Candidates: the best few peaks of the coarse envelope (non-maximum suppression over
  // the coarse patch radius).
  double top = -1;
  for (int n = 0; n < kCoarseCandidates; ++n) {
    double v;
    cv::Point at;
    cv::minMaxLoc(coarse_best, nullptr, &v, nullptr, &at);
    if (n == 0) top = v;
    if (v < top - kCoarseSlack || v < min_score - kCoarseSlack) break;
    std::size_t jb = 0;
    for (std::size_t j = 1; j < coarse_of.size(); ++j) {
      if (coarse_results[j].at<float>(at) > coarse_results[jb].at<float>(at)) jb = j;
    }
    cv::circle(coarse_best, at, hc, cv::Scalar(-1), cv::FILLED);
    // Coarse placement (template's top-left) at -> template centre 2 (at + hc) in the
    // window -> full-resolution placement 2 (at + hc) - h.
    const cv::Point c(2 * (at.x + hc) - h, 2 * (at.y + hc) - h);
    const cv::Rect region = cv::Rect(c.x - kFineRadius, c.y - kFineRadius, 2 * kFineRadius + 1, 2 * kFineRadius + 1) &
                            cv::Rect(0, 0, full.width, full.height);
    if (region.empty()) continue;
    const cv::Mat img = window(cv::Rect(region.x, region.y, region.width + p - 1, region.height + p - 1));
    const std::size_t mid = coarse_of[jb];
    const std::size_t lo = mid >= 2 ? mid - 2 : 0, hi = std::min(angles.size() - 1, mid + 2);
    for (std::size_t i = lo; i <= hi; ++i) {
      normed_correlation(img, make_template(angles[i]), part);
      part.copyTo(results[i](region));
      cv::Mat env = best_map(region);
      cv::max(env, part, env);
    }
  }
}

PointTracker::PointTracker(const PointTrackerOptions& options) : impl_(std::make_unique<Impl>()) {
  if (const std::string e = options.validate(); !e.empty()) throw InputError("point tracker: " + e);
  impl_->opt = options;
}
PointTracker::~PointTracker() = default;
PointTracker::PointTracker(PointTracker&&) noexcept = default;
PointTracker& PointTracker::operator=(PointTracker&&) noexcept = default;

Observation PointTracker::start(const Frame& first, double x_px, double y_px,
                                const std::string& name) {
  Impl& m = *impl_;
  // The start frame's grey image, whole (the reference patch and its surroundings; once per track).
  cv::Mat buf;
  const cv::Mat gray = gray_region(first, cv::Rect(cv::Point(), frame_size(first)), buf);
  if (gray.empty() || gray.type() != CV_8UC1) {
    throw InputError(name, "no grey image in frame " + std::to_string(first.index));
  }
  require_finite(x_px, name + " start x");
  require_finite(y_px, name + " start y");
  const double h = m.half();
  if (x_px < 0 || y_px < 0 || x_px > gray.cols - 1 || y_px > gray.rows - 1) {
    throw InputError(name, "start point (" + std::to_string(x_px) + ", " + std::to_string(y_px) +
                               ") px lies outside the " + std::to_string(gray.cols) + "x" +
                               std::to_string(gray.rows) + " image");
  }
  if (x_px < h || y_px < h || x_px > gray.cols - 1 - h || y_px > gray.rows - 1 - h) {
    throw InputError(name, "start point (" + std::to_string(x_px) + ", " + std::to_string(y_px) +
                               ") px is closer than " + std::to_string(m.half()) +
                               " px to the image border: the pattern around it is cut");
  }
  // The reference patch is wide enough that every rotation of the central patch_px square,
  // grown by half the longest smear (max_blur) and a pixel on each side, stays inside it
  // (sqrt(2) times, plus a pixel for the interpolation).
  // (+2: the coarse search's template is two px wider than the patch.)
  const int side = 2 * static_cast<int>(std::ceil(std::sqrt(2.0) * (h + m.opt.patch_px + 3))) + 3;
  cv::Mat g32, big;
  cv::getRectSubPix(gray, cv::Size(side, side), cv::Point2f(x_px, y_px), big, CV_32F);
  cv::getRectSubPix(gray, cv::Size(m.opt.patch_px, m.opt.patch_px), cv::Point2f(x_px, y_px), g32,
                    CV_32F);
  // Threshold: rms gradient of 2 grey levels per px in the weakest direction; sensor noise of
  // sigma 2 grey levels on a flat patch gives about 0.9 (Sobel/8 of white noise: 0.43 sigma).
  const double energy = weakest_gradient_energy(g32);
  if (energy < 4.0) {
    throw InputError(name, "the " + std::to_string(m.opt.patch_px) + " px patch around (" +
                               std::to_string(x_px) + ", " + std::to_string(y_px) +
                               ") px has too little texture to follow (weakest rms gradient " +
                               std::to_string(std::sqrt(energy)) +
                               " grey levels/px, needs 2): start on a mark or corner");
  }
  // A pattern that correlates >= 0.97 with itself turned by one and by three angle steps
  // (a plain ball or disc) has no measurable orientation: only the position is searched and
  // its angle stays 0, instead of wandering along a flat correlation.
  m.big = big;  // only now: a refused start leaves the tracker as it was
  m.blur = {0, 0};
  m.have_v0 = false;
  m.shutter = 0;
  m.start_frame = first.index;
  m.turns = false;
  if (m.opt.max_turn_deg > 0) {
    const cv::Mat t0 = m.make_template(0).clone();
    for (double a : {m.angle_step(), 3 * m.angle_step()}) {
      cv::Mat c;
      normed_correlation(t0, m.make_template(a), c);
      if (!(c.at<float>(0, 0) >= 0.97f)) m.turns = true;
    }
  }
  m.name = name;
  m.image_size = gray.size();
  m.model.reset();
  m.model.add(first.index, x_px, y_px, 0);
  m.last_frame = first.index;
  m.gap = 0;
  m.gave_up = false;
  m.restarted = false;
  m.innovation_px.clear();
  m.innovation_rad.clear();
  m.recent_scores.clear();
  m.scene.reset(SceneMemory::stride_for(m.opt.step_s));
  std::fill(std::begin(m.lost_by), std::end(m.lost_by), 0);
  m.searched_afresh = 0;
  m.scene.remember(first, cv::Point2d(x_px, y_px));
  Observation o;
  o.frame = first.index;
  o.x_px = x_px;
  o.y_px = y_px;
  o.score = 1;
  return o;
}

std::string PointTracker::loss_hint() const {
  const Impl& m = *impl_;
  using Loss = Impl::Loss;
  int most = 0;
  for (int i = 1; i < Impl::kLosses; ++i) {
    if (m.lost_by[i] > m.lost_by[most]) most = i;
  }
  const int n = m.lost_by[most];
  if (n == 0) return "";
  const std::string frames = "in " + std::to_string(n) + " frame(s) ";
  std::string hint;
  switch (static_cast<Loss>(most)) {
    case Loss::view:
      hint = frames + "the point's predicted place was outside the image (it left the view)";
      break;
    case Loss::none:
      hint = frames + "nothing within the search correlated " + field("min_score") + " (" +
             message_number(m.opt.min_score) + ") with the pattern (hidden, blurred, turned by more than " +
             field("max_turn_deg") + " in a frame, or moving farther than the search): a lower " +
             field("min_score") + ", a larger " + field("max_turn_deg") + " or " + field("search") + "; or " +
             field("mark") + " the point in one of those frames";
      break;
    case Loss::rival:
      hint = frames + "a look-alike matched about as well near the predicted place, so the point was not guessed: " +
             field("mark") + " it in one of those frames";
      break;
    case Loss::score:
      hint = frames + "the best match scored far below what the point had scored just before (a hand over it, " +
             "its look changing): " + field("mark") + " it in one of those frames";
      break;
    case Loss::first:
      hint = frames + "the first match after the start scored below " + message_number(kFirstMatchScore) +
             ", the least a first match must look like the start (a small point on texture: the template is " +
             "mostly background): a smaller " + field("patch") + ", or " + field("point_tracker") +
             " path (the default), which tells the object from the background";
      break;
    case Loss::still:
      hint = frames + "the best match was the still background: the place looked as it did when the point was " +
             "elsewhere (the point hidden, and texture there like it): a larger " + field("max_gap") +
             " bridges a hidden point; or " + field("mark") + " it in one of those frames";
      break;
  }
  const int still = m.lost_by[static_cast<int>(Loss::still)];
  if (most != static_cast<int>(Loss::still) && still > 0) {
    hint += "; in " + std::to_string(still) + " frame(s) the best match was the still background";
  }
  if (m.searched_afresh > 0) {
    hint += "; after more than " + field("max_gap") + " (" + std::to_string(m.opt.max_gap_frames) +
            ") lost frames in a row the point was searched for afresh in " + std::to_string(m.searched_afresh) +
            " frame(s), where only an unambiguous match within reach is taken";
  }
  return hint;
}

Observation PointTracker::update(const Frame& frame) {
  if (!impl_ || impl_->big.empty()) throw InputError("point tracker: update() before start()");
  return impl_->update(frame);
}

Observation PointTracker::mark(const Frame& frame, double x_px, double y_px) {
  if (!impl_ || impl_->big.empty()) throw InputError("point tracker: mark() before start()");
  Impl& m = *impl_;
  cv::Mat buf;
  const cv::Mat gray = gray_region(frame, cv::Rect(cv::Point(), frame_size(frame)), buf);
  if (gray.size() != m.image_size) {
    throw InputError(m.name, "frame " + std::to_string(frame.index) + " is not of the start frame's size");
  }
  if (frame.index <= m.last_frame) {
    throw InputError(m.name, "frame " + std::to_string(frame.index) + " does not follow frame " +
                                 std::to_string(m.last_frame));
  }
  if (!(x_px >= 0 && y_px >= 0 && x_px <= gray.cols - 1 && y_px <= gray.rows - 1)) {
    throw InputError(m.name, "the mark (" + std::to_string(x_px) + ", " + std::to_string(y_px) +
                                 ") px of frame " + std::to_string(frame.index) + " lies outside the image");
  }
  // The pattern's angle carries on from the prediction. A mark where the motion model predicts
  // the point (within the gate an accepted match must fall in) continues it; elsewhere the
  // motion restarts from the mark (what was followed before it may have been something else),
  // as after a start.
  const MotionState pred = m.model.predict(frame.index);
  const double angle = pred.angle_rad;
  double worst = 0;
  for (double e : m.innovation_px) worst = std::max(worst, e);
  const bool continues = m.model.size() >= 3 && m.gap == 0 && !m.gave_up &&
                         std::hypot(x_px - pred.x_px, y_px - pred.y_px) <= std::max<double>(m.half(), 4 + 3 * worst);
  m.last_frame = frame.index;
  if (!continues) {
    m.model.reset();
    m.restarted = true;
    m.innovation_px.clear();
    m.innovation_rad.clear();
  }
  m.model.add(frame.index, x_px, y_px, angle);
  m.gap = 0;
  m.gave_up = false;
  Observation o;
  o.frame = frame.index;
  o.x_px = x_px;
  o.y_px = y_px;
  o.score = 1;
  o.angle_rad = angle;
  o.manual = true;
  m.scene.remember(frame, cv::Point2d(x_px, y_px));
  return o;
}

cv::Point2d PointTracker::Impl::blur_change(const MotionState& pred) const {
  cv::Point2d dv(0, 0);
  if (have_v0) {
    const double c = std::cos(pred.angle_rad), sn = std::sin(pred.angle_rad);
    dv = cv::Point2d(pred.vx_px - (c * v0.x + sn * v0.y), pred.vy_px - (-sn * v0.x + c * v0.y));
  }
  return dv;
}

PointTracker::Impl::SearchReach PointTracker::Impl::search_reach(const MotionState& pred, bool reacquire) const {
  const int p = opt.patch_px, h = half();
  SearchReach r;
  r.first_search = std::max({2 * p, 48, std::min(image_size.width, image_size.height) / 4});
  double worst = 0;
  for (double e : innovation_px) worst = std::max(worst, e);
  double s;
  if (opt.search_px > 0) {
    s = opt.search_px;
  } else if (model.size() < 2) {
    s = r.first_search;
  } else if (model.size() < 3) {
    s = std::max<double>(h, 4 + 0.5 * std::hypot(pred.vx_px, pred.vy_px));  // no acceleration yet
  } else {
    s = std::max<double>(h, 4 + 3 * worst);
  }
  if (reacquire) {
    // Re-acquisition: the gate (where a match is accepted) is the first step's window; the
    // search looks twice as far, so that a look-alike just outside the gate is seen as a
    // rival and leaves the point lost rather than guessed.
    s = 2.0 * r.first_search;
  } else if (gap > 0) {
    s = std::min<double>(s + 2 + 3 * worst * (gap + 1) * (gap + 1), 2.0 * r.first_search + s);
  }
  r.half_width = static_cast<int>(std::ceil(s));
  return r;
}

PointTracker::Impl::AngleSearch PointTracker::Impl::angle_search(const MotionState& pred) const {
  AngleSearch a;
  a.search = opt.max_turn_deg > 0 && turns;
  a.spacing = angle_step();
  if (a.search) {
    double range = to_rad(opt.max_turn_deg);
    if (model.size() >= 3 && gap == 0) {
      double worst = 0;
      for (double e : innovation_rad) worst = std::max(worst, e);
      range = std::min(range, 3 * worst);
    }
    const int k = range <= a.spacing / 2 ? 0 : static_cast<int>(std::ceil(range / a.spacing));
    if (k > 0) a.spacing = range / k;
    for (int i = -k; i <= k; ++i) a.angles.push_back(pred.angle_rad + i * a.spacing);
  } else {
    a.angles.push_back(0);
  }
  return a;
}

void PointTracker::Impl::correlate(const std::vector<double>& angles, int half_width) {
  results.resize(angles.size());
  if (half_width > kCoarseFromPatches * opt.patch_px) {
    coarse_to_fine(angles, opt.min_score);
  } else {
    for (std::size_t i = 0; i < angles.size(); ++i) {
      normed_correlation(window, make_template(angles[i]), results[i]);
      if (i == 0) {
        results[0].copyTo(best_map);
      } else {
        cv::max(best_map, results[i], best_map);
      }
    }
  }
}

PointTracker::Impl::PeakChoice PointTracker::Impl::choose_peak(const MotionState& pred, const cv::Rect& win,
                                                               bool reacquire, int first_search) {
  const int h = half();
  constexpr double kRival = 0.1;  // NCC scatter between frames of one object is ~0.02
  const cv::Point2d pred_in_map(pred.x_px - win.x - h, pred.y_px - win.y - h);
  struct Peak {
    cv::Point at;
    double score, dist;
  };
  std::vector<Peak> peaks;
  double top_score = -1;
  best_map.copyTo(scratch);
  for (int n = 0; n < 4; ++n) {
    double v;
    cv::Point at;
    cv::minMaxLoc(scratch, nullptr, &v, nullptr, &at);
    if (n == 0) top_score = v;
    if (v < opt.min_score || v < top_score - kRival) break;
    peaks.push_back({at, v, std::hypot(at.x - pred_in_map.x, at.y - pred_in_map.y)});
    cv::circle(scratch, at, h, cv::Scalar(-1), cv::FILLED);
  }
  if (peaks.empty()) return {false, false, {}, top_score};
  std::sort(peaks.begin(), peaks.end(), [](const Peak& a, const Peak& b) { return a.dist < b.dist; });
  if (peaks.size() > 1 && peaks[1].dist < 2 * peaks[0].dist + 2) return {false, true, {}, peaks[0].score};
  if (reacquire && peaks[0].dist > first_search) return {false, false, {}, peaks[0].score};
  return {true, false, peaks[0].at, peaks[0].score};
}

PointTracker::Impl::Refined PointTracker::Impl::refine(const cv::Mat& gray, cv::Point origin, const cv::Rect& win,
                                                       cv::Point at, const AngleSearch& as, cv::Point2d dv) {
  const int p = opt.patch_px, h = half();
  const std::vector<double>& angles = as.angles;
  std::size_t kb = 0;
  for (std::size_t i = 1; i < angles.size(); ++i) {
    if (results[i].at<float>(at) > results[kb].at<float>(at)) kb = i;
  }
  double angle = angles[kb];
  const cv::Point2d off = subpixel_peak(results[kb], at);
  cv::Point2d centre(win.x + at.x + off.x + h, win.y + at.y + off.y + h);
  const cv::Point mid(2, 2);
  auto peak_value = [&](double a, cv::Point2d* shift) {
    normed_correlation(local, make_template(a), small_result);
    cv::Point loc;
    cv::minMaxLoc(small_result, nullptr, nullptr, nullptr, &loc);
    double v;
    const cv::Point2d sub = subpixel_peak(small_result, loc, &v);
    if (shift) *shift = cv::Point2d(loc - mid) + sub;
    return v;
  };
  double score = 0;
  double hstep = as.search ? 0.5 * as.spacing : 0;
  for (int pass = 0; pass < 2; ++pass, hstep /= 2) {
    // (The float centre less the integer origin, exactly: the same bilinear weights as in the whole image.)
    cv::getRectSubPix(gray, cv::Size(p + 4, p + 4), cv::Point2f(centre) - cv::Point2f(origin), local, CV_32F);
    if (hstep > 0) {
      const double f0 = peak_value(angle, nullptr);
      const double fm = peak_value(angle - hstep, nullptr), fp = peak_value(angle + hstep, nullptr);
      angle += hstep * parabola_vertex(fm, f0, fp);
    }
    const double lo = std::clamp(shutter - 0.25, 0.0, 0.5), xs[3] = {lo, lo + 0.25, lo + 0.5};
    const double dv_len = std::hypot(dv.x, dv.y);
    if (pass == 0 && dv_len >= 3 && xs[2] * dv_len <= max_blur()) {
      // Exposure fraction: parabola through the peak values at shutter -+ 0.25 (in [0, 1]),
      // kept from frame to frame (it is the camera's); not where the smear would be capped.
      double f[3];
      for (int i = 0; i < 3; ++i) {
        set_blur(xs[i] * dv);
        f[i] = peak_value(angle, nullptr);
      }
      shutter = std::clamp(xs[1] + 0.25 * best_vertex(f[0], f[1], f[2]), 0.0, 1.0);
      set_blur(shutter * dv);
    }
    cv::Point2d shift;
    score = peak_value(angle, &shift);
    centre += shift;
  }
  return {centre, angle, score};
}

bool PointTracker::Impl::score_accepted(double score) {
  if (score < opt.min_score) return false;
  // The first match has nothing to be compared with and the widest window: it must look
  // like the start (a small ball on a textured background scored 0.84 on the background it
  // left, which then held the track).
  if (model.size() == 1 && score < kFirstMatchScore) return false;
  // A sudden drop of the score below what this object scored lately means the view changed
  // (a hand partly over it, another object in the gate): lost rather than a biased position.
  if (recent_scores.size() >= 3) {
    const double typical = upper_median(std::vector<double>(recent_scores.begin(), recent_scores.end()));
    if (score < typical - kMaxScoreDrop) return false;
  }
  recent_scores.push_back(score);
  if (recent_scores.size() > 5) recent_scores.pop_front();
  return true;
}

void PointTracker::Impl::accept(Observation& o, const MotionState& pred, bool reacquire) {
  if (reacquire) {
    // Found again: the motion model starts afresh from here (its extrapolation across the
    // gap says nothing of the motion now), as after start().
    o.refound = true;
    gave_up = false;
    model.reset();
    innovation_px.clear();
    innovation_rad.clear();
    restarted = true;
  } else if (model.size() >= 2) {  // the first prediction (no velocity yet) says nothing of the model
    // Across a gap of g frames the error is scaled back to one frame's by (g + 1)^2, the
    // growth assumed for the gate above.
    const double k = 1.0 / ((gap + 1) * (gap + 1));
    innovation_px.push_back(k * std::hypot(o.x_px - pred.x_px, o.y_px - pred.y_px));
    innovation_rad.push_back(k * std::abs(o.angle_rad - pred.angle_rad));
  }
  while (innovation_px.size() > 3) innovation_px.pop_front();
  while (innovation_rad.size() > 3) innovation_rad.pop_front();
  gap = 0;
  model.add(o.frame, o.x_px, o.y_px, o.angle_rad);
  if (!have_v0 && !restarted && model.size() == 3) {
    // The start's velocity from the parabola through the first three positions.
    const MotionState at_start = model.predict(start_frame);
    v0 = cv::Point2d(at_start.vx_px, at_start.vy_px);
    have_v0 = true;
  }
}

Observation PointTracker::Impl::update(const Frame& frame) {
  const Observation o = follow(frame);
  scene.remember(frame, o.lost ? std::nullopt : std::optional<cv::Point2d>(cv::Point2d(o.x_px, o.y_px)));
  return o;
}

Observation PointTracker::Impl::follow(const Frame& frame) {
  if (frame_size(frame) != image_size || (frame.bgr.empty() && frame.gray.type() != CV_8UC1)) {
    throw InputError(name, "frame " + std::to_string(frame.index) + " has no grey image of the " +
                               "start frame's size");
  }
  if (frame.index <= last_frame) {
    throw InputError(name, "frame " + std::to_string(frame.index) + " does not follow frame " +
                               std::to_string(last_frame));
  }
  last_frame = frame.index;
  const MotionState pred = model.predict(frame.index);
  // Given up (more than max_gap_frames lost in a row): every frame is searched again, as
  // after a start, around the motion model's prediction (docs/theory.md#point-tracking).
  const bool reacquire = gave_up;

  // Motion blur: the template already carries the start's smear (shutter * v0, turned with
  // the pattern); the frame's smear is shutter * v, so the template is smeared further by
  // shutter * (v - R(theta) v0) (docs/theory.md#point-tracking). Not after a lost frame: v is
  // then extrapolated across the gap and often wrong (a bounce inside it reverses the fall),
  // and a pattern smeared along a wrong velocity is a streak that matches edges: a nearly sharp
  // sticker after a bounce was missed for the ball's edge, 21 px off, scoring 0.93.
  const cv::Point2d dv = gap > 0 ? cv::Point2d(0, 0) : blur_change(pred);
  set_blur(shutter * dv);

  // Search half-width (also the gate a match must fall in): three times the largest of the
  // last prediction errors plus a margin; wide on the first step (no velocity known yet: a
  // quarter of the image's smaller side, since a toss filmed at 15 fps moves 70 px a frame).
  // While lost, the extrapolation error grows with the horizon like the squared number of
  // frames bridged times the one-frame error (a polynomial model's error grows at least
  // that fast), so the gate widens from the recent prediction quality, not from the speed:
  // a ballistic object predicted to 0.1 px keeps a tight gate that a look-alike resting a
  // few radii away cannot enter (docs/theory.md#point-tracking).
  const int p = opt.patch_px, h = half();
  const SearchReach reach = search_reach(pred, reacquire);
  const int si = reach.half_width;

  // Angles: around the predicted one, within three times the recent angle error (all of
  // max_turn_deg at the start or after a loss), in steps that move the patch's corner by at
  // most ~1.5 px. When that range is within half a step, the predicted angle alone is
  // correlated and the refinement below (which reaches 0.75 step) finds the angle.
  const AngleSearch as = angle_search(pred);

  // Window in the image around the prediction (clipped); too small: the point left the view.
  const int cx = static_cast<int>(std::lround(pred.x_px)), cy = static_cast<int>(std::lround(pred.y_px));
  const cv::Rect want(cx - si - h, cy - si - h, 2 * (si + h) + 1, 2 * (si + h) + 1);
  const cv::Rect win = want & cv::Rect(cv::Point(), image_size);
  if (win.width < p + 2 || win.height < p + 2) return lost_observation(frame.index, pred, 0, Loss::view);
  // Only the window's grey image is made, and h + kRefineSlackPx px around it for the refinement.
  const int margin = h + kRefineSlackPx;
  const cv::Rect region =
      (win + cv::Point(-margin, -margin) + cv::Size(2 * margin, 2 * margin)) & cv::Rect(cv::Point(), image_size);
  const cv::Mat gray = gray_region(frame, region, region_gray);
  gray(win - region.tl()).convertTo(window, CV_32F);

  // Correlation maps for every angle and their upper envelope: directly for a narrow
  // window, coarse to fine for a wide one (the first step, a long gap).
  correlate(as.angles, si);

  // Candidate peaks above min_score (non-maximum suppression over a patch radius). Peaks
  // within kRival of the best score are rivals: an object that looks the same. Of several
  // rivals the one nearest the prediction is taken only if every other lies more than twice
  // as far (+2 px): two look-alikes near the prediction leave the point lost, not guessed.
  // Weaker peaks (part of the pattern matching part of the template) never compete.
  const PeakChoice peak = choose_peak(pred, win, reacquire, reach.first_search);
  if (!peak.found) return lost_observation(frame.index, pred, peak.score, peak.rival ? Loss::rival : Loss::none);

  // Refinement (docs/theory.md#point-tracking): the image is resampled (bilinear) on a
  // (patch + 4) px square centred on the current estimate, so the peak sits at the centre
  // of a 5x5 correlation map and every angle is compared at the same, sub-pixel, position
  // (comparing integer-pixel peaks couples the angle to the pixel grid). The angle is the
  // vertex of a parabola through the fitted peak values at the current angle and half a
  // step either side; the position moves to the quadratic peak at that angle. Twice, the
  // second time with half the angle step.
  const Refined r = refine(gray, region.tl(), win, peak.at, as, dv);
  Observation o;
  o.frame = frame.index;
  o.x_px = r.centre.x;
  o.y_px = r.centre.y;
  o.angle_rad = r.angle;
  o.score = std::clamp(r.score, 0.0, 1.0);
  // A match showing what its place showed when the object was elsewhere is the still background
  // (docs/theory.md#point-tracking, "still texture"): lost, not a point on the wall.
  if (r.score >= opt.min_score && still(gray, region.tl(), r.centre)) {
    return lost_observation(frame.index, pred, r.score, Loss::still);
  }
  if (!score_accepted(r.score)) {
    return lost_observation(frame.index, pred, r.score, model.size() == 1 ? Loss::first : Loss::score);
  }
  accept(o, pred, reacquire);
  return o;
}

}  // namespace tribolab::video
