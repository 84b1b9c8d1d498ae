#include "io/theta_c_table.hpp"

#include "numerics/error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace tribolab::io {
namespace {

using ::testing::HasSubstr;

std::string theta_c_error_of(const std::string& text) {
  try {
    parse_theta_c_table(text, "t.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ThetaCTable, ReadsColumnsInAnyOrderSkippingCommentsAndBlanks) {
  const auto pts = parse_theta_c_table("# runs\nsigma_cos_theta_c, cos_theta_c ,phi_deg\n\n0.01,0.5,30\n"
                                       "# next\n0,0.25,10\n",
                                       "t.csv");
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[0].phi, 30 * (M_PI / 180));  // the same product the core's conversion gives
  EXPECT_EQ(pts[0].cos_theta_c, 0.5);
  EXPECT_EQ(pts[0].sigma_cos_theta_c, 0.01);
  EXPECT_EQ(pts[0].source, "t.csv:4");
  EXPECT_EQ(pts[1].source, "t.csv:6");
  EXPECT_EQ(pts[1].sigma_cos_theta_c, 0);
}

TEST(ThetaCTable, WithoutTheSigmaColumnTheSigmaIsUnknown) {
  const auto pts = parse_theta_c_table("phi_deg,cos_theta_c\n12,0.3", "t.csv");  // no final newline
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_EQ(pts[0].sigma_cos_theta_c, 0);
}

TEST(ThetaCTable, ErrorsNameTheLine) {
  EXPECT_THAT(theta_c_error_of(""), HasSubstr("t.csv: is empty"));
  EXPECT_THAT(theta_c_error_of("# only a comment\n"), HasSubstr("t.csv: is empty"));
  EXPECT_THAT(theta_c_error_of("phi,cos\n"), HasSubstr("t.csv:1: header must name"));
  EXPECT_THAT(theta_c_error_of("phi_deg,cos_theta_c\n10\n"), HasSubstr("t.csv:2: expected 2 cells, got 1"));
  EXPECT_THAT(theta_c_error_of("phi_deg,cos_theta_c\n10,x\n"), HasSubstr("t.csv:2"));
  EXPECT_THAT(theta_c_error_of("phi_deg,cos_theta_c\n\n90,0.5\n"), HasSubstr("t.csv:3: phi_deg must be in (0, 90)"));
  // Regression (issue 26): a value the fit cannot carry is refused with its line.
  EXPECT_THAT(theta_c_error_of("phi_deg,cos_theta_c\n10,0.3\n20,1e308\n"), HasSubstr("t.csv:3: cos_theta_c must be in [0, 1], got 1e+308"));
  EXPECT_THAT(theta_c_error_of("phi_deg,cos_theta_c,sigma_cos_theta_c\n10,0.3,-1\n"), HasSubstr("t.csv:2: sigma_cos_theta_c"));
}

}  // namespace
}  // namespace tribolab::io
