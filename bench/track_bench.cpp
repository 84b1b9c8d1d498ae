// Tracked data at scale: import a 1,000,000-point Tracker Export Data file and differentiate
// it (docs/benchmarks.md#tracked-data). The file is generated once per run in the temporary
// directory: a ball bouncing elastically from 1 m at 240 fps (one bounce every 0.9 s, ~4600
// impacts) with 1 mm Gaussian noise, written by io::write_export_text (tab delimited).
#include "io/track_import.hpp"
#include "io/tracker_export.hpp"
#include "track/kinematics.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

namespace {

using namespace tribolab;

constexpr int kPoints = 1'000'000;

track::Track bouncing(int n) {
  track::Track t{"ball", {}};
  t.points.reserve(static_cast<std::size_t>(n));
  std::mt19937_64 rng(1);
  std::normal_distribution<double> noise(0, 0.001);
  const double g = 9.8, h = 1.0, period = 2 * std::sqrt(2 * h / g);
  for (int i = 0; i < n; ++i) {
    const double time = i / 240.0;
    const double s = std::fmod(time + 0.5 * period, period) - 0.5 * period;  // 0 at the apex
    t.points.push_back({i, time, 0.3 * time + noise(rng), h - 0.5 * g * s * s + noise(rng)});
  }
  return t;
}

const std::string& bench_file() {
  static const std::string path = [] {
    const auto p = (std::filesystem::temp_directory_path() / "tribolab_track_bench_1M.txt").string();
    std::ofstream(p) << io::write_export_text({bouncing(kPoints)});
    return p;
  }();
  return path;
}

const track::Track& bench_track() {
  static const track::Track t = io::read_tracks(bench_file()).tracks.front();
  return t;
}

void BM_ImportExportText1M(benchmark::State& state) {
  const std::string& path = bench_file();
  state.counters["bytes"] = static_cast<double>(std::filesystem::file_size(path));
  for (auto _ : state) {
    const auto set = io::read_tracks(path);
    benchmark::DoNotOptimize(set.tracks.front().points.back().y);
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
}
BENCHMARK(BM_ImportExportText1M)->Unit(benchmark::kMillisecond);

void BM_TrackerStencils1M(benchmark::State& state) {
  const track::Track& t = bench_track();
  track::KinematicsOptions o;
  o.split_at_impacts = state.range(0) != 0;
  for (auto _ : state) {
    const auto k = track::differentiate(t, o);
    benchmark::DoNotOptimize(k.rows[kPoints / 2].ay);
    state.counters["impacts"] = static_cast<double>(k.impacts.size());
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
}
BENCHMARK(BM_TrackerStencils1M)->Arg(0)->Arg(1)->ArgName("impacts")->Unit(benchmark::kMillisecond);

void BM_SavitzkyGolay1M(benchmark::State& state) {
  const track::Track& t = bench_track();
  track::KinematicsOptions o;
  o.method = track::DerivativeMethod::savgol;
  o.window = static_cast<int>(state.range(0));
  o.order = 2;
  for (auto _ : state) {
    const auto k = track::differentiate(t, o);
    benchmark::DoNotOptimize(k.rows[kPoints / 2].sigma_ay);
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
}
BENCHMARK(BM_SavitzkyGolay1M)->Arg(7)->Arg(15)->ArgName("window")->Unit(benchmark::kMillisecond);

void BM_ImportAndDifferentiate1M(benchmark::State& state) {
  const std::string& path = bench_file();
  track::KinematicsOptions o;
  o.method = track::DerivativeMethod::savgol;
  for (auto _ : state) {
    const auto set = io::read_tracks(path);
    const auto k = track::differentiate(set.tracks.front(), o);
    benchmark::DoNotOptimize(k.rows.back().vx);
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
}
BENCHMARK(BM_ImportAndDifferentiate1M)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
