// The error convention (src/numerics/error.hpp, docs/design.md "Errors: input, solver, bug")
// as the user sees it: a solver that fails on valid input is one line on stderr, exit 1, no
// partial output.
#include "cli_test_util.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace tribolab::cli::testing {
namespace {

// A Hooke law so overdamped (K = 1e3 N/m, D = 1e9 N s/m) that the ball creeps into the floor
// and the contact integrator's step budget runs out: a SolverError, not the user's input.
TEST(ErrorConvention, SolverFailureIsOneErrorLineAndExit1) {
  const std::string dir = temp_dir("solver_failure");
  const std::string history = dir + "/h.csv";
  const RunResult r =
      run_tribolab("bounce simulate --vy -4 --model hooke --K 1e3 --D 1e9 --json --history '" + history + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err, "tribolab: error: contact simulation failed: integrator step budget exhausted\n");
  EXPECT_FALSE(std::filesystem::exists(history));
}

}  // namespace
}  // namespace tribolab::cli::testing
