#include "io/bounce_table.hpp"

#include "numerics/error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace tribolab::io {
namespace {

using ::testing::HasSubstr;

std::string error_of(const std::string& text) {
  try {
    parse_bounce_table(text, "t.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BounceTable, RoundTripIsExact) {
  std::vector<analysis::BounceRow> rows = {{12.5, 1.0 / 3, -4.2, 30, 0.1, 2.0 / 7, -5},
                                           {-80, 0, -2, 0, 1e-17, 3, 1e3}};
  const auto back = parse_bounce_table(write_bounce_table(rows), "t.csv");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].vx_in, 1.0 / 3);  // shortest round-trip numbers: bit exact
  EXPECT_EQ(back[0].vy_out, 2.0 / 7);
  EXPECT_EQ(back[1].vx_out, 1e-17);
}

TEST(BounceTable, ColumnsInAnyOrderWithCommentsAndExtras) {
  const auto rows = parse_bounce_table(
      "# measured\nid,omega_out,vy_out,vx_out,omega_in,vy_in,vx_in,theta_deg\n\n7,1,2,3,4,-5,6,7\n", "t.csv");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].theta_deg, 7);
  EXPECT_EQ(rows[0].vy_in, -5);
  EXPECT_EQ(rows[0].omega_out, 1);
}

TEST(BounceTable, ErrorsNameFileAndLine) {
  const std::string h = "theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out\n";
  EXPECT_THAT(error_of(h + "1,2,3,4,5,6,7\n1,2,3,x,5,6,7\n"), HasSubstr("t.csv:3"));
  EXPECT_THAT(error_of(h + "1,2,3,4,5,6\n"), HasSubstr("t.csv:2"));
  EXPECT_THAT(error_of("theta_deg,vx_in\n1,2\n"), HasSubstr("missing column 'vy_in'"));
  EXPECT_THAT(error_of(h), HasSubstr("no data rows"));
  EXPECT_THAT(error_of(""), HasSubstr("empty table"));
  EXPECT_THAT(error_of(h + "1,2,3,4,5,6,nan\n"), HasSubstr("t.csv:2"));
  // Regression (issue 26): one 1e308 among good rows: refused with its line, not fitted.
  EXPECT_THAT(error_of(h + "1,2,3,4,5,6,7\n1,2,1e308,4,5,6,7\n"),
              HasSubstr("t.csv:3: vy_in: 1e+308 m/s is outside the physical range [-1000, 1000] m/s"));
  EXPECT_THAT(error_of(h + "400,2,3,4,5,6,7\n"), HasSubstr("t.csv:2: theta_deg: 400 deg is outside"));
}

}  // namespace
}  // namespace tribolab::io
