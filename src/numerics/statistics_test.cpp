// The order statistics of numerics/statistics.hpp, on samples small enough to check by hand.
#include "numerics/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tribolab {
namespace {

TEST(Statistics, MedianAveragesTheMiddlePairUpperMedianTakesTheUpperOne) {
  EXPECT_EQ(median({3, 1, 2}), 2);
  EXPECT_EQ(median({4, 1, 3, 2}), 2.5);  // R's and numpy's convention
  EXPECT_TRUE(std::isnan(median({})));
  EXPECT_EQ(upper_median(std::vector<double>{3, 1, 2}), 2);
  EXPECT_EQ(upper_median(std::vector<double>{4, 1, 3, 2}), 3);  // a value of the sample
  EXPECT_EQ(upper_median(std::vector<unsigned char>{200, 10, 90, 90}), 90);  // pixel levels
  EXPECT_EQ(upper_median(std::vector<int>{7}), 7);
}

TEST(Statistics, MadSdIsTheNormalScaleOfTheMedianAbsoluteDeviation) {
  // |x - 3| = 2, 1, 0, 1, 7: MAD 1, so the sd is kMadToSd (the outlier 10 does not move it).
  EXPECT_DOUBLE_EQ(mad_sd({1, 2, 3, 4, 10}), kMadToSd);
  EXPECT_NEAR(kMadToSd, 1.4826, 1e-4);  // 1 / Phi^-1(0.75), Huber & Ronchetti sec. 5.1
}

}  // namespace
}  // namespace tribolab
