#include "track/outliers.hpp"

#include "track/synthetic_test_util.hpp"

#include <gtest/gtest.h>

namespace tribolab::track {
namespace {

// Regression (issue 26): one value 100 times off (a lost decimal point) in an otherwise good
// run was fitted: incline analyze gave mu 2.86 for a run of mu 0.634, with no word of the
// point. Here the screen itself: a bouncing ball at 240 fps, 1 mm noise, with three impacts
// (kinks the screen must not take for outliers), one y multiplied by 100 mid-flight and one
// x by 100 at the last frame (judged from one side).
TEST(IsolatedOutliers, AValueAHundredTimesOffIsFoundAndImpactsAreNot) {
  Track t = testing::bouncing_ball(240, 2.0, 1.0, 0.5, 0.7, 1e-3, 7).track;
  ASSERT_GT(t.points.size(), 400u);
  EXPECT_TRUE(isolated_outliers(t).empty());  // three bounces, no outlier
  const std::size_t k = 100;
  const double y = t.points[k].y;
  t.points[k].y *= 100;
  t.points.back().x *= 100;
  const std::vector<Outlier> found = isolated_outliers(t);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].index, k);
  EXPECT_EQ(found[0].axis, 'y');
  // The neighbours' prediction: within 5 mm of the true height (1 mm noise, quadratics
  // through 4 points extrapolate it with a few times that sd).
  EXPECT_NEAR(found[0].expected, y, 5e-3);
  EXPECT_EQ(found[1].index, t.points.size() - 1);
  EXPECT_EQ(found[1].axis, 'x');
  const Track kept = without(t, found);
  EXPECT_EQ(kept.points.size(), t.points.size() - 2);
  EXPECT_NE(outlier_warning(t, found[0]).find("frame " + std::to_string(t.points[k].frame)), std::string::npos);
}

// Exact data (no noise): the robust noise is 0, and only the quarter-extent bound keeps the
// impacts (velocity kinks) from being called outliers; a run of a few wild frames in a row is
// not an isolated outlier (the bounce analysis' glitch screen is for those).
TEST(IsolatedOutliers, ExactDataAndARunOfWildFramesAreLeftAlone) {
  Track t = testing::bouncing_ball(240, 2.0, 1.0, 0.5, 0.7, 0.0, 7).track;
  const auto exact = isolated_outliers(t);
  for (const auto& o : exact) ADD_FAILURE() << outlier_warning(t, o);
  for (std::size_t k = 100; k < 103; ++k) t.points[k].y += 5;
  for (const auto& o : isolated_outliers(t)) ADD_FAILURE() << o.index << ": " << outlier_warning(t, o);
}

}  // namespace
}  // namespace tribolab::track
