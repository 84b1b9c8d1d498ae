// The command-line text of sweeps: ranges, single values and shards (cli/sweep_cmd.hpp).
#include "sweep_cmd.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <sstream>

#include "numerics/error.hpp"

namespace tribolab::cli {
namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SweepOptionsParsing, AxesRangesAndShards) {
  const sweep::Axis a = parse_axis("100:170:71", sweep::Quantity::theta_deg, "--theta-deg");
  EXPECT_EQ(a, (sweep::Axis{sweep::Quantity::theta_deg, 100, 170, 71}));
  EXPECT_EQ(parse_axis("4:4:1", sweep::Quantity::speed, "--speed").count, 1);
  auto err = [](std::string_view text) {
    return message_of([&] { parse_axis(text, sweep::Quantity::omega, "--omega"); });
  };
  EXPECT_EQ(err("30:50"), "--omega: expected a range lo:hi:count (e.g. 100:170:71), got '30:50'");
  EXPECT_EQ(err("30:x:5"), "--omega: malformed number 'x'");
  EXPECT_EQ(err("30:50:0"), "--omega: count must be at least 1, got 0");
  EXPECT_EQ(err("30:50:2.5"), "--omega: count must be a whole number >= 1, got '2.5'");
  EXPECT_EQ(err("30:50:1"), "--omega: a single value (count 1) needs lo = hi, got 30 and 50");
  EXPECT_EQ(err("30:nan:3"), "--omega: number must be finite, got 'nan'");
  EXPECT_EQ(message_of([&] { parse_axis("0:8:3", sweep::Quantity::speed, "--speed"); }),
            "--speed: the incoming speed must be > 0 m/s");

  const sweep::ValueOrAxis fixed = parse_value_or_axis("8", sweep::Quantity::speed, "--speed");
  EXPECT_FALSE(fixed.axis.has_value());
  EXPECT_EQ(fixed.value, 8);
  EXPECT_TRUE(parse_value_or_axis("0.2:0.8:4", sweep::Quantity::mu, "--mu").axis.has_value());
  EXPECT_EQ(message_of([&] { parse_value_or_axis("-0.1", sweep::Quantity::mu, "--mu"); }),
            "--mu: mu must be >= 0");

  EXPECT_EQ(parse_shard("2/5", "--shard"), (sweep::Shard{2, 5}));
  EXPECT_EQ(message_of([&] { parse_shard("5/5", "--shard"); }),
            "--shard: shard index must be in 0..4, got 5");
  EXPECT_EQ(message_of([&] { parse_shard("1", "--shard"); }),
            "--shard: expected i/N with whole numbers 0 <= i < N (e.g. 0/4), got '1'");
  EXPECT_NE(message_of([&] { parse_shard("0/0", "--shard"); }).find("at least 1"), std::string::npos);
}

TEST(SweepProgress, PrintsOneLineWithCountsAndPercent) {
  std::ostringstream out;
  sweep::Progress p;
  p.done = 270;
  p.total = 270;
  p.rate = 100;
  p.elapsed_s = 2.7;
  print_progress(out, p);
  EXPECT_NE(out.str().find("sweep: 270/270 cells (100.0%)"), std::string::npos) << out.str();
}

}  // namespace
}  // namespace tribolab::cli
