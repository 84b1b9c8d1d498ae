#include "app/sweep/sweep_command.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app/sweep/sweep_checkpoint.hpp"
#include "io/sweep_file.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "sweep/synthetic.hpp"
#include "app/track/track_test_util.hpp"

namespace tribolab::app {
using namespace ::tribolab::io;
namespace {

using testing::temp_dir;

namespace fs = std::filesystem;

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// The seed's map at 4 m/s (figure 53), coarser: theta 100-170 deg x omega 30-50 rad/s,
/// with mu swept too so that an extra column appears.
SweepCommandOptions options_for(const std::string& out) {
  SweepCommandOptions o;
  o.grid.axes = {sweep::Axis{sweep::Quantity::mu, 0.3, 0.7, 2},
                 sweep::Axis{sweep::Quantity::theta_deg, 100, 170, 15},
                 sweep::Axis{sweep::Quantity::omega, 30, 50, 9}};
  o.out = out;
  o.threads = 2;
  o.chunk_cells = 4;
  return o;
}

std::string command_message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SweepCommand, ThreadCountsGiveByteIdenticalFilesEqualToCellsOneByOne) {
  const std::string dir = temp_dir("threads");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  std::string reference;
  for (int threads : {1, 2, 7}) {
    SweepCommandOptions o = options_for(dir + "/t" + std::to_string(threads) + ".csv");
    o.threads = threads;
    o.chunk_cells = 0;
    const SweepCommandResult r = run_sweep_command(o, m, nullptr);
    EXPECT_EQ(r.status, SweepStatus::completed);
    EXPECT_EQ(r.cells_computed, 2 * 15 * 9);
    EXPECT_FALSE(fs::exists(o.out + ".partial"));
    const std::string text = read_file(o.out);
    if (reference.empty()) reference = text;
    EXPECT_EQ(text, reference) << threads << " threads";
  }
  // The file holds exactly the cells computed one at a time, in cell order.
  std::vector<double> values;
  const SweepFileScan scan = scan_sweep_file(dir + "/t1.csv", &values);
  const SweepCommandOptions o = options_for("");
  ASSERT_EQ(scan.complete_cells, o.grid.cell_count());
  for (std::int64_t i = 0; i < o.grid.cell_count(); ++i) {
    const sweep::CellOutputs expect = m.evaluate(o.grid.cell(i));
    for (std::size_t j = 0; j < 4; ++j) EXPECT_EQ(values[static_cast<std::size_t>(i) * 4 + j], expect[j]);
  }
  EXPECT_EQ(reference.substr(reference.find('\n') + 1, 41), "theta_deg,omega,vx,vy,omega_out,e,mu\n100,");
}

TEST(SweepCommand, ShardsMergeIntoTheUnshardedFileByteForByte) {
  const std::string dir = temp_dir("shards");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  run_sweep_command(options_for(dir + "/full.csv"), m, nullptr);
  const std::string full = read_file(dir + "/full.csv");
  for (std::int64_t n : {1, 2, 3}) {
    std::vector<std::string> parts;
    for (std::int64_t i = n; i-- > 0;) {  // shards given in reverse order: merge sorts them
      SweepCommandOptions o = options_for(dir + "/part" + std::to_string(i) + "of" + std::to_string(n) + ".csv");
      o.shard = sweep::Shard{i, n};
      o.threads = static_cast<int>(i) + 1;
      const SweepCommandResult r = run_sweep_command(o, m, nullptr);
      EXPECT_EQ(r.cells_shard, o.shard.cells(o.grid.cell_count()));
      parts.push_back(o.out);
    }
    const std::string merged = dir + "/merged" + std::to_string(n) + ".csv";
    const MergeResult r = run_merge_command(parts, merged);
    EXPECT_EQ(r.shards, n);
    EXPECT_EQ(read_file(merged), full) << n << " shards";
  }
}

TEST(SweepCommand, MergeRefusesMissingDuplicateForeignAndIncompleteShards) {
  const std::string dir = temp_dir("merge_errors");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  std::vector<std::string> parts;
  for (std::int64_t i = 0; i < 3; ++i) {
    SweepCommandOptions o = options_for(dir + "/p" + std::to_string(i) + ".csv");
    o.shard = sweep::Shard{i, 3};
    run_sweep_command(o, m, nullptr);
    parts.push_back(o.out);
  }
  const std::string out = dir + "/merged.csv";
  EXPECT_NE(command_message_of([&] { run_merge_command({parts[0], parts[2]}, out); }).find("missing shard(s) 1/3"),
            std::string::npos);
  EXPECT_NE(command_message_of([&] { run_merge_command({parts[0], parts[1], parts[1], parts[2]}, out); })
                .find("given twice"),
            std::string::npos);
  EXPECT_NE(command_message_of([&] { run_merge_command({}, out); }).find("no input files"), std::string::npos);
  EXPECT_NE(command_message_of([&] { run_merge_command({dir + "/nope.csv"}, out); }).find("no such file"),
            std::string::npos);
  // A shard of another sweep (other physics).
  {
    sweep::CellModel other = m;
    other.description = "other physics";
    SweepCommandOptions o = options_for(dir + "/foreign1.csv");
    o.shard = sweep::Shard{1, 3};
    run_sweep_command(o, other, nullptr);
    EXPECT_NE(command_message_of([&] { run_merge_command({parts[0], o.out, parts[2]}, out); })
                  .find("foreign1.csv:1: is a shard of a different sweep than " + parts[0] +
                        " (differs in physical options)"),
              std::string::npos);
  }
  // An incomplete shard (its last lines cut off) and a corrupted line.
  const std::string p1 = read_file(parts[1]);
  write_text(dir + "/cut1.csv", p1.substr(0, p1.size() - 30));
  EXPECT_NE(command_message_of([&] { run_merge_command({parts[0], dir + "/cut1.csv", parts[2]}, out); })
                .find("incomplete shard"),
            std::string::npos);
  std::string bad = p1;
  bad[bad.find('\n', bad.find('\n') + 1) + 1] = '9';  // first data line, theta_deg changed
  write_text(dir + "/bad1.csv", bad);
  EXPECT_NE(command_message_of([&] { run_merge_command({parts[0], dir + "/bad1.csv", parts[2]}, out); })
                .find("bad1.csv:3: theta_deg"),
            std::string::npos);
  write_text(dir + "/long1.csv", p1 + p1.substr(p1.rfind('\n', p1.size() - 2) + 1));
  EXPECT_NE(command_message_of([&] { run_merge_command({parts[0], dir + "/long1.csv", parts[2]}, out); })
                .find("more lines"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(out));  // no partial output after any error
}

TEST(SweepCommand, ResumeAfterTruncationAtRandomPointsEqualsAnUninterruptedRun) {
  const std::string dir = temp_dir("truncate");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  run_sweep_command(options_for(dir + "/full.csv"), m, nullptr);
  const std::string full = read_file(dir + "/full.csv");
  std::mt19937 rng(7);
  std::vector<std::size_t> cuts = {0, 1, 20, full.find('\n'), full.find('\n') + 1, full.size() - 1};
  std::uniform_int_distribution<std::size_t> pick(0, full.size() - 1);
  for (int k = 0; k < 40; ++k) cuts.push_back(pick(rng));
  for (std::size_t cut : cuts) {
    const std::string out = dir + "/resumed.csv";
    fs::remove(out);
    write_text(out + ".partial", full.substr(0, cut));  // "killed" after writing cut bytes
    SweepCommandOptions o = options_for(out);
    o.threads = 1 + static_cast<int>(cut % 3);
    const SweepCommandResult r = run_sweep_command(o, m, nullptr);
    EXPECT_EQ(r.status, SweepStatus::completed);
    EXPECT_EQ(r.cells_resumed + r.cells_computed, r.cells_shard) << "cut at " << cut;
    ASSERT_EQ(read_file(out), full) << "cut at byte " << cut;
    EXPECT_FALSE(fs::exists(out + ".partial"));
  }
}

TEST(SweepCommand, ResumeAfterCancellationEqualsAnUninterruptedRun) {
  const std::string dir = temp_dir("cancel");
  const sweep::CellModel base = sweep::synthetic::wave_model();
  run_sweep_command(options_for(dir + "/full.csv"), base, nullptr);
  const std::string full = read_file(dir + "/full.csv");
  const std::string out = dir + "/stopped.csv";
  std::atomic<bool> cancel{false};
  std::int64_t resumed_before = -1;
  for (int stop_after : {40, 70, 1000000}) {  // stopped twice, then left to finish
    std::atomic<int> calls{0};
    sweep::CellModel m = base;
    m.evaluate = [&, stop_after](const sweep::CellInput& in) {
      if (++calls == stop_after) cancel = true;
      return base.evaluate(in);
    };
    cancel = false;
    const SweepCommandResult r = run_sweep_command(options_for(out), m, nullptr, &cancel);
    if (stop_after < 1000) {
      EXPECT_EQ(r.status, SweepStatus::cancelled);
      EXPECT_EQ(r.out, out + ".partial");
      EXPECT_FALSE(fs::exists(out));  // never a partial file under the final name
      const SweepFileScan scan = scan_sweep_file(out + ".partial");
      EXPECT_EQ(scan.complete_cells, r.cells_resumed + r.cells_computed);
      EXPECT_GT(scan.complete_cells, resumed_before);
      resumed_before = scan.complete_cells;
    } else {
      EXPECT_EQ(r.status, SweepStatus::completed);
      EXPECT_EQ(r.cells_resumed, resumed_before);
    }
  }
  EXPECT_EQ(read_file(out), full);
}

TEST(SweepCommand, ReusesAFinishedOutputAndRefusesAnotherSweepsFiles) {
  const std::string dir = temp_dir("reuse");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  const SweepCommandOptions o = options_for(dir + "/map.csv");
  run_sweep_command(o, m, nullptr);
  const std::string first = read_file(o.out);
  const SweepCommandResult again = run_sweep_command(o, m, nullptr);
  EXPECT_EQ(again.status, SweepStatus::reused);
  EXPECT_EQ(again.cells_computed, 0);
  EXPECT_EQ(read_file(o.out), first);

  SweepCommandOptions other = o;
  other.grid.axes[2].count = 5;
  EXPECT_NE(command_message_of([&] { run_sweep_command(other, m, nullptr); })
                .find("map.csv: exists and holds a different sweep (differs in grid); pass restart"),
            std::string::npos);
  EXPECT_EQ(read_file(o.out), first);  // untouched
  other.restart = true;
  EXPECT_EQ(run_sweep_command(other, m, nullptr).status, SweepStatus::completed);
  EXPECT_NE(read_file(o.out), first);

  write_text(dir + "/notes.csv", "my precious notes\n");
  EXPECT_NE(command_message_of([&] { run_sweep_command(options_for(dir + "/notes.csv"), m, nullptr); })
                .find("not a tribolab sweep file"),
            std::string::npos);
  EXPECT_EQ(read_file(dir + "/notes.csv"), "my precious notes\n");
}

TEST(SweepCommand, RefusesTheCheckpointOfADifferentSweep) {
  const std::string dir = temp_dir("foreign_checkpoint");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  std::atomic<bool> cancel{true};  // stop at once: leaves a checkpoint with no cells
  const SweepCommandOptions o = options_for(dir + "/map.csv");
  EXPECT_EQ(run_sweep_command(o, m, nullptr, &cancel).status, SweepStatus::cancelled);
  sweep::CellModel other = m;
  other.description = "different K";
  EXPECT_NE(command_message_of([&] { run_sweep_command(o, other, nullptr); })
                .find("map.csv.partial: is the checkpoint of a different sweep (differs in physical "
                      "options); delete it or pass restart"),
            std::string::npos);
  SweepCommandOptions restart = o;
  restart.restart = true;
  EXPECT_EQ(run_sweep_command(restart, other, nullptr).status, SweepStatus::completed);
}

TEST(SweepCommand, RefusesACheckpointLockedByAnotherRun) {
  const std::string dir = temp_dir("locked");
  const SweepCommandOptions o = options_for(dir + "/map.csv");
  const int fd = ::open((o.out + ".partial").c_str(), O_WRONLY | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX), 0);  // another process owns it (flock is per open file)
  EXPECT_NE(command_message_of([&] { run_sweep_command(o, sweep::synthetic::wave_model(), nullptr); })
                .find("is being written by another running sweep"),
            std::string::npos);
  ::close(fd);
}

TEST(SweepCommand, RefusesASecondWriterEvenWithRestart) {
  // Issue 26: a second sweep started with --restart deleted the running one's checkpoint,
  // wrote its own under the same name, and the first then renamed the second's unfinished
  // rows to FILE and said "completed".
  const std::string dir = temp_dir("second_writer");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  const SweepCommandOptions o = options_for(dir + "/map.csv");
  const SweepHeader header{o.grid, o.shard, m.output_names, m.description};
  SweepCheckpoint first(o, header);
  SweepCommandOptions second = o;
  second.restart = true;
  EXPECT_NE(command_message_of([&] { run_sweep_command(second, m, nullptr); })
                .find("map.csv.partial: is being written by another running sweep"),
            std::string::npos);
  first.append("");
  first.finish(true);
  // The first run's file, whole: its header, untouched by the refused second run.
  EXPECT_EQ(read_file(o.out), format_header(header) + format_columns(header));
  EXPECT_FALSE(fs::exists(o.out + ".partial"));
}

TEST(SweepCommand, ALockOnlyCheckpointLeavesNoFileBehind) {
  // The lock is taken on FILE.partial before FILE is looked at; a run that then reuses
  // FILE removes the checkpoint it created only to hold the lock.
  const std::string dir = temp_dir("lock_only");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  const SweepCommandOptions o = options_for(dir + "/map.csv");
  ASSERT_EQ(run_sweep_command(o, m, nullptr).status, SweepStatus::completed);
  EXPECT_EQ(run_sweep_command(o, m, nullptr).status, SweepStatus::reused);
  EXPECT_FALSE(fs::exists(o.out + ".partial"));
}

TEST(SweepCommand, MapsOfAFileChangedUnderneathAreAnErrorNotACrash) {
  // The contour indexes the map by cell; a file holding fewer cells than the grid (another
  // writer, a hand edit) aborted on an assertion (contour.cpp, "values size").
  const std::string dir = temp_dir("changed_underneath");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  SweepCommandOptions o = options_for(dir + "/map.csv");
  ASSERT_EQ(run_sweep_command(o, m, nullptr).status, SweepStatus::completed);
  std::string text = read_file(o.out);
  text.resize(text.rfind('\n', text.size() - 2) + 1);  // drop the last cell
  write_text(o.out, text);
  o.contour_out = dir + "/boundary.csv";
  SweepCommandResult r;
  EXPECT_NE(command_message_of([&] { write_derived_maps(o, m, r); })
                .find("map.csv: changed while the contour/threshold maps were made (holds 269 of 270"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(o.contour_out));
}

TEST(SweepCommand, OutputThroughASymlinkKeepsTheLinkAndADeviceIsRefused) {
  // Issue 26: `--out /dev/full` (as root) grew /dev/full.partial in /dev to 2.1 GB and would
  // have renamed it over the device; a symlink was replaced by a plain file.
  const std::string dir = temp_dir("out_kinds");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  fs::create_directories(dir + "/real");
  fs::create_symlink("real/map.csv", dir + "/link.csv");
  SweepCommandOptions o = options_for(dir + "/link.csv");
  ASSERT_EQ(run_sweep_command(o, m, nullptr).status, SweepStatus::completed);
  EXPECT_TRUE(fs::is_symlink(dir + "/link.csv"));
  EXPECT_EQ(read_file(dir + "/real/map.csv").substr(0, 16), "# tribolab-sweep");
  EXPECT_EQ(run_sweep_command(o, m, nullptr).status, SweepStatus::reused);  // found through the link
  ASSERT_EQ(::mkfifo((dir + "/pipe").c_str(), 0600), 0);
  o.out = dir + "/pipe";
  EXPECT_NE(command_message_of([&] { run_sweep_command(o, m, nullptr); })
                .find("pipe: is a device or FIFO, not a regular file (a sweep is checkpointed"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir + "/pipe.partial"));
}

TEST(SweepCommand, WritesContourAndThresholdMaps) {
  const std::string dir = temp_dir("maps");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  SweepCommandOptions o = options_for(dir + "/map.csv");
  o.contour_out = dir + "/boundary.csv";
  o.threshold_out = dir + "/threshold.csv";
  const SweepCommandResult r = run_sweep_command(o, m, nullptr);
  EXPECT_EQ(r.contour_lines, 2);  // one curve per mu slice
  EXPECT_EQ(r.thresholds_found, 30);
  std::istringstream contour(read_file(o.contour_out));
  std::string line;
  std::getline(contour, line);
  EXPECT_EQ(line, "line,closed,mu,theta_deg,omega,refined");
  int points = 0;
  while (std::getline(contour, line)) {
    const auto f = split(line, ',');
    ASSERT_EQ(f.size(), 6u);
    const double mu = std::stod(f[2]), theta = std::stod(f[3]), omega = std::stod(f[4]);
    // Root tolerance 1e-9 of a 2.5 rad/s or 5 deg cell (slope <= 5*pi/90 rad/s per deg).
    EXPECT_NEAR(omega, sweep::synthetic::wave_threshold(theta, 4, mu), 1e-8);
    EXPECT_EQ(f[5], "1");
    ++points;
  }
  EXPECT_EQ(points, r.contour_points);
  std::istringstream thr(read_file(o.threshold_out));
  std::getline(thr, line);
  EXPECT_EQ(line, "mu,theta_deg,status,omega,ratio,energy_ratio,refined");
  while (std::getline(thr, line)) {
    const auto f = split(line, ',');
    ASSERT_EQ(f.size(), 7u);
    EXPECT_EQ(f[2], "found");
    const double w = std::stod(f[3]);
    EXPECT_NEAR(w, sweep::synthetic::wave_threshold(std::stod(f[1]), 4, std::stod(f[0])), 1e-8);
    EXPECT_DOUBLE_EQ(std::stod(f[5]), 4.1e-3 * w * w / (0.435 * 16));
  }
  // The maps of a reused output are the same.
  const std::string first = read_file(o.contour_out);
  EXPECT_EQ(run_sweep_command(o, m, nullptr).status, SweepStatus::reused);
  EXPECT_EQ(read_file(o.contour_out), first);
}

// Issue 26: --contour/--threshold/--report read the whole map into memory (430 MB for 4e6
// cells) to trace it. Now the finished file is streamed once: the maps from the stream are
// those of the whole map in memory (the same polylines, point for point, and thresholds),
// every cell reaches the visitor once and in order, and no values are kept unless asked.
TEST(SweepCommand, DerivedMapsFromTheStreamEqualThoseOfTheWholeMap) {
  const std::string dir = temp_dir("stream");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  SweepCommandOptions o = options_for(dir + "/map.csv");
  ASSERT_EQ(run_sweep_command(o, m, nullptr).status, SweepStatus::completed);
  o.keep_derived = true;
  std::int64_t next = 0;
  bool in_order = true;
  o.visit_cells = [&](std::int64_t c, const std::vector<double>& v) {
    in_order = in_order && c == next && v.size() == m.output_names.size();
    ++next;
  };
  SweepCommandResult r;
  write_derived_maps(o, m, r);
  EXPECT_TRUE(in_order);
  EXPECT_EQ(next, o.grid.cell_count());
  EXPECT_TRUE(r.values.empty());
  std::vector<double> values;
  scan_sweep_file(o.out, &values);
  sweep::ContourOptions co;
  co.threads = o.threads;
  const sweep::ContourResult whole = sweep::trace_contour(o.grid, m, values, co);
  ASSERT_TRUE(r.boundary.has_value());
  ASSERT_EQ(r.boundary->lines.size(), whole.lines.size());
  ASSERT_GT(whole.lines.size(), 0u);
  for (std::size_t l = 0; l < whole.lines.size(); ++l) {
    ASSERT_EQ(r.boundary->lines[l].points.size(), whole.lines[l].points.size());
    for (std::size_t k = 0; k < whole.lines[l].points.size(); ++k) {
      EXPECT_EQ(r.boundary->lines[l].points[k].theta_deg, whole.lines[l].points[k].theta_deg);
      EXPECT_EQ(r.boundary->lines[l].points[k].spin, whole.lines[l].points[k].spin);
    }
  }
  const std::vector<sweep::Threshold> rows = sweep::spin_thresholds(o.grid, m, values, co);
  ASSERT_TRUE(r.thresholds.has_value());
  ASSERT_EQ(r.thresholds->size(), rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) EXPECT_EQ((*r.thresholds)[k].omega, rows[k].omega);
}

TEST(SweepCommand, ProgressGoesToTheGivenCallbackOnly) {
  const std::string dir = temp_dir("progress");
  sweep::Progress last;
  int calls = 0;
  SweepCommandOptions o = options_for(dir + "/map.csv");
  run_sweep_command(o, sweep::synthetic::wave_model(), [&](const sweep::Progress& p) {
    last = p;
    ++calls;
  });
  EXPECT_GE(calls, 1);
  EXPECT_EQ(last.done, 270);
  EXPECT_EQ(last.total, 270);
}

TEST(SweepCommand, InvalidOptionsNameTheOptionAndWriteNothing) {
  const std::string dir = temp_dir("invalid");
  const sweep::CellModel m = sweep::synthetic::wave_model();
  SweepCommandOptions o = options_for(dir + "/map.csv");
  o.shard = sweep::Shard{0, 2};
  o.contour_out = dir + "/c.csv";
  EXPECT_NE(command_message_of([&] { run_sweep_command(o, m, nullptr); }).find("contour: needs the whole grid"),
            std::string::npos);
  o = options_for(dir + "/missing_dir/map.csv");
  EXPECT_NE(command_message_of([&] { run_sweep_command(o, m, nullptr); }).find("directory does not exist"),
            std::string::npos);
  o = options_for(dir + "/map.csv");
  o.grid.axes[0].count = 0;
  EXPECT_NE(command_message_of([&] { run_sweep_command(o, m, nullptr); }).find("mu: count must be at least 1"),
            std::string::npos);
  o = options_for(dir + "/map.csv");
  o.threads = -1;
  EXPECT_NE(command_message_of([&] { run_sweep_command(o, m, nullptr); }).find("threads"), std::string::npos);
  o = options_for("");
  EXPECT_NE(command_message_of([&] { run_sweep_command(o, m, nullptr); }).find("out"), std::string::npos);
  o = options_for(dir + "/map.csv");
  o.threshold_out = dir + "/t.csv";
  sweep::CellModel no_e = m;
  no_e.output_names = {"vx", "vy", "omega_out", "cor"};
  EXPECT_NE(command_message_of([&] { run_sweep_command(o, no_e, nullptr); }).find("no output 'e'"),
            std::string::npos);
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
}  // namespace tribolab::app

namespace tribolab::app {
using namespace ::tribolab::io;
namespace {

TEST(SweepCommand, JsonResultHasTheDocumentedKeys) {
  const std::string dir = temp_dir("json");
  SweepCommandOptions o = options_for(dir + "/map.csv");
  o.threshold_out = dir + "/t.csv";
  const nlohmann::json j = sweep_result_json(run_sweep_command(o, sweep::synthetic::wave_model(), nullptr), o);
  for (const char* key : {"status", "out", "cells_grid", "cells_shard", "cells_resumed",
                          "cells_computed", "threads", "seconds", "cells_per_second", "contour",
                          "threshold"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["cells_grid"], 270);
  EXPECT_TRUE(j["contour"].is_null());
  EXPECT_EQ(j["threshold"]["found"], 30);
  EXPECT_EQ(j["threshold"]["file"], o.threshold_out);
}

// Regression (issue 26): a sweep whose every cell was NaN said "completed".
TEST(SweepCommand, EveryCellNaNIsNoResultNotCompleted) {
  const std::string dir = temp_dir("nan");
  sweep::CellModel m = sweep::synthetic::wave_model();
  m.evaluate = [](const sweep::CellInput&) { return sweep::CellOutputs{NAN, NAN, NAN, NAN}; };
  SweepCommandOptions o = options_for(dir + "/nan.csv");
  const SweepCommandResult r = run_sweep_command(o, m, nullptr);
  EXPECT_EQ(r.cells_computed_with_result, std::int64_t{0});
  EXPECT_EQ(sweep_result_json(r, o)["status"], "no_result");
  // One finite output in one cell is a result.
  m.evaluate = [](const sweep::CellInput& in) {
    return sweep::CellOutputs{in.omega == 30 && in.theta_deg == 100 && in.mu == 0.3 ? 1.0 : NAN, NAN, NAN, NAN};
  };
  o.restart = true;
  const SweepCommandResult one = run_sweep_command(o, m, nullptr);
  EXPECT_EQ(one.cells_computed_with_result, std::int64_t{1});
  EXPECT_EQ(sweep_result_json(one, o)["status"], "completed");
}

}  // namespace
}  // namespace tribolab::app
