// Fitting benchmarks of the incline analyses (docs/benchmarks.md#incline-analyses): model B
// (closed form, numeric Jacobian), model A (integrator inside the least squares), the whole
// `incline analyze`, and the straight-slide fit, on synthetic runs of the seed's setup.
#include "analysis/incline_fit.hpp"
#include "analysis/incline_slide.hpp"
#include "analysis/incline_synthetic.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace tribolab;

analysis::InclineSynthOptions seed_run(double fps) {
  analysis::InclineSynthOptions o;
  o.params.mu = 0.634;
  o.params.phi = incline::deg_to_rad(20.96);
  o.params.v0 = 2.62;
  o.fps = fps;
  o.seed = 3;
  return o;
}

void BM_FitModelB(benchmark::State& state) {
  const auto s = seed_run(static_cast<double>(state.range(0)));
  const auto run = analysis::synthesize_incline_run(s);
  analysis::InclineFitOptions o;
  o.phi = s.params.phi;
  for (auto _ : state) benchmark::DoNotOptimize(analysis::fit_model_b(run.track, o));
  state.counters["points"] = static_cast<double>(run.track.points.size());
}
BENCHMARK(BM_FitModelB)->Arg(80)->Arg(240)->Unit(benchmark::kMillisecond);

void BM_FitModelA(benchmark::State& state) {
  const auto s = seed_run(static_cast<double>(state.range(0)));
  const auto run = analysis::synthesize_incline_run(s);
  analysis::InclineFitOptions o;
  o.phi = s.params.phi;
  const auto b = analysis::fit_model_b(run.track, o);
  for (auto _ : state) benchmark::DoNotOptimize(analysis::fit_model_a(run.track, o, b));
  state.counters["points"] = static_cast<double>(run.track.points.size());
}
BENCHMARK(BM_FitModelA)->Arg(80)->Arg(240)->Unit(benchmark::kMillisecond);

void BM_AnalyzeRun(benchmark::State& state) {
  const auto s = seed_run(static_cast<double>(state.range(0)));
  const auto run = analysis::synthesize_incline_run(s);
  analysis::InclineFitOptions o;
  o.phi = s.params.phi;
  for (auto _ : state) benchmark::DoNotOptimize(analysis::analyze_incline_run(run.track, o));
}
BENCHMARK(BM_AnalyzeRun)->Arg(80)->Arg(240)->Unit(benchmark::kMillisecond);

void BM_MuFromSlide(benchmark::State& state) {
  // 0.6 s slide at 240 fps (145 points) down the seed's 41.09 deg incline.
  track::Track t{"disc", {}};
  const double a = 1.758;
  for (int i = 0; i < 145; ++i) {
    const double ti = i / 240.0;
    t.points.push_back({i, ti, 0.1 + 1e-4 * (i % 3), -0.5 * a * ti * ti + 1e-4 * (i % 5)});
  }
  analysis::SlideOptions o;
  o.phi = incline::deg_to_rad(41.09);
  for (auto _ : state) benchmark::DoNotOptimize(analysis::mu_from_slide(t, o));
}
BENCHMARK(BM_MuFromSlide)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
