// The shared physical-range check (docs/cli.md#physical-ranges): one message style for every
// command, non-finite numbers refused, open lower bounds honoured.
#include "numerics/physical_range.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace tribolab {
namespace {

TEST(PhysicalRange, MessageNamesValueRangeAndUnit) {
  EXPECT_EQ(range_error(1e308, ranges::speed), "1e+308 m/s is outside the physical range [0, 1000] m/s");
  EXPECT_EQ(range_error(11, ranges::friction, "mu"), "mu: 11 is outside the physical range [0, 10]");
  EXPECT_EQ(range_error(1000, ranges::speed), "");  // closed upper bound
  EXPECT_EQ(range_error(0, ranges::speed), "");     // closed lower bound
}

TEST(PhysicalRange, NonFiniteIsAlwaysOutside) {
  for (double v : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity()})
    EXPECT_FALSE(range_error(v, ranges::spin).empty()) << v;
}

TEST(PhysicalRange, OpenLowerBoundExcludesIt) {
  EXPECT_FALSE(range_error(0, ranges::stiffness).empty());
  EXPECT_NE(range_error(0, ranges::stiffness).find("(0, 1e+12]"), std::string::npos);
  EXPECT_EQ(range_error(1e-300, ranges::stiffness), "");
}

TEST(PhysicalRange, CheckRangeThrowsNamingTheOption) {
  try {
    check_range(-2000, ranges::velocity, "--vy");
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--vy: -2000 m/s is outside the physical range [-1000, 1000] m/s");
  }
  EXPECT_EQ(check_range(-4, ranges::velocity, "--vy"), -4);
}

// Regression (issue 26): `bounce sweep --K 1e-320` made every cell NaN and `bounce render
// --scale 1e-320` printed an origin of -inf px; a subnormal passed every range with lo = 0.
TEST(PhysicalRange, SubnormalIsRefusedEvenInsideTheRange) {
  EXPECT_EQ(range_error(1e-320, ranges::stiffness, "K"),
            "K: 1e-320 is subnormal (closer to 0 than 2.2e-308, where doubles lose their precision): give 0 or a normal number");
  EXPECT_FALSE(range_error(-1e-320, ranges::velocity).empty());
  EXPECT_EQ(range_error(std::numeric_limits<double>::min(), ranges::stiffness), "");  // the smallest normal
  EXPECT_EQ(range_error(0.0, ranges::velocity), "");
}

// Regression (issue 26): `--max-turn-deg 1e308` was echoed with 309 digits (std::to_string).
TEST(MessageNumber, SixSignificantDigits) {
  EXPECT_EQ(message_number(1e308), "1e+308");
  EXPECT_EQ(message_number(1e-7), "1e-07");
  EXPECT_EQ(message_number(0.5), "0.5");
  EXPECT_EQ(message_number(-std::numeric_limits<double>::infinity()), "-inf");
}

}  // namespace
}  // namespace tribolab
