// The incline workflows called directly (no command line): values against the seed's closed
// form and against each other, arrays beside the JSON, files only when asked, and errors that
// name the option as the command line spells it. (That the binary prints exactly these JSON
// objects is checked in cli/incline_app_test.cpp.)
#include "app/incline/incline_forward.hpp"
#include "app/incline/incline_stop.hpp"
#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

namespace tribolab::app {
namespace {

InclineLaunchOptions launch(double mu, double phi_deg, double v0) {
  InclineLaunchOptions l;
  l.mu = mu;
  l.phi_deg = phi_deg;
  l.v0 = v0;
  return l;
}

/// Runs `f`, which must throw InputError whose message starts with `option` + ": ".
void expect_forward_error(const std::function<void()>& f, const std::string& option) {
  try {
    f();
    ADD_FAILURE() << "no error for " << option;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(option + ": ", 0), 0u) << e.what();
  }
}

TEST(InclinePredict, StopsWhereTheSeedsClosedFormSays) {
  InclinePredictOptions o;
  o.launch = launch(0.634, 20.96, 2.62);
  const InclinePredictResult r = incline_predict(o);
  const double phi = 20.96 * M_PI / 180, a = 9.8 * 0.634 * std::cos(phi), k = std::tan(phi) / 0.634;
  // Rounding of the formulas only (the library evaluates the same expressions differently).
  EXPECT_NEAR(r.json["t_stop"].get<double>(), 2.62 / (a * (1 - k * k)), 1e-13);           // seed eq 七
  EXPECT_NEAR(r.json["x_stop"].get<double>(), 2 * 2.62 * 2.62 / (a * (4 - k * k)), 1e-13);  // eq 八
  // The trajectory runs to 1.25 t_stop and rests at the stopping point after it.
  ASSERT_EQ(r.trajectory.size(), 401u);
  EXPECT_NEAR(r.trajectory.back().t, 1.25 * r.json["t_stop"].get<double>(), 1e-12);
  EXPECT_NEAR(r.trajectory.back().x, r.json["x_stop"].get<double>(), 1e-12);
  EXPECT_NEAR(r.trajectory.back().y, r.json["y_stop"].get<double>(), 1e-12);
}

TEST(InclinePredict, ErrorsNameTheOption) {
  InclinePredictOptions o;
  o.launch = launch(0.5, 90, 1);
  expect_forward_error([&] { incline_predict(o); }, "phi_deg");
  o.launch = launch(-0.1, 10, 1);
  expect_forward_error([&] { incline_predict(o); }, "mu");
  o.launch = launch(0.5, 10, 1);
  o.launch.v0.reset();
  expect_forward_error([&] { incline_predict(o); }, "v0");
  o.launch = launch(0.5, 10, 1);
  o.launch.g = 0;
  expect_forward_error([&] { incline_predict(o); }, "g");
}

TEST(InclineSimulate, AnalyticAndNumericTrajectoriesAgreeWithoutFiles) {
  InclineSimulateOptions o;
  o.launch = launch(0.634, 20.96, 2.62);
  o.dt = 0.01;
  o.t_end = 1;
  const InclineSimulateResult a = incline_simulate(o);
  o.method = "numeric";
  const InclineSimulateResult n = incline_simulate(o);
  ASSERT_EQ(a.trajectory.size(), 101u);
  ASSERT_EQ(n.trajectory.size(), a.trajectory.size());
  EXPECT_TRUE(a.json["out"].is_null());
  EXPECT_TRUE(a.comparison.empty());  // no report asked for: nothing else computed
  // Two independent methods: the closed form and Dormand-Prince at the library's default
  // tolerance agree to ~1e-9 m (src/incline/numeric_test.cpp), 1e-7 leaves margin.
  for (std::size_t i = 0; i < a.trajectory.size(); ++i) {
    EXPECT_NEAR(n.trajectory[i].x, a.trajectory[i].x, 1e-7) << i;
    EXPECT_NEAR(n.trajectory[i].y, a.trajectory[i].y, 1e-7) << i;
  }
}

TEST(InclineSimulate, TheReportDrawsTheOtherMethodTheWorkflowComputed) {
  const auto dir = std::filesystem::temp_directory_path() / "tribolab_app_incline_sim";
  std::filesystem::create_directories(dir);
  InclineSimulateOptions o;
  o.launch = launch(0.634, 20.96, 2.62);
  o.report = (dir / "r.html").string();
  const InclineSimulateResult r = incline_simulate(o);
  EXPECT_TRUE(std::filesystem::exists(o.report));
  ASSERT_EQ(r.comparison.size(), r.trajectory.size());  // 501 samples: all drawn
  EXPECT_EQ(r.comparison_name, "numeric (Dormand–Prince 5(4))");
  EXPECT_NEAR(r.comparison.back().x, r.trajectory.back().x, 1e-7);  // as above
  std::filesystem::remove_all(dir);
}

TEST(InclineSimulate, ErrorsNameTheOption) {
  InclineSimulateOptions o;
  o.launch = launch(0.5, 10, 1);
  o.model = "C";
  expect_forward_error([&] { incline_simulate(o); }, "model");
  o.model = "A";
  o.method = "analytic";
  expect_forward_error([&] { incline_simulate(o); }, "method");
  o = {};
  o.launch = launch(0.5, 10, 1);
  o.normal_accel = 1;
  expect_forward_error([&] { incline_simulate(o); }, "normal_accel");
  o = {};
  o.launch = launch(0.5, 10, 1);
  o.dt = 0;
  expect_forward_error([&] { incline_simulate(o); }, "dt");
}

TEST(InclineFamilies, StopRatiosDoNotDependOnV0) {
  InclineFamiliesOptions o;
  o.launch = launch(0.634, 20.96, 0);
  o.launch.v0.reset();
  o.vary = "v0";
  o.values = {1, 2, 3};
  o.samples = 11;
  const InclineFamiliesResult r = incline_families(o);
  ASSERT_EQ(r.family.members.size(), 3u);
  const auto& m = r.json["members"];
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(r.family.members[i].trajectory.size(), 11u);
    // y_stop / x_stop does not depend on v0 (seed eqs 八, 九): rounding only.
    EXPECT_NEAR(m[i]["y_stop_over_x_stop"].get<double>(), m[0]["y_stop_over_x_stop"].get<double>(), 1e-14);
  }
  EXPECT_EQ(r.json["rows"], 33);
  o.samples = 1;
  expect_forward_error([&] { incline_families(o); }, "samples");
  o.samples = 11;
  o.vary = "g";
  expect_forward_error([&] { incline_families(o); }, "vary");
  o.vary = "phi";
  o.values = {95};
  o.launch.v0 = 2;
  o.launch.phi_deg.reset();
  expect_forward_error([&] { incline_families(o); }, "values");
}

TEST(InclineMuFromStop, RecoversTheFrictionOfAPredictedStop) {
  // Two directions of one model: predict where a launch stops, then infer mu from that point.
  InclinePredictOptions p;
  p.launch = launch(0.6, 15, 2);
  const InclinePredictResult pr = incline_predict(p);
  InclineMuFromStopOptions o;
  o.phi_deg = 15;
  o.x_stop = pr.json["x_stop"].get<double>();
  o.y_stop = pr.json["y_stop"].get<double>();
  const InclineMuFromStopResult r = incline_mu_from_stop(o);
  EXPECT_NEAR(r.json["mu"].get<double>(), 0.6, 1e-12);  // a root solve on exact data: rounding
  EXPECT_NEAR(r.json["v0"].get<double>(), 2.0, 1e-10);
  EXPECT_TRUE(r.json["sigma_mu"].is_null());
  o.plate_size = 1;
  expect_forward_error([&] { incline_mu_from_stop(o); }, "plate_size");  // needs a sigma
  o.plate_size.reset();
  o.y_stop = 0.05;
  expect_forward_error([&] { incline_mu_from_stop(o); }, "y_stop");
}

}  // namespace
}  // namespace tribolab::app
