// Sweep engine overhead and thread scaling (docs/benchmarks.md#sweep). The bounce contact
// is not used here: cells are synthetic (src/sweep/synthetic.hpp) so that these numbers
// measure the engine itself - work distribution, ordered commit, CSV encoding.
#include <benchmark/benchmark.h>

#include <cmath>

#include "io/sweep_file.hpp"
#include "sweep/contour.hpp"
#include "sweep/runner.hpp"
#include "sweep/synthetic.hpp"

namespace {

using namespace tribolab;

sweep::GridSpec grid(std::int64_t n_theta, std::int64_t n_omega) {
  sweep::GridSpec g;
  g.axes = {sweep::Axis{sweep::Quantity::theta_deg, 100, 170, n_theta},
            sweep::Axis{sweep::Quantity::omega, 30, 50, n_omega}};
  return g;
}

/// A cell costing about `iterations` dependent multiply-adds (~1 ns each), standing in for
/// a contact simulation of known cost.
sweep::CellModel busy_model(int iterations) {
  sweep::CellModel m = sweep::synthetic::wave_model();
  const auto base = m.evaluate;
  m.evaluate = [base, iterations](const sweep::CellInput& in) {
    double x = in.omega * 1e-3;
    for (int i = 0; i < iterations; ++i) x = x * 0.999999 + 1e-9;
    sweep::CellOutputs o = base(in);
    o[0] += x * 1e-300;  // keep the loop
    return o;
  };
  return m;
}

/// Baseline: the cells evaluated in a plain loop on one thread, no engine.
void BM_PlainLoopTrivial(benchmark::State& state) {
  const sweep::GridSpec g = grid(500, 400);
  const sweep::CellModel m = sweep::synthetic::trivial_model();
  for (auto _ : state) {
    double sum = 0;
    for (std::int64_t i = 0; i < g.cell_count(); ++i) sum += m.evaluate(g.cell(i))[1];
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * g.cell_count());
}
BENCHMARK(BM_PlainLoopTrivial)->Unit(benchmark::kMillisecond);

/// Engine overhead per cell: trivial cells, results committed in order (no file).
void BM_RunnerTrivial(benchmark::State& state) {
  const sweep::GridSpec g = grid(500, 400);
  const sweep::CellModel m = sweep::synthetic::trivial_model();
  sweep::RunOptions o;
  o.threads = static_cast<int>(state.range(0));
  sweep::ResultSink sink;
  double sum = 0;
  sink.commit = [&](const sweep::ChunkView& c, const std::string&) { sum += c.outputs[0]; };
  for (auto _ : state) run_cells(g, m, sweep::Shard{}, 0, o, sink);
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations() * g.cell_count());
}
BENCHMARK(BM_RunnerTrivial)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The full write path: trivial cells encoded as CSV lines on the workers and appended to
/// a buffer in order (what `bounce sweep` does, minus the write() system calls).
void BM_RunnerTrivialCsv(benchmark::State& state) {
  const sweep::GridSpec g = grid(500, 400);
  const sweep::CellModel m = sweep::synthetic::wave_model();
  sweep::RunOptions o;
  o.threads = static_cast<int>(state.range(0));
  sweep::ResultSink sink;
  std::string file;
  sink.encode = [&](const sweep::ChunkView& c, std::string& buf) { io::append_cell_lines(buf, g, c); };
  sink.commit = [&](const sweep::ChunkView&, const std::string& buf) { file += buf; };
  for (auto _ : state) {
    file.clear();
    run_cells(g, m, sweep::Shard{}, 0, o, sink);
  }
  state.SetItemsProcessed(state.iterations() * g.cell_count());
  state.counters["bytes_per_cell"] = static_cast<double>(file.size()) / static_cast<double>(g.cell_count());
}
BENCHMARK(BM_RunnerTrivialCsv)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Thread scaling with cells of ~10 microseconds (the order of one adaptive contact).
void BM_RunnerBusyCells(benchmark::State& state) {
  const sweep::GridSpec g = grid(100, 100);
  const sweep::CellModel m = busy_model(10000);
  sweep::RunOptions o;
  o.threads = static_cast<int>(state.range(0));
  sweep::ResultSink sink;
  sink.encode = [&](const sweep::ChunkView& c, std::string& buf) { io::append_cell_lines(buf, g, c); };
  for (auto _ : state) run_cells(g, m, sweep::Shard{}, 0, o, sink);
  state.SetItemsProcessed(state.iterations() * g.cell_count());
}
BENCHMARK(BM_RunnerBusyCells)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Boundary tracing and refinement on a 200 x 200 map (refinement evaluations dominate).
void BM_ContourRefined(benchmark::State& state) {
  const sweep::GridSpec g = grid(200, 200);
  const sweep::CellModel m = sweep::synthetic::wave_model();
  const std::vector<double> v = sweep::evaluate_grid(g, m);
  sweep::ContourOptions o;
  o.threads = 1;
  std::int64_t evaluations = 0;
  for (auto _ : state) evaluations = sweep::trace_contour(g, m, v, o).evaluations;
  state.counters["evaluations"] = static_cast<double>(evaluations);
}
BENCHMARK(BM_ContourRefined)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
