// Bounce analyses (docs/benchmarks.md#bounce-analysis): analyze_bounce on one synthetic video
// (240 fps, 1 mm noise, ~165 frames per tip), and fit_bounces on synthetic tables of 10, 30
// and 100 rows (K and n fixed: 2 free parameters; and all 4 free on 30 rows).
#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_fit.hpp"
#include "analysis/bounce_synth.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace tribolab::analysis;

void BM_AnalyzeBounce(benchmark::State& state) {
  SynthVideoOptions o;
  o.fps = static_cast<double>(state.range(0));
  auto v = synth_video(o);
  for (auto* t : {&v.tip_a, &v.tip_b})
    for (auto& p : t->points) p.t /= o.time_factor;
  for (auto _ : state) {
    auto r = analyze_bounce(v.tip_a, v.tip_b);
    benchmark::DoNotOptimize(r.e_velocity);
  }
  state.counters["frames"] = static_cast<double>(v.tip_a.points.size());
}
BENCHMARK(BM_AnalyzeBounce)->Arg(80)->Arg(240)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_FitBounces(benchmark::State& state) {
  SynthTableOptions t;
  t.rows = static_cast<int>(state.range(0));
  const auto rows = synth_table(t);
  BounceFitOptions o;
  if (state.range(1) == 2) o.fixed = {{"K", 101054}, {"n", 1.51}};
  int iterations = 0;
  for (auto _ : state) {
    auto r = fit_bounces(rows, o);
    iterations = r.fit.iterations;
    benchmark::DoNotOptimize(r.D);
  }
  state.counters["solver_iterations"] = iterations;
}
BENCHMARK(BM_FitBounces)->Args({10, 2})->Args({30, 2})->Args({100, 2})->Args({30, 4})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
