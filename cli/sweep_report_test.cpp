// Golden tests of `bounce sweep --report` and `bounce merge --report` with the real binary:
// the report holds the expected figures, draws exactly the --contour points as the e = 1
// boundary, is the same for fresh, resumed, reused and merged sweeps, and is never written
// for a shard, a bad path or a failed sweep (docs/cli.md#bounce-sweep).
#include "cli_test_util.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace tribolab::cli::testing {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// The seed's window with a weakly damped law: an e = 1 boundary crosses it (see
// bounce_sweep_test.cpp), so every kind of figure appears. Loose tolerance: fast.
const std::string kSweep = "bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --D 3000 --tol 1e-6";

/// The figures' JSON embedded in a report (<script type="application/json" id="tribolab-figures">).
json figures_of(const std::string& html) {
  const std::string open = "id=\"tribolab-figures\">";
  const auto a = html.find(open);
  if (a == std::string::npos) return json();
  const auto b = html.find("</script>", a);
  return json::parse(html.substr(a + open.size(), b - a - open.size()))["figures"];
}

/// Titles of the figures of a report, in order.
std::vector<std::string> titles(const std::string& html) {
  std::vector<std::string> out;
  for (const json& f : figures_of(html)) out.push_back(f["layout"]["title"]["text"].get<std::string>());
  return out;
}

/// Whether a title is that of an e map ("Restitution e" or "Restitution e, speed = 3 m/s").
bool is_e_map(const std::string& title) {
  return title == "Restitution e" || title.rfind("Restitution e, ", 0) == 0;
}

/// (x, y) of every point of the "e = 1 boundary" traces of the e maps, in order (gaps skipped).
std::vector<std::pair<double, double>> drawn_boundary(const std::string& html) {
  std::vector<std::pair<double, double>> out;
  for (const json& f : figures_of(html)) {
    if (!is_e_map(f["layout"]["title"]["text"].get<std::string>())) continue;
    for (const json& t : f["data"]) {
      if (t.value("name", "") != "e = 1 boundary") continue;
      for (std::size_t i = 0; i < t["x"].size(); ++i) {
        if (t["x"][i].is_null()) continue;
        out.emplace_back(t["x"][i].get<double>(), t["y"][i].get<double>());
      }
    }
  }
  return out;
}

/// (omega, theta_deg) of the rows of a --contour CSV without leading axes.
std::vector<std::pair<double, double>> contour_points(const std::string& path) {
  std::vector<std::pair<double, double>> out;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // line,closed,theta_deg,omega,refined
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    out.emplace_back(std::stod(f[3]), std::stod(f[2]));
  }
  return out;
}

TEST(SweepReportCli, DrawsTheContourPointsAndAllFigures) {
  const std::string dir = temp_dir("sreport_contour");
  const json j = run_json(kSweep + " --out " + dir + "/m.csv --contour " + dir + "/c.csv --report " + dir + "/r.html");
  EXPECT_EQ(j["status"], "completed") << j.dump();
  ASSERT_TRUE(fs::exists(dir + "/r.html"));
  const std::string html = slurp(dir + "/r.html");
  // e map, omega_out map, spin threshold, energy ratio.
  EXPECT_EQ(count(html, "class=\"tribolab-plot\""), 4u);
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  // The physics from the header, shown as parameters with the unit of D from the law.
  const auto d_row = html.find("<tr><td>D</td><td>N s/m");
  ASSERT_NE(d_row, std::string::npos) << "the physics from the header, shown as parameters";
  const auto value = html.find(">3000</td></tr>", d_row);
  EXPECT_TRUE(value != std::string::npos && value < html.find("</tr>", d_row)) << html.substr(d_row, 120);
  const auto csv = contour_points(dir + "/c.csv");
  ASSERT_GE(csv.size(), 2u);
  // Both maps draw the boundary; the e map's points are exactly the CSV's (same doubles:
  // both are printed in the shortest round-trip form).
  const auto drawn = drawn_boundary(html);
  EXPECT_EQ(drawn, csv);
}

TEST(SweepReportCli, ResumedReusedAndMergedSweepsGiveTheSameReport) {
  const std::string dir = temp_dir("sreport_same");
  run_json(kSweep + " --out " + dir + "/full.csv --report " + dir + "/full.html");
  const std::string full_csv = slurp(dir + "/full.csv");
  const std::string full = slurp(dir + "/full.html");
  ASSERT_FALSE(full.empty());

  // Killed after 13 cells and half a line, then run again.
  std::size_t cut = 0;
  for (int i = 0; i < 15; ++i) cut = full_csv.find('\n', cut) + 1;
  cut += (full_csv.find('\n', cut) - cut) / 2;
  {
    std::ofstream partial(dir + "/resumed.csv.partial", std::ios::binary);
    partial << full_csv.substr(0, cut);
  }
  const json j = run_json(kSweep + " --out " + dir + "/resumed.csv --report " + dir + "/resumed.html");
  EXPECT_EQ(j["cells_resumed"].get<int>(), 13) << j.dump();
  EXPECT_EQ(slurp(dir + "/resumed.html"), full);

  // The complete file is reused: only the report is made.
  const json k = run_json(kSweep + " --out " + dir + "/full.csv --report " + dir + "/reused.html");
  EXPECT_EQ(k["status"], "reused");
  EXPECT_EQ(slurp(dir + "/reused.html"), full);

  // Shards merged with --report: the physics is rebuilt from the header, so the figures
  // (boundary refined on the same cell function) are the same; only the subtitle names merge.
  run_json(kSweep + " --shard 0/2 --out " + dir + "/p0.csv");
  run_json(kSweep + " --shard 1/2 --out " + dir + "/p1.csv");
  run_json("bounce merge " + dir + "/p1.csv " + dir + "/p0.csv --out " + dir + "/merged.csv --report " + dir +
           "/merged.html");
  const std::string merged = slurp(dir + "/merged.html");
  ASSERT_FALSE(merged.empty());
  EXPECT_EQ(figures_of(merged), figures_of(full));
  EXPECT_EQ(count(merged, "class=\"tribolab-plot\""), 4u);
  EXPECT_NE(merged.find("tribolab bounce merge"), std::string::npos);
}

TEST(SweepReportCli, ThirdAxisGivesOneMapPerValueUpToSix) {
  const std::string dir = temp_dir("sreport_speed");
  // 3 speeds: 3 e maps + 3 omega_out maps + threshold + energy ratio.
  run_json(kSweep + " --speed 3:5:3 --out " + dir + "/a.csv --report " + dir + "/a.html");
  EXPECT_EQ(count(slurp(dir + "/a.html"), "class=\"tribolab-plot\""), 8u);
  // 8 values of mu: 6 of them drawn (first and last included), the table lists all 8.
  run_json("bounce sweep --theta-deg 100:170:4 --omega 30:50:3 --D 3000 --tol 1e-6 --mu 0.2:0.9:8 --out " + dir +
           "/b.csv --report " + dir + "/b.html");
  const std::string b = slurp(dir + "/b.html");
  int e_maps = 0, spin_maps = 0;
  for (const std::string& t : titles(b)) {
    e_maps += is_e_map(t);
    spin_maps += t.rfind("Outgoing spin ω_out, ", 0) == 0;
  }
  EXPECT_EQ(e_maps, 6);
  EXPECT_EQ(spin_maps, 6);
  EXPECT_NE(b.find("6 of the 8 slices are drawn"), std::string::npos);
  EXPECT_NE(b.find("mu = 0.2"), std::string::npos);
  EXPECT_NE(b.find("mu = 0.9"), std::string::npos);
}

TEST(SweepReportCli, ShardIsRefusedBeforeAnyWork) {
  const std::string dir = temp_dir("sreport_shard");
  expect_error(kSweep + " --shard 0/2 --out " + dir + "/p.csv --report " + dir + "/r.html", "--report");
  const auto r = run_tribolab(kSweep + " --shard 1/2 --out " + dir + "/p.csv --report " + dir + "/r.html");
  EXPECT_NE(r.err.find("bounce merge"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir)) << "no CSV, no checkpoint, no report";
}

TEST(SweepReportCli, BadReportPathWritesNothing) {
  const std::string dir = temp_dir("sreport_bad");
  for (const std::string& bad : {dir + "/r.txt", dir + "/missing/r.html", dir, dir + "/m.csv"}) {
    expect_error(kSweep + " --out " + dir + "/m.csv --report " + bad, "--report");
    EXPECT_FALSE(fs::exists(dir + "/m.csv")) << bad;
    EXPECT_FALSE(fs::exists(dir + "/m.csv.partial")) << bad;
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(SweepReportCli, FailedSweepOrMergeWritesNoReport) {
  const std::string dir = temp_dir("sreport_fail");
  // --out holds another sweep: the command fails, no report.
  run_json(kSweep + " --out " + dir + "/m.csv");
  expect_error("bounce sweep --theta-deg 100:170:8 --omega 30:50:6 --D 3000 --tol 1e-6 --out " + dir +
                   "/m.csv --report " + dir + "/r.html",
               "m.csv");
  EXPECT_FALSE(fs::exists(dir + "/r.html"));
  // A merge missing a shard: no merged file, no report.
  run_json(kSweep + " --shard 0/2 --out " + dir + "/p0.csv");
  expect_error("bounce merge " + dir + "/p0.csv --out " + dir + "/all.csv --report " + dir + "/r.html", "1/2");
  EXPECT_FALSE(fs::exists(dir + "/all.csv"));
  EXPECT_FALSE(fs::exists(dir + "/r.html"));
}

// `bounce merge --report` rebuilds the cell model from the header's physics line: with
// options far from the defaults (another law and friction, a restitution target, negative
// v_x, the orientation convention) the figures still equal those of the unsharded sweep.
TEST(SweepReportCli, MergeRebuildsNonDefaultPhysics) {
  const std::string dir = temp_dir("sreport_physics");
  for (const std::string& physics :
       {std::string(" --model flores --restitution 0.95 --friction regularized --slip-scale 0.02 --vx -0.3"),
        std::string(" --model hunt-crossley --K 2e5 --n 1.5 --D 100 --friction spring --k-t 3e4 --c-t 2 --g 9.81"),
        std::string(" --model hertz --a 0.14 --mass 0.4 --inertia 4e-3")}) {
    const std::string sweep = "bounce sweep --angle orientation --theta-deg 10:60:6 --omega 30:50:4 --tol 1e-6 --mu 0.4" +
                              physics;
    run_json(sweep + " --restart --out " + dir + "/all.csv --report " + dir + "/all.html");
    run_json(sweep + " --restart --shard 0/2 --out " + dir + "/p0.csv");
    run_json(sweep + " --restart --shard 1/2 --out " + dir + "/p1.csv");
    std::filesystem::remove(dir + "/merged.csv");
    run_json("bounce merge " + dir + "/p0.csv " + dir + "/p1.csv --out " + dir + "/merged.csv --report " + dir +
             "/merged.html");
    const json a = figures_of(slurp(dir + "/all.html"));
    EXPECT_FALSE(a.empty()) << physics;
    EXPECT_EQ(figures_of(slurp(dir + "/merged.html")), a) << physics;
  }
}

// A header whose physics this tribolab did not write cannot be reported on: the merge fails
// before writing anything.
TEST(SweepReportCli, MergeRefusesPhysicsItCannotRebuild) {
  const std::string dir = temp_dir("sreport_foreign");
  for (const char* part : {"0", "1"}) {
    run_json(kSweep + " --shard " + part + "/2 --out " + dir + "/p" + part + ".csv");
    std::string text = slurp(dir + "/p" + part + ".csv");
    const auto at = text.find(" tol=");
    ASSERT_NE(at, std::string::npos);
    text.insert(at, " colour=red");
    std::ofstream(dir + "/p" + part + ".csv", std::ios::binary) << text;
  }
  expect_error("bounce merge " + dir + "/p0.csv " + dir + "/p1.csv --out " + dir + "/all.csv --report " + dir +
                   "/r.html",
               "colour=red");
  EXPECT_FALSE(fs::exists(dir + "/all.csv"));
  EXPECT_FALSE(fs::exists(dir + "/r.html"));
  // Without --report the same files merge (the physics line is only compared, not read).
  run_json("bounce merge " + dir + "/p0.csv " + dir + "/p1.csv --out " + dir + "/all.csv");
  EXPECT_TRUE(fs::exists(dir + "/all.csv"));
}

}  // namespace
}  // namespace tribolab::cli::testing
