// Sub-pixel ellipse fitting on a contrast image (docs/theory.md#ellipse-tracking), the
// numerical core of EllipseTracker: edge points located along the normals of an estimated
// ellipse by the first moment of the edge profile, and a robust algebraic refit.
#pragma once

#include <opencv2/core.hpp>

#include <limits>
#include <vector>

namespace tribolab::video {

/// An ellipse in image coordinates (x right, y down), px.
struct Ellipse {
  double cx = 0, cy = 0;  ///< centre, px
  double a = 0, b = 0;    ///< semi-major >= semi-minor axis, px
  double psi = 0;         ///< major-axis direction in image coordinates (y down), rad, mod pi
};

/// Converts OpenCV's RotatedRect (full axes, angle in degrees of the `width` axis) to an Ellipse.
Ellipse ellipse_from_box(const cv::RotatedRect& box);

/// The ellipse of a binary region from its area moments (a filled ellipse has covariance
/// eigenvalues a^2/4 and b^2/4). `mask` is CV_8U, non-zero inside; offset added to the centre.
Ellipse ellipse_from_moments(const cv::Mat& mask, cv::Point2d offset);

/// Signed distance of (x, y) from the ellipse, px, to first order (Sampson: F / |grad F|).
double ellipse_distance(const Ellipse& e, double x, double y);

/// An edge point with the normal of the outline it was found along (image px).
struct EdgePoint {
  cv::Point2d at;      ///< the mean edge over the exposure, px
  cv::Point2d normal;  ///< unit, outward
  /// The edge's ramp along the normal, px: twice the span between the occupancy's quarter and
  /// three-quarter crossings (a linear ramp's length); NaN where it could not be read.
  double ramp_px = std::numeric_limits<double>::quiet_NaN();
};

struct EdgeFitOptions {
  double reach_px = 6;        ///< profile half-length outside the edge, px (covers the blur)
  /// The object's motion per frame, to size each profile's edge window to its blur (the
  /// edge's travel along the normal in one frame: the most an exposure can smear it).
  double vx_px = 0, vy_px = 0;  ///< centre velocity, px per frame (image axes)
  double dpsi_rad = 0;          ///< turn per frame in image axes (y down), rad
  double blur_px = 0;           ///< blur allowed along every normal besides, px (unknown motion)
  double max_blur_px = 1e4;     ///< cap on the blur allowed along a normal, px
  double step_px = 0.5;       ///< sampling step along the profile, px
  double min_contrast = 20;   ///< smallest outside - inside level of a usable profile
  double max_inside = 1e9;    ///< largest inside level of a usable profile (object-like)
  int iterations = 2;         ///< sample-and-refit rounds
  /// Known semi-axes (px; 0 = free): the pose (centre, orientation) is fitted first with the
  /// shape held, robustly (Tukey), so points off a partly hidden or touching object are
  /// rejected against the whole expected outline; the free fit then uses the inliers only.
  double known_a = 0, known_b = 0;
};

struct EdgeFit {
  Ellipse ellipse;            ///< the refined ellipse (valid when ok)
  bool ok = false;            ///< false: too few usable edge points
  int profiles = 0;           ///< normals sampled in the last round
  int inliers = 0;            ///< edge points kept by the robust fit in the last round
  int off_image = 0;          ///< normals of the last round that left the image
  double rms_px = 0;          ///< rms distance of the inliers from the ellipse, px
  std::vector<EdgePoint> points;  ///< inlier edge points, last round
};

/// Refines `init` on `contrast` (CV_32F, low inside the object, high outside; its pixel (0, 0)
/// is image pixel `offset`): edge points along normals, robust refit, `iterations` times.
EdgeFit fit_ellipse_edges(const cv::Mat& contrast, cv::Point offset, const Ellipse& init,
                          const EdgeFitOptions& options);

/// How an ellipse moves within one frame period (image axes, y down).
struct FrameMotion {
  cv::Point2d velocity;          ///< centre, px per frame
  cv::Point2d acceleration;      ///< centre, px per frame squared
  double turn_rad = 0;           ///< turn per frame in image axes, rad
};

/// The exposure, a fraction of the frame period, read from the edge points of `e` moving as
/// `m`: for each normal the motion crosses head-on (its boundary point travels 8 px or more per
/// frame, nine tenths of it along the normal) the ramp's length over that travel. Appended to
/// `out` (docs/theory.md#ellipse-tracking, item 4).
void read_exposure(const std::vector<EdgePoint>& points, const Ellipse& e, const FrameMotion& m,
                   std::vector<double>& out);

/// The ellipse at the frame's time (mid-exposure) from edge points of the blurred outline. A
/// profile's edge is the mean over the exposure of where the moving outline crosses that fixed
/// normal line; where the outline slides along itself (the tips of a falling ball) that lies
/// inside the mid-exposure ellipse by about (v_t T_e)^2 / (24 rho), and a parabola's piece lies
/// below its middle by acc T_e^2 / 24. Each point is moved by that difference, computed on the
/// ellipse being refined (16 sub-poses across an exposure of `exposure` frame periods), and
/// the ellipse refitted robustly from `found` with its semi-axes tied to (a0, b0) as
/// fit_ellipse_edges does for a known shape; twice. False when too few points remain.
bool fit_at_frame_time(const std::vector<EdgePoint>& points, const Ellipse& found, double a0, double b0,
                       const FrameMotion& m, double exposure, Ellipse& out);

}  // namespace tribolab::video
