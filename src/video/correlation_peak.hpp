// Sub-pixel peaks of correlation maps, shared by the point trackers
// (docs/theory.md#point-tracking, item 6).
#pragma once

#include <opencv2/core.hpp>

namespace tribolab::video {

/// Vertex of the parabola through (-1, fm), (0, f0), (1, fp), clamped to [-1, 1]; 0 when it
/// has no maximum.
double parabola_vertex(double fm, double f0, double fp);

/// Sub-pixel offset of the maximum of `r` (CV_32F) near integer peak p: least-squares
/// quadratic over the 3x3 neighbourhood, stationary point; `value` (if given) receives the
/// fitted maximum. Falls back to a parabola per axis when that surface has no maximum within
/// a pixel, and to 0 on the border of r.
cv::Point2d subpixel_peak(const cv::Mat& r, cv::Point p, double* value = nullptr);

}  // namespace tribolab::video
