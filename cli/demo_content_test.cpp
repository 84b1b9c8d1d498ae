// In-process tests of the demo's content: the numbers the report shows are the library's
// (table 1 from incline::seed000_case_study), and every erratum is on the errata page.
#include "cli_test_util.hpp"
#include "demo.hpp"

#include "analysis/bounce_analyze.hpp"
#include "incline/case_study.hpp"
#include "io/track_import.hpp"
#include "report/format.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace tribolab::cli {
namespace {

const report::Table* find_table(const report::Report& r, const std::string& caption_start) {
  for (const auto& s : r.sections)
    for (const auto& b : s.blocks)
      if (const auto* t = std::get_if<report::Table>(&b); t && t->caption.rfind(caption_start, 0) == 0) return t;
  return nullptr;
}

TEST(DemoContent, Table1IsTheCaseStudys) {
  report::Report r;
  std::ostringstream log;
  add_incline_case_study(r, log);
  const report::Table* t = find_table(r, "Table 1");
  ASSERT_NE(t, nullptr);
  const incline::CaseStudy cs = incline::seed000_case_study();
  ASSERT_EQ(t->rows.size(), cs.table1.size());
  ASSERT_EQ(t->rows.size(), 5u);  // the seed's five angles
  for (std::size_t i = 0; i < cs.table1.size(); ++i) {
    const auto& row = cs.table1[i];
    EXPECT_EQ(t->rows[i][0], report::format_value(row.phi_deg, 4));
    EXPECT_EQ(t->rows[i][3], report::format_value(row.mu_printed, 3));
    EXPECT_EQ(t->rows[i][4], report::format_value(row.mu, 4));
    // The shown value reads back to the case study's mu within its 4 significant digits.
    EXPECT_NEAR(std::stod(t->rows[i][4]), row.mu, 5e-4);
  }
  // The printed mu_A of the first column is the one erratum of table 1 (0.601 vs 0.6017).
  EXPECT_EQ(t->rows[0][3], "0.601");
  EXPECT_EQ(t->rows[0][4], "0.6017");
  // The log summarises the table: one line per angle.
  EXPECT_NE(log.str().find("4.82  0.601  0.6017"), std::string::npos) << log.str();
}

TEST(DemoContent, Figure8TableShowsOursAndThePrintedSlopes) {
  report::Report r;
  std::ostringstream log;
  add_incline_case_study(r, log);
  const report::Table* t = find_table(r, "Figure 八 slopes");
  ASSERT_NE(t, nullptr);
  ASSERT_EQ(t->rows.size(), 4u);
  EXPECT_EQ(t->rows[0][1], "0.2242");  // printed
  EXPECT_EQ(t->rows[0][2], "0.1966");  // eq 七, docs/theory.md errata
  EXPECT_EQ(t->rows[1][2], "0.09089");
}

TEST(DemoContent, ErrataPageListsEveryErratumOfBothSeeds) {
  report::Report r;
  std::ostringstream log;
  add_errata_section(r, log);
  const report::Table* t0 = find_table(r, "Seed 000");
  const report::Table* t1 = find_table(r, "Seed 001");
  ASSERT_NE(t0, nullptr);
  ASSERT_NE(t1, nullptr);
  EXPECT_EQ(t0->rows.size(), incline::seed000_case_study().errata.size());
  EXPECT_EQ(t1->rows.size(), seed001_errata().size());
  // docs/theory.md lists 9 seed 001 errata (2 analysis, 5 bounce, 2 sweep).
  EXPECT_EQ(seed001_errata().size(), 9u);
  for (const Erratum& e : seed001_errata()) {
    EXPECT_FALSE(e.where.empty());
    EXPECT_FALSE(e.text.empty());
    EXPECT_FALSE(e.check.empty()) << e.where;
  }
}

std::vector<const report::Table*> find_tables(const report::Report& r, const std::string& caption_start) {
  std::vector<const report::Table*> found;
  for (const auto& s : r.sections)
    for (const auto& b : s.blocks)
      if (const auto* t = std::get_if<report::Table>(&b); t && t->caption.rfind(caption_start, 0) == 0) found.push_back(t);
  return found;
}

TEST(DemoContent, BounceRunsShowTheAnalysisOfTheShippedFilesAgainstTheTruth) {
  report::Report r;
  std::ostringstream log;
  const std::string out = testing::temp_dir("demo_bounce_runs");
  add_bounce_runs_case_study(r, log, DemoContext{out});
  ASSERT_EQ(r.sections.size(), 4u);  // three videos and the table fit
  EXPECT_EQ(r.figure_count(), 3 * 6 + 5);
  const auto truth = find_tables(r, "Recovered vs the simulation's truth");
  ASSERT_EQ(truth.size(), 3u);
  // The first run is the seed's headline: e > 1 from velocities and from heights, and the
  // recovered value's 95% interval holds the truth (rows 6 and 7 of the table).
  const auto& higher = *truth[0];
  ASSERT_EQ(higher.rows[6][0], "e from velocities");
  ASSERT_EQ(higher.rows[7][0], "e from apex heights");
  for (int row : {6, 7}) {
    EXPECT_GT(std::stod(higher.rows[row][2]), 1.0) << higher.rows[row][0];
    EXPECT_EQ(higher.rows[row][3], "yes") << higher.rows[row][0] << ": " << higher.rows[row][1] << " vs " << higher.rows[row][2];
  }
  // Over the 30 velocity/restitution/apex rows of the three runs, a 95% interval misses
  // the truth about 1.5 times; more than 5 misses (P < 0.5% by the binomial law) would mean
  // intervals that are too narrow. (The data are fixed, so this is a golden check.)
  int misses = 0;
  for (const auto* t : truth)
    for (const auto& row : t->rows) misses += row[3] == "no" ? 1 : 0;
  EXPECT_LE(misses, 5) << log.str();
  // The numbers are those of analyze_bounce on the file the demo wrote (as the command would).
  io::ImportOptions io;
  io.time_scale = 0.125;
  io.tracks = {"A", "B"};
  const auto set = io::read_tracks(out + "/data/bounce/higher.txt", io);
  analysis::BounceAnalyzeOptions o;
  o.floor_y = 0.0;
  const auto a = analysis::analyze_bounce(set.find("A"), set.find("B"), o);
  EXPECT_EQ(higher.rows[6][1], report::format_uncertain(a.e_velocity, a.sigma_e_velocity));
  EXPECT_EQ(higher.rows[0][1], report::format_uncertain(a.pre.vx, a.pre.sigma_vx));
  // The table fit: the law that made the table is inside the 95% intervals of D/K and mu.
  const auto fit = find_tables(r, "Fitted vs the law that made the table");
  ASSERT_EQ(fit.size(), 1u);
  ASSERT_EQ(fit[0]->rows.size(), 5u);
  EXPECT_EQ(fit[0]->rows[3][3], "yes") << fit[0]->rows[3][1];  // mu
  EXPECT_EQ(fit[0]->rows[4][3], "yes") << fit[0]->rows[4][1];  // D/K
}

}  // namespace
}  // namespace tribolab::cli
