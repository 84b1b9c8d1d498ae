#include "video/path_search.hpp"

#include "numerics/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tribolab::video::detail {

PathSearch::PathSearch(const std::vector<StepCandidates>& steps, int max_gap_frames, double reach, double radius,
                       double click_px)
    : steps(steps), T(static_cast<int>(steps.size())), G(max_gap_frames + 1), reach(reach), radius(radius),
      click_px(click_px) {
  // Manual marks: the path passes through every one (no transition skips a marked step, the
  // path ends at or after the last).
  marks_before.assign(T + 1, 0);
  for (int t = 0; t < T; ++t) {
    const bool marked = t > 0 && !steps[t].c.empty() && steps[t].c.front().manual;
    marks_before[t + 1] = marks_before[t] + (marked ? 1 : 0);
    if (marked) last_mark = t;
  }
  // The states of every step, in blocks (k, g) of one state per candidate of t - g.
  S.resize(T);
  off.resize(T);
  S[0].push_back(PathState{0, kInf, -1, 0, 0, 0});
  for (int t = 1; t < T; ++t) {
    const int K = static_cast<int>(steps[t].c.size());
    off[t].assign(K * G + 1, 0);
    int n = 0;
    for (int k = 0; k < K; ++k) {
      for (int g = 1; g <= G; ++g) {
        off[t][k * G + g - 1] = n;
        if (t - g >= 0) {
          for (int j = 0; j < static_cast<int>(steps[t - g].c.size()); ++j) {
            PathState st;
            st.k = static_cast<short>(k);
            st.g = static_cast<short>(g);
            st.j = static_cast<short>(j);
            S[t].push_back(st);
            ++n;
          }
        }
      }
    }
    off[t][K * G] = n;
  }
}

bool PathSearch::gate(int t0, int k0, int t1, int k1) const {
  const cv::Point2d d = pos(t1, k1) - pos(t0, k0);
  // From the start (no velocity known) a gap does not widen the reach: the object was
  // clicked where it is, and something far away found frames later is something else.
  if (manual(t0, k0) || manual(t1, k1)) return true;  // the user's mark: anywhere
  const double r = reach * (t0 == 0 ? 1 : t1 - t0);
  return d.x * d.x + d.y * d.y <= r * r;
}

double PathSearch::accel(int ta, int ka, int tb, int kb, int tc, int kc) const {
  const cv::Point2d v1 = (pos(tb, kb) - pos(ta, ka)) / (tb - ta), v2 = (pos(tc, kc) - pos(tb, kb)) / (tc - tb);
  const cv::Point2d a = (v2 - v1) / (0.5 * (tc - ta));
  // The mean speed; across a gap the slower of the two, so that a jump to something far
  // away does not widen its own tolerance (an oscillation, slow at its turning points, needs
  // the mean).
  // (std::sqrt of the squares, not std::hypot: the dynamic programme's most frequent call, and
  // hypot's care for overflow costs 4 times the time here for px-sized values.)
  const auto norm = [](cv::Point2d v) { return std::sqrt(v.x * v.x + v.y * v.y); };
  const double speed = tc - ta == 2 ? 0.5 * norm(v1 + v2) : std::min(norm(v1), norm(v2));
  const double sigma = kAccAbs + kAccRel * speed;
  if (manual(ta, ka) || manual(tb, kb) || manual(tc, kc)) {
    // A mark is where the user clicked, within click_px of the object's point: its error
    // enters the acceleration with the weight of its point (d a / d point).
    const double h = 0.5 * (tc - ta), w_a = 1 / ((tb - ta) * h), w_c = 1 / ((tc - tb) * h), w_b = w_a + w_c;
    double var = sigma * sigma;
    if (manual(ta, ka)) var += std::pow(click_px * w_a, 2);
    if (manual(tb, kb)) var += std::pow(click_px * w_b, 2);
    if (manual(tc, kc)) var += std::pow(click_px * w_c, 2);
    const double z = std::hypot(a.x, a.y) / std::sqrt(var);
    return std::min(0.5 * z * z, kMarkAccCap);
  }
  if (tc - tb > 1) {
    // Found again after a gap: within reach of where the motion before it leads (linear
    // extrapolation), else something else has been found.
    const cv::Point2d d = pos(tc, kc) - (pos(tb, kb) + v1 * (tc - tb));
    if (norm(d) > 2 * radius + kAccRel * norm(v1) * (tc - tb)) return kInf;
  }
  const double z = norm(a) / sigma;
  return z > kAccGate ? kInf : 0.5 * z * z;
}

void PathSearch::forward() {
  // Per step, the states of each candidate's blocks (k, 1..G) by forward cost, cheapest first
  // (ties by index): made once the step's costs are final.
  std::vector<std::vector<int>> cheapest(T);
  for (int t = 1; t < T; ++t) {
    if (t >= 2) {
      std::vector<int>& order = cheapest[t - 1];
      order.resize(S[t - 1].size());
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
      const int K = static_cast<int>(steps[t - 1].c.size());
      for (int k = 0; k < K; ++k) {
        std::stable_sort(order.begin() + off[t - 1][k * G], order.begin() + off[t - 1][k * G + G],
                         [&](int a, int b) { return S[t - 1][a].F < S[t - 1][b].F; });
      }
    }
    for (PathState& s : S[t]) {
      const int tp = t - s.g;
      if (skips_mark(tp, t) || !gate(tp, s.j, t, s.k)) continue;
      const double u = steps[t].c[s.k].cost + kMissCost * (s.g - 1);
      if (tp == 0) {
        s.F = static_cast<float>(u);
        s.back = 0;
        continue;
      }
      // The predecessors (the states of tp ending at candidate j), cheapest first: accel() >= 0,
      // so the first costing more than the best so far ends the search. The same choice as
      // taking them in index order: of equal costs, the lowest index.
      double best = kInf;
      int arg = -1;
      const std::vector<int>& order = cheapest[tp];
      for (int x = off[tp][s.j * G]; x < off[tp][s.j * G + G]; ++x) {
        const int i = order[x];
        const PathState& q = S[tp][i];
        if (!(q.F < kInf) || q.F > best) break;
        const double c = q.F + accel(tp - q.g, q.j, tp, s.j, t, s.k);
        if (c < best || (c == best && i < arg)) {
          best = c;
          arg = i;
        }
      }
      if (arg >= 0) {
        s.F = static_cast<float>(u + best);
        s.back = arg;
      }
    }
  }
}

void PathSearch::backward() {
  struct Successor {
    double bound;  // its cost and B without the acceleration: no path through it costs less
    int t3, k3, idx;
  };
  std::vector<Successor> next;
  for (int t = T - 1; t >= 0; --t) {
    for (int k = 0; k < static_cast<int>(steps[t].c.size()); ++k) {
      // The successors of a path point at candidate k of step t (the same for every state
      // ending there), cheapest bound first: the acceleration cost is never negative and
      // rounding is monotone, so the first whose bound is no better than the best so far
      // ends the search with the same minimum as visiting them all.
      next.clear();
      for (int g3 = 1; g3 <= G && t + g3 < T; ++g3) {
        const int t3 = t + g3;
        if (skips_mark(t, t3)) break;
        for (int k3 = 0; k3 < static_cast<int>(steps[t3].c.size()); ++k3) {
          const auto [a, b] = block(t3, k3, g3);
          const int idx = a + k;  // the successor whose previous point is this one
          if (idx >= b || !gate(t, k, t3, k3)) continue;
          const double u = steps[t3].c[k3].cost + kMissCost * (g3 - 1);
          next.push_back({u + S[t3][idx].B, t3, k3, idx});
        }
      }
      std::sort(next.begin(), next.end(), [](const Successor& x, const Successor& y) { return x.bound < y.bound; });
      // The states ending at candidate k (step 0: its one state).
      const int first = t == 0 ? 0 : off[t][k * G], end = t == 0 ? 1 : off[t][k * G + G];
      for (int i = first; i < end; ++i) {
        PathState& s = S[t][i];
        double best = t >= last_mark ? kMissCost * (T - 1 - t) : kInf;  // ends after the last mark
        for (const Successor& n : next) {
          if (!(n.bound < best)) break;
          const int g3 = n.t3 - t;
          const double u = steps[n.t3].c[n.k3].cost + kMissCost * (g3 - 1);
          const double acc = t == 0 ? 0.0 : accel(t - s.g, s.j, t, s.k, n.t3, n.k3);
          best = std::min(best, u + acc + S[n.t3][n.idx].B);
        }
        s.B = static_cast<float>(best);
      }
    }
  }
}

BestPath PathSearch::best_path() const {
  // (The optimum is also S[0][0].B, the backward pass's best from the start.)
  BestPath p;
  p.total = last_mark == 0 ? kMissCost * (T - 1) : kInf;  // the start alone, every further frame lost
  int bs = 0;
  for (int t = std::max(1, last_mark); t < T; ++t) {
    for (int i = 0; i < static_cast<int>(S[t].size()); ++i) {
      const double c = S[t][i].F + kMissCost * (T - 1 - t);
      if (c < p.total) {
        p.total = c;
        p.end = t;
        bs = i;
      }
    }
  }
  p.chosen.assign(T, -1);
  for (int t = p.end, i = bs; t > 0;) {
    const PathState& s = S[t][i];
    p.chosen[t] = s.k;
    i = s.back;
    t -= s.g;
  }
  return p;
}

bool PathSearch::has_rival(int t, int k, double total, double rival_px) const {
  const Candidate& c = steps[t].c[k];
  bool rival = false;
  for (int r = 0; r < static_cast<int>(steps[t].c.size()) && !rival; ++r) {
    const Candidate& q = steps[t].c[r];
    if (r == k || std::hypot(q.x - c.x, q.y - c.y) <= rival_px) continue;
    double m = kInf;
    for (int i = off[t][r * G]; i < off[t][r * G + G]; ++i) m = std::min<double>(m, S[t][i].F + S[t][i].B);
    rival = m < total + kRivalMargin;
  }
  return rival;
}

PathForeground path_foreground(const std::vector<StepCandidates>& steps, const std::vector<int>& chosen) {
  const int T = static_cast<int>(steps.size());
  PathForeground out;
  std::vector<double> path_fg;
  for (int t = 1; t < T; ++t) {
    if (chosen[t] >= 0 && !steps[t].c[chosen[t]].manual) path_fg.push_back(steps[t].c[chosen[t]].fg);
  }
  if (!path_fg.empty()) out.typical = upper_median(std::move(path_fg));
  // The object where the user clicked it is the object: a path that spends most of its points
  // on a still patch (reached across a gap) does not lower what the object's difference is.
  if (T > 0 && !steps[0].c.empty()) out.typical = std::max(out.typical, steps[0].c[0].fg);
  // Per run of consecutive path frames, its median difference (an object slowing down at the
  // turning point of a swing sits in the background median for a frame or two; a run of
  // still texture after a gap does throughout).
  out.run.assign(T, 0);
  for (int t = 1; t < T;) {
    if (chosen[t] < 0) {
      ++t;
      continue;
    }
    int e = t;
    std::vector<double> v;
    for (; e < T && chosen[e] >= 0; ++e) {
      if (!steps[e].c[chosen[e]].manual) v.push_back(steps[e].c[chosen[e]].fg);
    }
    double run = out.typical;  // a run of marks alone is not background
    if (!v.empty()) run = upper_median(std::move(v));
    for (int i = t; i < e; ++i) out.run[i] = run;
    t = e;
  }
  return out;
}

}  // namespace tribolab::video::detail
