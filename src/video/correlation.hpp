// Normalised cross-correlation of a template over an image, the trackers' search
// (docs/theory.md#tracking-on-real-film, "the correlation").
#pragma once

#include <opencv2/core.hpp>

namespace tribolab::video {

/// The correlation coefficient of `templ` with `img` at every placement of the template inside
/// the image (both CV_32F, one channel): `result` (CV_32F) is (img.rows - templ.rows + 1) x
/// (img.cols - templ.cols + 1), as cv::matchTemplate's TM_CCOEFF_NORMED gives it, its values
/// equal to those to float rounding (~1e-6), a flat placement 0 and NaN replaced by -1.
/// OpenCV computes it by Fourier transforms of blocks of the image, at a cost per placement
/// that does not fall with the template's size (~25 ns on one core). A template of at most
/// kDirectNccMaxArea px over many placements is correlated here by direct sums instead
/// (OpenCV's vectorised filter2D, the template cut into bands it sums directly; the
/// placements' norms from integral images): 2 times cheaper at 13 px, 3 times at 7 px; few
/// placements by normed_correlation_sums (bench/video_bench.cpp, BM_NormedCorrelation).
void normed_correlation(const cv::Mat& img, const cv::Mat& templ, cv::Mat& result);

/// The same by direct sums over each placement (cheapest for few placements: a refinement).
void normed_correlation_sums(const cv::Mat& img, const cv::Mat& templ, cv::Mat& result);

/// The next level of a Gaussian pyramid of `src` (CV_32F, one channel): cv::pyrDown's image
/// ((cols + 1) / 2 x (rows + 1) / 2, the kernel [1 4 6 4 1] / 16 each way at every other pixel,
/// borders reflected as BORDER_REFLECT_101) to float rounding, computed on the calling thread.
/// OpenCV 4.6 splits every pyrDown between its worker threads whatever the image's size, and
/// for a search window's few thousand pixels waking a worker costs more CPU than it saves: the
/// 1080p path tracker spent 107 ms of CPU per clip with pyrDown, 91 ms without
/// (docs/benchmarks.md#tracking-at-1080p).
void half_resolution(const cv::Mat& src, cv::Mat& dst);

/// The largest template area (px) that normed_correlation() correlates by direct sums.
inline constexpr int kDirectNccMaxArea = 225;

}  // namespace tribolab::video
