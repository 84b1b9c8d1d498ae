// Incline benchmarks (results in docs/benchmarks.md#incline): closed-form evaluation of one
// state (with and without inverting t(s)), a 1000-sample trajectory, the numerical
// integration to the stop, and mu from the stopping point.
#include "incline/closed_form.hpp"
#include "incline/inverse.hpp"
#include "incline/numeric.hpp"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

using namespace tribolab::incline;

Parameters seed_setup() {  // seed 000, figure 五: phi = 20.96 deg, mu = 0.634, v0 = 2.62 m/s
  Parameters p;
  p.mu = 0.634;
  p.phi = deg_to_rad(20.96);
  p.v0 = 2.62;
  return p;
}

void BM_ClosedFormStateAtSpeed(benchmark::State& state) {
  const ClosedForm cf(seed_setup());
  double s = 0.7;
  for (auto _ : state) {
    benchmark::DoNotOptimize(cf.at_log_speed_ratio(s));
    s += 1e-9;
  }
}
BENCHMARK(BM_ClosedFormStateAtSpeed);

void BM_ClosedFormStateAtTime(benchmark::State& state) {
  const ClosedForm cf(seed_setup());
  const double t = 0.4 * cf.t_stop();
  for (auto _ : state) benchmark::DoNotOptimize(cf.at(t));
}
BENCHMARK(BM_ClosedFormStateAtTime);

void BM_ClosedFormTrajectory1000(benchmark::State& state) {
  const ClosedForm cf(seed_setup());
  std::vector<double> times(1000);
  for (int i = 0; i < 1000; ++i) times[i] = 1.2 * cf.t_stop() * i / 999;
  for (auto _ : state) benchmark::DoNotOptimize(cf.trajectory(times));
  state.SetItemsProcessed(state.iterations() * 1000);
}
BENCHMARK(BM_ClosedFormTrajectory1000);

void BM_NumericToStop(benchmark::State& state) {
  const Parameters p = seed_setup();
  NumericOptions o;
  o.t_max = 2 * ClosedForm(p).t_stop();
  std::size_t steps = 0;
  for (auto _ : state) {
    const NumericResult r = simulate(p, {}, o);
    steps = r.steps;
    benchmark::DoNotOptimize(r.t_stop);
  }
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(BM_NumericToStop)->Unit(benchmark::kMicrosecond);

void BM_NumericTrajectory1000(benchmark::State& state) {
  const Parameters p = seed_setup();
  std::vector<double> times(1000);
  const double T = ClosedForm(p).t_stop();
  for (int i = 0; i < 1000; ++i) times[i] = 1.2 * T * i / 999;
  for (auto _ : state) benchmark::DoNotOptimize(simulate(p, times).samples.data());
}
BENCHMARK(BM_NumericTrajectory1000)->Unit(benchmark::kMicrosecond);

void BM_MuFromStop(benchmark::State& state) {
  StopMeasurement m;
  m.phi = deg_to_rad(10.37);
  m.x_stop = 0.214;
  m.y_stop = -0.036;
  m.sigma_phi = deg_to_rad(0.2);
  m.sigma_pos = 0.002;
  for (auto _ : state) benchmark::DoNotOptimize(mu_from_stop(m).mu);
}
BENCHMARK(BM_MuFromStop);

}  // namespace

BENCHMARK_MAIN();
