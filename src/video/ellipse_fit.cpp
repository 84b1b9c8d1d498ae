#include "video/ellipse_fit.hpp"
#include "numerics/statistics.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace tribolab::video {
namespace {

constexpr double kPi = std::numbers::pi;

/// An ellipse with its trigonometry done once, for distances to many points.
struct Prepared {
  double cx, cy, c, s, ia2, ib2, b;
  explicit Prepared(const Ellipse& e)
      : cx(e.cx), cy(e.cy), c(std::cos(e.psi)), s(std::sin(e.psi)), ia2(1 / (e.a * e.a)), ib2(1 / (e.b * e.b)), b(e.b) {}
  /// Sampson distance F / |grad F| of F = u^2/a^2 + v^2/b^2 - 1 in the ellipse frame (u, v).
  double distance(double x, double y) const {
    const double dx = x - cx, dy = y - cy;
    const double u = c * dx + s * dy, v = -s * dx + c * dy;
    const double f = u * u * ia2 + v * v * ib2 - 1;
    const double gu = 2 * u * ia2, gv = 2 * v * ib2;
    const double g = std::sqrt(gu * gu + gv * gv);
    return g > 0 ? f / g : -b;
  }
};

/// Bilinear interpolation of a CV_32F image at (x, y); false outside its pixel centres.
bool sample(const cv::Mat& img, double x, double y, double& value) {
  if (!(x >= 0 && y >= 0 && x <= img.cols - 1 && y <= img.rows - 1)) return false;
  const int x0 = std::min(static_cast<int>(x), img.cols - 2 < 0 ? 0 : img.cols - 2);
  const int y0 = std::min(static_cast<int>(y), img.rows - 2 < 0 ? 0 : img.rows - 2);
  const int x1 = std::min(x0 + 1, img.cols - 1), y1 = std::min(y0 + 1, img.rows - 1);
  const double fx = x - x0, fy = y - y0;
  const float* r0 = img.ptr<float>(y0);
  const float* r1 = img.ptr<float>(y1);
  value = (1 - fy) * ((1 - fx) * r0[x0] + fx * r0[x1]) + fy * ((1 - fx) * r1[x0] + fx * r1[x1]);
  return true;
}


/// Algebraic fit (OpenCV's AMS, Taubin-like, low bias) on points centred first so that
/// single precision loses nothing; false when the points do not make an ellipse.
bool fit_points(const std::vector<EdgePoint>& pts, Ellipse& out) {
  if (pts.size() < 6) return false;
  double mx = 0, my = 0;
  for (const auto& p : pts) mx += p.at.x, my += p.at.y;
  mx /= static_cast<double>(pts.size());
  my /= static_cast<double>(pts.size());
  std::vector<cv::Point2f> centred;
  centred.reserve(pts.size());
  for (const auto& p : pts) centred.emplace_back(static_cast<float>(p.at.x - mx), static_cast<float>(p.at.y - my));
  const cv::RotatedRect box = cv::fitEllipseAMS(centred);
  Ellipse e = ellipse_from_box(box);
  if (!std::isfinite(e.cx) || !std::isfinite(e.cy) || !std::isfinite(e.a) || !std::isfinite(e.b) ||
      !std::isfinite(e.psi) || e.b <= 0.5 || e.a > 1e5) {
    return false;
  }
  e.cx += mx;
  e.cy += my;
  out = e;
  return true;
}

/// Robust refit: fit, drop points farther than 3 robust sds (at least 0.25 px), refit.
bool robust_fit(std::vector<EdgePoint> pts, EdgeFit& fit) {
  Ellipse e;
  if (!fit_points(pts, e)) return false;
  for (int round = 0; round < 2; ++round) {
    std::vector<double> absd;
    absd.reserve(pts.size());
    const Prepared q(e);
    for (const auto& p : pts) absd.push_back(std::abs(q.distance(p.at.x, p.at.y)));
    const double sd = kMadToSd * upper_median(absd);
    const double cut = std::max(3 * sd, 0.25);
    std::vector<EdgePoint> kept;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (absd[i] <= cut) kept.push_back(pts[i]);
    }
    if (kept.size() == pts.size()) break;
    Ellipse refit;
    if (!fit_points(kept, refit)) return false;
    pts = std::move(kept);
    e = refit;
  }
  double ss = 0;
  for (const auto& p : pts) {
    const double d = ellipse_distance(e, p.at.x, p.at.y);
    ss += d * d;
  }
  fit.ellipse = e;
  fit.inliers = static_cast<int>(pts.size());
  fit.rms_px = std::sqrt(ss / static_cast<double>(pts.size()));
  fit.points = std::move(pts);
  return true;
}

/// Robust geometric fit from `e`: Gauss-Newton on the Sampson distances with Tukey biweights,
/// the semi-axes tied to (a0, b0) by a prior of sd `shape_sd_px` (one point's residual of 1 px
/// weighs as much as an axis off by one sd). First the pose alone (axes held) with the weights'
/// width from the residuals' robust sd, 4.685 sd (the start may be a few px off), then pose and
/// axes with the width narrowed to 1.2 px so that points on an occluder or a touching object
/// drop out completely. Returns the points within 3 robust sds (at least 0.3 px) of the result.
std::vector<EdgePoint> geometric_inliers(const std::vector<EdgePoint>& pts, Ellipse& e, double a0, double b0,
                                         double shape_sd_px) {
  const std::size_t n = pts.size();
  std::vector<double> d(n), absd(n);
  const auto residuals = [&] {
    const Prepared q(e);
    for (std::size_t i = 0; i < n; ++i) absd[i] = std::abs(d[i] = q.distance(pts[i].at.x, pts[i].at.y));
  };
  using Vec5 = cv::Vec<double, 5>;
  // One Gauss-Newton step with Tukey weights of width c; false when converged or singular.
  const auto step = [&](double c, double sd) {
    cv::Matx<double, 5, 5> H = cv::Matx<double, 5, 5>::zeros();
    Vec5 g = Vec5::all(0);
    constexpr double h = 1e-5;
    std::array<Ellipse, 5> shifted;
    shifted.fill(e);
    shifted[0].cx += h, shifted[1].cy += h, shifted[2].psi += h, shifted[3].a += h, shifted[4].b += h;
    const std::array<Prepared, 5> q{Prepared(shifted[0]), Prepared(shifted[1]), Prepared(shifted[2]),
                                    Prepared(shifted[3]), Prepared(shifted[4])};
    for (std::size_t i = 0; i < n; ++i) {
      if (absd[i] >= c) continue;
      const double u = d[i] / c, w = (1 - u * u) * (1 - u * u);
      Vec5 J;
      for (int k = 0; k < 5; ++k) J[k] = (q[static_cast<std::size_t>(k)].distance(pts[i].at.x, pts[i].at.y) - d[i]) / h;
      H += w * J * J.t();
      g += w * d[i] * J;
    }
    H(3, 3) += 1 / (sd * sd), H(4, 4) += 1 / (sd * sd);  // prior on the axes
    g[3] += (e.a - a0) / (sd * sd), g[4] += (e.b - b0) / (sd * sd);
    Vec5 dx;
    if (!cv::solve(H, -g, dx, cv::DECOMP_CHOLESKY)) return false;
    e.cx += dx[0], e.cy += dx[1], e.psi += dx[2], e.a += dx[3], e.b += dx[4];
    if (!(e.b > 0.5 && e.a > 0.5)) return false;
    return std::abs(dx[0]) + std::abs(dx[1]) + e.a * std::abs(dx[2]) + std::abs(dx[3]) + std::abs(dx[4]) > 1e-3;  // px
  };
  e.a = a0, e.b = b0;
  for (int it = 0; it < 12; ++it) {
    residuals();
    if (!step(4.685 * std::max(kMadToSd * upper_median(absd), 0.1), 1e-4)) break;
  }
  for (int it = 0; it < 8; ++it) {
    residuals();
    if (!step(std::min(1.2, 4.685 * std::max(kMadToSd * upper_median(absd), 0.1)), shape_sd_px)) break;
  }
  if (e.a < e.b) std::swap(e.a, e.b), e.psi += kPi / 2;
  e.psi = std::remainder(e.psi, kPi);
  residuals();
  std::vector<double> near;
  for (double a : absd) {
    if (a < 1.2) near.push_back(a);
  }
  const double cut = std::max(3 * kMadToSd * (near.empty() ? 0.0 : upper_median(near)), 0.3);
  std::vector<EdgePoint> kept;
  for (std::size_t i = 0; i < n; ++i) {
    if (absd[i] <= cut) kept.push_back(pts[i]);
  }
  return kept;
}

/// The ellipse refitted to `pts` from `e` with its semi-axes tied to (a0, b0) by a prior of
/// 5 % (fit_ellipse_edges' fit of a known shape); false when fewer than `least` points are
/// kept or the result is not finite.
bool known_shape_fit(const std::vector<EdgePoint>& pts, Ellipse e, double a0, double b0, int least, EdgeFit& fit) {
  if (static_cast<int>(pts.size()) < std::max(least, 6)) return false;
  std::vector<EdgePoint> kept = geometric_inliers(pts, e, a0, b0, std::max(0.05 * a0, 0.3));
  if (static_cast<int>(kept.size()) < least || !std::isfinite(e.cx) || !std::isfinite(e.cy) || !std::isfinite(e.psi) ||
      !(e.a < 1e5)) {
    return false;
  }
  double ss = 0;
  const Prepared q(e);
  for (const auto& p : kept) ss += q.distance(p.at.x, p.at.y) * q.distance(p.at.x, p.at.y);
  fit.ellipse = e;
  fit.inliers = static_cast<int>(kept.size());
  fit.rms_px = std::sqrt(ss / static_cast<double>(kept.size()));
  fit.points = std::move(kept);
  return true;
}

/// An edge along a profile: its position and the length of its ramp, px (NaN: none).
struct EdgePlace {
  double r = std::nan("");
  double ramp = std::nan("");
};

/// Edge along a profile (prof[i] at r = -inner + i ds). The crossing of the mid-level between
/// the far plateaus `lo` (inside) and `hi` (outside) nearest r = 0 places a window of
/// half-width w = 1.5 px + ramp/2 (the blur's half-length) around the edge; inside it, the
/// first moment of the object's occupancy (hi' - D)/(hi' - lo'), with lo', hi' the means of the
/// 1.5 px just beyond each end of the window, is the mean edge position over the exposure.
/// Local levels keep a textured or graded background from biasing the edge. The ramp's length
/// is twice the span between the occupancy's three-quarter and quarter crossings (a linear
/// ramp's middle half).
EdgePlace edge_position(const std::vector<double>& prof, int m, double lo, double hi, double inner, double ds,
                        double ramp_px) {
  EdgePlace out;
  const double mid = 0.5 * (lo + hi);
  const auto at = [&](int i) { return prof[static_cast<std::size_t>(i)]; };
  int cross = -1;  // the edge lies between samples cross and cross + 1
  double best = 1e300;
  for (int i = 0; i + 1 < m; ++i) {
    if ((at(i) < mid) != (at(i + 1) < mid)) {
      const double r = -inner + (i + 0.5) * ds;
      if (std::abs(r) < best) best = std::abs(r), cross = i;
    }
  }
  if (cross < 0) return out;
  const int w = static_cast<int>(std::ceil((1.5 + 0.5 * std::min(ramp_px, 1e4)) / ds));
  const int k = static_cast<int>(std::ceil(1.5 / ds));  // samples per local level
  const int first = std::max(k, cross - w + 1), last = std::min(m - 1 - k, cross + w);  // window
  if (last - first < 2) return out;
  double lo_l = 0, hi_l = 0;
  for (int j = 1; j <= k; ++j) lo_l += at(first - j), hi_l += at(last + j);
  lo_l /= k, hi_l /= k;
  if (hi_l - lo_l < 0.5 * (hi - lo)) return out;  // no clear step at this place
  const auto occ = [&](int i) { return (hi_l - at(i)) / (hi_l - lo_l); };
  double occupancy = 0;
  for (int i = first; i <= last; ++i) occupancy += occ(i);
  const double r_edge = -inner + (first - 0.5) * ds + occupancy * ds;
  if (r_edge < -inner + first * ds || r_edge > -inner + last * ds) return out;
  out.r = r_edge;
  int o = cross + 1, n = cross;  // the first samples past the quarter and three-quarter crossings
  while (o < last && occ(o) > 0.25) ++o;
  while (n > first && occ(n) < 0.75) --n;
  if (o < last && n > first && occ(o - 1) > occ(o) && occ(n) > occ(n + 1)) {
    const double r_quarter = (o - 1) + (occ(o - 1) - 0.25) / (occ(o - 1) - occ(o));
    const double r_three = n + (occ(n) - 0.75) / (occ(n) - occ(n + 1));
    out.ramp = 2 * (r_quarter - r_three) * ds;
  }
  return out;
}

/// Where the line p + r n crosses the outline of `e` on its outer side (the larger root), or
/// NaN when the line misses the ellipse.
double outer_crossing(const Ellipse& e, cv::Point2d p, cv::Point2d n) {
  const double c = std::cos(e.psi), s = std::sin(e.psi);
  const double dx = p.x - e.cx, dy = p.y - e.cy;
  const double u0 = c * dx + s * dy, v0 = -s * dx + c * dy;
  const double du = c * n.x + s * n.y, dv = -s * n.x + c * n.y;
  const double ia = 1 / (e.a * e.a), ib = 1 / (e.b * e.b);
  const double qa = du * du * ia + dv * dv * ib, qb = 2 * (u0 * du * ia + v0 * dv * ib);
  const double qc = u0 * u0 * ia + v0 * v0 * ib - 1;
  const double disc = qb * qb - 4 * qa * qc;
  if (!(disc >= 0) || !(qa > 0)) return std::nan("");
  return (-qb + std::sqrt(disc)) / (2 * qa);
}

/// How far the mean over the exposure of the moving outline's crossing of the normal line
/// p + r n lies beyond the crossing of `e` itself (the ellipse at mid-exposure): the ellipse
/// moved by t x v + t^2 x^2 acc / 2 and turned by t x turn for t from -1/2 to 1/2 across an
/// exposure of x frame periods, averaged over 16 sub-poses. Zero without motion; NaN when a
/// sub-pose misses the line.
double exposure_offset(const Ellipse& e, cv::Point2d p, cv::Point2d n, const FrameMotion& m, double x) {
  constexpr int kSubPoses = 16;
  const double r0 = outer_crossing(e, p, n);
  double sum = 0;
  for (int k = 0; k < kSubPoses; ++k) {
    const double t = (k + 0.5) / kSubPoses - 0.5;
    Ellipse q = e;
    q.cx += t * x * m.velocity.x + 0.5 * t * t * x * x * m.acceleration.x;
    q.cy += t * x * m.velocity.y + 0.5 * t * t * x * x * m.acceleration.y;
    q.psi += t * x * m.turn_rad;
    const double r = outer_crossing(q, p, n);
    if (!std::isfinite(r)) return std::nan("");
    sum += r;
  }
  return sum / kSubPoses - r0;
}

}  // namespace

Ellipse ellipse_from_box(const cv::RotatedRect& box) {
  Ellipse e;
  e.cx = box.center.x;
  e.cy = box.center.y;
  const double w = 0.5 * box.size.width, h = 0.5 * box.size.height;
  const double ang = box.angle * kPi / 180;  // direction of the `width` axis, image coordinates
  if (w >= h) {
    e.a = w, e.b = h, e.psi = ang;
  } else {
    e.a = h, e.b = w, e.psi = ang + kPi / 2;
  }
  e.psi = std::remainder(e.psi, kPi);
  return e;
}

Ellipse ellipse_from_moments(const cv::Mat& mask, cv::Point2d offset) {
  const cv::Moments m = cv::moments(mask, true);
  Ellipse e;
  if (m.m00 <= 0) return e;
  e.cx = m.m10 / m.m00 + offset.x;
  e.cy = m.m01 / m.m00 + offset.y;
  const double sxx = m.mu20 / m.m00, syy = m.mu02 / m.m00, sxy = m.mu11 / m.m00;
  const double mean = 0.5 * (sxx + syy);
  const double diff = std::sqrt(0.25 * (sxx - syy) * (sxx - syy) + sxy * sxy);
  e.a = 2 * std::sqrt(std::max(mean + diff, 0.0));
  e.b = 2 * std::sqrt(std::max(mean - diff, 0.0));
  e.psi = 0.5 * std::atan2(2 * sxy, sxx - syy);
  return e;
}

double ellipse_distance(const Ellipse& e, double x, double y) { return Prepared(e).distance(x, y); }

EdgeFit fit_ellipse_edges(const cv::Mat& contrast, cv::Point offset, const Ellipse& init,
                          const EdgeFitOptions& options) {
  CV_Assert(contrast.type() == CV_32F);
  EdgeFit fit;
  Ellipse e = init;
  for (int iter = 0; iter < options.iterations; ++iter) {
    if (!(e.a > 0 && e.b > 0 && e.a < 1e5 && std::isfinite(e.cx) && std::isfinite(e.cy))) return fit;
    // Normals evenly spaced in the parametric angle (denser at the tips, which carry the
    // orientation), about one per 3 px of perimeter.
    const double perimeter = kPi * (3 * (e.a + e.b) - std::sqrt((3 * e.a + e.b) * (e.a + 3 * e.b)));
    const int n = static_cast<int>(std::clamp(perimeter / 3, 24.0, 120.0));
    const double inner = std::min(options.reach_px, 0.7 * e.b);  // stay clear of the far side
    const double outer = options.reach_px;
    const double ds = options.step_px;
    const int m = static_cast<int>(std::floor(std::min(inner + outer, 1e4) / ds)) + 1;
    const double c = std::cos(e.psi), s = std::sin(e.psi);
    std::vector<EdgePoint> pts;
    int off_image = 0;
    std::vector<double> prof(static_cast<std::size_t>(m));
    const int plateau = std::max(2, m / 8);
    for (int k = 0; k < n; ++k) {
      const double t = 2 * kPi * k / n;
      const double u = e.a * std::cos(t), v = e.b * std::sin(t);
      const double px = e.cx + c * u - s * v - offset.x, py = e.cy + s * u + c * v - offset.y;
      double nu = std::cos(t) / e.a, nv = std::sin(t) / e.b;
      const double nn = std::hypot(nu, nv);
      nu /= nn, nv /= nn;
      const double nx = c * nu - s * nv, ny = s * nu + c * nv;
      bool inside_image = true;
      for (int i = 0; i < m && inside_image; ++i) {
        const double r = -inner + i * ds;
        inside_image = sample(contrast, px + r * nx, py + r * ny, prof[static_cast<std::size_t>(i)]);
      }
      if (!inside_image) {
        ++off_image;
        continue;
      }
      double lo = 0, hi = 0;
      for (int i = 0; i < plateau; ++i) {
        lo += prof[static_cast<std::size_t>(i)];
        hi += prof[static_cast<std::size_t>(m - 1 - i)];
      }
      lo /= plateau, hi /= plateau;
      if (hi - lo < options.min_contrast || lo > options.max_inside) continue;
      // Blur along this normal: travel of this boundary point along n in one frame.
      const double rx = c * u - s * v, ry = s * u + c * v;  // from the centre, image axes
      const double vn = (options.vx_px - options.dpsi_rad * ry) * nx + (options.vy_px + options.dpsi_rad * rx) * ny;
      const EdgePlace edge =
          edge_position(prof, m, lo, hi, inner, ds, std::min(std::abs(vn) + options.blur_px, options.max_blur_px));
      if (!std::isfinite(edge.r)) continue;
      pts.push_back({{px + edge.r * nx + offset.x, py + edge.r * ny + offset.y}, {nx, ny}, edge.ramp});
    }
    fit.profiles = n;
    fit.off_image = off_image;
    if (options.known_a > 0 && options.known_b > 0 && pts.size() >= 6) {
      // Known shape: robust geometric fit, the axes free within a prior of 5 % (a blurred or
      // turning object changes its outline; a hidden part must not bend it).
      if (!known_shape_fit(pts, e, options.known_a, options.known_b, std::max(8, n / 4), fit)) return fit;
      e = fit.ellipse;
      fit.ok = true;
      continue;
    }
    if (static_cast<int>(pts.size()) < std::max(8, n / 4)) {
      fit.ok = false;
      return fit;
    }
    if (!robust_fit(std::move(pts), fit)) {
      fit.ok = false;
      return fit;
    }
    e = fit.ellipse;
    fit.ok = true;
  }
  return fit;
}

void read_exposure(const std::vector<EdgePoint>& points, const Ellipse& e, const FrameMotion& m,
                   std::vector<double>& out) {
  constexpr double kLeastTravelPx = 8;  // a shorter ramp is mostly the edge's own width
  constexpr double kHeadOn = 0.9;       // share of the point's travel along the normal
  for (const EdgePoint& p : points) {
    if (!std::isfinite(p.ramp_px)) continue;
    const double rx = p.at.x - e.cx, ry = p.at.y - e.cy;
    const double vx = m.velocity.x - m.turn_rad * ry, vy = m.velocity.y + m.turn_rad * rx;
    const double along = std::abs(vx * p.normal.x + vy * p.normal.y);
    if (along >= kLeastTravelPx && along >= kHeadOn * std::hypot(vx, vy)) out.push_back(p.ramp_px / along);
  }
}

bool fit_at_frame_time(const std::vector<EdgePoint>& points, const Ellipse& found, double a0, double b0,
                       const FrameMotion& m, double exposure, Ellipse& out) {
  Ellipse e = found;
  for (int round = 0; round < 2; ++round) {
    std::vector<EdgePoint> moved;
    moved.reserve(points.size());
    for (const EdgePoint& p : points) {
      const double shift = exposure_offset(e, p.at, p.normal, m, exposure);
      if (!std::isfinite(shift)) continue;
      EdgePoint q = p;
      q.at -= shift * p.normal;
      moved.push_back(q);
    }
    EdgeFit fit;
    if (!known_shape_fit(moved, e, a0, b0, std::max(8, static_cast<int>(points.size()) / 2), fit)) return false;
    e = fit.ellipse;
  }
  out = e;
  return true;
}

}  // namespace tribolab::video
