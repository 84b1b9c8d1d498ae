#include "video/correlation.hpp"

#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tribolab::video {
namespace {

// filter2D sums a float kernel of fewer than this many elements directly (OpenCV 4.6's
// threshold with SSE3; at or above it, it switches to Fourier transforms).
constexpr int kFilterDirectArea = 130;
// Band sums pay for their passes over the image from this many placements on, and direct
// sums per placement (normed_correlation_sums) are cheapest up to this many products
// (placements x template px): bench/video_bench.cpp, BM_NormedCorrelation.
constexpr int kBandsMinPlacements = 256;
constexpr int kSumsMaxProducts = 49152;

// The coefficient from the cross sum `num` (zero-mean template) and the product `den` of the
// template's and the placement's norms, as matchTemplate finishes it: within float rounding
// of ±1 it is ±1, and beyond (a flat placement or template, den ~ 0) 0.
float coefficient(double num, double den) {
  const double a = std::abs(num);
  const double v = a < den ? num / den : a < 1.125 * den ? (num > 0 ? 1.0 : -1.0) : 0.0;
  return std::isnan(v) ? -1.0f : static_cast<float>(v);
}

// The template less its mean, and its norm.
double zero_mean(const cv::Mat& templ, cv::Mat& t) {
  templ.convertTo(t, CV_32F, 1.0, -cv::mean(templ)[0]);
  return cv::norm(t);
}

// Σ img(y + i, x + j) t(i, j) over the template for every placement: the template cut into
// bands of rows that filter2D sums directly, each band's filter read where the whole template
// lies inside the image.
void band_cross_sums(const cv::Mat& img, const cv::Mat& t, cv::Mat& cross) {
  const cv::Size out(img.cols - t.cols + 1, img.rows - t.rows + 1);
  const int band = std::max(1, (kFilterDirectArea - 1) / t.cols);
  cross = cv::Mat::zeros(out, CV_32F);
  cv::Mat part;
  for (int r0 = 0; r0 < t.rows; r0 += band) {
    const int r1 = std::min(t.rows, r0 + band);
    const cv::Mat rows = img.rowRange(r0, r0 + out.height + (r1 - r0) - 1);
    cv::filter2D(rows, part, CV_32F, t.rowRange(r0, r1), cv::Point(0, 0), 0, cv::BORDER_CONSTANT | cv::BORDER_ISOLATED);
    cross += part(cv::Rect(cv::Point(), out));
  }
}

// By band sums, the placements' norms from integral images.
void correlate_bands(const cv::Mat& img, const cv::Mat& templ, cv::Mat& result) {
  cv::Mat t;
  const double tnorm = zero_mean(templ, t);
  cv::Mat cross;
  band_cross_sums(img, t, cross);
  cv::Mat sum, sqsum;
  cv::integral(img, sum, sqsum, CV_64F, CV_64F);
  result.create(cross.size(), CV_32F);
  const int tw = templ.cols, th = templ.rows, n = tw * th;
  for (int y = 0; y < result.rows; ++y) {
    const double* s0 = sum.ptr<double>(y);
    const double* s1 = sum.ptr<double>(y + th);
    const double* q0 = sqsum.ptr<double>(y);
    const double* q1 = sqsum.ptr<double>(y + th);
    const float* c = cross.ptr<float>(y);
    float* out = result.ptr<float>(y);
    for (int x = 0; x < result.cols; ++x) {
      const double s = s1[x + tw] - s1[x] - s0[x + tw] + s0[x];
      const double q = q1[x + tw] - q1[x] - q0[x + tw] + q0[x];
      out[x] = coefficient(c[x], std::sqrt(std::max(q - s * s / n, 0.0)) * tnorm);
    }
  }
}

}  // namespace

void normed_correlation_sums(const cv::Mat& img, const cv::Mat& templ, cv::Mat& result) {
  const int tw = templ.cols, th = templ.rows, n = tw * th;
  result.create(img.rows - th + 1, img.cols - tw + 1, CV_32F);
  thread_local cv::Mat t;
  const double tnorm = zero_mean(templ, t);
  for (int v = 0; v < result.rows; ++v) {
    for (int u = 0; u < result.cols; ++u) {
      double sum = 0, sum2 = 0, cross = 0;
      for (int y = 0; y < th; ++y) {
        const float* row = img.ptr<float>(v + y) + u;
        const float* tr = t.ptr<float>(y);
        // OpenCV's universal intrinsics: a vector of floats per partial sum (a float sum in
        // order is not vectorised by the compiler).
        cv::v_float32 a1 = cv::vx_setzero_f32(), a2 = cv::vx_setzero_f32(), ac = cv::vx_setzero_f32();
        int x = 0;
        for (; x + cv::v_float32::nlanes <= tw; x += cv::v_float32::nlanes) {
          const cv::v_float32 a = cv::vx_load(row + x);
          a1 += a;
          a2 = cv::v_fma(a, a, a2);
          ac = cv::v_fma(a, cv::vx_load(tr + x), ac);
        }
        float s1 = cv::v_reduce_sum(a1), s2 = cv::v_reduce_sum(a2), sc = cv::v_reduce_sum(ac);
        for (; x < tw; ++x) {
          s1 += row[x];
          s2 += row[x] * row[x];
          sc += row[x] * tr[x];
        }
        sum += s1;
        sum2 += s2;
        cross += sc;
      }
      result.at<float>(v, u) = coefficient(cross, std::sqrt(std::max(0.0, sum2 - sum * sum / n)) * tnorm);
    }
  }
}

void half_resolution(const cv::Mat& src, cv::Mat& dst) {
  CV_Assert(src.type() == CV_32FC1 && !src.empty());
  const int w = src.cols, h = src.rows, dw = (w + 1) / 2, dh = (h + 1) / 2;
  // BORDER_REFLECT_101 (for an image of one pixel, that pixel).
  const auto reflect = [](int i, int n) { return n == 1 ? 0 : cv::borderInterpolate(i, n, cv::BORDER_REFLECT_101); };
  constexpr int kLanes = cv::v_float32::nlanes;
  const cv::v_float32 six = cv::vx_setall_f32(6), four = cv::vx_setall_f32(4), scale = cv::vx_setall_f32(1.0f / 256);
  // Each output row: the five source rows about twice its index summed down (weights 1 4 6 4 1),
  // then across at every other column (OpenCV's universal intrinsics, even and odd columns
  // loaded apart), scaled by 1/256 at the end as pyrDown does.
  thread_local std::vector<float> down;
  down.resize(static_cast<std::size_t>(w));
  dst.create(dh, dw, CV_32F);
  for (int y = 0; y < dh; ++y) {
    const int c = 2 * y;
    const float* r0 = src.ptr<float>(reflect(c - 2, h));
    const float* r1 = src.ptr<float>(reflect(c - 1, h));
    const float* r2 = src.ptr<float>(reflect(c, h));
    const float* r3 = src.ptr<float>(reflect(c + 1, h));
    const float* r4 = src.ptr<float>(reflect(c + 2, h));
    float* v = down.data();
    int x = 0;
    for (; x + kLanes <= w; x += kLanes) {
      const cv::v_float32 mid = cv::vx_load(r1 + x) + cv::vx_load(r3 + x);
      const cv::v_float32 outer = cv::vx_load(r0 + x) + cv::vx_load(r4 + x);
      cv::v_store(v + x, cv::v_fma(cv::vx_load(r2 + x), six, cv::v_fma(mid, four, outer)));
    }
    for (; x < w; ++x) v[x] = r2[x] * 6 + (r1[x] + r3[x]) * 4 + r0[x] + r4[x];
    float* d = dst.ptr<float>(y);
    const auto across = [&](int i) {
      const int k = 2 * i;
      return (v[reflect(k, w)] * 6 + (v[reflect(k - 1, w)] + v[reflect(k + 1, w)]) * 4 + v[reflect(k - 2, w)] +
              v[reflect(k + 2, w)]) *
             (1.0f / 256);
    };
    // Output column 0 reflects; from column 1 on, kLanes columns at a time read
    // v[2x - 2 .. 2x + 2 kLanes + 1], inside while 2x + 2 kLanes + 1 <= w - 1.
    int i = 0;
    for (; i < std::min(1, dw); ++i) d[i] = across(i);
    for (; 2 * i + 2 * kLanes + 1 <= w - 1; i += kLanes) {
      cv::v_float32 a, b, e, f, g, unused;
      cv::v_load_deinterleave(v + 2 * i - 2, a, b);  // v[2x - 2], v[2x - 1]
      cv::v_load_deinterleave(v + 2 * i, e, f);      // v[2x], v[2x + 1]
      cv::v_load_deinterleave(v + 2 * i + 2, g, unused);  // v[2x + 2]
      cv::v_store(d + i, cv::v_fma(e, six, cv::v_fma(b + f, four, a + g)) * scale);
    }
    for (; i < dw; ++i) d[i] = across(i);
  }
}

void normed_correlation(const cv::Mat& img, const cv::Mat& templ, cv::Mat& result) {
  CV_Assert(img.type() == CV_32FC1 && templ.type() == CV_32FC1 && img.cols >= templ.cols && img.rows >= templ.rows);
  const int area = templ.cols * templ.rows;
  const int placements = (img.cols - templ.cols + 1) * (img.rows - templ.rows + 1);
  if (area <= kDirectNccMaxArea && placements >= kBandsMinPlacements) {
    correlate_bands(img, templ, result);
  } else if (static_cast<long>(placements) * area <= kSumsMaxProducts) {
    normed_correlation_sums(img, templ, result);
  } else {
    cv::matchTemplate(img, templ, result, cv::TM_CCOEFF_NORMED);
    cv::patchNaNs(result, -1);
  }
}

}  // namespace tribolab::video
