// Golden tests of the program's shared behaviour: help, unknown commands and options.
#include "cli_test_util.hpp"

#include <gtest/gtest.h>

namespace tribolab::cli::testing {
namespace {

TEST(Cli, HelpListsTheAreas) {
  const auto r = run_tribolab("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* area : {"incline", "bounce", "track", "demo"}) {
    EXPECT_NE(r.out.find(area), std::string::npos) << area << " missing from:\n" << r.out;
  }
}

TEST(Cli, UnknownCommandIsOneErrorLine) {
  const auto r = run_tribolab("frobnicate");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("frobnicate"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST(Cli, NoArgumentsIsAnError) {
  const auto r = run_tribolab("");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
}

}  // namespace
}  // namespace tribolab::cli::testing
