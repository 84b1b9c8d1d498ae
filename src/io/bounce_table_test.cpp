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

// Issue 27 (spreadsheets): `bounce analyze --bounces-out` names each row's file in a last
// column instead of '#' lines, so Excel and csv.DictReader open it. A name holding a comma or a
// quote is quoted (RFC 4180) and the table still reads: the row's numbers are not shifted.
TEST(BounceTable, AFileColumnWithCommasAndQuotesReads) {
  const std::vector<analysis::BounceRow> rows = {{12.5, 1.0 / 3, -4.2, 30, 0.1, 2.0 / 7, -5},
                                                 {-80, 0, -2, 0, 1e-17, 3, 1e3}};
  const std::string text = write_bounce_table(rows, {"run 1, take \"2\".txt", "b.txt"});
  EXPECT_EQ(text.substr(0, text.find('\n')), "theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out,file");
  EXPECT_NE(text.find(",\"run 1, take \"\"2\"\".txt\"\n"), std::string::npos) << text;
  EXPECT_EQ(text.find('#'), std::string::npos);
  const auto back = parse_bounce_table(text, "t.csv");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].vx_in, 1.0 / 3);
  EXPECT_EQ(back[0].omega_out, -5);
  EXPECT_EQ(back[1].omega_out, 1e3);
  // A quoted cell before the numbers does not move them either.
  const auto moved = parse_bounce_table("file,theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out\n"
                                        "\"a,b\",1,2,-3,4,5,6,7\n",
                                        "t.csv");
  ASSERT_EQ(moved.size(), 1u);
  EXPECT_EQ(moved[0].theta_deg, 1);
  EXPECT_EQ(moved[0].omega_out, 7);
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

// The sigma columns bounce analyze --bounces-out writes (issue 27): written when every row
// has its sigmas and read back exactly; a table without them (every file written before) still
// reads, unweighted; a partial set or a non-positive outgoing sigma is an error naming the line.
TEST(BounceTable, SigmaColumnsRoundTripAndOldTablesStillRead) {
  analysis::BounceRow row{12.5, 1.0 / 3, -4.2, 30, 0.1, 2.0 / 7, -5};
  row.sigma_theta_deg = 0.3, row.sigma_vx_in = 0.004, row.sigma_vy_in = 0.005, row.sigma_omega_in = 0.2;
  row.sigma_vx_out = 0.006, row.sigma_vy_out = 1.0 / 3, row.sigma_omega_out = 0.7;
  const std::string text = write_bounce_table({row});
  EXPECT_THAT(text, HasSubstr(",sigma_theta_deg,sigma_vx_in,sigma_vy_in,sigma_omega_in,sigma_vx_out,sigma_vy_out,sigma_omega_out\n"));
  const auto back = parse_bounce_table(text, "t.csv");
  ASSERT_EQ(back.size(), 1u);
  EXPECT_TRUE(back[0].has_sigmas());
  EXPECT_EQ(back[0].sigma_vy_out, 1.0 / 3);
  EXPECT_EQ(back[0].sigma_theta_deg, 0.3);
  // Without sigmas: the old header, and rows read without them.
  const analysis::BounceRow plain{12.5, 1.0 / 3, -4.2, 30, 0.1, 2.0 / 7, -5};
  const std::string old = write_bounce_table({plain});
  EXPECT_EQ(old.substr(0, old.find('\n')), "theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out");
  EXPECT_FALSE(parse_bounce_table(old, "t.csv")[0].has_sigmas());
  const std::string h = "theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out,sigma_vx_out\n";
  EXPECT_THAT(error_of(h + "1,2,3,4,5,6,7,0.1\n"), HasSubstr("t.csv:1"));
  const std::string all = "theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out,sigma_theta_deg,sigma_vx_in,"
                          "sigma_vy_in,sigma_omega_in,sigma_vx_out,sigma_vy_out,sigma_omega_out\n";
  EXPECT_THAT(error_of(all + "1,2,3,4,5,6,7,0,0,0,0,0.1,0,0.1\n"), HasSubstr("t.csv:2"));
  EXPECT_THAT(error_of(all + "1,2,3,4,5,6,7,0,0,0,0,0.1,-1,0.1\n"), HasSubstr("t.csv:2"));
}

}  // namespace
}  // namespace tribolab::io
