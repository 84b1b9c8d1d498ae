// Tests of the series runner (analysis/series.hpp): outcomes in input order whatever the
// threads, a failing run keeps its error and never stops the others, progress is reported
// once per run without overlapping calls.
#include "analysis/series.hpp"

#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <set>
#include <stdexcept>
#include <thread>

namespace tribolab::analysis {
namespace {

std::vector<std::string> names(int n) {
  std::vector<std::string> v;
  for (int i = 0; i < n; ++i) v.push_back("run" + std::to_string(i) + ".csv");
  return v;
}

TEST(Series, OutcomesAreInInputOrderOnEveryThreadCount) {
  const auto files = names(40);
  for (int threads : {1, 2, 3, 8}) {
    SeriesOptions o;
    o.threads = threads;
    const auto out = run_series<int>(
        files,
        [](std::size_t i, const std::string&) {
          // Later runs finish first: completion order is the reverse of input order.
          std::this_thread::sleep_for(std::chrono::microseconds(50 * (40 - static_cast<int>(i))));
          return static_cast<int>(i * i);
        },
        o);
    ASSERT_EQ(out.size(), files.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      EXPECT_EQ(out[i].source, files[i]);
      ASSERT_TRUE(out[i].ok()) << i;
      EXPECT_EQ(*out[i].result, static_cast<int>(i * i));
      EXPECT_FALSE(out[i].error.has_value());
    }
  }
}

TEST(Series, AFailingRunKeepsItsErrorAndTheOthersTheirResults) {
  const auto files = names(9);
  std::atomic<int> calls{0};
  SeriesOptions o;
  o.threads = 3;
  const auto out = run_series<double>(
      files,
      [&](std::size_t i, const std::string& f) -> double {
        ++calls;
        if (i == 4) throw InputError(f + ":12", "malformed number 'abc'");
        if (i == 6) throw std::runtime_error("the fit did not converge");
        if (i == 7) throw InputError("--phi-deg", "must be in [0, 90), got 95");
        return 1.5 * static_cast<double>(i);
      },
      o);
  EXPECT_EQ(calls.load(), 9);  // every run was attempted
  EXPECT_EQ(count_failed(out), 3u);
  for (std::size_t i : {0u, 1u, 2u, 3u, 5u, 8u}) {
    ASSERT_TRUE(out[i].ok()) << i;
    EXPECT_EQ(*out[i].result, 1.5 * static_cast<double>(i));
    EXPECT_TRUE(out[i].located_error().empty());
  }
  ASSERT_FALSE(out[4].ok());
  EXPECT_EQ(out[4].error->where, "run4.csv:12");
  // The message already starts with the file: it is not repeated.
  EXPECT_EQ(out[4].located_error(), "run4.csv:12: malformed number 'abc'");
  EXPECT_EQ(out[6].error->where, "");
  EXPECT_EQ(out[6].located_error(), "run6.csv: the fit did not converge");
  EXPECT_EQ(out[7].located_error(), "run7.csv: --phi-deg: must be in [0, 90), got 95");
}

TEST(Series, ProgressIsReportedOncePerRunAndNeverConcurrently) {
  const auto files = names(25);
  std::atomic<int> inside{0};
  int max_inside = 0, calls = 0;
  std::size_t last_done = 0, last_failed = 0;
  std::set<std::size_t> finished;
  bool monotonic = true;
  SeriesOptions o;
  o.threads = 4;
  o.progress = [&](const SeriesProgress& p) {
    const int now = ++inside;
    max_inside = std::max(max_inside, now);
    ++calls;
    monotonic = monotonic && p.done == last_done + 1 && p.failed >= last_failed && p.total == 25;
    last_done = p.done;
    last_failed = p.failed;
    finished.insert(p.last);
    std::this_thread::sleep_for(std::chrono::microseconds(100));  // widen any overlap
    --inside;
  };
  const auto out = run_series<int>(
      files,
      [](std::size_t i, const std::string&) {
        if (i % 5 == 0) throw InputError("bad");
        return 1;
      },
      o);
  EXPECT_EQ(calls, 25);
  EXPECT_EQ(max_inside, 1);
  EXPECT_TRUE(monotonic);
  EXPECT_EQ(last_failed, 5u);
  EXPECT_EQ(finished.size(), 25u);  // every index reported once
  EXPECT_EQ(count_failed(out), 5u);
}

TEST(Series, EmptySeriesAndInvalidOptions) {
  EXPECT_TRUE(run_series<int>({}, [](std::size_t, const std::string&) { return 1; }).empty());
  SeriesOptions o;
  o.threads = -1;
  EXPECT_FALSE(o.validate().empty());
}

TEST(Series, LocateDoesNotRepeatTheSource) {
  EXPECT_EQ(locate("a.csv", "a.csv:3: bad"), "a.csv:3: bad");
  EXPECT_EQ(locate("a.csv", "no motion"), "a.csv: no motion");
  EXPECT_EQ(locate("", "no motion"), "no motion");
}

}  // namespace
}  // namespace tribolab::analysis
