// The error convention of numerics/error.hpp: input errors and solver failures are distinct
// types sharing one base (where() + message), and a failed fit throws the type its status means.
#include "numerics/error.hpp"
#include "numerics/least_squares.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tribolab {
namespace {

TEST(ErrorConvention, InputAndSolverErrorsAreDistinctErrorsWithWhere) {
  try {
    throw SolverError("model A", "integration failed: step underflow");
  } catch (const InputError&) {
    FAIL() << "a solver failure must not be an InputError";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), "model A");
    EXPECT_STREQ(e.what(), "model A: integration failed: step underflow");
  }
  try {
    throw InputError("--mu", "must be >= 0");
  } catch (const SolverError&) {
    FAIL() << "an input error must not be a SolverError";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), "--mu");
    EXPECT_STREQ(e.what(), "--mu: must be >= 0");
  }
}

TEST(ErrorConvention, FitFailureTypeFollowsItsStatus) {
  numerics::FitResult f;
  // The data cannot support the fit: the user's input.
  for (auto s : {numerics::FitStatus::too_few_points, numerics::FitStatus::not_identifiable}) {
    f.status = s;
    EXPECT_THROW(numerics::throw_fit_failure(f, "run.csv", "cannot be fitted"), InputError);
  }
  // The solver failed on data it should handle.
  for (auto s : {numerics::FitStatus::no_convergence, numerics::FitStatus::failed}) {
    f.status = s;
    EXPECT_THROW(numerics::throw_fit_failure(f, "run.csv", "cannot be fitted"), SolverError);
  }
  try {
    f.status = numerics::FitStatus::no_convergence;
    numerics::throw_fit_failure(f, "run.csv", "model B cannot be fitted: no convergence");
  } catch (const SolverError& e) {
    EXPECT_EQ(e.where(), "run.csv");
    EXPECT_STREQ(e.what(), "run.csv: model B cannot be fitted: no convergence");
  }
}

}  // namespace
}  // namespace tribolab
