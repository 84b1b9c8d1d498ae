// Offline point tracking: candidates per frame, background model, best path by dynamic
// programming, min-marginal rival check (docs/theory.md#tracking-on-real-film).
#include "video/path_tracker.hpp"

#include "numerics/error.hpp"
#include "video/correlation.hpp"
#include "video/correlation_peak.hpp"
#include "video/path_search.hpp"
#include "video/scene_memory.hpp"
#include "numerics/statistics.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>

namespace tribolab::video {
namespace {

using detail::BestPath;
using detail::Candidate;
using detail::PathForeground;
using detail::PathSearch;
using detail::StepCandidates;
using detail::kInf;
using detail::kRivalMargin;

// Candidates kept per frame (correlation peaks, best first) and the least correlation a
// candidate may have (below it nothing in the window resembles the object).
constexpr int kCandidates = 8;
// A start patch whose grey levels vary less than this (standard deviation) is flat.
constexpr double kFlatSd = 3;
// The least half-side of an automatic template, px (a 15 px square): a smaller one (9-11 px
// around a 2-4 px blob) holds too few pixels to be told from texture once the object blurs.
// On the 36-throw grid a blurred spinning sticker's 9-11 px template fell to 0.8 while still
// texture correlated 0.9; with this floor 305 of 2839 sticker frames are lost instead of 435.
// Real film bounds it: a 17 px floor loses 2 of the 6 px rolling ball's 18 frames (its rail
// fills the square), 15 px none (docs/benchmarks.md, "A template's least size").
constexpr double kMinHalfSidePx = 7;
// Peaks taken from each anchor's window (the candidates of a step come from up to five).
constexpr int kPerWindow = 3;
// Candidates kept per frame for each look of a mark searched there (add_look).
constexpr int kCandidatesPerLook = 4;
// A best candidate correlating this well is a confident sighting (the lead anchor).
constexpr double kConfident = 0.9;
// A template that turns (PathTracker::Impl::update, docs/theory.md#tracking-on-real-film): where
// no look's best peak in a step correlates kConfident, each look is also correlated turned by
// +-kTurnStep and +-2 kTurnStep degrees about its point from its heading, around the step's
// candidates. A turn becomes the look's heading (searched in full from the next step on) where
// it matches a candidate at least kTurnGain better than the look did and at least min_score.
constexpr int kTurnStep = 15;
constexpr double kTurnGain = 0.05;
// A look that correlates less than this with itself turned by 2 kTurnStep degrees changes with
// a turn (a checker sticker: ~0.2; a plain disc: ~1): a lost track names the frame tracker.
constexpr double kTurnSensitive = 0.8;
constexpr double kCandidateFloor = 0.3;
// Coarse to fine (PathTracker::Impl::correlate_union, coarse_peaks): with a template of at
// least kCoarseMinPatch px, a union of windows larger than kCoarseMinArea px², or any union in
// an image of kCoarseImageArea px² or more (HD: its objects keep their detail at half
// resolution; in a smaller image halving lost frames: docs/benchmarks.md#tracking-at-1080p), is
// correlated at half resolution first (floor kCoarseFloor there: halving blurs a peak), each
// peak refined within kRefinePx at each finer level down to full resolution, where its ridge is
// measured (full_ridge_px). A template of kQuarterMinPatch px or more is searched at quarter
// resolution, where it still has 13 px or more (a 7 px quarter of the 1080p benchmark's 25 px
// sticker lost 8 more frames).
constexpr int kCoarseMinArea = 400000;
constexpr int kCoarseImageArea = 1280 * 720;
constexpr int kCoarseMinPatch = 15;
constexpr int kQuarterMinPatch = 49;
constexpr double kCoarseFloor = 0.2;
// Coarse peaks refined per window, of which the best kPerWindow are kept (6 before: the same
// tracks of the four real projects, with and without the human's marks, and of the grid, in
// 92 ms instead of 99 per 1080p clip; docs/benchmarks.md#tracking-at-1080p).
constexpr int kCoarsePeaks = kPerWindow + 1;
constexpr int kRefinePx = 3;
// Older anchors' windows from the motion (PathTracker::Impl::seen_speed): while the object is
// seen confidently (two confident sightings at most kWindowSpeedSteps steps apart, the later
// within max_gap_frames + 1 steps), an anchor `age` steps back reaches `reach` for the first
// step and kWindowSpeeds times the speed between those sightings for each further one (a
// reversal at a bounce keeps the speed), never more than `reach` per step.
constexpr int kWindowSpeedSteps = 2;
constexpr double kWindowSpeeds = 2;
// The automatic reach is a quarter of the image's smaller side per this much real time, s:
// per frame at 30 fps (PathTrackerOptions::step_s).
constexpr double kReachPeriodS = 1.0 / 30;
// Cost of a candidate: (1 - correlation) / kNccScale + kFgWeight * (1 - fg / (fg + kFgHalf)),
// fg the mean absolute difference from the background over the object, grey levels. A
// frame without the object costs kMissCost (video/path_search.hpp): a candidate correlating 0.7 with the object and
// as different from the background as the object's typical 8+ grey levels costs 3 + 1.
constexpr double kNccScale = 0.1;
constexpr double kFgWeight = 2;
constexpr double kFgHalf = 8;
// A run of consecutive path points differing from the background by less than this share of
// the path's median difference (medians over the run and over the path) is background (when that median is well above noise, 2 kFgHalf).
constexpr double kFgShare = 0.15;
// A candidate's unary cost (above) from its correlation and its difference from the background.
double unary_cost(double ncc, double fg) { return (1 - ncc) / kNccScale + kFgWeight * (1 - fg / (fg + kFgHalf)); }
// The background seen so far is trusted once it holds this many samples: their median leaves
// out an object that covered a pixel in fewer than half of them. Before, where the object was
// at the start reads as moving (its place in the first frames is in the samples).
constexpr std::size_t kTrustedSamples = 8;
// A user's click scatters about the object's point by this, px per 640 px of image width (at
// least 1 px): half the correction distance (4 px per 640), so that a click a user would not
// correct lies within 2 sigma. The acceleration through a mark allows for it (PathSearch::accel),
// so that a mark a few px off does not make its neighbours cheaper to drop than to keep
// (jmoljana's human marks, on a 2.8 px grid, scatter 3-7 px: with every 5th given, 44 of the
// 120 frames between were lost, the frames next to the marks first).
constexpr double kClickPx = 2;
// Ridge of a correlation peak (peak_ridge_px): the line through the peak along which the
// correlation stays within kRidgeDrop of the peak, walked at most kRidgeMaxSteps map pixels
// each way.
constexpr double kRidgeDrop = 0.05;
constexpr int kRidgeMaxSteps = 64;
// The longest ridge a reported point may have, px per 640 px of image width (and at least
// this): the correction distance, 4 px per 640 px.
constexpr double kRidgeMinPx = 4;
// A run of reported path points shorter than this between lost frames is unconfirmed (finish()).
constexpr int kMinRun = 3;

// update()'s steps and their results.
// A place the object can be: a recent candidate (or where the confident sightings lead) and
// the steps since it, px.
struct Anchor {
  cv::Point2d at;
  int age;
};

}  // namespace

// Named, not anonymous: PathTracker::Impl, a member of a class of the header, holds looks.
namespace detail {

// What the object looks like: a template (CV_32F) and its coarse copies (`coarse[l - 1]` at
// 1/2^l resolution, made when first needed), taken at the start or at a user's mark (`frame`).
struct Look {
  int frame = 0;
  cv::Point2d at;  // where it was taken, px
  cv::Mat templ;
  std::vector<cv::Mat> coarse;
  cv::Mat source;           // CV_32F square about `at`, wide enough for the template turned any way
  int deg = 0;              // a turned copy's turn from the look, degrees
  int heading = 0;          // the turn the object was last seen at (kTurnGain), degrees
  int heading_step = -1;    // the step it was seen at (-1: not yet; the start's look: 0)
  // A spinning object: the last turn chosen (a heading that changed), its step (-1: none yet;
  // the start's look: 0), the way it turned then (-1, 0, 1), and the turn per step since the
  // one before, degrees.
  int changed_to = 0, changed_step = -1, turn_sign = 0;
  double turn_rate = 0;
  // The turn expected at step n: the heading carried on at the turn rate, in whole `step`s.
  int expected(int n, int step) const {
    if (heading_step < 0) return heading;
    return heading + step * static_cast<int>(std::lround(turn_rate * (n - heading_step) / step));
  }
  // The object seen turned by `deg` at step n: the expected turn confirmed, or (`chosen`) a
  // turn chosen among others, which gives the rate since the turn chosen before.
  void seen_at(int deg, int n, bool chosen) {
    if (chosen) {
      if (changed_step >= 0 && n > changed_step) {
        const int turn = ((deg - changed_to) % 360 + 540) % 360 - 180;  // (-180, 180)
        // A single kTurnStep is within what a look matches best by chance a little turned: it
        // gives a rate only after a turn the same way (a rate from it alone would spin the
        // heading of a ball that hardly turns).
        const int sign = (turn > 0) - (turn < 0);
        const bool spins = std::abs(turn) >= 2 * kTurnStep || (sign != 0 && sign == turn_sign);
        turn_rate = spins ? std::clamp(static_cast<double>(turn) / (n - changed_step), -90.0, 90.0) : 0;
        turn_sign = sign;
      }
      changed_to = deg;
      changed_step = n;
    }
    heading = deg;
    heading_step = n;
  }
  std::vector<Look> turns;  // the turned copies made so far (turned())
};

// The side of a look's source square for a template of side p: its diagonal and a pixel.
int turn_source_side(int p) { return 2 * static_cast<int>(std::ceil((p / 2) * std::sqrt(2.0))) + 3; }

// `look` turned by `deg` degrees about its point (itself for 0; made once, kept in look.turns);
// nullptr when the look has no source or the turned template is flat.
Look* turned(Look& look, int deg, int p) {
  deg = ((deg % 360) + 540) % 360 - 180;  // (-180, 180]
  if (deg == -180) deg = 180;
  if (deg == 0) return &look;
  if (look.source.empty()) return nullptr;
  for (Look& t : look.turns) {
    if (t.deg == deg) return t.templ.empty() ? nullptr : &t;
  }
  Look t;
  t.frame = look.frame;
  t.at = look.at;
  t.deg = deg;
  const float c = static_cast<float>(look.source.cols - 1) / 2;
  cv::Mat rotated;
  cv::warpAffine(look.source, rotated, cv::getRotationMatrix2D(cv::Point2f(c, c), deg, 1), look.source.size(),
                 cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  cv::getRectSubPix(rotated, cv::Size(p, p), cv::Point2f(c, c), t.templ);
  cv::Scalar mean, sd;
  cv::meanStdDev(t.templ, mean, sd);
  if (sd[0] < kFlatSd) t.templ.release();  // flat: nothing to match
  look.turns.push_back(std::move(t));
  return look.turns.back().templ.empty() ? nullptr : &look.turns.back();
}

}  // namespace detail

namespace {

using detail::Look;
using detail::turn_source_side;
using detail::turned;

// The anchors' search windows (each within reach of its anchor, clipped to the image, with its
// anchor's age) in groups, px: windows near each other are correlated over their union, and
// windows far apart each over their own (a candidate hundreds of px from the object would
// otherwise make the union span the empty picture between them).
struct SearchWindows {
  std::vector<cv::Rect> wins;
  std::vector<int> age;       // each window's anchor's age, steps
  std::vector<int> group_of;  // each window's group
  std::vector<cv::Rect> uni;  // each group's union
  // The windows of anchors at most `max_age` steps back, in the same groups (each group's union
  // that of its windows kept, inside the group's; empty where none is kept).
  SearchWindows newest(int max_age) const;
};

// The grey images of a step's groups of windows: each group's union with a 2 px ring (a
// sub-pixel peak rounds to at most a pixel outside its window), made only there.
struct GroupImages {
  std::vector<cv::Rect> region;
  std::vector<cv::Mat> gray;
  // The Gaussian pyramids (CV_32F, half_resolution) made, with the union each is of: every look
  // searched in a step reads the one of its union.
  mutable std::vector<std::pair<cv::Rect, std::vector<cv::Mat>>> pyr;
  // Group g's pyramid of `uni` (inside its region) down to `level` (made once per union).
  std::vector<cv::Mat> pyramid(int g, const cv::Rect& uni, int level) const;
  // The group whose region holds the point (the first; -1: none).
  int holding(cv::Point at) const {
    for (std::size_t g = 0; g < region.size(); ++g) {
      if (region[g].contains(at)) return static_cast<int>(g);
    }
    return -1;
  }
};

// The correlation over the windows' union: at full resolution (`all`), or at the coarse level
// `level` (`coarse_res`, 1/2^level resolution) with the union's grey levels at every level
// (`pyramid[0]` full resolution) and the look's templates kept for the refinement.
struct UnionCorrelation {
  bool coarse = false;
  int level = 0;
  std::vector<cv::Mat> pyramid, templ;
  cv::Mat all, coarse_res;
  // The full-resolution refinements made, by their placements (x, y, width, height in the
  // union's result): the windows overlap, and a coarse peak seen from several is refined once.
  // Each holds the best placement (in the union's result), its value, fitted value and offset.
  struct Refined {
    cv::Point at;
    double v, fitted;
    double ridge = -1;  // at full resolution (full_ridge_px; -1: not measured yet)
    cv::Mat map;        // the correlation around it (placements from `map_at`), for the ridge
    cv::Point map_at;
    cv::Point2d off;
  };
  std::map<std::array<int, 4>, Refined> refined;
};

// A correlation peak in one window.
struct Peak {
  cv::Point at;     // template top-left in the window's result, px
  double v;         // correlation there
  cv::Point2d off;  // sub-pixel offset
  double fitted;    // the peak fit's value
  double ridge = 0; // peak_ridge_px
};

// The candidates found in a step's windows, and the index in `c` of each window's best peak.
struct FoundPeaks {
  std::vector<Candidate> c;
  std::vector<std::size_t> window_best;
};

// The best kPerWindow peaks of a window's full-resolution correlation `res`.
std::vector<Peak> fine_peaks(const cv::Mat& res, int suppress);

// The best correlation among the windows' peaks (-1: none).
double best_peak(const std::vector<std::vector<Peak>>& peaks) {
  double best = -1;
  for (const std::vector<Peak>& in_window : peaks) {
    for (const Peak& pk : in_window) best = std::max(best, pk.v);
  }
  return best;
}

// Scale-normalised Laplacian-of-Gaussian magnitude sigma^2 |LoG| at `p`, maximised over
// scale (Lindeberg's automatic scale selection): the blob radius is sigma * sqrt(2).
double blob_radius(const cv::Mat& gray, cv::Point2d p) {
  const int side = std::min({gray.cols, gray.rows, 257});
  cv::Mat roi;
  cv::getRectSubPix(gray, cv::Size(side, side), cv::Point2f(p), roi, CV_32F);
  const int c = side / 2;
  double best = -1, radius = 3;
  for (double sigma = 1.0; sigma * 6 < side && sigma <= 24; sigma *= std::sqrt(2.0)) {
    cv::Mat g, lap;
    cv::GaussianBlur(roi, g, cv::Size(0, 0), sigma);
    cv::Laplacian(g, lap, CV_32F, 3);
    const double v = sigma * sigma * std::abs(lap.at<float>(c, c));
    if (v > best) {
      best = v;
      radius = sigma * std::sqrt(2.0);
    }
  }
  return radius;
}

// Half-length, px, of the longest straight line through a correlation peak at `at` along
// which the correlation stays within kRidgeDrop of the peak's value (over four axes, each
// walked both ways, at most kRidgeMaxSteps steps; `high(q)`: the correlation at q is inside the
// map and that high). A sharp match drops within a pixel or two every way; a motion-blurred
// streak or a plain edge matches all along itself: its position along the ridge is unknown.
template <class High>
double ridge_px(cv::Point at, const High& high) {
  static const cv::Point kAxes[4] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  double longest = 0;
  for (const cv::Point& d : kAxes) {
    int total = 0;
    for (int sign = -1; sign <= 1; sign += 2) {
      int s = 1;
      while (s <= kRidgeMaxSteps && high(at + sign * s * d)) ++s;
      total += s - 1;
    }
    longest = std::max(longest, 0.5 * total * std::hypot(d.x, d.y));
  }
  return longest;
}

// The ridge through the peak `at` (value `v`) of the correlation map `res`.
double peak_ridge_px(const cv::Mat& res, cv::Point at, double v) {
  const float floor = static_cast<float>(v - kRidgeDrop);
  return ridge_px(at, [&](cv::Point q) {
    return q.x >= 0 && q.y >= 0 && q.x < res.cols && q.y < res.rows && res.at<float>(q) >= floor;
  });
}

// The ridge through the placement `at` (correlating `v`) of the template `templ` in `img`, at
// full resolution: read from `map` (the correlation at the placements `map_at` + its pixels: the
// refinement's) where it holds the placement, else correlated there alone, along the four axes
// only. A coarse peak's ridge measured on the half-resolution map is blurred by the pyramid: a
// streak's ridge came out shorter there than at full resolution, and was reported.
double full_ridge_px(const cv::Mat& img, const cv::Mat& templ, const cv::Mat& map, cv::Point map_at, cv::Point at,
                     double v) {
  const float floor = static_cast<float>(v - kRidgeDrop);
  const cv::Rect in_map(map_at, map.size());
  cv::Mat one;
  return ridge_px(at, [&](cv::Point q) {
    if (in_map.contains(q)) return map.at<float>(q - map_at) >= floor;
    if (q.x < 0 || q.y < 0 || q.x > img.cols - templ.cols || q.y > img.rows - templ.rows) return false;
    normed_correlation_sums(img(cv::Rect(q, templ.size())), templ, one);
    return one.at<float>(0, 0) >= floor;
  });
}

}  // namespace

std::string PathTrackerOptions::validate() const {
  if (patch_px != 0 && (patch_px < 7 || patch_px % 2 == 0)) {
    return "patch_px must be odd and >= 7 (or 0: automatic), got " + std::to_string(patch_px);
  }
  if (search_px < 0) return "search_px must be >= 0, got " + std::to_string(search_px);
  if (!(min_score > 0 && min_score < 1)) return "min_score must lie in (0, 1), got " + std::to_string(min_score);
  if (max_gap_frames < 0) return "max_gap_frames must be >= 0, got " + std::to_string(max_gap_frames);
  if (!(step_s >= 0 && std::isfinite(step_s))) return "step_s must be >= 0 (0: unknown), got " + std::to_string(step_s);
  return {};
}

struct PathTracker::Impl {
  PathTrackerOptions opt;
  std::string name;
  cv::Size size;
  int p = 0, h = 0;        // template side and half side, px
  double radius = 0;       // object radius from scale selection, px
  double reach = 0;        // largest motion per frame, px
  Look start_look;         // the object at the click
  std::vector<Look> looks;  // the object at the user's marks (add_look), by frame
  std::vector<cv::Mat> region_bufs;  // the grey images of a step's groups of windows (reused from step to step)
  // The candidates found in every step, steps[0] the start (the click): they do not depend on
  // the marks, so that finish() can be run again with other marks without a frame.
  std::vector<StepCandidates> steps;
  std::map<int, ManualMark> marks;    // by frame index
  bool fg_done = false;               // the candidates' fg and cost are computed (at the first finish())
  // Background samples: grey frames spread over the clip, at most 16, at least 1/30 s apart
  // (start()); the background is their per-pixel median.
  SceneMemory background;
  cv::Point2d lead[2];            // the last two confident sightings, px
  int lead_frames[2] = {-1, -1};  // their step indices (-1: none yet)
  // Loss causes counted by finish().
  int lost_none = 0, lost_rival = 0, lost_score = 0, lost_background = 0, lost_ridge = 0;
  // Of lost_none, the frames after the path's last point (the track ended) and that point's frame.
  int lost_end = 0, end_frame = -1;
  int lost_alone = 0;      // frames of a short run between lost frames, unconfirmed (finish())
  int lost_unlinked = 0;  // frames of a run reached only through doubtful points (finish())
  double ridge_max_px = 0;  // the longest ridge a reported point may have (finish())
  int turned_deg = 0, turned_frame = -1;  // the largest turn a look was seen at, and where (update())
  double turn_ncc = 1;  // the start's look against itself turned by 2 kTurnStep degrees (start())

  // A candidate at (x, y) px; `gray` is the grey image of a rectangle at `origin` holding its
  // patch (or, where the patch leaves it, sharing that border with the image).
  Candidate make_candidate(const cv::Mat& gray, cv::Point origin, double x, double y, double ncc) const {
    Candidate c;
    c.x = x;
    c.y = y;
    c.ncc = ncc;
    c.at = cv::Point(static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)));
    cv::getRectSubPix(gray, cv::Size(p, p), cv::Point2f(c.at - origin), c.patch);
    return c;
  }

  // Mean absolute difference of the object's central square from the background median there
  // (every `stride`-th pixel of it each way: 1 for the unary cost; a quick look with more).
  // With `median` and `known`, the samples' per-pixel median is kept where `known` is set and
  // filled as needed: a clip's candidates overlap, so each pixel's median is taken once (for
  // samples that no longer change: finish()).
  double foreground(const Candidate& c, int stride = 1, cv::Mat* median = nullptr, cv::Mat* known = nullptr) const {
    const int r = std::clamp(static_cast<int>(std::ceil(radius)), 1, h);
    std::vector<unsigned char> v(background.size());
    double sum = 0;
    int n = 0;
    for (int y = -r; y <= r; y += stride) {
      // A patch's pixel outside the image is its nearest inside (getRectSubPix replicates the
      // border), in the candidate's patch and the samples alike.
      const int iy = std::clamp(c.at.y + y, 0, size.height - 1);
      for (int x = -r; x <= r; x += stride) {
        const int ix = std::clamp(c.at.x + x, 0, size.width - 1);
        unsigned char bg = 0;
        if (median != nullptr && known->at<unsigned char>(iy, ix) != 0) {
          bg = median->at<unsigned char>(iy, ix);
        } else {
          for (std::size_t k = 0; k < background.size(); ++k) v[k] = background.gray(k).at<unsigned char>(iy, ix);
          std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
          bg = v[v.size() / 2];
          if (median != nullptr) {
            median->at<unsigned char>(iy, ix) = bg;
            known->at<unsigned char>(iy, ix) = 1;
          }
        }
        sum += std::abs(c.patch.at<unsigned char>(h + y, h + x) - bg);
        ++n;
      }
    }
    return sum / n;
  }

  void update(const Frame& f);
  // The start's look correlates kConfident or more within max(2, radius) px of `at` in `gray`.
  bool start_matches_near(const cv::Mat& gray, cv::Point2d at) const {
    const int r = static_cast<int>(std::ceil(std::max(2.0, radius)));
    const cv::Rect near = cv::Rect(static_cast<int>(std::lround(at.x)) - r - h, static_cast<int>(std::lround(at.y)) - r - h,
                                   2 * r + p, 2 * r + p) &
                          cv::Rect(0, 0, gray.cols, gray.rows);
    if (near.width < p || near.height < p) return false;
    cv::Mat w32, res;
    gray(near).convertTo(w32, CV_32F);
    normed_correlation(w32, start_look.templ, res);
    double best = -1;
    cv::minMaxLoc(res, nullptr, &best);
    return best >= kConfident;
  }
  // Where the object can be in the step of frame `index`: the anchors of its search windows.
  std::vector<Anchor> find_anchors(int index) const;
  // The object's speed between its last two confident sightings, px per step, while it
  // bounds the older anchors' windows of step n (kWindowSpeeds); negative when it does not.
  double seen_speed(int n) const;
  // The looks searched in the frame `index`: the start's, then those of the nearest marks
  // before and after it.
  std::vector<Look*> looks_for(int index);
  // The candidates of one look in the windows `w`; `img` holds the grey image of each group's
  // union and a pixel around it. Returns the best peak's correlation (-1: none).
  double find_peaks(const SearchWindows& w, const GroupImages& img, Look& look, bool other_look, int suppress,
                    FoundPeaks& found) const;
  // The peaks of one look in each of the windows `w` (find_peaks without adding them).
  std::vector<std::vector<Peak>> window_peaks(const SearchWindows& w, const GroupImages& img, Look& look,
                                              int suppress) const;
  // The correlation of `templ` around candidate `c` (within kRefinePx of it, in the grey image
  // of the group holding it). With `take`, where it is better than c's, c moves to its peak
  // and takes it. Returns that correlation (-1: none).
  double rescore(const GroupImages& img, const cv::Mat& templ, Candidate& c, bool take) const;
  // The anchors' windows in the image, in groups.
  SearchWindows search_windows(const std::vector<Anchor>& anchors) const;
  // A look's correlation over `uni`, the union of some of group g's windows (coarse for a
  // large union; makes the look's coarse templates).
  UnionCorrelation correlate_union(const GroupImages& img, int g, const cv::Rect& uni, Look& look) const;
  // The best kPerWindow peaks of one window (`rrect` in the union's result) found coarse to fine.
  std::vector<Peak> coarse_peaks(UnionCorrelation& u, const cv::Rect& rrect, int suppress) const;
  // Adds a window's peaks as candidates, a peak already found from another window once (from
  // another look: the better correlation kept). `gray` is the grey image of a rectangle at
  // `origin` holding the window and a pixel around it.
  void add_window_peaks(const std::vector<Peak>& peaks, const cv::Rect& win, const cv::Mat& gray, cv::Point origin,
                        int suppress, bool other_look, FoundPeaks& found) const;
  // At most `n_keep` of the found (every window's best first); updates the lead sightings (step n).
  std::vector<Candidate> keep_best(FoundPeaks& found, int n, int n_keep);
  std::vector<Observation> finish();
  // Each candidate's fg and unary cost (once: the background samples are complete at the first finish()).
  void compute_unary_costs();
  // The steps with each marked step's candidates replaced by its mark.
  std::vector<StepCandidates> steps_with_marks() const;
  // Per step after the start: the best path's point, or lost and why (counts the loss causes).
  std::vector<Observation> observe_path(const PathSearch& search, const BestPath& best, const PathForeground& fg);
  // Reports as lost a short run of points between lost frames (lost_alone).
  void drop_unconfirmed_runs(std::vector<Observation>& obs);
  // Reports as lost a run reached only across more than G steps without a reported point (lost_unlinked).
  void drop_unlinked_runs(std::vector<Observation>& obs, int G);
  std::string main_loss_hint() const;  // the likeliest cause but a streak (loss_hint)
  std::string reach_said() const;      // the reach per frame, for the hints
};

std::string PathTracker::Impl::reach_said() const {
  // The reach as the user can set it (--search), with where the automatic one came from.
  std::string said = std::to_string(static_cast<long>(std::lround(reach))) + " px per frame (" + field("search");
  if (opt.search_px == 0 && opt.step_s > 0 && opt.step_s < kReachPeriodS) {
    said += "; automatic at " + std::to_string(static_cast<long>(std::lround(1 / opt.step_s))) + " frames per second";
  }
  return said + ")";
}

namespace {
// The remedy for a lost mark on a ball, whose look spins and smears: the ball's own tracker
// (docs/benchmarks.md, "A template's least size, the ellipse's fit bar").
std::string on_a_ball() {
  return "for a mark on a ball, " + field("ellipse") + " follows the ball itself, its centre and its turn";
}
}  // namespace

std::string PathTracker::Impl::main_loss_hint() const {
  const Impl& m = *this;
  if (m.lost_none + m.lost_rival + m.lost_score + m.lost_background == 0) return "";
  if (m.lost_background > std::max({m.lost_none, m.lost_rival, m.lost_score})) {
    return "in " + std::to_string(m.lost_background) +
           " frame(s) the best match did not stand out from the still background (the object hidden or at rest): "
           "a larger " + field("max_gap") + " bridges a hidden object";
  }
  if (m.lost_rival >= std::max(m.lost_none, m.lost_score)) {
    return "a look-alike within reach made " + std::to_string(m.lost_rival) +
           " frame(s) doubtful: start on a more distinctive mark, or a smaller " + field("search");
  }
  if (m.lost_score >= m.lost_none) {
    return "the object matched its first look poorly in " + std::to_string(m.lost_score) +
           " frame(s) (blur, a lossy video, a turning or growing object): a lower " + field("min_score") +
           " (e.g. 0.4) or another " + field("patch") + "; for a mark that turns (on a wheel), " + field("point_tracker") +
           " frame; or " + field("mark") + " the object in one of those frames: the frames around a mark are searched "
           "for its look there";
  }
  if (m.lost_end > m.lost_none - m.lost_end) {
    // The track ended: after its last point nothing within reach that resembles the object's
    // first look continues its motion.
    return "after frame " + std::to_string(m.end_frame) + " (the path's last point) nothing within reach that " +
           "resembled the object's first look continued its motion in the " + std::to_string(m.lost_end) +
           " frame(s) left "
           "(the object left the view or was hidden, moved more than " + reach_said() +
           ", or turned or changed its look): a larger " + field("search") + " or " + field("max_gap") +
           "; for an object that turns, " + field("point_tracker") + " frame (" + on_a_ball() + "); or " + field("mark") +
           " the object in one of those frames: the frames around a mark are searched for its look there";
  }
  return "the object was not found in " + std::to_string(m.lost_none) +
         " frame(s) (hidden, out of view, or moving more than " + reach_said() + "): a larger " +
         field("search") + " or " + field("max_gap");
}

PathTracker::PathTracker(const PathTrackerOptions& options) : impl_(std::make_unique<Impl>()) {
  impl_->opt = options;
}
PathTracker::~PathTracker() = default;
PathTracker::PathTracker(PathTracker&&) noexcept = default;
PathTracker& PathTracker::operator=(PathTracker&&) noexcept = default;
int PathTracker::patch_px() const { return impl_->p; }

Observation PathTracker::start(const Frame& first, double x_px, double y_px, const std::string& name) {
  if (const auto e = impl_->opt.validate(); !e.empty()) throw InputError(name, e);
  Impl& m = *impl_;
  cv::Mat buf;  // the start frame's grey image, whole (scale selection, template, first sample)
  const cv::Mat gray = gray_region(first, cv::Rect(cv::Point(), frame_size(first)), buf);
  if (gray.empty()) throw InputError(name, "frame " + std::to_string(first.index) + " has no image");
  if (!(x_px >= 0 && y_px >= 0 && x_px <= gray.cols - 1 && y_px <= gray.rows - 1)) {
    throw InputError(name, "start point (" + std::to_string(x_px) + ", " + std::to_string(y_px) +
                               ") px lies outside the " + std::to_string(gray.cols) + "x" +
                               std::to_string(gray.rows) + " image");
  }
  m.name = name;
  m.size = gray.size();
  const int small_side = std::min(gray.cols, gray.rows);
  m.radius = blob_radius(gray, {x_px, y_px});
  // The template holds the object and a ring of its surroundings (1.5 radii): enough contrast
  // for a plain object, little background for a small one, and never fewer than 15 px a side.
  int p = m.opt.patch_px;
  if (p == 0) p = 2 * static_cast<int>(std::ceil(std::max(kMinHalfSidePx, 1.5 * m.radius))) + 1;
  p = std::min(p, 2 * (small_side / 8) + 1);
  m.p = std::max(p, 7);
  m.h = m.p / 2;
  // Reach: a quarter of the image's smaller side per 1/30 s of real time, per frame at 30 fps
  // or fewer (Tracker's BallToss, filmed at 15 fps, moves 100 px of 480 in its last frame), at
  // least two templates. A speed, not a per-frame step: at 240 fps an object covers an eighth
  // of what it covers in a frame at 30 fps, and so do the search windows and the path's gate
  // (an unknown time base keeps it per frame).
  const double frame_share = m.opt.step_s > 0 ? std::min(1.0, m.opt.step_s / kReachPeriodS) : 1.0;
  m.reach = m.opt.search_px > 0 ? m.opt.search_px : std::max(2.0 * m.p, small_side / 4.0 * frame_share);
  cv::Mat templ;
  cv::getRectSubPix(gray, cv::Size(m.p, m.p), cv::Point2f(x_px, y_px), templ, CV_32F);
  // Only a flat patch is refused (sensor noise alone: standard deviation ~2 grey levels): a
  // plain object's outline is enough.
  cv::Scalar mean, sd;
  cv::meanStdDev(templ, mean, sd);
  if (sd[0] < kFlatSd) {
    throw InputError(name, "the " + std::to_string(m.p) + " px patch around (" + std::to_string(x_px) + ", " +
                               std::to_string(y_px) + ") px is flat (standard deviation " + std::to_string(sd[0]) +
                               " grey levels, needs " + std::to_string(static_cast<int>(kFlatSd)) +
                               "): there is nothing to follow; start on the object");
  }
  m.start_look = Look();
  m.start_look.frame = first.index;
  m.start_look.at = cv::Point2d(x_px, y_px);
  m.start_look.templ = templ;
  m.start_look.heading_step = m.start_look.changed_step = 0;  // seen as taken at the start (step 0)
  const int side = turn_source_side(m.p);
  cv::getRectSubPix(gray, cv::Size(side, side), cv::Point2f(x_px, y_px), m.start_look.source, CV_32F);
  m.turn_ncc = 1;
  if (const Look* t = turned(m.start_look, 2 * kTurnStep, m.p)) {
    cv::Mat r;
    normed_correlation(templ, t->templ, r);
    m.turn_ncc = r.at<float>(0, 0);
  }
  m.looks.clear();
  m.steps.clear();
  m.marks.clear();
  m.fg_done = false;
  // At least 1/30 s of real time between samples (SceneMemory::stride_for).
  m.background.reset(SceneMemory::stride_for(m.opt.step_s));
  m.turned_deg = 0;
  m.turned_frame = -1;
  m.lead[1] = cv::Point2d(x_px, y_px);
  m.lead_frames[0] = -1;
  m.lead_frames[1] = 0;
  StepCandidates s;
  s.index = first.index;
  s.c.push_back(m.make_candidate(gray, cv::Point(), x_px, y_px, 1));
  s.c.back().x = x_px;
  s.c.back().y = y_px;
  m.steps.push_back(std::move(s));
  m.background.remember(first, std::nullopt);
  Observation o;
  o.frame = first.index;
  o.x_px = x_px;
  o.y_px = y_px;
  o.score = 1;
  return o;
}

void PathTracker::set_marks(std::vector<ManualMark> marks) {
  Impl& m = *impl_;
  if (m.steps.empty()) throw InputError("path tracker: set_marks() before start()");
  m.marks.clear();
  for (const ManualMark& k : marks) {
    const std::string where = m.name + " mark at frame " + std::to_string(k.frame);
    if (!(k.x_px >= 0 && k.y_px >= 0 && k.x_px <= m.size.width - 1 && k.y_px <= m.size.height - 1)) {
      throw InputError(where, "(" + std::to_string(k.x_px) + ", " + std::to_string(k.y_px) + ") px lies outside the " +
                                  std::to_string(m.size.width) + "x" + std::to_string(m.size.height) + " image");
    }
    if (k.frame <= m.steps.front().index) {
      throw InputError(where, "the track starts at frame " + std::to_string(m.steps.front().index) +
                                  ": a mark must come after its start (move the start instead)");
    }
    if (!m.marks.emplace(k.frame, k).second) throw InputError(where, "two marks on one frame");
  }
  // A look belongs to its mark: gone with it, or when it moved.
  m.looks.erase(std::remove_if(m.looks.begin(), m.looks.end(),
                               [&](const Look& l) {
                                 const auto mk = m.marks.find(l.frame);
                                 return mk == m.marks.end() || mk->second.x_px != l.at.x || mk->second.y_px != l.at.y;
                               }),
                m.looks.end());
}

cv::Rect PathTracker::look_crop(cv::Size image, double x_px, double y_px) {
  // The template side is at most 2 (small side / 8) + 1 (start()); the look's source square for
  // turning it (turn_source_side) is its diagonal and a pixel more.
  const int r = turn_source_side(2 * (std::min(image.width, image.height) / 8) + 1) / 2 + 2;
  const int x = static_cast<int>(std::lround(x_px)), y = static_cast<int>(std::lround(y_px));
  return cv::Rect(x - r, y - r, 2 * r + 1, 2 * r + 1) & cv::Rect(0, 0, image.width, image.height);
}

void PathTracker::add_look(int frame, const cv::Mat& gray, double x_px, double y_px) {
  Impl& m = *impl_;
  if (m.steps.empty()) throw InputError("path tracker: add_look() before start()");
  const std::string where = m.name + " mark at frame " + std::to_string(frame);
  if (m.marks.count(frame) == 0) throw InputError(where, "a look is taken at a mark (none on this frame)");
  if (m.steps.back().index >= frame) throw InputError(where, "its look comes after the frame was tracked");
  if (gray.type() != CV_8UC1 || !(x_px >= 0 && y_px >= 0 && x_px <= gray.cols - 1 && y_px <= gray.rows - 1)) {
    throw InputError(where, "the look's image does not hold the mark");
  }
  const ManualMark& mk = m.marks.at(frame);
  Look look;
  look.frame = frame;
  look.at = cv::Point2d(mk.x_px, mk.y_px);
  cv::getRectSubPix(gray, cv::Size(m.p, m.p), cv::Point2f(static_cast<float>(x_px), static_cast<float>(y_px)),
                    look.templ, CV_32F);
  cv::Scalar mean, sd;
  cv::meanStdDev(look.templ, mean, sd);
  if (sd[0] < kFlatSd) return;  // nothing to match: the mark still holds its own frame
  // Where the object still looks as at the start (the start's look correlates kConfident or
  // more within the object's radius of the mark), the start's candidates find it: a look
  // centred on the click would add the click's own error (a mark 2.5 px off the object's
  // point) to the frames around it, as rivals of the right candidates.
  if (m.start_matches_near(gray, cv::Point2d(x_px, y_px))) return;
  const int side = turn_source_side(m.p);
  cv::getRectSubPix(gray, cv::Size(side, side), cv::Point2f(static_cast<float>(x_px), static_cast<float>(y_px)),
                    look.source, CV_32F);
  const auto at = std::find_if(m.looks.begin(), m.looks.end(), [&](const Look& l) { return l.frame >= frame; });
  if (at != m.looks.end() && at->frame == frame) {
    *at = std::move(look);
  } else {
    m.looks.insert(at, std::move(look));
  }
}

void PathTracker::update(const Frame& frame) {
  if (!impl_ || impl_->steps.empty()) throw InputError("path tracker: update() before start()");
  impl_->update(frame);
}

std::vector<Anchor> PathTracker::Impl::find_anchors(int index) const {
  std::vector<Anchor> anchors;
  const int n = static_cast<int>(steps.size());
  // A place within a template of an anchor already taken adds nothing.
  const auto add_unless_near = [&](cv::Point2d at, int age) {
    const bool near = std::any_of(anchors.begin(), anchors.end(), [&](const Anchor& a) {
      return std::hypot(a.at.x - at.x, a.at.y - at.y) < p;
    });
    if (!near) anchors.push_back({at, age});
  };
  for (int k = n - 1, used = 0; k >= 0 && used < 3; --k) {
    // A marked step's only place is its mark (the path passes there).
    const auto mk = k > 0 ? marks.find(steps[k].index) : marks.end();
    if (mk != marks.end()) {
      anchors.push_back({cv::Point2d(mk->second.x_px, mk->second.y_px), n - k});
      ++used;
      continue;
    }
    if (steps[k].c.empty()) continue;
    std::vector<const Candidate*> best;
    for (const Candidate& c : steps[k].c) best.push_back(&c);
    std::sort(best.begin(), best.end(), [](const Candidate* a, const Candidate* b) { return a->ncc > b->ncc; });
    const std::size_t take = used == 0 ? 3 : 1;
    for (std::size_t i = 0; i < best.size() && i < take; ++i) add_unless_near({best[i]->x, best[i]->y}, n - k);
    if (used == 0 && background.size() >= kTrustedSamples && steps[k].c.front().fg_quick >= 0) {
      // And, where no look was found confidently in the newest step (its candidates' quick
      // difference from the background is judged only then), its best three by correlation and
      // that difference together (the unary cost on the quick difference): still texture
      // correlating 0.83 in every frame outranks a spinning sticker that correlates 0.69 in
      // one, and would take the search away from it for good (grid throw 4).
      std::stable_sort(best.begin(), best.end(), [](const Candidate* a, const Candidate* b) {
        return unary_cost(a->ncc, a->fg_quick) < unary_cost(b->ncc, b->fg_quick);
      });
      for (std::size_t i = 0; i < best.size() && i < take; ++i) add_unless_near({best[i]->x, best[i]->y}, n - k);
    }
    ++used;
  }
  // And where the last two confident sightings (best candidate correlating 0.9 or more)
  // lead, extrapolated linearly: an object hidden for a while reappears there.
  if (lead_frames[0] >= 0) {
    const double k = double(n - lead_frames[1]) / (lead_frames[1] - lead_frames[0]);
    const cv::Point2d at = lead[1] + k * (lead[1] - lead[0]);
    if (at.x >= 0 && at.y >= 0 && at.x < size.width && at.y < size.height) anchors.push_back({at, 1});
  }
  // And the last confident sighting itself, as far back as a path may skip (max_gap + 1 steps),
  // with its age: the object lost since (turning, bouncing) is within reach of it for every
  // step since, as the path's gate allows. One seen up to 3 steps back is an anchor above (the
  // best candidate of its step).
  if (lead_frames[1] >= 0 && n - lead_frames[1] > 3 && n - lead_frames[1] <= opt.max_gap_frames + 1) {
    add_unless_near(lead[1], n - lead_frames[1]);
  }
  // And the next mark, when it is at most three steps ahead: the object is within reach of it.
  const auto next = marks.upper_bound(index - 1);
  if (next != marks.end() && n >= 1) {
    const int step = n >= 2 ? std::max(1, steps[n - 1].index - steps[n - 2].index) : 1;
    const int ahead = (next->first - index) / step;
    if (ahead <= 3) anchors.push_back({cv::Point2d(next->second.x_px, next->second.y_px), ahead + 1});
  }
  return anchors;
}

std::vector<Look*> PathTracker::Impl::looks_for(int index) {
  std::vector<Look*> out{&start_look};
  const auto after = std::upper_bound(looks.begin(), looks.end(), index,
                                      [](int i, const Look& l) { return i < l.frame; });
  if (after != looks.begin()) out.push_back(&*(after - 1));
  if (after != looks.end()) out.push_back(&*after);
  return out;
}

double PathTracker::Impl::seen_speed(int n) const {
  const int apart = lead_frames[1] - lead_frames[0];
  if (lead_frames[0] < 0 || apart > kWindowSpeedSteps || n - lead_frames[1] > opt.max_gap_frames + 1) return -1;
  return std::hypot(lead[1].x - lead[0].x, lead[1].y - lead[0].y) / apart;
}

SearchWindows PathTracker::Impl::search_windows(const std::vector<Anchor>& anchors) const {
  SearchWindows w;
  const double speed = seen_speed(static_cast<int>(steps.size()));
  for (const Anchor& a : anchors) {
    const double motion =
        speed < 0 ? reach * a.age : std::min(reach * a.age, reach + kWindowSpeeds * speed * (a.age - 1));
    const double r = motion + h + 1;  // px
    const cv::Rect win = cv::Rect(static_cast<int>(std::floor(a.at.x - r)), static_cast<int>(std::floor(a.at.y - r)),
                                  static_cast<int>(std::ceil(2 * r)) + 1, static_cast<int>(std::ceil(2 * r)) + 1) &
                         cv::Rect(cv::Point(), size);
    if (win.width <= p + 2 || win.height <= p + 2) continue;
    w.wins.push_back(win);
    w.age.push_back(a.age);
  }
  // Groups: each window alone at first; two groups are joined while the union of both costs no
  // more to correlate than the two apart (its area at most the sum of theirs).
  std::vector<cv::Rect> groups(w.wins.begin(), w.wins.end());
  std::vector<int> of(w.wins.size());
  for (std::size_t i = 0; i < of.size(); ++i) of[i] = static_cast<int>(i);
  for (bool joined = true; joined;) {
    joined = false;
    for (std::size_t a = 0; a < groups.size() && !joined; ++a) {
      for (std::size_t b = a + 1; b < groups.size() && !joined; ++b) {
        if (groups[a].area() == 0 || groups[b].area() == 0) continue;
        const cv::Rect both = groups[a] | groups[b];
        if (static_cast<double>(both.area()) > static_cast<double>(groups[a].area()) + groups[b].area()) continue;
        groups[a] = both;
        groups[b] = cv::Rect();
        for (int& g : of) {
          if (g == static_cast<int>(b)) g = static_cast<int>(a);
        }
        joined = true;
      }
    }
  }
  // Numbered in order of their first window.
  std::vector<int> number(groups.size(), -1);
  for (std::size_t i = 0; i < of.size(); ++i) {
    if (number[of[i]] < 0) {
      number[of[i]] = static_cast<int>(w.uni.size());
      w.uni.push_back(groups[of[i]]);
    }
    w.group_of.push_back(number[of[i]]);
  }
  return w;
}

SearchWindows SearchWindows::newest(int max_age) const {
  SearchWindows out;
  out.uni.assign(uni.size(), cv::Rect());
  for (std::size_t i = 0; i < wins.size(); ++i) {
    if (age[i] > max_age) continue;
    out.wins.push_back(wins[i]);
    out.age.push_back(age[i]);
    out.group_of.push_back(group_of[i]);
    cv::Rect& u = out.uni[group_of[i]];
    u = u.area() == 0 ? wins[i] : (u | wins[i]);
  }
  return out;
}

std::vector<cv::Mat> GroupImages::pyramid(int g, const cv::Rect& uni, int level) const {
  auto made = std::find_if(pyr.begin(), pyr.end(), [&](const auto& m) { return m.first == uni; });
  if (made == pyr.end()) {
    pyr.emplace_back(uni, std::vector<cv::Mat>(1));
    made = pyr.end() - 1;
    const std::size_t k = static_cast<std::size_t>(g);
    gray[k](uni - region[k].tl()).convertTo(made->second[0], CV_32F);
  }
  std::vector<cv::Mat>& levels = made->second;
  while (static_cast<int>(levels.size()) <= level) {
    levels.emplace_back();
    half_resolution(levels[levels.size() - 2], levels.back());
  }
  return levels;
}

UnionCorrelation PathTracker::Impl::correlate_union(const GroupImages& img, int g, const cv::Rect& uni,
                                                    Look& look) const {
  UnionCorrelation u;
  u.coarse = p >= kCoarseMinPatch && (uni.area() > kCoarseMinArea || size.area() >= kCoarseImageArea);
  u.level = u.coarse ? (p >= kQuarterMinPatch ? 2 : 1) : 0;
  u.pyramid = img.pyramid(g, uni, u.level);
  if (u.coarse) {
    while (static_cast<int>(look.coarse.size()) < u.level) {
      look.coarse.emplace_back();
      half_resolution(look.coarse.size() == 1 ? look.templ : look.coarse[look.coarse.size() - 2], look.coarse.back());
    }
    u.templ.push_back(look.templ);
    for (int l = 1; l <= u.level; ++l) u.templ.push_back(look.coarse[l - 1]);
    normed_correlation(u.pyramid[u.level], u.templ[u.level], u.coarse_res);
  } else {
    normed_correlation(u.pyramid[0], look.templ, u.all);
  }
  return u;
}

namespace {

std::vector<Peak> fine_peaks(const cv::Mat& res, int suppress) {
  std::vector<Peak> peaks;
  cv::Mat scratch = res.clone();
  for (int k = 0; k < kPerWindow; ++k) {
    Peak pk;
    cv::minMaxLoc(scratch, nullptr, &pk.v, nullptr, &pk.at);
    if (pk.v < kCandidateFloor) break;
    cv::circle(scratch, pk.at, suppress, cv::Scalar(-1), cv::FILLED);
    pk.fitted = pk.v;
    pk.off = subpixel_peak(res, pk.at, &pk.fitted);
    pk.ridge = peak_ridge_px(res, pk.at, pk.v);
    peaks.push_back(pk);
  }
  return peaks;
}

}  // namespace

std::vector<Peak> PathTracker::Impl::coarse_peaks(UnionCorrelation& u, const cv::Rect& rrect, int suppress) const {
  std::vector<Peak> peaks;
  const int f = 1 << u.level;
  const cv::Rect crect = cv::Rect(rrect.x / f, rrect.y / f, (rrect.width + f - 1) / f, (rrect.height + f - 1) / f) &
                         cv::Rect(0, 0, u.coarse_res.cols, u.coarse_res.rows);
  if (crect.width < 1 || crect.height < 1) return peaks;
  cv::Mat scratch = u.coarse_res(crect).clone();
  std::vector<std::pair<Peak, UnionCorrelation::Refined*>> refined;
  for (int k = 0; k < kCoarsePeaks; ++k) {
    double v;
    cv::Point c;
    cv::minMaxLoc(scratch, nullptr, &v, nullptr, &c);
    if (v < kCoarseFloor) break;
    cv::circle(scratch, c, std::max(1, suppress / f), cv::Scalar(-1), cv::FILLED);
    // Refine at each finer level: the correlation within kRefinePx of twice the coarser
    // level's best place (in the union's result at that level); at full resolution, within
    // the window.
    cv::Point at = crect.tl() + c;
    for (int l = u.level - 1; l >= 1; --l) {
      const cv::Mat& img = u.pyramid[l];
      const cv::Mat& t = u.templ[l];
      const cv::Rect near = cv::Rect(2 * at.x - kRefinePx, 2 * at.y - kRefinePx, 2 * kRefinePx + 1, 2 * kRefinePx + 1) &
                            cv::Rect(0, 0, img.cols - t.cols + 1, img.rows - t.rows + 1);
      if (near.width < 1 || near.height < 1) break;
      cv::Mat r;
      normed_correlation(img(cv::Rect(near.tl(), near.size() + t.size() - cv::Size(1, 1))), t, r);
      cv::Point in;
      cv::minMaxLoc(r, nullptr, nullptr, nullptr, &in);
      at = near.tl() + in;
    }
    const cv::Point tl(2 * at.x - rrect.x, 2 * at.y - rrect.y);  // in the window's result
    const cv::Rect near = cv::Rect(tl.x - kRefinePx, tl.y - kRefinePx, 2 * kRefinePx + 1, 2 * kRefinePx + 1) &
                          cv::Rect(0, 0, rrect.width, rrect.height);
    if (near.width < 1 || near.height < 1) continue;
    const std::array<int, 4> key{rrect.x + near.x, rrect.y + near.y, near.width, near.height};
    auto done = u.refined.find(key);
    if (done == u.refined.end()) {
      cv::Mat fine;
      normed_correlation(u.pyramid[0](cv::Rect(key[0], key[1], near.width + p - 1, near.height + p - 1)), u.templ[0],
                         fine);
      UnionCorrelation::Refined r;
      cv::Point in;
      cv::minMaxLoc(fine, nullptr, &r.v, nullptr, &in);
      r.fitted = r.v;
      r.off = subpixel_peak(fine, in, &r.fitted);
      r.at = cv::Point(key[0], key[1]) + in;
      r.map = fine;
      r.map_at = cv::Point(key[0], key[1]);
      done = u.refined.emplace(key, r).first;
    }
    Peak pk;
    pk.v = done->second.v;
    pk.fitted = done->second.fitted;
    pk.off = done->second.off;
    pk.at = done->second.at - rrect.tl();
    refined.push_back({pk, &done->second});
  }
  std::sort(refined.begin(), refined.end(), [](const auto& a, const auto& b) { return a.first.v > b.first.v; });
  for (auto& item : refined) {
    // (Not a structured binding: clang 14, the sanitizer build's compiler, cannot capture one.)
    Peak& pk = item.first;
    UnionCorrelation::Refined* r = item.second;
    if (static_cast<int>(peaks.size()) >= kPerWindow || pk.v < kCandidateFloor) break;
    const bool dup = std::any_of(peaks.begin(), peaks.end(), [&](const Peak& q) {
      return std::hypot(q.at.x - pk.at.x, q.at.y - pk.at.y) <= suppress;
    });
    if (dup) continue;
    // The ridge at full resolution, measured once for a peak kept (the walk costs a few
    // placements' correlations).
    if (r->ridge < 0) r->ridge = full_ridge_px(u.pyramid[0], u.templ[0], r->map, r->map_at, r->at, r->v);
    pk.ridge = r->ridge;
    peaks.push_back(pk);
  }
  return peaks;
}

void PathTracker::Impl::add_window_peaks(const std::vector<Peak>& peaks, const cv::Rect& win, const cv::Mat& gray,
                                         cv::Point origin, int suppress, bool other_look, FoundPeaks& found) const {
  for (std::size_t k = 0; k < peaks.size(); ++k) {
    const cv::Point at = peaks[k].at;
    const cv::Point2d off = peaks[k].off;
    const double fitted = peaks[k].fitted;
    const double ridge = peaks[k].ridge;
    const double x = win.x + at.x + off.x + h, y = win.y + at.y + off.y + h;
    // The same peak seen from two windows is kept once.
    const auto same = std::find_if(found.c.begin(), found.c.end(), [&](const Candidate& c) {
      return std::hypot(c.x - x, c.y - y) < suppress;
    });
    if (same != found.c.end()) {
      if (k == 0) found.window_best.push_back(static_cast<std::size_t>(same - found.c.begin()));
      if (other_look && std::min(1.0, fitted) > same->ncc) {
        *same = make_candidate(gray, origin, x, y, std::min(1.0, fitted));
        same->spread = ridge;
      }
      continue;
    }
    if (k == 0) found.window_best.push_back(found.c.size());
    found.c.push_back(make_candidate(gray, origin, x, y, std::min(1.0, fitted)));
    found.c.back().spread = ridge;
  }
}

std::vector<Candidate> PathTracker::Impl::keep_best(FoundPeaks& found, int n, int n_keep) {
  std::vector<bool> keep(found.c.size(), false);
  int kept = 0;
  for (std::size_t i : found.window_best) {
    if (!keep[i] && kept < n_keep) {
      keep[i] = true;
      ++kept;
    }
  }
  std::vector<std::size_t> order(found.c.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return found.c[a].ncc > found.c[b].ncc; });
  for (std::size_t i : order) {
    if (!keep[i] && kept < n_keep) {
      keep[i] = true;
      ++kept;
    }
  }
  if (!order.empty() && found.c[order[0]].ncc >= kConfident) {
    lead[0] = lead[1];
    lead_frames[0] = lead_frames[1];
    lead[1] = cv::Point2d(found.c[order[0]].x, found.c[order[0]].y);
    lead_frames[1] = n;
  }
  std::vector<Candidate> out;
  for (std::size_t i = 0; i < found.c.size(); ++i) {
    if (keep[i]) out.push_back(std::move(found.c[i]));
  }
  return out;
}

void PathTracker::Impl::update(const Frame& f) {
  if (frame_size(f) != size || (f.bgr.empty() && f.gray.type() != CV_8UC1)) {
    throw InputError(name, "frame " + std::to_string(f.index) + " has no image of the start frame's size");
  }
  background.remember(f, std::nullopt);
  // Where the object can be: within reach (times the frames elapsed) of the best three
  // candidates of the last step that had any and of the best one of the two such steps
  // before it (anchors). Each anchor's window gives its own best few peaks, so that junk
  // peaks far away never crowd out a blurred object near an anchor.
  const std::vector<Anchor> anchors = find_anchors(f.index);
  const int n = static_cast<int>(steps.size());
  StepCandidates out;
  out.index = f.index;
  const int suppress = std::max(2, static_cast<int>(std::lround(radius)));
  FoundPeaks found;
  // The anchors' windows overlap (the oldest anchor's covers most of the image): the
  // correlation is computed once over the union of each group of windows near each other,
  // and each window reads its part of it (the same values as correlating the window alone:
  // the template inside the window).
  const SearchWindows w = search_windows(anchors);
  // Only the groups' grey images are made, each with a 2 px ring for the candidates' patches
  // (a sub-pixel peak rounds to at most a pixel outside its window).
  GroupImages img;
  if (region_bufs.size() < w.uni.size()) region_bufs.resize(w.uni.size());
  for (std::size_t g = 0; g < w.uni.size(); ++g) {
    img.region.push_back((w.uni[g] + cv::Point(-2, -2) + cv::Size(4, 4)) & cv::Rect(cv::Point(), size));
    img.gray.push_back(gray_region(f, img.region.back(), region_bufs[g]));
  }
  // Each look is searched in the windows: the start's, and the looks of the user's nearest
  // marks before and after this frame (a corrected frame shows the tracker the object as it
  // looks there, both ways). A candidate's correlation is its best look's.
  const std::vector<Look*> searched = looks_for(f.index);
  // Each look as taken and, where it has turned (its heading) and is not found confidently as
  // taken, turned so: an object that does not turn has one search per look, and a heading gone
  // wrong loses nothing.
  // A turned look is searched in the windows of the newest anchors only (a step's worth of
  // motion from the last step's candidates, not the older anchors' wide windows): a turning
  // object is one followed from step to step, and this bounds the search's cost.
  const SearchWindows near = w.newest(1);
  double best = -1;
  std::vector<double> primary;  // each look's best, as taken or at its heading
  FoundPeaks at_heading;        // the peaks of the looks turned to their headings
  int heading_searches = 0;
  if (!w.wins.empty()) {
    for (Look* look : searched) {
      primary.push_back(find_peaks(w, img, *look, look != &start_look, suppress, found));
      // (Where the look as taken is found confidently, its heading is not searched.)
      // (A spinning object's heading is carried on at its turn rate: Look::expected.)
      const int expected = look->expected(n, kTurnStep);
      Look* at = expected % 360 != 0 && primary.back() < kConfident ? turned(*look, expected, p) : nullptr;
      if (at != nullptr && !near.wins.empty()) {
        const double v = find_peaks(near, img, *at, true, suppress, at_heading);
        ++heading_searches;
        primary.back() = std::max(primary.back(), v);
        if (v >= kConfident) look->seen_at(at->deg, n, false);  // the expected turn confirmed
      }
      best = std::max(best, primary.back());
    }
  }
  // At most kCandidates (and kCandidatesPerLook more per mark's look): every window's best,
  // then the best of the rest.
  const int n_keep = kCandidates + kCandidatesPerLook * static_cast<int>(searched.size() - 1);
  out.c = keep_best(found, n, n_keep);
  // And the best kCandidatesPerLook of each turned search's peaks on top: those the looks as
  // taken found are all kept (a heading gone wrong crowds none of them out); a peak at one of
  // them gives it its correlation where better.
  std::sort(at_heading.c.begin(), at_heading.c.end(),
            [](const Candidate& a, const Candidate& b) { return a.ncc > b.ncc; });
  const int n_turned = kCandidatesPerLook * heading_searches;
  for (std::size_t i = 0, added = 0; i < at_heading.c.size() && static_cast<int>(added) < n_turned; ++i) {
    Candidate& c = at_heading.c[i];
    const auto same = std::find_if(out.c.begin(), out.c.end(), [&](const Candidate& q) {
      return std::hypot(q.x - c.x, q.y - c.y) < suppress;
    });
    if (same == out.c.end()) {
      out.c.push_back(std::move(c));
      ++added;
    } else if (c.ncc > same->ncc) {
      *same = std::move(c);
    }
  }
  // Where no look is found confidently, each candidate's difference from the background seen so
  // far, judged on about 8 x 8 pixels of the object's square (a quick look): the turns below
  // and the next step's anchors use it.
  if (best < kConfident) {
    const int fg_stride = std::max(1, static_cast<int>(std::ceil(radius)) / 4);
    for (Candidate& c : out.c) c.fg_quick = foreground(c, fg_stride);
  }
  // A template that turns: where no look is found confidently, each is correlated turned a
  // little and a little more either way from its heading (+-kTurnStep, +-2 kTurnStep) around
  // each candidate kept (within kRefinePx). The best turn that matches a candidate kTurnGain
  // better than the look did becomes the look's heading (searched from the next step on: the
  // car going round a loop), and the candidates take its correlation (and its place) where it
  // is better. No candidate is added or dropped here (a turned look finds the same object a few
  // px along itself, a rival of the right candidate, and turned texture elsewhere).
  if (!w.wins.empty() && best < kConfident) {
    // Only candidates that stand out from the background seen so far (kFgHalf, judged on about
    // 8 x 8 pixels of the object's square: a quick look) take part: a turned look matches some
    // texture better than the look did (a heading turned by it moved the windows and the costs,
    // and a look-alike's path became certain).
    std::vector<std::size_t> moving;
    for (std::size_t i = 0; i < out.c.size(); ++i) {
      if (out.c[i].fg_quick >= kFgHalf) moving.push_back(i);
    }
    struct Match {
      double v;
      int deg;
      bool found;
    };
    for (std::size_t l = 0; l < searched.size() && !moving.empty(); ++l) {
      Look* look = searched[l];
      // Only a turn that matches a candidate clearly better than the look did (kTurnGain) and
      // well enough to be reported (min_score) is taken, the best such.
      const double bar = std::max(primary[l] + kTurnGain, opt.min_score);
      Match taken{bar, 0, false};
      for (const int d : {-kTurnStep, kTurnStep, -2 * kTurnStep, 2 * kTurnStep}) {
        Look* t = turned(*look, look->expected(n, kTurnStep) + d, p);
        if (t == nullptr) continue;
        for (std::size_t i : moving) {
          const double v = rescore(img, t->templ, out.c[i], false);
          if (v > taken.v || (v == taken.v && !taken.found)) taken = {v, t->deg, true};
        }
      }
      if (!taken.found) continue;
      // Only that turn gives the candidates its correlation: the best of several turns at every
      // candidate would favour texture that some turn happens to match.
      look->seen_at(taken.deg, n, true);
      if (std::abs(taken.deg) > std::abs(turned_deg)) {
        turned_deg = taken.deg;
        turned_frame = f.index;
      }
      const Look* t = turned(*look, taken.deg, p);  // (a turned copy's address changes as more are made)
      for (std::size_t i : moving) rescore(img, t->templ, out.c[i], true);
    }
  }
  steps.push_back(std::move(out));
}

std::vector<std::vector<Peak>> PathTracker::Impl::window_peaks(const SearchWindows& w, const GroupImages& img,
                                                              Look& look, int suppress) const {
  // A large union with a template that survives halving is searched coarse to fine: the
  // correlation at half (a large template: quarter) resolution finds each window's peaks, each
  // refined within 3 px at every finer level (a quarter, or a sixteenth, of the work over the
  // union; a peak seen from several windows is refined once). Each group of windows is
  // correlated over its own union.
  std::vector<UnionCorrelation> u(w.uni.size());
  for (std::size_t g = 0; g < w.uni.size(); ++g) {
    if (w.uni[g].area() > 0) u[g] = correlate_union(img, static_cast<int>(g), w.uni[g], look);
  }
  std::vector<std::vector<Peak>> out;
  for (std::size_t i = 0; i < w.wins.size(); ++i) {
    // The window in its union's result.
    const cv::Rect& win = w.wins[i];
    const cv::Rect& uni = w.uni[w.group_of[i]];
    UnionCorrelation& c = u[w.group_of[i]];
    const cv::Rect rrect(win.x - uni.x, win.y - uni.y, win.width - p + 1, win.height - p + 1);
    out.push_back(c.coarse ? coarse_peaks(c, rrect, suppress) : fine_peaks(c.all(rrect), suppress));
  }
  return out;
}

double PathTracker::Impl::rescore(const GroupImages& img, const cv::Mat& templ, Candidate& c, bool take) const {
  const int g = img.holding(c.at);
  if (g < 0) return -1;
  const cv::Mat& gray = img.gray[g];
  const cv::Point origin = img.region[g].tl();
  const cv::Point at = c.at - origin;
  const cv::Rect near = cv::Rect(at.x - h - kRefinePx, at.y - h - kRefinePx, p + 2 * kRefinePx, p + 2 * kRefinePx) &
                        cv::Rect(0, 0, gray.cols, gray.rows);
  if (near.width < p || near.height < p) return -1;
  cv::Mat w32, res;
  gray(near).convertTo(w32, CV_32F);
  normed_correlation(w32, templ, res);
  double v;
  cv::Point in;
  cv::minMaxLoc(res, nullptr, &v, nullptr, &in);
  double fitted = v;
  const cv::Point2d off = subpixel_peak(res, in, &fitted);
  if (take && std::min(1.0, fitted) > c.ncc) {
    // The same object within kRefinePx: its ridge and its quick difference from the background
    // (judged on a few px of its square) stay.
    const double spread = c.spread, fg_quick = c.fg_quick;
    c = make_candidate(gray, origin, origin.x + near.x + in.x + off.x + h, origin.y + near.y + in.y + off.y + h,
                       std::min(1.0, fitted));
    c.spread = spread;
    c.fg_quick = fg_quick;
  }
  return v;
}

double PathTracker::Impl::find_peaks(const SearchWindows& w, const GroupImages& img, Look& look, bool other_look,
                                     int suppress, FoundPeaks& found) const {
  const std::vector<std::vector<Peak>> peaks = window_peaks(w, img, look, suppress);
  for (std::size_t i = 0; i < w.wins.size(); ++i) {
    const int g = w.group_of[i];
    add_window_peaks(peaks[i], w.wins[i], img.gray[g], img.region[g].tl(), suppress, other_look, found);
  }
  return best_peak(peaks);
}

std::vector<Observation> PathTracker::finish() {
  if (!impl_ || impl_->steps.empty()) throw InputError("path tracker: finish() before start()");
  return impl_->finish();
}

void PathTracker::Impl::compute_unary_costs() {
  if (fg_done) return;
  cv::Mat median(size, CV_8U), known = cv::Mat::zeros(size, CV_8U);
  // The start's too: the object's own difference from the background, where the user clicked it.
  for (int t = 0; t < static_cast<int>(this->steps.size()); ++t) {
    for (Candidate& c : this->steps[t].c) {
      c.fg = foreground(c, 1, &median, &known);
      if (t == 0) continue;
      c.cost = unary_cost(c.ncc, c.fg);
    }
  }
  fg_done = true;
}

std::vector<StepCandidates> PathTracker::Impl::steps_with_marks() const {
  std::vector<StepCandidates> out = this->steps;
  for (int t = 1; t < static_cast<int>(out.size()); ++t) {
    const auto mk = marks.find(out[t].index);
    if (mk == marks.end()) continue;
    Candidate c;
    c.x = mk->second.x_px;
    c.y = mk->second.y_px;
    c.ncc = 1;
    c.cost = 0;
    c.fg = std::numeric_limits<double>::quiet_NaN();
    c.manual = true;
    out[t].c.assign(1, c);
  }
  return out;
}

std::vector<Observation> PathTracker::Impl::observe_path(const PathSearch& search, const BestPath& best,
                                                         const PathForeground& fg) {
  const std::vector<StepCandidates>& steps = search.steps;
  const int T = search.T;
  // Per frame: the best full path through each candidate (min-marginal); a far candidate
  // nearly as good as the chosen one makes the frame doubtful.
  const double rival_px = std::max(3.0, radius);
  std::vector<Observation> obs;
  lost_none = lost_rival = lost_score = lost_background = lost_ridge = lost_end = lost_alone = lost_unlinked = 0;
  end_frame = steps[best.end].index;
  // A path point whose correlation peak is a ridge longer than a user's correction distance
  // (4 px per 640 px of image width, at least 4 px) cannot be placed along it: lost.
  ridge_max_px = std::max(kRidgeMinPx, kRidgeMinPx * size.width / 640.0);
  for (int t = 1; t < T; ++t) {
    Observation o;
    o.frame = steps[t].index;
    o.lost = true;
    const int k = best.chosen[t];
    if (k < 0 && !steps[t].c.empty() && steps[t].c.front().manual) {
      // No path reaches the mark (the object hidden longer than max_gap_frames around it): the mark stands.
      o.x_px = steps[t].c.front().x;
      o.y_px = steps[t].c.front().y;
      o.score = 1;
      o.lost = false;
      o.manual = true;
      obs.push_back(o);
      continue;
    }
    if (k < 0) {
      ++lost_none;
      if (t > best.end) ++lost_end;
      obs.push_back(o);
      continue;
    }
    const Candidate& c = steps[t].c[k];
    o.x_px = c.x;
    o.y_px = c.y;
    o.score = std::clamp(c.ncc, 0.0, 1.0);
    if (c.manual) {
      o.lost = false;
      o.manual = true;
      o.score = 1;
      obs.push_back(o);
      continue;
    }
    if (search.has_rival(t, k, best.total, rival_px)) {
      ++lost_rival;
      o.score = std::min(o.score, 0.1);
    } else if (fg.typical > 2 * kFgHalf && fg.run[t] < kFgShare * fg.typical) {
      ++lost_background;
      o.score = std::min(o.score, 0.1);
    } else if (c.spread > ridge_max_px) {
      ++lost_ridge;
      o.score = std::min(o.score, 0.1);
    } else if (c.ncc < opt.min_score) {
      ++lost_score;
    } else {
      o.lost = false;
    }
    obs.push_back(o);
  }
  return obs;
}

void PathTracker::Impl::drop_unconfirmed_runs(std::vector<Observation>& obs) {
  for (std::size_t i = 0; i < obs.size();) {
    if (obs[i].lost) {
      ++i;
      continue;
    }
    std::size_t e = i;
    bool anchored = i == 0;  // frame t = 1 follows the start
    for (; e < obs.size() && !obs[e].lost; ++e) anchored = anchored || obs[e].manual;
    if (e < obs.size() && obs[e].manual) anchored = true;
    const bool bounded = e < obs.size();  // a run at the clip's end has no later neighbour to confirm it
    if (!anchored && bounded && static_cast<int>(e - i) < kMinRun) {
      for (std::size_t q = i; q < e; ++q) {
        obs[q].lost = true;
        obs[q].score = std::min(obs[q].score, 0.1);
        ++lost_alone;
      }
    }
    i = e;
  }
}

void PathTracker::Impl::drop_unlinked_runs(std::vector<Observation>& obs, int G) {
  int last_reported = 0;  // step index; the start
  for (std::size_t i = 0; i < obs.size();) {
    if (obs[i].lost) {
      ++i;
      continue;
    }
    std::size_t e = i;
    bool marked = false;
    for (; e < obs.size() && !obs[e].lost; ++e) marked = marked || obs[e].manual;
    const int first = static_cast<int>(i) + 1;  // step index of the run's first point
    if (!marked && first - last_reported > G) {
      for (std::size_t q = i; q < e; ++q) {
        obs[q].lost = true;
        obs[q].score = std::min(obs[q].score, 0.1);
        ++lost_unlinked;
      }
    } else {
      last_reported = static_cast<int>(e);  // step index of the run's last point
    }
    i = e;
  }
}

std::vector<Observation> PathTracker::Impl::finish() {
  // Unary costs: likeness and difference from the background median (once: the background
  // samples are complete at the first finish()).
  compute_unary_costs();
  // The steps the path is chosen among: a marked step's only candidate is its mark (cost 0;
  // no fg: it takes no part in the background check below).
  const std::vector<StepCandidates> steps = steps_with_marks();
  PathSearch search(steps, opt.max_gap_frames, reach, radius, std::max(1.0, kClickPx * size.width / 640.0));
  search.forward();
  search.backward();
  // The best path (forward and backward agree on its cost: F + B is the same along it).
  const BestPath best = search.best_path();
  // A path point that stands out from the background far less than the object does along
  // the path (a still patch of texture reached across a gap) is not the object.
  const PathForeground fg = path_foreground(steps, best.chosen);
  std::vector<Observation> obs = observe_path(search, best, fg);
  // Confirmation (the M-of-N rule of radar tracking): a run of fewer than kMinRun consecutive
  // reported points, with lost frames on both sides (the start and a mark count as reported),
  // is not confirmed by its neighbours' motion: lost. (CarInLoop with patch 25: frame 2
  // alone between lost frames 1 and 3, 47 px from the human's mark.)
  drop_unconfirmed_runs(obs);
  // Identity: a run of reported points whose last reported point before it (the start, or a
  // point of an earlier run) lies more than max_gap + 1 frames back is reached only through
  // doubtful path points: it may be anything that the template resembles. Lost, unless it holds
  // a mark. (CarInLoop with patch 75: the path hopped from the car, its points lost, to a
  // still edge 390 px away and held it for 17 frames.)
  drop_unlinked_runs(obs, search.G);
  return obs;
}

std::string PathTracker::loss_hint() const {
  const Impl& m = *impl_;
  std::string hint = m.main_loss_hint();
  const auto add = [&](const std::string& part) { hint += (hint.empty() ? "" : "; ") + part; };
  if (m.lost_alone > 0) {
    add(std::to_string(m.lost_alone) + " frame(s) found alone between lost frames were not confirmed by their "
        "neighbours' motion: " + field("mark") + " one of them if it is right");
  }
  if (m.lost_unlinked > 0) {
    add(std::to_string(m.lost_unlinked) + " frame(s) were reached only across more than " + field("max_gap") +
        " frames without a reported point, so what was found there may be something else: " + field("mark") +
        " one of them if it is right");
  }
  if (m.lost_ridge > 0) {
    char bar[32];
    std::snprintf(bar, sizeof bar, "%.0f", m.ridge_max_px);
    add("in " + std::to_string(m.lost_ridge) +
        " frame(s) the template matched all along a streak (motion blur, or a plain edge): the position along it was "
        "uncertain by more than " + std::string(bar) + " px; a shorter exposure when filming helps, or mark those "
        "frames (" + field("mark") + " NAME@FRAME=X,Y)");
  }
  // Frames were lost and the object was seen turned (a look matched best turned), or its look
  // changes with a turn: the frame tracker searches every turn from frame to frame (a sticker
  // on a ball spinning 20-45 degrees per frame at 60 fps, which the path tracker's turns of 15
  // and 30 degrees about its heading carried on at its turn rate still miss:
  // docs/benchmarks.md#a-spinning-looks-turn-rate). A mark on a ball: the ellipse tracker follows
  // the ball itself, its centre and its turn, where at 30 fps both point trackers lose the
  // smeared sticker (docs/benchmarks.md, "A template's least size, the ellipse's fit bar").
  if (!hint.empty() && hint.find(field("point_tracker")) == std::string::npos) {
    const std::string ball = "; " + on_a_ball();
    if (m.turned_deg != 0) {
      add("the object turns (its look matched best turned by " + std::to_string(m.turned_deg) + " degrees at frame " +
          std::to_string(m.turned_frame) + "): " + field("point_tracker") + " frame searches every turn from frame "
          "to frame" + ball);
    } else if (m.turn_ncc < kTurnSensitive) {
      char ncc[32];
      std::snprintf(ncc, sizeof ncc, "%.2f", m.turn_ncc);
      add("if the object turns (a mark on a spinning ball or a wheel), " + field("point_tracker") +
          " frame searches every turn from frame to frame (this look turned by " + std::to_string(2 * kTurnStep) +
          " degrees correlates " + ncc + " with itself)" + ball);
    }
  }
  return hint;
}

}  // namespace tribolab::video
