// The text listing for people (cli/text_listing.hpp): uncertainties rounded, units from the
// declared result keys only, nested results as blocks and sub-tables, null explained; and every
// command's listing free of raw JSON.
#include "text_listing.hpp"

#include "cli_test_util.hpp"

#include <gtest/gtest.h>

namespace tribolab::cli {
namespace {

using nlohmann::json;

TEST(TextListing, AValueWithItsUncertaintyAndIntervalIsOneRoundedRow) {
  const json r = {{"mu", 0.633116}, {"sigma_mu", 0.000419333}, {"ci95", {{"mu", {0.632287437, 0.633942838}}}},
                  {"v0", 2.61891}, {"sigma_v0", 0.0014591}};
  const std::string t = text_listing(r, {{"mu", "", ""}, {"v0", "m/s", ""}});
  // sigma to 2 significant digits, the value and the interval to the same place.
  EXPECT_NE(t.find("mu  0.63312 ± 0.00042  (95 % interval 0.63229 to 0.63394)\n"), std::string::npos) << t;
  EXPECT_NE(t.find("v0  2.6189 ± 0.0015 m/s\n"), std::string::npos) << t;
  EXPECT_EQ(t.find("sigma_"), std::string::npos) << t;  // shown with their values, not again
  EXPECT_EQ(t.find("ci95"), std::string::npos) << t;
}

TEST(TextListing, AnIntervalWithoutUncertaintyKeepsItsBoundsApart) {
  // A series' stop relation gives mu with a 95 % interval and no sigma: rounded to 4 digits the
  // listing said "(95 % interval 0.4 to 0.4)". The interval's own width sets the place.
  const std::string t = text_listing({{"mu", 0.399984}, {"mu_ci95", {0.3999754273, 0.3999926194}}}, {{"mu", "", ""}});
  EXPECT_NE(t.find("mu  0.399984  (95 % interval 0.3999754 to 0.3999926)\n"), std::string::npos) << t;
}

TEST(TextListing, NullSaysWhatItMeansAndEmptyListsSayNone) {
  const std::string t = text_listing({{"t_stop", nullptr}, {"first_above_release", nullptr}, {"other", nullptr},
                                      {"notes", json::array()}, {"stays_at_rest", false}},
                                     {});
  EXPECT_NE(t.find("t_stop               does not stop\n"), std::string::npos) << t;
  EXPECT_NE(t.find("first_above_release  never\n"), std::string::npos) << t;
  EXPECT_NE(t.find("other                none\n"), std::string::npos) << t;
  EXPECT_NE(t.find("notes                none\n"), std::string::npos) << t;
  EXPECT_NE(t.find("stays_at_rest        no\n"), std::string::npos) << t;
  EXPECT_EQ(t.find(" -\n"), std::string::npos) << t;
}

TEST(TextListing, UnitsComeFromTheDeclarationsNeverFromTheKeyNames) {
  // Issue 27: rules on key names printed "height 480 m" for pixels and "accelerations_defined
  // 89 m/s^2" for a count. Only the declaration counts: an undeclared key has no unit, whatever
  // its name suggests, and a declared key its declared unit.
  const json r = {{"height", 480}, {"accelerations_defined", 89}, {"t_stop", 1.25}, {"law", {{"K", 101054}}},
                  {"mean_normal_force", {{"mean", 1.7}}}};
  const app::ResultKeys keys = {{"height", "px", ""}, {"law.K", "N/m^1.5", ""}, {"mean_normal_force.mean", "N", ""}};
  const std::string t = text_listing(r, keys);
  EXPECT_NE(t.find("height                 480 px\n"), std::string::npos) << t;
  EXPECT_NE(t.find("accelerations_defined  89\n"), std::string::npos) << t;
  EXPECT_NE(t.find("t_stop                 1.25\n"), std::string::npos) << t;  // a "t_" name, but not declared
  EXPECT_NE(t.find("  K  101054 N/m^1.5\n"), std::string::npos) << t;
  EXPECT_NE(t.find("  mean  1.7 N\n"), std::string::npos) << t;
  EXPECT_EQ(column_label("vx_in", "m/s"), "vx_in (m/s)");
  EXPECT_EQ(column_label("theta_deg", "deg"), "theta_deg");  // the name says it
  EXPECT_EQ(column_label("n", ""), "n");
}

TEST(TextListing, NestedObjectsAreBlocksAndListsOfObjectsAreSubTables) {
  const json few = {{"law", {{"K", 101054}, {"model", "hunt-crossley"}}},
                    {"bounces", {{{"t_touch", 0.42976}, {"e", 0.33197}}, {{"t_touch", 0.73704}, {"e", nullptr}}}}};
  const std::string t = text_listing(few, {{"bounces.t_touch", "s", ""}});
  EXPECT_NE(t.find("law:\n  K      101054\n  model  hunt-crossley\n"), std::string::npos) << t;
  // Few elements side by side, one row per field with its unit.
  EXPECT_NE(t.find("bounces:\n               bounce 1  bounce 2\n"), std::string::npos) << t;
  EXPECT_NE(t.find("  t_touch (s)  0.42976   0.73704\n"), std::string::npos) << t;
  EXPECT_NE(t.find("  e            0.33197   undefined"), std::string::npos) << t;
  // Many elements: one row each.
  json runs = json::array();
  for (int i = 0; i < 12; ++i) runs.push_back({{"mu", 0.5 + 0.01 * i}, {"t_stop", 1.0}});
  const std::string m = text_listing({{"runs", runs}}, {{"runs.t_stop", "s", ""}});
  EXPECT_NE(m.find("runs:\n  #   mu    t_stop (s)\n  1   0.5   1\n"), std::string::npos) << m;
  EXPECT_NE(m.find("  12  0.61  1\n"), std::string::npos) << m;
}

TEST(TextListing, NoCommandPrintsRawJsonToPeople) {
  const std::string dir = std::string(TRIBOLAB_SOURCE_DIR) + "/data/demo/";
  const std::string out = testing::temp_dir("text_listing");
  for (const std::string& args : std::vector<std::string>{"bounce drop --height 1 --bounces 3", "bounce simulate --vy -3 --omega 10 --theta-deg 30",
        "incline families --mu 0.3 --phi-deg 20 --vary v0 --values 1,2,3 --out " + out + "/f.csv",
        "incline analyze '" + dir + "incline/run_20.96deg.txt' --phi-deg 20.96"}) {
    const auto r = testing::run_tribolab(args);
    ASSERT_EQ(r.exit_code, 0) << args << ": " << r.err;
    for (const char* raw : {"{\"", "[{", "[0.", "[-", "\": "}) EXPECT_EQ(r.out.find(raw), std::string::npos) << args << ":\n" << r.out;
    EXPECT_EQ(r.out.find("  -\n"), std::string::npos) << args << ":\n" << r.out;
  }
}

}  // namespace
}  // namespace tribolab::cli
