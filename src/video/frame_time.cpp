#include "video/frame_time.hpp"

#include "numerics/polyfit.hpp"
#include "numerics/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tribolab::video {
namespace {

constexpr std::size_t kSide = 3;             ///< neighbours each side in a frame's motion fit
constexpr std::size_t kTurnSide = 2;         ///< and in its turn's
constexpr std::size_t kLeastReadings = 10;   ///< head-on ramps to read the exposure from
constexpr std::size_t kMostReadings = 1000;  ///< more do not change their median
/// Frames held waiting for the exposure to be read; beyond, the oldest are left as fitted
/// (an object that moves too slowly for the exposure to be read blurs too little to matter).
constexpr std::size_t kMostWaiting = 240;
constexpr double kLeastShiftPx = 0.01;

/// Up to `side` entries of `pos` each side of position `at` (sorted positions), more on one
/// side where the other has fewer, up to 2 side + 1 in all.
std::vector<std::size_t> around(const std::vector<std::size_t>& pos, std::size_t at, std::size_t side) {
  const std::size_t before = at, after = pos.size() - 1 - at;
  std::size_t b = std::min(before, side), a = std::min(after, side);
  b = std::min(before, b + (side - a));
  a = std::min(after, a + (side - std::min(before, side)));
  return {pos.begin() + static_cast<std::ptrdiff_t>(at - b), pos.begin() + static_cast<std::ptrdiff_t>(at + a + 1)};
}

}  // namespace

void FrameTimePass::add(FittedFrame frame) {
  if (frame.round) frame.edges.clear();
  held_.push_back({std::move(frame), false, {}});
  advance(false);
}

FrameTimePass::Result FrameTimePass::result() const {
  FrameTimePass rest = *this;
  rest.advance(true);
  Result r;
  if (rest.readings_.size() < kLeastReadings) return r;
  r.exposure = std::clamp(median(rest.readings_), 0.0, 1.0);
  r.frames = std::move(rest.done_);
  return r;
}

bool FrameTimePass::motion_of(std::size_t i, bool track_ended) {
  // The held frames of its piece (consecutive: pieces do not decrease).
  const int piece = held_[i].f.piece;
  std::size_t lo = i, hi = i + 1;
  while (lo > 0 && held_[lo - 1].f.piece == piece) --lo;
  while (hi < held_.size() && held_[hi].f.piece == piece) ++hi;
  const bool piece_ended = track_ended || hi < held_.size();
  const std::size_t before = i - lo, after = hi - 1 - i;
  if (!piece_ended && after < kSide + (kSide - std::min(before, kSide))) return false;  // wait for the next frames
  Held& h = held_[i];
  std::vector<std::size_t> all(hi - lo), turning;
  for (std::size_t j = lo; j < hi; ++j) all[j - lo] = j;
  std::size_t at_turning = 0;
  for (std::size_t j = lo; j < hi; ++j) {
    if (held_[j].f.round) continue;
    if (j == i) at_turning = turning.size();
    turning.push_back(j);
  }
  const std::vector<std::size_t> near = around(all, before, kSide);
  if (near.size() < 2) {
    h.f.edges.clear();  // alone in its piece: no motion to correct for
    return true;
  }
  std::vector<double> t, x, y;
  for (std::size_t j : near) {
    t.push_back(held_[j].f.index - h.f.index);
    x.push_back(held_[j].f.found.cx);
    y.push_back(held_[j].f.found.cy);
  }
  const int degree = near.size() >= 3 ? 2 : 1;
  const std::vector<double> cx = numerics::least_squares_polynomial(t, x, degree);
  const std::vector<double> cy = numerics::least_squares_polynomial(t, y, degree);
  h.motion.velocity = {cx[1], cy[1]};
  if (degree == 2) h.motion.acceleration = {2 * cx[2], 2 * cy[2]};
  if (!h.f.round) {
    t.clear();
    std::vector<double> phi;
    for (std::size_t j : around(turning, at_turning, kTurnSide)) {
      t.push_back(held_[j].f.index - h.f.index);
      phi.push_back(held_[j].f.phi);
    }
    // Screen counter-clockwise is clockwise in image axes.
    if (t.size() >= 2) h.motion.turn_rad = -numerics::least_squares_polynomial(t, phi, 1)[1];
  }
  if (!h.f.edges.empty() && readings_.size() < kMostReadings) read_exposure(h.f.edges, h.f.found, h.motion, readings_);
  return true;
}

void FrameTimePass::advance(bool track_ended) {
  for (std::size_t i = 0; i < held_.size(); ++i) {
    if (held_[i].read) continue;
    if (!motion_of(i, track_ended)) break;  // the frames after it wait too
    held_[i].read = true;
  }
  const auto waiting = [](const Held& h) { return h.read && !h.f.edges.empty(); };
  const bool any_waiting = std::any_of(held_.begin(), held_.end(), waiting);
  if (any_waiting && readings_.size() >= kLeastReadings) {
    // The exposure read so far: a flight's first frames are refitted with the median of the
    // readings of the frames up to a few after them (10 or more), the later ones with more.
    const double x = std::clamp(median(readings_), 0.0, 1.0);
    for (Held& h : held_) {
      if (!waiting(h)) continue;
      const Ellipse& e = h.f.found;
      const FrameMotion& m = h.motion;
      // The largest shift: the slide over the exposure along the sharpest bend of the outline
      // (radius b^2 / a), (x travel)^2 / (24 rho), and the parabola's sag, x^2 |acc| / 24.
      const double travel = x * (std::hypot(m.velocity.x, m.velocity.y) + e.a * std::abs(m.turn_rad));
      const double most =
          travel * travel / (24 * e.b * e.b / e.a) + x * x * std::hypot(m.acceleration.x, m.acceleration.y) / 24;
      Ellipse at;
      if (most >= kLeastShiftPx && fit_at_frame_time(h.f.edges, e, h.f.a0, h.f.b0, m, x, at) &&
          std::hypot(at.cx - e.cx, at.cy - e.cy) <= 2 * most + 1) {  // the small move expected
        FittedFrame f = h.f;
        f.edges.clear();
        const double phi = f.phi + std::remainder(-at.psi - f.phi, std::numbers::pi);
        done_.push_back({std::move(f), at, phi});
      }
      h.f.edges.clear();
    }
  } else if (any_waiting) {
    std::size_t n = static_cast<std::size_t>(std::count_if(held_.begin(), held_.end(), waiting));
    for (Held& h : held_) {
      if (n <= kMostWaiting) break;
      if (waiting(h)) h.f.edges.clear(), --n;
    }
  }
  // Keep the 2 kSide frames before the first one not yet read (its neighbours) and every frame
  // still waiting to be refitted.
  const auto first_unread = static_cast<std::size_t>(
      std::find_if(held_.begin(), held_.end(), [](const Held& h) { return !h.read; }) - held_.begin());
  std::size_t drop = 0;
  while (drop < held_.size() && drop + 2 * kSide < first_unread && !waiting(held_[drop])) ++drop;
  held_.erase(held_.begin(), held_.begin() + static_cast<std::ptrdiff_t>(drop));
}

}  // namespace tribolab::video
