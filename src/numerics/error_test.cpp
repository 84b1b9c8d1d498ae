// The error convention of numerics/error.hpp: input errors and solver failures are distinct
// types sharing one base (where() + message), and a failed fit throws the type its status means.
#include "numerics/error.hpp"
#include "numerics/least_squares.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

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

TEST(ErrorConvention, FieldsAreNamedByTheCoreAndSpelledByEachFrontEnd) {
  const auto flag = [](std::string_view name) {  // the command line's spelling (cli::flag_of)
    std::string f = "--" + std::string(name);
    for (char& c : f)
      if (c == '_') c = '-';
    return f;
  };
  const InputError e(field("time_scale"), "must name a track other than " + field("track_a"));
  EXPECT_EQ(e.where(), "time_scale");  // what library users and Python see
  EXPECT_STREQ(e.what(), "time_scale: must name a track other than track_a");
  EXPECT_EQ(e.message(flag), "--time-scale: must name a track other than --track-a");
  // A message without a place, the field inside it.
  EXPECT_EQ(InputError(field("order") + " must be 1..6, got 9").message(flag), "--order must be 1..6, got 9");
  // Text around the marks is never touched, even with dashes and underscores.
  EXPECT_EQ(InputError("file_1--x.csv:3", "bad").message(flag), "file_1--x.csv:3: bad");
}

TEST(ErrorConvention, ValidateMessagesNameTheirFieldThroughInputErrorOf) {
  const auto flag = [](std::string_view name) { return "<" + std::string(name) + ">"; };
  EXPECT_EQ(input_error_of("slip_scale: must be positive").message(flag), "<slip_scale>: must be positive");
  EXPECT_EQ(input_error_of("slip-scale: must be positive").where(), "slip_scale");  // older spelling
  EXPECT_EQ(input_error_of("model A: no fit").message(flag), "model A: no fit");    // not a field
  EXPECT_EQ(input_error_of("thumbnails must be from 0 to 100").message(flag), "thumbnails must be from 0 to 100");
  EXPECT_EQ(input_error_of(field("fps") + ": 0 is outside").message(flag), "<fps>: 0 is outside");
  EXPECT_THROW(throw input_error_of("a: b"), InputError);
  EXPECT_THROW(throw MissingOptionError("nothing to track"), InputError);
}

}  // namespace
}  // namespace tribolab
