#include "app/bounce/bounce_sweep.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "numerics/error.hpp"
#include "app/track/track_test_util.hpp"

namespace tribolab::app {
namespace {

using testing::temp_dir;

namespace fs = std::filesystem;

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A small map of the seed's figure 53: 4 angles x 3 spins at 4 m/s.
BounceSweepOptions small_sweep(const std::string& out) {
  BounceSweepOptions o;
  o.theta_deg = sweep::Axis{sweep::Quantity::theta_deg, 100, 160, 4};
  o.omega = sweep::Axis{sweep::Quantity::omega, 30, 50, 3};
  o.out = out;
  o.threads = 2;
  return o;
}

std::string sweep_message_of(const BounceSweepOptions& o) {
  try {
    bounce_sweep(o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BounceSweep, ReturnsTheJsonAndTheMapShapedByTheAxes) {
  const std::string dir = temp_dir("map");
  BounceSweepOptions o = small_sweep(dir + "/map.csv");
  o.return_map = true;
  int progress_calls = 0;
  o.progress = [&](const sweep::Progress&) { ++progress_calls; };
  const BounceSweepResult r = bounce_sweep(o);
  EXPECT_EQ(r.json["status"], "completed");
  EXPECT_EQ(r.json["cells_grid"], 12);
  EXPECT_EQ(r.json["cells_computed"], 12);
  EXPECT_TRUE(r.json["contour"].is_null());
  EXPECT_GE(progress_calls, 1);
  ASSERT_TRUE(r.map.has_value());
  const SweepMap& m = *r.map;
  ASSERT_EQ(m.axis_names, (std::vector<std::string>{"theta_deg", "omega"}));
  EXPECT_EQ(m.axis_values[0], (std::vector<double>{100, 120, 140, 160}));
  EXPECT_EQ(m.axis_values[1], (std::vector<double>{30, 40, 50}));
  ASSERT_EQ(m.output_names, bounce_cell_outputs(BounceCellKind::impact));
  ASSERT_EQ(m.outputs.size(), 11u);
  for (const auto& column : m.outputs) EXPECT_EQ(column.size(), 12u);
  // Cell (theta 140, omega 50) is row-major index 2 * 3 + 2: the same e as the cell model.
  const BounceCell cell = make_bounce_cell(BounceCellOptions{});
  sweep::CellInput in;
  in.theta_deg = 140;
  in.omega = 50;
  in.speed = 4;
  in.mu = 0.5;
  EXPECT_EQ(m.outputs[3][8], cell(in)[3]);
  // Run again: the finished file is reused, the same map comes back.
  const BounceSweepResult again = bounce_sweep(o);
  EXPECT_EQ(again.json["status"], "reused");
  EXPECT_EQ(again.map->outputs, m.outputs);
  // Without return_map nothing is kept.
  o.return_map = false;
  EXPECT_FALSE(bounce_sweep(o).map.has_value());
}

TEST(BounceSweep, InvalidOptionsNameTheOptionAndWriteNothing) {
  const std::string dir = temp_dir("invalid");
  BounceSweepOptions o = small_sweep(dir + "/map.csv");
  o.ratio = sweep::Axis{sweep::Quantity::ratio, 5, 15, 3};
  EXPECT_EQ(sweep_message_of(o), "give exactly one of omega (spin range) and ratio (spin/speed range)");
  o = small_sweep(dir + "/map.csv");
  o.theta_deg = sweep::Axis{sweep::Quantity::theta_deg, 100, 190, 4};
  EXPECT_NE(sweep_message_of(o).find("theta_deg: a collision angle lies in 0..180 deg, got 190"), std::string::npos);
  o = small_sweep(dir + "/map.csv");
  o.speed.value = -1;
  EXPECT_EQ(sweep_message_of(o).rfind("speed", 0), 0u) << sweep_message_of(o);
  o = small_sweep(dir + "/map.csv");
  o.contour_tol = 2;
  EXPECT_EQ(sweep_message_of(o).rfind("contour_tol", 0), 0u);
  o = small_sweep(dir + "/map.csv");
  o.shard = sweep::Shard{0, 2};
  o.report = dir + "/r.html";
  EXPECT_NE(sweep_message_of(o).find("report: needs the whole grid"), std::string::npos);
  o = small_sweep(dir + "/map.csv");
  o.cell.angle = "sideways";
  EXPECT_NE(sweep_message_of(o).find("angle"), std::string::npos);
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(BounceSweep, CancelledRunSavesItsCellsAndSaysHowToResume) {
  const std::string dir = temp_dir("cancel");
  BounceSweepOptions o = small_sweep(dir + "/map.csv");
  const std::atomic<bool> stop{true};
  o.cancel = &stop;
  EXPECT_NE(sweep_message_of(o).find("; run the same command again to resume"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir + "/map.csv.partial"));
  o.cancel = nullptr;
  EXPECT_EQ(bounce_sweep(o).json["status"], "completed");
}

TEST(BounceMerge, ShardsJoinAndTheReportRebuildsThePhysicsFromTheHeader) {
  const std::string dir = temp_dir("merge");
  BounceSweepOptions whole = small_sweep(dir + "/whole.csv");
  bounce_sweep(whole);
  BounceMergeOptions m;
  for (int i = 0; i < 2; ++i) {
    BounceSweepOptions s = small_sweep(dir + "/s" + std::to_string(i) + ".csv");
    s.shard = sweep::Shard{i, 2};
    bounce_sweep(s);
    m.files.push_back(s.out);
  }
  m.out = dir + "/merged.csv";
  m.report = dir + "/merged.html";
  const BounceMergeResult r = bounce_merge(m);
  EXPECT_EQ(r.json, (nlohmann::json{{"out", m.out}, {"shards", 2}, {"cells", 12}}));
  EXPECT_EQ(read_file(m.out), read_file(whole.out));
  EXPECT_TRUE(fs::exists(m.report));
}

TEST(SweepStatus, ToStringGivesTheJsonText) {
  EXPECT_EQ(to_string(SweepStatus::completed), "completed");
  EXPECT_EQ(to_string(SweepStatus::reused), "reused");
  EXPECT_EQ(to_string(SweepStatus::cancelled), "cancelled");
  EXPECT_EQ(to_string(SweepStatus::worker), "worker");
}

}  // namespace
}  // namespace tribolab::app
