#include "io/text.hpp"

#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace tribolab::io {
namespace {

TEST(Text, ParsesPlainAndSignedNumbers) {
  EXPECT_DOUBLE_EQ(parse_double("1.5", "x"), 1.5);
  EXPECT_DOUBLE_EQ(parse_double(" +2e-3 ", "x"), 2e-3);
  EXPECT_DOUBLE_EQ(parse_double("-7", "x"), -7.0);
}

TEST(Text, DecimalCommaOnlyWhenAsked) {
  EXPECT_DOUBLE_EQ(parse_double("1,25", "x", true), 1.25);
  EXPECT_THROW(parse_double("1,25", "x", false), InputError);
}

TEST(Text, MalformedNumberNamesTheLocation) {
  try {
    parse_double("1.2.3", "data.csv:7");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "data.csv:7: malformed number '1.2.3'");
  }
  EXPECT_THROW(parse_double("nan", "x"), InputError);
  EXPECT_THROW(parse_double("inf", "x"), InputError);
  EXPECT_THROW(parse_double("", "x"), InputError);
  EXPECT_THROW(parse_double("1e999", "x"), InputError);
}

TEST(Text, EmptyFieldIsMissingNotZero) {
  EXPECT_FALSE(parse_optional_double("  ", "x").has_value());
  EXPECT_DOUBLE_EQ(*parse_optional_double("3", "x"), 3.0);
}

TEST(Text, SplitKeepsEmptyFields) {
  const auto f = split("a,,b,", ',');
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[1], "");
  EXPECT_EQ(f[3], "");
}

TEST(Text, FormatNumberIsShortestRoundTrip) {
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(1e-9), "1e-09");
  EXPECT_EQ(format_number(2.0), "2");
}


TEST(NameText, AcceptsUtf8AndRefusesControlsAndInvalidBytes) {
  EXPECT_EQ(name_text_problem("tip A"), "");
  EXPECT_EQ(name_text_problem("\xc2\xb5m \xe2\x82\xac \xf0\x9f\x8e\xbe"), "");  // µm € and a 4-byte character
  EXPECT_EQ(name_text_problem(std::string("a\0b", 3)), "contains a control character (byte 0x00 at character 2)");
  EXPECT_EQ(name_text_problem("a\tb"), "contains a control character (byte 0x09 at character 2)");
  EXPECT_EQ(name_text_problem("\xff"), "is not valid UTF-8 (byte 0xff at character 1)");
  EXPECT_EQ(name_text_problem("\xc0\xaf"), "is not valid UTF-8 (byte 0xc0 at character 1)");        // overlong '/'
  EXPECT_EQ(name_text_problem("\xed\xa0\x80"), "is not valid UTF-8 (byte 0xa0 at character 2)");    // a surrogate
  EXPECT_EQ(name_text_problem("ab\xe2\x82"), "is not valid UTF-8 (byte 0xe2 at character 3)");      // cut short
}

}  // namespace
}  // namespace tribolab::io

namespace tribolab::io {
namespace {

TEST(ReadFile, ReadsWholeAndRefusesMoreThanItsBound) {
  // Issue 26: a plain 677 MB .trk was read with no bound (a .trk inside a .trz had one),
  // through a buffer that grew to 3-4x the file. Now one bound for both, and a device or
  // pipe (no size to check first) is cut off at the same bound while being read.
  namespace fs = std::filesystem;
  const std::string path = (fs::temp_directory_path() / ("tribolab_read_file_" + std::to_string(::getpid()))).string();
  std::ofstream(path, std::ios::binary) << std::string(100000, 'x');
  EXPECT_EQ(read_file(path).size(), 100000u);
  EXPECT_EQ(read_file(path, 100000).size(), 100000u);  // exactly the bound: accepted
  try {
    read_file(path, 99999);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": too large: over 99999 bytes, the most a text input may hold");
  }
  fs::remove(path);
  EXPECT_THROW(read_file("/dev/zero", 1 << 20), InputError);  // endless: stops at the bound
  EXPECT_EQ(kMaxTextInputBytes, 512ull << 20);
}

}  // namespace
}  // namespace tribolab::io
