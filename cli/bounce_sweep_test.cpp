// Golden tests of `tribolab bounce sweep` / `bounce merge` wired to the contact solver: the
// real binary, as a user runs it (docs/cli.md#bounce-sweep).
#include "cli_test_util.hpp"

#include "bounce/geometry.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace tribolab::cli::testing {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr double kDeg = 180.0 / std::numbers::pi;

std::string g17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// The data rows of a sweep or contour CSV (comment and column lines skipped), as numbers.
std::vector<std::vector<double>> rows(const std::string& path) {
  std::vector<std::vector<double>> out;
  std::ifstream in(path);
  std::string line;
  bool columns_seen = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!columns_seen) {
      columns_seen = true;
      continue;
    }
    std::vector<double> r;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) r.push_back(field.empty() ? std::nan("") : std::stod(field));
    out.push_back(r);
  }
  return out;
}

std::string column_line(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != '#') return line;
  }
  return {};
}

// A small orientation sweep with mu swept and a restitution-based law: each cell equals
// `bounce simulate` with the same inputs, bit for bit (same solver, same options; both
// print the shortest representation that reads back to the same double).
// A sweep runs the fastest compiled contact solver, `bounce simulate` the baseline one
// (docs/design.md#cpu-dispatch): with TRIBOLAB_CPU=baseline both run the same code and agree bit
// for bit; without it they agree to the tolerance's scale.
TEST(BounceSweepCli, CellsEqualSimulateOneByOne) {
  const std::string dir = temp_dir("bsweep_cells");
  const std::string physics = " --model flores --restitution 0.7 --vx 0.5 --tol 1e-8";
  const std::string sweep = "bounce sweep --angle orientation --theta-deg 10:40:3 --omega 30:50:2 --speed 3 "
                            "--mu 0.3:0.6:2 --threads 2";
  ::setenv("TRIBOLAB_CPU", "baseline", 1);
  const json j = run_json(sweep + " --out " + dir + "/m.csv" + physics);
  ::unsetenv("TRIBOLAB_CPU");
  run_json(sweep + " --out " + dir + "/fast.csv" + physics);
  const auto fast = rows(dir + "/fast.csv");
  EXPECT_EQ(j["cells_grid"].get<int>(), 12) << j.dump();
  EXPECT_EQ(column_line(dir + "/m.csv"),
            "theta_deg,omega,vx,vy,omega_out,e,contacts,contact_duration,vx_first,vy_first,omega_first,e_first,"
            "duration_first,mu");
  const auto cells = rows(dir + "/m.csv");
  ASSERT_EQ(cells.size(), 12u);
  for (const auto& c : cells) {
    ASSERT_EQ(c.size(), 14u);
    const json s = run_json("bounce simulate --vy -3 --theta-deg " + g17(c[0]) + " --omega " + g17(c[1]) +
                            " --mu " + g17(c[13]) + physics);
    EXPECT_EQ(c[2], s["vx"].get<double>()) << "theta " << c[0] << " omega " << c[1] << " mu " << c[13];
    EXPECT_EQ(c[3], s["vy"].get<double>());
    EXPECT_EQ(c[4], s["omega"].get<double>());
    EXPECT_EQ(c[5], s["e"].get<double>());
    EXPECT_EQ(c[6], s["contacts"].get<double>());
    EXPECT_EQ(c[7], s["contact_duration"].get<double>());
    const json& f = s["first_phase"];
    EXPECT_EQ(c[8], f["vx"].get<double>());
    EXPECT_EQ(c[9], f["vy"].get<double>());
    EXPECT_EQ(c[10], f["omega"].get<double>());
    EXPECT_EQ(c[11], f["e"].get<double>());
    EXPECT_EQ(c[12], f["contact_duration"].get<double>());
  }
  // The two kernels differ by at most ~2x the tolerance over the seed's map at 1e-6 (a rounding
  // difference flipping a step, ContactDispatch.BothCpuLevelsAgreeOnTheSeedsMap); 100x the
  // tolerance here (m/s, rad/s, s) leaves room for the spin's larger scale.
  ASSERT_EQ(fast.size(), cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (std::size_t k = 2; k < 14; ++k) EXPECT_NEAR(fast[i][k], cells[i][k], 1e-6) << "cell " << i << " column " << k;
  }
}

// Cells of the seed's map (D = 6000) whose first contact phase ends with e <= 0: the ball
// leaves the floor moving down and must touch again. `bounce simulate` reports the whole
// impact, which must equal `bounce drop` released 2 ms before the same touch, after the
// contact where simulate says the impact ends. Before the whole impact, simulate printed the
// first phase (`first_phase` now), 0.4 m/s and more away from drop's outcome.
TEST(BounceSweepCli, SimulateEqualsDropOverTheWholeImpact) {
  const bounce::Ball ball;
  const double g = 9.8, tau = 2e-3;
  for (const auto& [chi, w] : {std::pair{167.0, 44.0}, std::pair{170.0, 48.0}, std::pair{169.0, 46.0}}) {
    const double theta = bounce::theta_for_collision_angle(ball, chi, 1);
    const json s = run_json("bounce simulate --vy -4 --D 6000 --theta-deg " + g17(theta * kDeg) + " --omega " + g17(w));
    // Release tau before the touch on the same free flight (vy = -4 at the touch).
    const double height = bounce::support_depth(ball, theta) + 4 * tau - 0.5 * g * tau * tau;
    const json d = run_json("bounce drop --D 6000 --rest-height 0 --bounces 6 --height " + g17(height) +
                            " --theta-deg " + g17((theta - w * tau) * kDeg) + " --omega " + g17(w) +
                            " --vy " + g17(-4 + g * tau));
    // Where the impact ends, from drop alone: the first contact after which the ball rises
    // (vy_out > 0) and reaches its apex before the next touch.
    const json& bs = d["bounces"];
    std::size_t k = 0;
    while (k + 1 < bs.size() && !(bs[k]["vy_out"].get<double>() > 0 &&
                                  bs[k]["t_apex"].get<double>() < bs[k + 1]["t_touch"].get<double>())) {
      ++k;
    }
    ASSERT_LT(k + 1, bs.size()) << d.dump();
    EXPECT_GE(k, 1u) << "these cells leave the floor moving down: at least two contacts";
    EXPECT_EQ(s.value("contacts", 1), static_cast<int>(k + 1)) << s.dump();
    const json& b0 = bs[0];
    const json& last = bs[k];
    EXPECT_NEAR(b0["t_touch"].get<double>(), tau, 1e-12);
    // Same contacts from touch states equal to ~1e-15 (decimal round trip), each accurate to
    // ~1e-9 m/s at tolerance 1e-10: 1e-7 m/s is ample (docs/theory.md#bounce-contact).
    EXPECT_NEAR(s["vx"].get<double>(), last["vx_out"].get<double>(), 1e-7) << chi << " " << w;
    EXPECT_NEAR(s["vy"].get<double>(), last["vy_out"].get<double>(), 1e-7);
    EXPECT_NEAR(s["omega"].get<double>(), last["omega_out"].get<double>(), 1e-6);
    EXPECT_NEAR(s["e"].get<double>(), -last["vy_out"].get<double>() / b0["vy_in"].get<double>(), 1e-7);
    EXPECT_NEAR(s["contact_duration"].get<double>(),
                last["t_touch"].get<double>() + last["contact_duration"].get<double>() - b0["t_touch"].get<double>(), 1e-8);
    if (s.contains("first_phase")) {
      EXPECT_LE(s["first_phase"]["e"].get<double>(), 0);
      EXPECT_GT(std::abs(s["first_phase"]["vy"].get<double>() - last["vy_out"].get<double>()), 0.1);
    }
  }
}

// The default convention: theta_deg is the seed's collision angle. `bounce simulate` at the
// orientation theta_for_collision_angle(angle) reports that collision angle and the same
// rebound. The orientation passes through a decimal string (17 digits, ~1e-16 relative),
// so the outputs agree to ~1e-12 (their sensitivity to theta is O(1) per rad).
TEST(BounceSweepCli, CollisionAngleAxisMatchesSimulate) {
  const std::string dir = temp_dir("bsweep_collision");
  run_json("bounce sweep --theta-deg 110:160:3 --omega 40:40:1 --tol 1e-8 --out " + dir + "/m.csv");
  EXPECT_NE(tribolab::cli::testing::slurp(dir + "/m.csv").find("angle=collision"), std::string::npos);
  const auto cells = rows(dir + "/m.csv");
  ASSERT_EQ(cells.size(), 3u);
  const bounce::Ball ball;
  for (const auto& c : cells) {
    const double theta = bounce::theta_for_collision_angle(ball, c[0], 1);
    const json s = run_json("bounce simulate --vy -4 --tol 1e-8 --omega 40 --theta-deg " + g17(theta * kDeg));
    EXPECT_NEAR(s["collision_angle_deg"].get<double>(), c[0], 1e-9);
    EXPECT_NEAR(c[2], s["vx"].get<double>(), 1e-9) << c[0];
    EXPECT_NEAR(c[3], s["vy"].get<double>(), 1e-9) << c[0];
    EXPECT_NEAR(c[4], s["omega"].get<double>(), 1e-7) << c[0];  // omega ~40 rad/s: same relative size
    EXPECT_NEAR(c[5], s["e"].get<double>(), 1e-9) << c[0];
  }
}

const std::string kMap = "bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --tol 1e-6";

TEST(BounceSweepCli, ThreadCountDoesNotChangeTheBytes) {
  const std::string dir = temp_dir("bsweep_threads");
  run_json(kMap + " --threads 1 --out " + dir + "/t1.csv");
  run_json(kMap + " --threads 2 --out " + dir + "/t2.csv");
  const std::string a = slurp(dir + "/t1.csv");
  EXPECT_EQ(count_lines(a), 42);  // header, columns, 40 cells
  EXPECT_EQ(a, slurp(dir + "/t2.csv"));
}

TEST(BounceSweepCli, MergedShardsEqualTheWholeSweep) {
  const std::string dir = temp_dir("bsweep_shards");
  run_json(kMap + " --out " + dir + "/all.csv");
  run_json(kMap + " --shard 1/2 --out " + dir + "/p1.csv");
  run_json(kMap + " --shard 0/2 --out " + dir + "/p0.csv");
  const json m = run_json("bounce merge " + dir + "/p1.csv " + dir + "/p0.csv --out " + dir + "/merged.csv");
  EXPECT_EQ(m["cells"].get<int>(), 40);
  EXPECT_EQ(slurp(dir + "/merged.csv"), slurp(dir + "/all.csv"));
}

TEST(BounceSweepCli, PlainCsvOpensInASpreadsheetAndTheMapStaysMergeable) {
  // --plain-csv: the map without its '#' metadata lines (a spreadsheet or csv.reader sees the
  // column names first), the metadata verbatim in FILE.meta.txt; the sweep file is unchanged,
  // so merge still reads it.
  const std::string dir = temp_dir("bsweep_plain");
  run_json(kMap + " --out " + dir + "/all.csv");
  run_json(kMap + " --out " + dir + "/again.csv --plain-csv " + dir + "/plain.csv");
  const std::string map = slurp(dir + "/all.csv"), plain = slurp(dir + "/plain.csv");
  EXPECT_EQ(slurp(dir + "/again.csv"), map);
  std::string metadata, rest;
  std::istringstream in(map);
  for (std::string line; std::getline(in, line);) (line.rfind('#', 0) == 0 && rest.empty() ? metadata : rest) += line + "\n";
  ASSERT_FALSE(metadata.empty());
  EXPECT_EQ(plain, rest);
  EXPECT_EQ(count_lines(plain), 41);  // columns, 40 cells
  EXPECT_EQ(plain.find('#'), std::string::npos);
  EXPECT_EQ(slurp(dir + "/plain.csv.meta.txt"), metadata);
  // Merge writes one too.
  run_json(kMap + " --shard 1/2 --out " + dir + "/p1.csv");
  run_json(kMap + " --shard 0/2 --out " + dir + "/p0.csv");
  run_json("bounce merge " + dir + "/p1.csv " + dir + "/p0.csv --out " + dir + "/merged.csv --plain-csv " + dir +
           "/merged_plain.csv");
  EXPECT_EQ(slurp(dir + "/merged_plain.csv"), plain);
  expect_error(run_tribolab(kMap + " --out " + dir + "/x.csv --plain-csv " + dir + "/x.csv"), "--plain-csv");
}

// A version-1 file (written before whole impacts: the first contact phase only, outputs vx vy
// omega_out e, model bounce-contact) is still read: merged, and reported with the physics
// rebuilt from its header. It is made here from a v2 file's first-phase columns, which are
// what the old cell computed.
TEST(BounceSweepCli, ReadsVersionOneFiles) {
  const std::string dir = temp_dir("bsweep_v1");
  run_json(kMap + " --out " + dir + "/new.csv");
  std::ifstream in(dir + "/new.csv");
  std::string line, v1;
  std::getline(in, line);
  line.replace(line.find("v2"), 2, "v1");
  line.replace(line.find("outputs vx vy omega_out e contacts contact_duration vx_first vy_first omega_first e_first "
                         "duration_first"),
               std::string("outputs vx vy omega_out e contacts contact_duration vx_first vy_first omega_first e_first "
                           "duration_first").size(),
               "outputs vx vy omega_out e");
  line.replace(line.find("model bounce-impact"), 19, "model bounce-contact");
  v1 = line + "\ntheta_deg,omega,vx,vy,omega_out,e\n";
  std::getline(in, line);  // columns
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string x;
    while (std::getline(ss, x, ',')) f.push_back(x);
    ASSERT_EQ(f.size(), 13u);
    v1 += f[0] + "," + f[1] + "," + f[8] + "," + f[9] + "," + f[10] + "," + f[11] + "\n";
  }
  {
    std::ofstream out(dir + "/old.csv", std::ios::binary);
    out << v1;
  }
  const json m = run_json("bounce merge " + dir + "/old.csv --out " + dir + "/merged.csv --report " + dir + "/r.html");
  EXPECT_EQ(m["cells"].get<int>(), 40) << m.dump();
  const std::string merged = slurp(dir + "/merged.csv");
  EXPECT_EQ(merged.substr(merged.find('\n')), v1.substr(v1.find('\n')));  // same cells, relabelled v2
  EXPECT_NE(slurp(dir + "/r.html").find("first contact phase only"), std::string::npos);
  // A v2 file's report counts the impacts with several contacts and the first-phase e.
  run_json("bounce merge " + dir + "/new.csv --out " + dir + "/m2.csv --report " + dir + "/r2.html");
  EXPECT_NE(slurp(dir + "/r2.html").find("cells whose impact has several contacts"), std::string::npos);
  EXPECT_NE(slurp(dir + "/r2.html").find("largest e of the first contact phase alone"), std::string::npos);
}

// A run killed mid-write leaves a checkpoint ending in a torn line; running the same command
// again completes it to the bytes of an uninterrupted run.
TEST(BounceSweepCli, ResumedRunEqualsUninterrupted) {
  const std::string dir = temp_dir("bsweep_resume");
  run_json(kMap + " --out " + dir + "/full.csv");
  const std::string full = slurp(dir + "/full.csv");
  // Header + columns + 13 cells + half of the 14th line.
  std::size_t cut = 0;
  for (int i = 0; i < 15; ++i) cut = full.find('\n', cut) + 1;
  cut += (full.find('\n', cut) - cut) / 2;
  {
    std::ofstream partial(dir + "/resumed.csv.partial", std::ios::binary);
    partial << full.substr(0, cut);
  }
  const json j = run_json(kMap + " --out " + dir + "/resumed.csv");
  EXPECT_EQ(j["cells_resumed"].get<int>(), 13) << j.dump();
  EXPECT_EQ(j["cells_computed"].get<int>(), 27) << j.dump();
  EXPECT_EQ(slurp(dir + "/resumed.csv"), full);
  EXPECT_FALSE(fs::exists(dir + "/resumed.csv.partial"));
}

// The e = 1 boundary of the seed's window with a weakly damped law (--D 3000: the seed's
// fitted D gives e < 1 everywhere there, docs/theory.md#errata-in-the-seeds): at each refined boundary point a single contact
// computed by `bounce simulate` has e = 1. The point is located to 1e-9 of the grid spacing
// in the spin (de/domega ~ 0.03 per rad/s, so ~1e-10 in e) on contacts solved at tol 1e-10
// (~1e-10 m/s); the orientation goes through 17 decimal digits. 1e-7 leaves a wide margin
// while still failing for any point off the boundary by more than ~1e-5 rad/s.
TEST(BounceSweepCli, ContourPointsHaveUnitRestitution) {
  const std::string dir = temp_dir("bsweep_contour");
  const json j = run_json("bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --D 3000 --tol 1e-10 --out " + dir +
                          "/m.csv --contour " + dir + "/c.csv --threshold " + dir + "/t.csv");
  ASSERT_TRUE(j["contour"].is_object()) << j.dump();
  EXPECT_EQ(column_line(dir + "/c.csv"), "line,closed,theta_deg,omega,refined");
  const auto points = rows(dir + "/c.csv");
  ASSERT_GE(points.size(), 2u) << "the seed's map has an e = 1 boundary in this window";
  const bounce::Ball ball;
  int checked = 0;
  for (const auto& p : points) {
    if (p[4] != 1) continue;
    const double theta = bounce::theta_for_collision_angle(ball, p[2], 1);
    const json s = run_json("bounce simulate --vy -4 --D 3000 --tol 1e-10 --omega " + g17(p[3]) + " --theta-deg " +
                            g17(theta * kDeg));
    EXPECT_NEAR(s["e"].get<double>(), 1.0, 1e-7) << "boundary point theta " << p[2] << " omega " << p[3];
    if (++checked == 6) break;  // a handful of processes is enough
  }
  EXPECT_GE(checked, 2);
}

void expect_rejected(const std::string& args, const std::string& must_mention) {
  const std::string dir = temp_dir("bsweep_bad");
  const auto r = run_tribolab(args + " --out " + dir + "/x.csv");
  EXPECT_NE(r.exit_code, 0) << args;
  EXPECT_EQ(count_lines(r.err), 1) << args << "\n" << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find(must_mention), std::string::npos) << "expected '" << must_mention << "' in: " << r.err;
  EXPECT_FALSE(fs::exists(dir + "/x.csv")) << args;
  EXPECT_FALSE(fs::exists(dir + "/x.csv.partial")) << args;
}

TEST(BounceSweepCli, BadInputIsOneLineAndNoFile) {
  expect_rejected("bounce sweep --theta-deg 100:170 --omega 30:50:5", "--theta-deg");
  expect_rejected("bounce sweep --theta-deg 100:170:8 --omega 30:50:0", "--omega");
  expect_rejected("bounce sweep --theta-deg 100:170:8 --omega 30:x:5", "--omega");
  expect_rejected("bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --model bogus", "--model");
  expect_rejected("bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --shard 2/2", "--shard");
  expect_rejected("bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --angle sideways", "--angle");
  expect_rejected("bounce sweep --theta-deg 100:190:8 --omega 30:50:5", "--theta-deg");
  expect_rejected("bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --K -1", "--K");
  expect_rejected("bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --mu -0.1:0.5:3", "mu");
  expect_rejected("bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --friction sticky", "--friction");
  expect_rejected("bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --tol 0", "--tol");
  expect_rejected("bounce sweep --theta-deg 100:170:8 --omega 30:50:5 --vx nan", "--vx");
}

}  // namespace
}  // namespace tribolab::cli::testing
