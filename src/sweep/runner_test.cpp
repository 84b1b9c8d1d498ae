#include "sweep/runner.hpp"
#include "numerics/sanitizer.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include <sys/resource.h>
#include <stdexcept>

#include "numerics/error.hpp"
#include "sweep/synthetic.hpp"

namespace tribolab::sweep {
namespace {

GridSpec grid_4d() {
  GridSpec g;
  g.axes = {Axis{Quantity::speed, 4, 8, 2}, Axis{Quantity::mu, 0.3, 0.7, 3},
            Axis{Quantity::theta_deg, 100, 170, 15}, Axis{Quantity::omega, 30, 50, 11}};
  return g;
}

/// Outputs of every cell computed one at a time, without the runner.
std::vector<double> one_by_one(const GridSpec& g, const CellModel& m) {
  std::vector<double> v;
  for (std::int64_t i = 0; i < g.cell_count(); ++i) {
    const CellOutputs o = m.evaluate(g.cell(i));
    v.insert(v.end(), o.begin(), o.begin() + static_cast<std::ptrdiff_t>(m.output_names.size()));
  }
  return v;
}

bool bit_equal(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(Runner, SweepEqualsCellsComputedOneByOne) {
  const GridSpec g = grid_4d();
  const CellModel m = synthetic::wave_model();
  const std::vector<double> expected = one_by_one(g, m);
  for (int threads : {1, 2, 7}) {
    for (std::int64_t chunk : {0, 1, 5, 1000}) {
      RunOptions o;
      o.threads = threads;
      o.chunk_cells = chunk;
      EXPECT_TRUE(bit_equal(evaluate_grid(g, m, o), expected))
          << threads << " threads, chunk " << chunk;
    }
  }
}

TEST(Runner, CommitsChunksInCellOrderWithShards) {
  const GridSpec g = grid_4d();
  const CellModel m = synthetic::trivial_model();
  for (std::int64_t n : {1, 2, 3}) {
    for (std::int64_t i = 0; i < n; ++i) {
      const Shard shard{i, n};
      std::int64_t next = 0;
      ResultSink sink;
      sink.commit = [&](const ChunkView& c, const std::string&) {
        ASSERT_EQ(c.first_local, next);
        for (std::int64_t k = 0; k < c.count; ++k) {
          EXPECT_EQ(c.inputs[k].index, shard.global(next + k));
        }
        next += c.count;
      };
      RunOptions o;
      o.threads = 3;
      o.chunk_cells = 4;
      const RunSummary s = run_cells(g, m, shard, 0, o, sink);
      EXPECT_EQ(s.status, RunSummary::Status::completed);
      EXPECT_EQ(next, shard.cells(g.cell_count()));
      EXPECT_EQ(s.cells_computed, next);
    }
  }
}

TEST(Runner, CancellationCommitsAPrefixAndResumeCompletesIt) {
  const GridSpec g = grid_4d();
  const CellModel base = synthetic::wave_model();
  const std::vector<double> expected = one_by_one(g, base);
  std::atomic<bool> cancel{false};
  std::atomic<int> calls{0};
  CellModel m = base;
  m.evaluate = [&](const CellInput& in) {
    if (++calls == 200) cancel = true;  // "Ctrl-C" part-way through
    return base.evaluate(in);
  };
  std::vector<double> got;
  ResultSink sink;
  sink.commit = [&](const ChunkView& c, const std::string&) {
    ASSERT_EQ(static_cast<std::size_t>(c.first_local) * 4, got.size());
    got.insert(got.end(), c.outputs, c.outputs + c.count * 4);
  };
  RunOptions o;
  o.threads = 2;
  o.chunk_cells = 7;
  o.cancel = &cancel;
  const RunSummary s1 = run_cells(g, m, Shard{}, 0, o, sink);
  ASSERT_EQ(s1.status, RunSummary::Status::cancelled);
  ASSERT_GT(s1.cells_computed, 0);
  ASSERT_LT(s1.cells_computed, g.cell_count());
  ASSERT_EQ(got.size(), static_cast<std::size_t>(s1.cells_computed) * 4);
  cancel = false;
  const RunSummary s2 = run_cells(g, base, Shard{}, s1.cells_computed, o, sink);
  EXPECT_EQ(s2.status, RunSummary::Status::completed);
  EXPECT_EQ(s1.cells_computed + s2.cells_computed, g.cell_count());
  EXPECT_TRUE(bit_equal(got, expected));
}

TEST(Runner, ExceptionInACellEndsTheRunAndIsRethrown) {
  const GridSpec g = grid_4d();
  CellModel m = synthetic::trivial_model();
  m.evaluate = [](const CellInput& in) -> CellOutputs {
    if (in.index == 123) throw InputError("--K", "must be > 0");
    return {};
  };
  for (int threads : {1, 4}) {
    RunOptions o;
    o.threads = threads;
    o.chunk_cells = 3;
    EXPECT_THROW(run_cells(g, m, Shard{}, 0, o, ResultSink{}), InputError);
  }
}

TEST(Runner, ExceptionInCommitStopsTheWorkers) {
  const GridSpec g = grid_4d();
  ResultSink sink;
  int commits = 0;
  sink.commit = [&](const ChunkView&, const std::string&) {
    if (++commits == 3) throw std::runtime_error("disk full");
  };
  RunOptions o;
  o.threads = 3;
  o.chunk_cells = 2;
  EXPECT_THROW(run_cells(g, synthetic::trivial_model(), Shard{}, 0, o, sink), std::runtime_error);
  EXPECT_EQ(commits, 3);
}

TEST(Runner, EncodeRunsBeforeCommitAndProgressReachesTheTotal) {
  const GridSpec g = grid_4d();
  ResultSink sink;
  sink.encode = [](const ChunkView& c, std::string& buf) {
    buf = std::to_string(c.first_local) + ":" + std::to_string(c.count);
  };
  std::int64_t cells = 0;
  sink.commit = [&](const ChunkView& c, const std::string& buf) {
    EXPECT_EQ(buf, std::to_string(c.first_local) + ":" + std::to_string(c.count));
    cells += c.count;
  };
  Progress last;
  RunOptions o;
  o.threads = 2;
  o.progress = [&](const Progress& p) { last = p; };
  run_cells(g, synthetic::trivial_model(), Shard{1, 2}, 10, o, sink);
  EXPECT_EQ(cells, (Shard{1, 2}).cells(g.cell_count()) - 10);
  EXPECT_EQ(last.done, last.total);
  EXPECT_EQ(last.total, (Shard{1, 2}).cells(g.cell_count()));
}

TEST(Runner, ComputesASubRangeOfTheShard) {
  const GridSpec g = grid_4d();
  const Shard shard{2, 3};
  std::vector<std::int64_t> seen;
  ResultSink sink;
  sink.commit = [&](const ChunkView& c, const std::string&) {
    for (std::int64_t k = 0; k < c.count; ++k) seen.push_back(c.inputs[k].index);
  };
  RunOptions o;
  o.threads = 2;
  o.chunk_cells = 4;
  const RunSummary s = run_cells(g, synthetic::trivial_model(), shard, 10, o, sink, 27);
  EXPECT_EQ(s.cells_computed, 17);
  ASSERT_EQ(seen.size(), 17u);
  for (std::size_t k = 0; k < seen.size(); ++k) EXPECT_EQ(seen[k], shard.global(10 + static_cast<std::int64_t>(k)));
}

TEST(Runner, EmptyRemainderCompletesImmediately) {
  const GridSpec g = grid_4d();
  const RunSummary s = run_cells(g, synthetic::trivial_model(), Shard{}, g.cell_count(), RunOptions{}, ResultSink{});
  EXPECT_EQ(s.status, RunSummary::Status::completed);
  EXPECT_EQ(s.cells_computed, 0);
}

TEST(Runner, ThreadCountIsBounded) {
  // Issue 26: --threads 100000 ended in std::terminate. 1024 is kMaxThreads.
  RunOptions o;
  o.threads = 100000;
  EXPECT_EQ(o.validate(), "threads must be 0 (all cores) to 1024, got 100000");
  o.threads = kMaxThreads;
  EXPECT_EQ(o.validate(), "");
  o.threads = -1;
  EXPECT_EQ(o.validate(), "threads must be 0 (all cores) to 1024, got -1");
}

#if !TRIBOLAB_ASAN
/// In a death test's child: limits the address space to ~100 MiB above what is used (room
/// for a few 8 MiB thread stacks only), asks for 1000 threads, prints the InputError.
void start_1000_threads_under_a_limit() {
  long vm_kb = 0;
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmSize:", 0) == 0) vm_kb = std::stol(line.substr(7));
  }
  const auto limit = static_cast<rlim_t>(vm_kb + 100 * 1024) * 1024;
  const rlimit rl{limit, limit};
  if (vm_kb == 0 || setrlimit(RLIMIT_AS, &rl) != 0) std::_Exit(3);
  RunOptions o;
  o.threads = 1000;
  o.chunk_cells = 1;
  try {
    evaluate_grid(grid_4d(), synthetic::wave_model(), o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    std::_Exit(0);
  }
  std::_Exit(1);
}

TEST(RunnerDeathTest, ThreadsTheSystemRefusesAreOneErrorNotATerminate) {
  // Starting 1000 threads under the limit fails part-way: the started ones must be joined
  // and an InputError thrown (before: std::terminate from a vector of joinable threads,
  // rc 134). In a forked child (a death test), so the limit stays there. Not under ASan,
  // whose shadow memory needs far more address space than any such limit.
  EXPECT_EXIT(start_1000_threads_under_a_limit(), ::testing::ExitedWithCode(0),
              "threads: the system refused to start thread [0-9]+ of 1000 \\(.*\\); ask for fewer");
}
#endif

TEST(CellModel, ValidateChecksOutputNames) {
  CellModel m = synthetic::wave_model();
  EXPECT_EQ(m.validate(), "");
  EXPECT_EQ(m.output_index("e"), 3);
  m.output_names = {"e", "e"};
  EXPECT_NE(m.validate().find("twice"), std::string::npos);
  m.output_names = {"omega"};
  EXPECT_NE(m.validate().find("input column"), std::string::npos);
  m.output_names = {"bad name"};
  EXPECT_NE(m.validate().find("letters"), std::string::npos);
  m.output_names = {};
  EXPECT_NE(m.validate(), "");
  m = synthetic::wave_model();
  m.description = "two\nlines";
  EXPECT_NE(m.validate().find("one line"), std::string::npos);
}

TEST(ParallelFor, VisitsEveryIndexOnceAndRethrows) {
  std::vector<std::atomic<int>> hits(1000);
  parallel_for(1000, 3, [&](std::int64_t i) { ++hits[static_cast<std::size_t>(i)]; });
  for (const auto& h : hits) EXPECT_EQ(h.load(), 1);
  EXPECT_THROW(parallel_for(50, 2, [](std::int64_t i) { if (i == 7) throw std::runtime_error("x"); }),
               std::runtime_error);
}

}  // namespace
}  // namespace tribolab::sweep
