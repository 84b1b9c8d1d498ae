#include "video/ellipse_fit.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
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

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

/// Algebraic fit (OpenCV's AMS, Taubin-like, low bias) on points centred first so that
/// single precision loses nothing; false when the points do not make an ellipse.
bool fit_points(const std::vector<cv::Point2d>& pts, Ellipse& out) {
  if (pts.size() < 6) return false;
  double mx = 0, my = 0;
  for (const auto& p : pts) mx += p.x, my += p.y;
  mx /= static_cast<double>(pts.size());
  my /= static_cast<double>(pts.size());
  std::vector<cv::Point2f> centred;
  centred.reserve(pts.size());
  for (const auto& p : pts) centred.emplace_back(static_cast<float>(p.x - mx), static_cast<float>(p.y - my));
  const cv::RotatedRect box = cv::fitEllipseAMS(centred);
  Ellipse e = ellipse_from_box(box);
  if (!std::isfinite(e.cx) || !std::isfinite(e.cy) || !std::isfinite(e.a) || !std::isfinite(e.b) ||
      !std::isfinite(e.psi) || e.b <= 0.5) {
    return false;
  }
  e.cx += mx;
  e.cy += my;
  out = e;
  return true;
}

/// Robust refit: fit, drop points farther than 3 robust sds (at least 0.25 px), refit.
bool robust_fit(std::vector<cv::Point2d> pts, EdgeFit& fit) {
  Ellipse e;
  if (!fit_points(pts, e)) return false;
  for (int round = 0; round < 2; ++round) {
    std::vector<double> absd;
    absd.reserve(pts.size());
    const Prepared q(e);
    for (const auto& p : pts) absd.push_back(std::abs(q.distance(p.x, p.y)));
    const double sd = 1.4826 * median(absd);
    const double cut = std::max(3 * sd, 0.25);
    std::vector<cv::Point2d> kept;
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
    const double d = ellipse_distance(e, p.x, p.y);
    ss += d * d;
  }
  fit.ellipse = e;
  fit.inliers = static_cast<int>(pts.size());
  fit.rms_px = std::sqrt(ss / static_cast<double>(pts.size()));
  fit.points = std::move(pts);
  return true;
}

/// Robust pose fit with the shape held: Gauss-Newton on the Sampson distances with Tukey
/// biweights (c = 4.685 robust sds, the sd at least 0.1 px), starting from `e`. Returns the
/// points within 3 robust sds (at least 0.3 px) of the fitted outline.
std::vector<cv::Point2d> pose_inliers(const std::vector<cv::Point2d>& pts, Ellipse& e) {
  const std::size_t n = pts.size();
  std::vector<double> d(n), absd(n);
  const auto residuals = [&] {
    const Prepared q(e);
    for (std::size_t i = 0; i < n; ++i) absd[i] = std::abs(d[i] = q.distance(pts[i].x, pts[i].y));
  };
  // Gauss-Newton steps with Tukey weights of width c; false when the system is singular.
  const auto step = [&](double c) {
    cv::Matx33d H = cv::Matx33d::zeros();
    cv::Vec3d g(0, 0, 0);
    constexpr double h = 1e-5;
    Ellipse ex = e, ey = e, ep = e;
    ex.cx += h, ey.cy += h, ep.psi += h;
    const Prepared qx(ex), qy(ey), qp(ep);
    for (std::size_t i = 0; i < n; ++i) {
      if (absd[i] >= c) continue;
      const double w = (1 - (d[i] / c) * (d[i] / c)) * (1 - (d[i] / c) * (d[i] / c));
      const cv::Vec3d J((qx.distance(pts[i].x, pts[i].y) - d[i]) / h, (qy.distance(pts[i].x, pts[i].y) - d[i]) / h,
                        (qp.distance(pts[i].x, pts[i].y) - d[i]) / h);
      H += w * J * J.t();
      g += w * d[i] * J;
    }
    cv::Vec3d dx;
    if (!cv::solve(H, -g, dx, cv::DECOMP_CHOLESKY)) return false;
    e.cx += dx[0], e.cy += dx[1], e.psi += dx[2];
    return std::abs(dx[0]) + std::abs(dx[1]) + e.a * std::abs(dx[2]) > 1e-4;
  };
  // Width from the residuals' robust sd (the start may be a few px off), then narrowed to
  // 1.2 px so that points of an occluder or a touching object drop out completely.
  for (int it = 0; it < 12; ++it) {
    residuals();
    if (!step(4.685 * std::max(1.4826 * median(absd), 0.1))) break;
  }
  for (int it = 0; it < 8; ++it) {
    residuals();
    if (!step(std::min(1.2, 4.685 * std::max(1.4826 * median(absd), 0.1)))) break;
  }
  residuals();
  std::vector<double> near;
  for (double a : absd) {
    if (a < 1.2) near.push_back(a);
  }
  const double cut = std::max(3 * 1.4826 * median(near), 0.3);
  std::vector<cv::Point2d> kept;
  for (std::size_t i = 0; i < n; ++i) {
    if (absd[i] <= cut) kept.push_back(pts[i]);
  }
  return kept;
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
    if (!(e.a > 0 && e.b > 0)) return fit;
    // Normals evenly spaced in the parametric angle (denser at the tips, which carry the
    // orientation), about one per 3 px of perimeter.
    const double perimeter = kPi * (3 * (e.a + e.b) - std::sqrt((3 * e.a + e.b) * (e.a + 3 * e.b)));
    const int n = std::clamp(static_cast<int>(perimeter / 3), 24, 120);
    const double inner = std::min(options.reach_px, 0.7 * e.b);  // stay clear of the far side
    const double outer = options.reach_px;
    const double ds = options.step_px;
    const int m = static_cast<int>(std::floor((inner + outer) / ds)) + 1;
    const double c = std::cos(e.psi), s = std::sin(e.psi);
    std::vector<cv::Point2d> pts;
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
      if (!inside_image) continue;
      double lo = 0, hi = 0;
      for (int i = 0; i < plateau; ++i) {
        lo += prof[static_cast<std::size_t>(i)];
        hi += prof[static_cast<std::size_t>(m - 1 - i)];
      }
      lo /= plateau, hi /= plateau;
      if (hi - lo < options.min_contrast || lo > options.max_inside) continue;
      // First moment of the edge: the object's occupancy (hi - D)/(hi - lo) summed along the
      // profile is the distance from the profile's start to the edge, i.e. the mean edge
      // position over the exposure for a blurred edge (docs/theory.md#ellipse-tracking).
      double occupancy = 0;
      for (int i = 0; i < m; ++i) occupancy += (hi - prof[static_cast<std::size_t>(i)]) / (hi - lo);
      const double r_edge = -inner - 0.5 * ds + occupancy * ds;
      if (r_edge < -inner + ds || r_edge > -inner + (m - 2) * ds) continue;
      pts.emplace_back(px + r_edge * nx + offset.x, py + r_edge * ny + offset.y);
    }
    fit.profiles = n;
    if (options.known_a > 0 && options.known_b > 0 && pts.size() >= 6) {
      Ellipse pose = e;
      pose.a = options.known_a, pose.b = options.known_b;
      std::vector<cv::Point2d> kept = pose_inliers(pts, pose);
      if (static_cast<int>(kept.size()) < std::max(8, n / 4)) return fit;
      if (kept.size() < 0.9 * static_cast<double>(pts.size())) {
        // Part of the outline is hidden or touches something: a free fit on the rest would
        // bend; the pose with the known shape is the answer.
        double ss = 0;
        for (const auto& p : kept) ss += ellipse_distance(pose, p.x, p.y) * ellipse_distance(pose, p.x, p.y);
        fit.ellipse = pose;
        fit.inliers = static_cast<int>(kept.size());
        fit.rms_px = std::sqrt(ss / static_cast<double>(kept.size()));
        fit.points = std::move(kept);
        e = pose;
        fit.ok = true;
        continue;
      }
      pts = std::move(kept);
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

}  // namespace tribolab::video
