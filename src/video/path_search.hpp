// The path tracker's dynamic programme (docs/theory.md#tracking-on-real-film, items 4-6):
// the best path through every frame's candidates under the motion prior, and the rival
// check of each of its points. Internal to src/video (path_tracker.cpp).
#pragma once

#include <opencv2/core.hpp>

#include <limits>
#include <utility>
#include <vector>

namespace tribolab::video::detail {

constexpr float kInf = std::numeric_limits<float>::infinity();
// The cost of a frame without the object (path_tracker.cpp: the candidates' unary costs are
// on the same scale).
constexpr double kMissCost = 4;
// Motion prior: the acceleration a (px/frame^2) of three successive path points costs
// |a|^2 / (2 sigma^2), sigma = kAccAbs + kAccRel * speed (the mean of
// the two; across a gap the slower); beyond kAccGate sigma it is
// impossible. kAccAbs: marks scatter ~0.5 px, so a still object's acceleration ~1 px;
// kAccRel: a toss at 15 fps turns its 70 px/frame by 9 px/frame^2 (0.13), a car in a loop
// of radius 150 px at 20 px/frame by 2.7 (0.13).
constexpr double kAccAbs = 1.5;
constexpr double kAccRel = 0.3;
constexpr double kAccGate = 5;
// A frame is doubtful when a path through a candidate farther than the rival distance from
// the chosen one costs less than kRivalMargin more than the best path.
constexpr double kRivalMargin = 3;
// Where a manual mark is one of the three points of an acceleration, the path may turn
// sharply (the user marks a bounce, or a point the tracker had wrong): that acceleration is
// not gated but costs at most this (the gate's cost), and a mark has no reach limit.
constexpr double kMarkAccCap = 0.5 * kAccGate * kAccGate;

// A place the object may be in one frame (PathTracker::Impl::update).
struct Candidate {
  double x = 0, y = 0;  // px
  double ncc = 0;       // correlation with the first frame's template
  double cost = 0;      // unary cost
  double fg = 0;        // difference from the background, grey levels
  double fg_quick = -1; // the same on about 8 x 8 pixels, against the background seen so far (-1: not judged)
  cv::Mat patch;        // CV_8U, template-sized grey patch at the rounded position
  cv::Point at;         // the patch's centre, px
  bool manual = false;  // the user's mark: the step's only candidate
  double spread = 0;    // half-length of the correlation ridge through the peak, px (peak_ridge_px)
};

// One frame's candidates (`index`: the frame).
struct StepCandidates {
  int index = 0;
  std::vector<Candidate> c;
};

// One state of the path search: the path's last two points (step t, candidate k; back step g,
// candidate j of step t - g), enough for its acceleration at the next one.
struct PathState {
  float F = kInf, B = kInf;  // best cost up to and including this state / after it
  int back = -1;             // the predecessor's index in step t - g
  short k = 0, g = 0, j = 0;
};

// The best path: its cost, its last step and each step's chosen candidate (-1: none).
struct BestPath {
  double total = 0;
  int end = 0;
  std::vector<int> chosen;
};

// The path points' difference from the background (grey levels): the path's median, and per
// step the median over its run of consecutive path points.
struct PathForeground {
  double typical = 0;
  std::vector<double> run;
};

// The best path by dynamic programming over the steps' candidates under the motion prior
// (finish()). off[t][k * G + g - 1] is the first state of the block (k, g) of S[t]; the block
// holds one state per candidate of t - g.
struct PathSearch {
  // The states of every step, and where the marks are.
  PathSearch(const std::vector<StepCandidates>& steps, int max_gap_frames, double reach, double radius,
             double click_px);
  const std::vector<StepCandidates>& steps;  // a marked step holds its mark alone
  int T = 0;                                 // steps
  int G = 0;                                 // largest step between two path points
  double reach = 0, radius = 0;              // px (PathTracker::Impl's)
  double click_px = 1;                       // a mark's scatter, px (kClickPx)
  std::vector<int> marks_before;             // marked steps among 0 .. t-1
  int last_mark = 0;                         // the last marked step (0: none)
  std::vector<std::vector<PathState>> S;
  std::vector<std::vector<int>> off;

  // A mark in (t0, t1).
  bool skips_mark(int t0, int t1) const { return marks_before[t1] - marks_before[t0 + 1] > 0; }
  // Candidate k of step t is the user's mark.
  bool manual(int t, int k) const { return steps[t].c[k].manual; }
  // Candidate k of step t, px.
  cv::Point2d pos(int t, int k) const { return cv::Point2d(steps[t].c[k].x, steps[t].c[k].y); }
  // The states [first, end) of the block (k, g) of step t.
  std::pair<int, int> block(int t, int k, int g) const {
    return std::pair<int, int>(off[t][k * G + g - 1], off[t][k * G + g]);
  }
  // Candidate k1 of step t1 lies within reach of candidate k0 of step t0.
  bool gate(int t0, int k0, int t1, int k1) const;
  // Cost of the acceleration at b of the path points a, b, c (steps ta < tb < tc).
  double accel(int ta, int ka, int tb, int kb, int tc, int kc) const;
  // Forward: each state's best cost up to and including it (F) and its predecessor.
  void forward();
  // Backward: the best cost after a state, ending anywhere (the frames left cost kMissCost).
  void backward();
  // The best path from the forward costs.
  BestPath best_path() const;
  // Candidate k of step t has a rival: a candidate farther than rival_px whose best full
  // path costs less than kRivalMargin more than `total`.
  bool has_rival(int t, int k, double total, double rival_px) const;
};

// The chosen path points' difference from the background, over the path and over each run.
PathForeground path_foreground(const std::vector<StepCandidates>& steps, const std::vector<int>& chosen);

}  // namespace tribolab::video::detail
