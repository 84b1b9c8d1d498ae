// In-process tests of the demo's content: the numbers the report shows are the library's
// (table 1 from incline::seed000_case_study), and every erratum is on the errata page.
#include "demo.hpp"

#include "incline/case_study.hpp"
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

}  // namespace
}  // namespace tribolab::cli
