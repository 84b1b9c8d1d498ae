// The words a newcomer reads: the help of every command and the demo's report name the two
// studies (not "seed 000/001"), give every Chinese numeral its English reading, explain the
// models and diagnostics of the analyses, and fit in 80 columns (help_wrap.hpp).
#include "cli_test_util.hpp"
#include "help_wrap.hpp"
#include "words_check.hpp"

#include "app/demo/demo.hpp"
#include "report/html.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <tuple>

namespace tribolab::cli {
namespace {

using testing::run_tribolab;
using testing::unread_cjk_numerals;

/// The root help, each area's and each command's, concatenated.
std::string all_help() {
  std::string all = run_tribolab("--help").out;
  for (const char* area : {"incline", "bounce", "track", "demo"}) {
    const std::string out = run_tribolab(std::string(area) + " --help").out;
    all += out;
    const auto start = out.find("Subcommands:");
    if (start == std::string::npos) continue;
    std::istringstream lines(out.substr(start));
    std::string line;
    std::getline(lines, line);
    while (std::getline(lines, line)) {
      // A subcommand's name starts at column 2; continuation lines of its description are
      // indented to the description column.
      if (line.size() < 3 || line[2] == ' ') continue;
      std::istringstream words(line);
      std::string name;
      if (words >> name) all += run_tribolab(std::string(area) + " " + name + " --help").out;
    }
  }
  return all;
}

const std::string& help_text() {
  static const std::string text = all_help();
  return text;
}

TEST(Words, CheckerFindsNumeralsWithoutTheirReading) {
  // The checker itself: offences and accepted forms, so the scans below cannot pass vacuously.
  EXPECT_EQ(unread_cjk_numerals("(seed 000, eq 十A)").size(), 1u);
  EXPECT_EQ(unread_cjk_numerals("seed figures 五-七").size(), 2u);
  EXPECT_EQ(unread_cjk_numerals("eq c, 圖三-2)").size(), 1u);
  EXPECT_EQ(unread_cjk_numerals("Figure 八-2: t_f").size(), 1u);
  EXPECT_EQ(unread_cjk_numerals("seed 001 (eq 十A)").size(), 1u);  // a digit before, but not its reading
  EXPECT_TRUE(unread_cjk_numerals("incline study, equation 10A (十A)").empty());
  EXPECT_TRUE(unread_cjk_numerals("figures 5-7 (五-七) and 5A–8 (五A–八)").empty());
  EXPECT_TRUE(unread_cjk_numerals("figure 3-2 (圖三-2)").empty());
  EXPECT_TRUE(unread_cjk_numerals("discussion 2 (討論 (二))").empty());
  EXPECT_TRUE(unread_cjk_numerals("斜面二維運動與摩擦力的探討 (two-dimensional motion)").empty());  // a title
}

TEST(Words, WrapKeepsEveryLineWithinTheWidthCountingWideCharacters) {
  const std::string text = "a b c 斜面二維運動與摩擦力的探討 " + std::string(30, 'x') + " y";
  const std::string wrapped = wrap_text(text, 30);
  std::istringstream lines(wrapped);
  std::string line;
  int n = 0;
  while (std::getline(lines, line)) {
    ++n;
    EXPECT_LE(display_width(line), 30u) << line;
  }
  EXPECT_EQ(n, 4);  // "a b c", the title (26 columns), the 30 x, "y"
  EXPECT_EQ(display_width("斜面"), 4u);  // two columns per ideograph
  EXPECT_EQ(wrap_text("one\ntwo three", 80), "one\ntwo three");  // own breaks kept
  // A list of choices wider than the line breaks after its separators, not elsewhere.
  EXPECT_EQ(wrap_text("law: hooke|hertz|hunt-crossley|flores", 20), "law: hooke|hertz|\nhunt-crossley|flores");
}

TEST(Words, NoHelpLineIsWiderThanEightyColumns) {
  // CLI11 2.1 does not wrap (it prints each description on one line from column 30);
  // help_wrap.hpp wraps every description and footer to kHelpWidth = 80.
  const std::string& all = help_text();
  ASSERT_GT(all.size(), 10000u);  // every command's help was collected
  std::istringstream lines(all);
  std::string line;
  while (std::getline(lines, line)) EXPECT_LE(display_width(line), kHelpWidth) << line;
}

TEST(Words, HelpNamesTheStudiesNotSeedNumbers) {
  const std::string& all = help_text();
  EXPECT_EQ(all.find("seed 00"), std::string::npos);
  EXPECT_EQ(all.find("Seed 00"), std::string::npos);
  EXPECT_EQ(all.find("seed's"), std::string::npos);
  EXPECT_NE(all.find("the incline study"), std::string::npos);
  EXPECT_NE(all.find("the rugby-ball study"), std::string::npos);
}

TEST(Words, EveryChineseNumeralInTheHelpHasItsReading) {
  for (const auto& o : unread_cjk_numerals(help_text())) ADD_FAILURE() << "without its reading: " << o;
}

/// `text` with its line breaks and runs of spaces made one space (the help is wrapped).
std::string flat(const std::string& text) { return std::regex_replace(text, std::regex("\\s+"), " "); }

TEST(Words, InclineAnalysisHelpExplainsTheModelsAndEveryDiagnostic) {
  const std::string analyze = flat(run_tribolab("incline analyze --help").out);
  for (const char* phrase :
       {"Model B: Coulomb friction with one coefficient mu through the whole slide",
        "always points straight against the velocity", "Model A: model B plus a sideways friction force",
        "verdict: \"present\" when model A fits significantly better", "\"absent\" means no sideways friction was detected",
        "p_value: the chance", "test_size (5 %): how often the test errs", "a_N against sin(theta), equation b",
        "theta_c, equation c", "rms_residual", "chi2/dof near 1 means the runs agree"})
    EXPECT_NE(analyze.find(phrase), std::string::npos) << phrase;
  const std::string nft = flat(run_tribolab("incline normal-friction-test --help").out);
  for (const char* phrase : {"Model A:", "Model B:", "cos(theta_c) = tan(phi)/mu", "intercept excludes 0"})
    EXPECT_NE(nft.find(phrase), std::string::npos) << phrase;
  const std::string stop = flat(run_tribolab("incline mu-from-stop --help").out);
  for (const char* phrase : {"equation 10A (十A)", "needs only the angle and where the disc stopped", "sigma_mu:"})
    EXPECT_NE(stop.find(phrase), std::string::npos) << phrase;
  const std::string slide = flat(run_tribolab("incline mu-from-slide --help").out);
  for (const char* phrase : {"a = g sin(phi) - mu g cos(phi)", "r_squared:", "straightness_rms:", "chi2/dof"})
    EXPECT_NE(slide.find(phrase), std::string::npos) << phrase;
  for (const char* cmd : {"incline simulate --help", "incline predict --help"})
    EXPECT_NE(flat(run_tribolab(cmd).out).find("Model A: model B plus"), std::string::npos) << cmd;
}

TEST(Words, BounceAnalysisHelpExplainsEveryDiagnostic) {
  const std::string analyze = flat(run_tribolab("bounce analyze --help").out);
  for (const char* phrase :
       {"collision_angle_deg: at the first touch", "ray to the rear tip", "e_velocity: the coefficient of restitution",
        "e > 1 means the ball rebounds faster", "e_height:", "mean_normal_force:", "force_duration_method",
        "\"given\" (--contact-duration", "\"located\"", "floor_method:", "gravity_tilt_deg", "chi2/dof and p_value"})
    EXPECT_NE(analyze.find(phrase), std::string::npos) << phrase;
  const std::string fit = flat(run_tribolab("bounce fit --help").out);
  for (const char* phrase : {"N = K d^n + D d^n d'", "K is the stiffness", "D the damping", "mu the friction",
                             "sigma_*:", "rms:"})
    EXPECT_NE(fit.find(phrase), std::string::npos) << phrase;
}

/// The demo report's HTML without the embedded plotting library (minified JavaScript).
const std::string& demo_html() {
  static const std::string html = [] {
    const std::string dir = testing::temp_dir("words_demo");
    app::DemoContext context{dir};
    report::Report r;
    r.title = "tribolab demo";
    std::ostringstream log;
    // Every case study but the film (it renders and tracks a video: slow; its prose has no
    // study numbers or Chinese numerals).
    for (const auto& cs : app::demo_case_studies(context))
      if (cs.name != "film") cs.build(r, log);
    std::string h = report::to_html(r);
    const auto lib = h.find("<script>/* Plotly.js");
    if (lib != std::string::npos) h.erase(lib, h.find("</script>", lib) - lib);
    return h;
  }();
  return html;
}

/// The demo report's text: its HTML without tags.
std::string demo_text() {
  std::string text;
  bool in_tag = false;
  for (char c : demo_html()) {
    if (c == '<') in_tag = true;
    if (!in_tag) text += c;
    if (c == '>') in_tag = false;
  }
  return text;
}

TEST(Words, TheDemoReportNamesAndCitesTheStudies) {
  const std::string& html = demo_html();
  // "seed" is a random seed only: every other use is gone (the commands shown keep --seed).
  const std::string text = demo_text();
  const std::regex seed_word("(^|[^-])\\b[Ss]eed\\b");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), seed_word); it != std::sregex_iterator(); ++it)
    ADD_FAILURE() << "seed in: " << text.substr(it->position() > 40 ? it->position() - 40 : 0, 90);
  EXPECT_EQ(html.find("seed 00"), std::string::npos);
  EXPECT_EQ(html.find("Seed 00"), std::string::npos);
  EXPECT_EQ(html.find("seed's"), std::string::npos);
  // Each study cited once with its Chinese title, fair and year.
  for (const char* cite : {"斜面二維運動與摩擦力的探討", "有角速度之橄欖球的運動行為分析"}) {
    const auto at = html.find(cite);
    ASSERT_NE(at, std::string::npos) << cite;
    EXPECT_EQ(html.find(cite, at + 1), std::string::npos) << cite << " cited more than once";
  }
  EXPECT_NE(html.find("57th"), std::string::npos);
  EXPECT_NE(html.find("2017"), std::string::npos);
  EXPECT_NE(html.find("61st"), std::string::npos);
  EXPECT_NE(html.find("2021"), std::string::npos);
}

TEST(Words, EveryChineseNumeralInTheDemoReportHasItsReading) {
  const std::string text = demo_text();
  ASSERT_GT(text.size(), 10000u);
  for (const auto& o : unread_cjk_numerals(text)) ADD_FAILURE() << "without its reading: " << o;
}

TEST(Words, EachCommandReportCitesItsStudyOnce) {
  const std::string dir = testing::temp_dir("words_reports");
  const std::string stop = dir + "/stop.html", contact = dir + "/contact.html";
  ASSERT_EQ(run_tribolab("incline mu-from-stop --phi-deg 10.37 --x-stop 0.214 --y-stop -0.036 --report " + stop).exit_code, 0);
  ASSERT_EQ(run_tribolab("bounce contact-time --height 0.715 --omega -47.6 --theta-deg 11.3 --report " + contact).exit_code, 0);
  for (const auto& [file, title, other] :
       {std::tuple{stop, "斜面二維運動與摩擦力的探討", "有角速度之橄欖球的運動行為分析"},
        std::tuple{contact, "有角速度之橄欖球的運動行為分析", "斜面二維運動與摩擦力的探討"}}) {
    const std::string html = testing::slurp(file);
    const auto at = html.find(title);
    ASSERT_NE(at, std::string::npos) << file;
    EXPECT_EQ(html.find(title, at + 1), std::string::npos) << file;
    EXPECT_EQ(html.find(other), std::string::npos) << file;
    EXPECT_NE(html.find(">Source<"), std::string::npos) << file;
  }
}

}  // namespace
}  // namespace tribolab::cli
