#include "video/correlation.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace tribolab::video {
namespace {

// A textured grey image (smoothed noise) with a bright disc, and optionally a flat square
// (x from size.width / 2, y from 5, 30 px).
cv::Mat texture(cv::Size size, unsigned seed, bool flat_square = false) {
  cv::Mat m(size, CV_32F);
  cv::RNG rng(seed);
  rng.fill(m, cv::RNG::UNIFORM, 0, 255);
  cv::circle(m, cv::Point(size.width / 4, size.height / 2), 6, cv::Scalar(240), cv::FILLED);
  cv::GaussianBlur(m, m, cv::Size(0, 0), 1.5);
  if (flat_square) m(cv::Rect(size.width / 2, 5, 30, 30)).setTo(90);
  return m;
}

// The coefficient at every placement in double precision, and the placement's standard
// deviation (grey levels).
void reference(const cv::Mat& img, const cv::Mat& templ, cv::Mat& r, cv::Mat& sd) {
  cv::Mat t;
  templ.convertTo(t, CV_64F);
  t -= cv::mean(t)[0];
  const double tn = cv::norm(t);
  r.create(img.rows - templ.rows + 1, img.cols - templ.cols + 1, CV_64F);
  sd.create(r.size(), CV_64F);
  for (int y = 0; y < r.rows; ++y) {
    for (int x = 0; x < r.cols; ++x) {
      cv::Mat w;
      img(cv::Rect(cv::Point(x, y), templ.size())).convertTo(w, CV_64F);
      cv::Scalar mean, dev;
      cv::meanStdDev(w, mean, dev);
      w -= mean[0];
      sd.at<double>(y, x) = dev[0];
      const double den = cv::norm(w) * tn;
      r.at<double>(y, x) = den > 0 ? w.dot(t) / den : 0;
    }
  }
}

// Against the coefficient in double precision, wherever a placement varies by more than a
// grey level (on a near-flat placement every float method's rounding shows), and against
// OpenCV's there: each way of computing it (bands, sums, OpenCV's transform) is taken for
// some of these sizes.
TEST(NormedCorrelation, EqualsTheExactCoefficientAndOpenCVsForEveryTemplateSize) {
  for (const cv::Size size : {cv::Size(160, 120), cv::Size(61, 47), cv::Size(33, 33)}) {
    const cv::Mat img = texture(size, 7u + static_cast<unsigned>(size.width));
    for (const int side : {3, 7, 11, 13, 15, 21, 25, 31}) {
      if (side + 2 > size.height) continue;
      for (const cv::Point at : {cv::Point(size.width / 4 - side / 2, size.height / 2 - side / 2), cv::Point(2, 3)}) {
        const cv::Point in(std::clamp(at.x, 0, size.width - side), std::clamp(at.y, 0, size.height - side - 2));
        const cv::Mat templ = img(cv::Rect(in, cv::Size(side, side + 2))).clone();
        cv::Mat ours, theirs, exact, sd;
        normed_correlation(img, templ, ours);
        cv::matchTemplate(img, templ, theirs, cv::TM_CCOEFF_NORMED);
        reference(img, templ, exact, sd);
        ASSERT_EQ(ours.size(), exact.size()) << side;
        double worst_exact = 0, worst_opencv = 0, worst_cv_exact = 0;
        int compared = 0;
        for (int y = 0; y < ours.rows; ++y) {
          for (int x = 0; x < ours.cols; ++x) {
            if (sd.at<double>(y, x) < 1) continue;
            ++compared;
            worst_exact = std::max(worst_exact, std::abs(ours.at<float>(y, x) - exact.at<double>(y, x)));
            worst_opencv = std::max(worst_opencv, std::abs(double(ours.at<float>(y, x)) - theirs.at<float>(y, x)));
            worst_cv_exact = std::max(worst_cv_exact, std::abs(theirs.at<float>(y, x) - exact.at<double>(y, x)));
          }
        }
        EXPECT_GT(compared, ours.total() / 2) << size << " template " << side;
        // A 3 px wide template (smaller than any tracker's, 7 px and up) over smooth texture
        // leaves both float methods ~1e-3 from the exact value (OpenCV's up to 5e-4 here).
        const double tol = side < 7 ? 2e-3 : 2e-5;
        EXPECT_LT(worst_exact, tol) << size << " template " << side;
        EXPECT_LT(worst_cv_exact, 10 * tol) << size << " template " << side;
        EXPECT_LT(worst_opencv, 10 * tol) << size << " template " << side;
        // The template's own placement is the best, 1.
        double v = 0;
        cv::minMaxLoc(ours, nullptr, &v);
        EXPECT_NEAR(v, 1.0, tol);
      }
    }
  }
}

// Where the image is flat, OpenCV's transform leaves rounding noise that its normalisation
// can make anything in [-1, 1]; here such a placement is 0, as is every placement of a flat
// template.
TEST(NormedCorrelation, AFlatPlacementIsZeroAndAFlatTemplateZeroEverywhere) {
  const cv::Mat img = texture(cv::Size(160, 120), 3, true);
  const cv::Mat templ = img(cv::Rect(100, 40, 9, 9)).clone();
  cv::Mat r;
  normed_correlation(img, templ, r);
  // The flat square spans x 80..109, y 5..34: a placement wholly inside it.
  EXPECT_EQ(r.at<float>(10, 85), 0.0f);
  const cv::Mat flat(9, 9, CV_32F, cv::Scalar(90));
  normed_correlation(img, flat, r);
  double lo = 0, hi = 0;
  cv::minMaxLoc(r, &lo, &hi);
  EXPECT_EQ(lo, 0.0);
  EXPECT_EQ(hi, 0.0);
}

// half_resolution is cv::pyrDown's image, to float rounding, for every size down to a pixel
// (odd and even sides: the reflected border on both), with texture up to the edges.
TEST(HalfResolution, EqualsOpenCVsPyrDownForEverySize) {
  for (const cv::Size size : {cv::Size(1, 1), cv::Size(1, 6), cv::Size(5, 1), cv::Size(2, 3), cv::Size(4, 4),
                              cv::Size(7, 5), cv::Size(33, 20), cv::Size(101, 64), cv::Size(160, 121)}) {
    cv::Mat img(size, CV_32F);
    cv::RNG rng(static_cast<std::uint64_t>(size.area()));
    rng.fill(img, cv::RNG::UNIFORM, 0, 255);
    cv::Mat ours, theirs;
    half_resolution(img, ours);
    cv::pyrDown(img, theirs);
    ASSERT_EQ(ours.size(), theirs.size()) << size;
    // Float rounding of sums of grey levels up to 255 (~3e-5); a wrong tap or border is off by
    // grey levels.
    EXPECT_LT(cv::norm(ours, theirs, cv::NORM_INF), 1e-3) << size;
  }
}

}  // namespace
}  // namespace tribolab::video
