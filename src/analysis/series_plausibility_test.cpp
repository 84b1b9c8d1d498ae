// Runs of a series that contradict each other (docs/theory.md#plausibility-checks).
#include "analysis/series_plausibility.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tribolab::analysis {
namespace {

// Five runs of one surface: four agree on mu = 0.40 +- 0.01, one says 0.55 +- 0.01 (a run on
// another surface, or with the angle mistyped). chi2 ~ 180 for 4 dof: contradiction.
TEST(SeriesPlausibility, RunsThatContradictEachOtherAreSaid) {
  const std::vector<double> mu = {0.40, 0.41, 0.39, 0.40, 0.55}, s(5, 0.01);
  const auto m = weighted_mean(mu, s);
  const auto w = disagreement_warning(m, "mu", {"run5.csv: pull 12"});
  EXPECT_NE(w.find("contradict each other on mu"), std::string::npos) << w;
  EXPECT_NE(w.find("run5.csv"), std::string::npos) << w;
}

// Runs scattering as their uncertainties say (chi2 ~ dof) raise nothing; neither does one run.
TEST(SeriesPlausibility, AgreeingRunsAndASingleRunRaiseNothing) {
  const std::vector<double> mu = {0.40, 0.41, 0.39, 0.405, 0.395}, s(5, 0.01);
  EXPECT_EQ(disagreement_warning(weighted_mean(mu, s), "mu", {}), "");
  const std::vector<double> one = {0.4}, s1 = {0.01};
  EXPECT_EQ(disagreement_warning(weighted_mean(one, s1), "mu", {}), "");
}

BounceAnalysis run_with(double g, double sigma_g, double length) {
  BounceAnalysis r;
  r.gravity = g;
  r.sigma_gravity = sigma_g;
  r.body.length_mean = length;
  return r;
}

// Four throws filmed at 240 fps and one whose file was analysed as if at 235 fps (2 % off:
// g 4 % high) and calibrated on another stick (tips 31 cm apart instead of 28): the odd file
// is named for each, the others are not.
TEST(SeriesPlausibility, AFileWithAnotherTimeScaleOrCalibrationIsNamed) {
  const auto a = run_with(9.80, 0.05, 0.280), b = run_with(9.78, 0.05, 0.281), c = run_with(9.83, 0.05, 0.279),
             d = run_with(9.80 * 1.0404 * 1.02, 0.05, 0.310);
  const std::vector<const BounceAnalysis*> runs = {&a, &b, nullptr, &c, &d};
  const auto w = bounce_series_warnings(runs, {"a.trk", "b.trk", "failed.trk", "c.trk", "d.trk"});
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].rfind("d.trk: its flights fall at g", 0), 0u) << w[0];
  EXPECT_EQ(w[1].rfind("d.trk: its tips are", 0), 0u) << w[1];
  // The same runs without the odd one: nothing.
  EXPECT_TRUE(bounce_series_warnings({&a, &b, &c}, {"a", "b", "c"}).empty());
}

}  // namespace
}  // namespace tribolab::analysis
