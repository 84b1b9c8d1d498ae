// The numbers of the seed-001 erratum "fitted law vs heat maps" on the demo's errata page and in
// docs/theory.md are the ones the tools compute: the central restitution by the library's exact
// relation, the map maxima and the damping threshold by `tribolab bounce sweep` itself over the
// seed's map (the physics is pinned more tightly in src/bounce/seed_errata_test.cpp).
#include "bounce/normal_law.hpp"
#include "cli_test_util.hpp"
#include "app/demo/demo.hpp"
#include "incline/case_study.hpp"
#include "report/format.hpp"
#include "report/html.hpp"
#include "report/report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace tribolab::cli {
namespace {

using namespace tribolab::app;  // the demo lives in the application layer

using testing::run_tribolab;
using testing::slurp;
using testing::temp_dir;

const Erratum& fitted_law_erratum() {
  static const std::vector<Erratum> all = seed001_errata();
  for (const Erratum& e : all)
    if (e.where.find("fitted law vs heat maps") != std::string::npos) return e;
  ADD_FAILURE() << "no fitted-law erratum";
  return all.front();
}

/// The errata section of docs/theory.md.
std::string theory_errata() {
  const std::string t = slurp(std::string(TRIBOLAB_SOURCE_DIR) + "/docs/theory.md");
  const auto at = t.find("## Errata in the seeds");
  return at == std::string::npos ? std::string() : t.substr(at);
}

/// Largest e of `bounce sweep` over the seed's 71 x 21 map (collision angle 100-170 deg,
/// clockwise spin 30-50 rad/s, v_y = -4 m/s, v_x = 0, mu = 0.5) at tolerance 1e-10.
double map_max(const std::string& law_options) {
  const std::string out = temp_dir("errata_map") + "/map.csv";
  const auto r = run_tribolab("bounce sweep --theta-deg 100:170:71 --omega -30:-50:21 --tol 1e-10 --threads 2 " +
                              law_options + " --out '" + out + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(slurp(out));
  std::string line;
  double m = -std::numeric_limits<double>::infinity();
  int cells = 0;
  int e_column = -1;  // found by name in the column line (whole-impact e, not e_first)
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;  // header
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
    if (e_column < 0) {
      const auto at = std::find(fields.begin(), fields.end(), "e");
      EXPECT_NE(at, fields.end()) << line;
      e_column = static_cast<int>(at - fields.begin());
      continue;
    }
    m = std::max(m, std::stod(fields.at(static_cast<std::size_t>(e_column))));
    ++cells;
  }
  EXPECT_EQ(cells, 71 * 21);
  return m;
}

/// `text` contains `number` as a token (not as part of a longer number).
bool mentions(const std::string& text, const std::string& number) {
  for (auto at = text.find(number); at != std::string::npos; at = text.find(number, at + 1)) {
    const auto end = at + number.size();
    if (end == text.size() || !std::isdigit(static_cast<unsigned char>(text[end]))) return true;
  }
  return false;
}

TEST(DemoErrata, CentralRestitutionOfTheFittedLawIsTheComputedOne) {
  // e of N = 101054 d^1.51 + 60423 d^1.51 d' at 4 m/s (exact relation): 0.3638 -> "0.364".
  const std::string e = report::format_value(bounce::hunt_crossley_restitution(60423.0 / 101054.0 * 4), 3);
  EXPECT_EQ(e, "0.364");  // (the page said 0.44)
  EXPECT_TRUE(mentions(fitted_law_erratum().text, e)) << fitted_law_erratum().text;
  EXPECT_TRUE(mentions(theory_errata(), e));
}

TEST(DemoErrata, MapMaximaAreTheSweepsOwn) {
  // Seed's law: largest e 0.5156 -> "0.516"; elastic (D = 0): 1.37785 on the grid and 1.37785
  // between grid points -> "1.378" (the page said 1.25).
  const std::string seed = report::format_value(map_max(""), 3);
  const std::string elastic = report::format_value(map_max("--D 0"), 4);
  EXPECT_EQ(seed, "0.516");
  EXPECT_EQ(elastic, "1.378");
  for (const std::string& text : {fitted_law_erratum().text, theory_errata()}) {
    EXPECT_TRUE(mentions(text, seed)) << seed;
    EXPECT_TRUE(mentions(text, elastic)) << elastic;
  }
}

TEST(DemoErrata, DampingThresholdBracketsTheMapsLastEAboveOne) {
  // The page's threshold D* = 11749 N s/m^2.51: 1 % below it some cell of the map has e > 1,
  // 1 % above it none (the grid maximum moves by ~2.6e-3 per 1 % of D near D*, far above the
  // 1e-10 tolerance). The page said "about 9e3", which fails the second check.
  const double D_star = 11749;
  EXPECT_TRUE(mentions(fitted_law_erratum().text, "11749"));
  EXPECT_TRUE(mentions(theory_errata(), "11749"));
  EXPECT_GT(map_max("--D " + std::to_string(0.99 * D_star)), 1);
  EXPECT_LT(map_max("--D " + std::to_string(1.01 * D_star)), 1);
}

TEST(DemoErrata, MuAtMostTanPhiIsCitedWhereTheSeedPrintsIt) {
  // Seed 000 prints "mu <= 0.383" in 伍-三-(三)-4 (3), the v_y cases of 圖七-3; 圖七-4Y's case (3)
  // (item 6) reads "mu < 0.383". We used to cite 圖七-4 (3). That mu = 0.383 = tan(20.96 deg)
  // belongs to case (2) (terminal speed, no stop) is computed in
  // SeedIncline.EqualityMuEqualsTanPhiNeverStops.
  int cited = 0;
  for (const std::string& e : incline::seed000_case_study().errata) {
    EXPECT_EQ(e.find("圖七-4 (3) should"), std::string::npos) << e;
    if (e.find("伍-三-(三)-4 (3)") != std::string::npos && e.find("圖七-3") != std::string::npos) ++cited;
  }
  EXPECT_EQ(cited, 1);
  EXPECT_NE(theory_errata().find("**伍-三-(三)-4 (3)**, on the v_y of\n  圖七-3"), std::string::npos);
}

/// The demo's errata page as HTML (both studies), without the plotting library (its code is
/// not the page's text).
std::string errata_page() {
  report::Report rep;
  std::ostringstream log;
  add_errata_section(rep, log);
  return report::to_html(rep, report::PlotlyMode::cdn);
}

TEST(DemoErrata, RefereeCorrectionsAreOnThePageAndInTheory) {
  // An independent referee recomputed our errata from the studies' text; each correction is
  // checked where it is numeric in src/incline/case_study_test.cpp, src/bounce/geometry_test.cpp
  // and src/analysis/seed001_experiment1_test.cpp. Here: the page and docs/theory.md say it.
  const std::string page = errata_page(), theory = theory_errata();
  for (const std::string& text : {page, theory}) {
    // 圖八-5's 6.47 % is right (relative to the measured slope): no longer "not 6.47 %".
    EXPECT_EQ(text.find("not 6.47"), std::string::npos);
    // 3.856 and -3.50 are consistent with g = 9.79, not errata.
    EXPECT_EQ(text.find("not 3.856"), std::string::npos);
    EXPECT_NE(text.find("consistent with g = 9.79, not with 9.8"), std::string::npos);
    // The wrong root of 十A: 16x for the first column, 6.9-8.5x for the others.
    EXPECT_EQ(text.find("15 times"), std::string::npos);
    EXPECT_EQ(text.find("15x"), std::string::npos);
    // Group 1's e computes to 1.2071 (printed 1.20); group 2's pre-impact fit is 8.8 cm off.
    EXPECT_TRUE(mentions(text, "1.2071"));
    EXPECT_NE(text.find("8.8 cm"), std::string::npos);
    EXPECT_NE(text.find("17 % below g"), std::string::npos);
    // n = 1.51 vs 3/2: 0.67 %, printed 0.66 %.
    EXPECT_NE(text.find("0.67 %"), std::string::npos);
    // The missed errata: eq (1.3)'s minus sign, 附錄四's xdot for xddot, rugby-ball eqs 5, 9, 17.
    EXPECT_NE(text.find("附錄一"), std::string::npos);
    EXPECT_NE(text.find("eqs 5, 9 and 17"), std::string::npos);
  }
  EXPECT_NE(page.find("16x too small in the first column"), std::string::npos);
  EXPECT_NE(theory.find("16 times too small for the first column"), std::string::npos);
  EXPECT_NE(page.find("eq (1.3) in the main text"), std::string::npos);
  EXPECT_NE(theory.find("**Eq (1.3) in the main text"), std::string::npos);
  EXPECT_NE(page.find("xddot"), std::string::npos);
  EXPECT_NE(theory.find("sqrt(α² − ẋ²)"), std::string::npos);
}

TEST(DemoErrata, GravityImpulseIsTheOneSimulatePrints) {
  // docs/theory.md: with gravity the floor's impulse in the seed law's central impact at 4 m/s
  // is 2.43 N s (2.37 N s is the impulse at g = 0). `bounce simulate --vy -4` prints it.
  const auto r = run_tribolab("bounce simulate --vy -4 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto at = r.out.find("\"impulse_normal\"");
  ASSERT_NE(at, std::string::npos) << r.out;
  const double J = std::stod(r.out.substr(r.out.find(':', at) + 1));
  EXPECT_EQ(report::format_value(J, 3), "2.43");
  const std::string theory = slurp(std::string(TRIBOLAB_SOURCE_DIR) + "/docs/theory.md");
  EXPECT_TRUE(mentions(theory, "2.43 N s"));
  EXPECT_EQ(theory.find("of the\n2.37 N s impulse"), std::string::npos);
}

TEST(DemoErrata, ChecksNameNoTestFiles) {
  // The page is read by a jury: its check column describes the check, not our test files.
  const std::string page = errata_page();
  for (const char* internal : {"_test.cpp", "src/", "test Seed", "test Flight", "test Geometry", "(test "})
    EXPECT_EQ(page.find(internal), std::string::npos) << internal;
}

/// `text` cites our internal spec: "SPEC" as a word followed by a space, '§' or "'s" (the
/// embedded plotly.js contains "SPEC" inside identifiers, which is not a citation).
bool cites_spec(const std::string& text) {
  for (auto at = text.find("SPEC"); at != std::string::npos; at = text.find("SPEC", at + 1)) {
    const bool word_start = at == 0 || !std::isalnum(static_cast<unsigned char>(text[at - 1]));
    const char next = at + 4 < text.size() ? text[at + 4] : '\0';
    if (word_start && (next == ' ' || next == '\'' || next == '\xC2')) return true;  // '§' starts with C2
  }
  return false;
}

/// Subcommand names listed under "Subcommands:" in a help text.
std::vector<std::string> subcommands(const std::string& help) {
  std::vector<std::string> names;
  std::istringstream in(help);
  std::string line;
  bool in_list = false;
  while (std::getline(in, line)) {
    if (line.rfind("Subcommands:", 0) == 0) {
      in_list = true;
      continue;
    }
    if (in_list && line.size() > 2 && line[0] == ' ' && line[2] != ' ' && line[2] != '-') {
      std::istringstream w(line);
      std::string name;
      w >> name;
      names.push_back(name);
    }
  }
  return names;
}

TEST(DemoErrata, NoUserFacingTextCitesTheInternalSpec) {
  // Help and reports cite docs/theory.md or the seed's equations, never our internal spec
  // ("SPEC §3.1" was on the report's About page). Every help text, two levels deep:
  std::vector<std::string> commands{""};
  for (const std::string& top : subcommands(run_tribolab("--help").out)) {
    commands.push_back(top);
    for (const std::string& sub : subcommands(run_tribolab(top + " --help").out)) commands.push_back(top + " " + sub);
  }
  EXPECT_GT(commands.size(), 20u);
  for (const std::string& c : commands) {
    const auto r = run_tribolab(c + " --help");
    EXPECT_EQ(r.exit_code, 0) << c;
    EXPECT_FALSE(cites_spec(r.out)) << "tribolab " << c << " --help";
  }
  // The demo's About and Errata pages:
  report::Report rep;
  std::ostringstream log;
  add_about_section(rep, log);
  add_errata_section(rep, log);
  EXPECT_FALSE(cites_spec(report::to_html(rep)));
  // docs/theory.md is user documentation too.
  EXPECT_FALSE(cites_spec(slurp(std::string(TRIBOLAB_SOURCE_DIR) + "/docs/theory.md")));
}

}  // namespace
}  // namespace tribolab::cli
