#include "report/format.hpp"

#include "report/embedded.hpp"
#include "numerics/units.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

namespace tribolab::report {
namespace {

TEST(FormatUncertain, SigmaHasTwoSignificantDigitsAndValueMatchesItsPlace) {
  EXPECT_EQ(format_uncertain(0.63427, 0.01234), "0.634 ± 0.012");
  EXPECT_EQ(format_uncertain(0.63427, 0.0186), "0.634 ± 0.019");
  EXPECT_EQ(format_uncertain(-2.71828, 0.0031), "-2.7183 ± 0.0031");
  EXPECT_EQ(format_uncertain(0.5, 3.2), "0.5 ± 3.2");
  EXPECT_EQ(format_uncertain(0.0, 0.05), "0.000 ± 0.050");
}

TEST(FormatUncertain, RoundingSigmaUpToTheNextDecadeMovesTheDecimalPlace) {
  // 0.0996 rounds to 0.10 (2 significant digits), not to 0.100.
  EXPECT_EQ(format_uncertain(9.81, 0.0996), "9.81 ± 0.10");
  EXPECT_EQ(format_uncertain(1.0, 0.9996), "1.0 ± 1.0");
}

TEST(FormatUncertain, LargeSigmaRoundsTheValueToTensHundreds) {
  EXPECT_EQ(format_uncertain(1234.6, 23.4), "1235 ± 23");
  EXPECT_EQ(format_uncertain(123456.0, 1234.0), "123500 ± 1200");
}

TEST(FormatUncertain, VeryLargeOrSmallNumbersShareAPowerOfTen) {
  EXPECT_EQ(format_uncertain(6.02214e23, 1.2e21), "(6.022 ± 0.012)×10²³");
  EXPECT_EQ(format_uncertain(1.5e6, 2.0e4), "(1.500 ± 0.020)×10⁶");
  EXPECT_EQ(format_uncertain(1.234e-4, 1.2e-6), "(1.234 ± 0.012)×10⁻⁴");
  // 1e-3 itself is still written in fixed notation.
  EXPECT_EQ(format_uncertain(1.234e-3, 1.2e-5), "0.001234 ± 0.000012");
}

TEST(FormatUncertain, ValueRoundedToZeroHasNoSign) {
  EXPECT_EQ(format_uncertain(-0.00004, 0.012), "0.000 ± 0.012");
}

TEST(FormatUncertain, MissingOrInvalidNumbers) {
  EXPECT_EQ(format_uncertain(kNaN, 0.1), "—");
  EXPECT_EQ(format_uncertain(std::numeric_limits<double>::infinity(), 0.1), "—");
  EXPECT_EQ(format_uncertain(0.634, kNaN), "0.634");  // no uncertainty known
  EXPECT_EQ(format_uncertain(0.634, -0.1), "0.634");
  EXPECT_EQ(format_uncertain(0.634, 0.0), "0.634 ± 0");
}

TEST(FormatUncertain, PrintedSigmaIsWithinRoundingOfTheTrueSigmaOverManyDecades) {
  // Two significant digits: the printed sigma differs from the true one by at most half a
  // unit of the second digit, i.e. at most 5 % (0.5 / 10) relative. Fixed-notation cases
  // only (|x| in [1e-3, 1e6)), where the text parses back directly.
  for (int k = 0; k < 40; ++k) {
    const double sigma = 1e-3 * std::pow(1.37, k);
    const double value = 7.3 * sigma * (k + 1);
    if (std::max(value, sigma) >= 1e6) break;
    const std::string s = format_uncertain(value, sigma);
    const auto pm = s.find(" ± ");
    ASSERT_NE(pm, std::string::npos) << s;
    const std::string sig_text = s.substr(pm + std::string(" ± ").size());
    const double printed = std::stod(sig_text);
    EXPECT_LE(std::fabs(printed - sigma), 0.05 * sigma) << s << " for sigma " << sigma;
    std::string digits;
    for (char c : sig_text) {
      if (std::isdigit(static_cast<unsigned char>(c)) && !(digits.empty() && c == '0')) {
        digits += c;
      }
    }
    // "1200" has trailing zeros that only fix the place: count up to the last non-zero.
    while (digits.size() > 2 && digits.back() == '0') digits.pop_back();
    EXPECT_LE(digits.size(), 2u) << s;
  }
}

TEST(FormatValue, SignificantDigitsAndMissing) {
  EXPECT_EQ(format_value(0.63427), "0.6343");
  EXPECT_EQ(format_value(1.25e-5, 3), "1.25e-05");
  EXPECT_EQ(format_value(kNaN), "—");
}

TEST(Escape, HtmlSpecialCharactersAreEscaped) {
  EXPECT_EQ(html_escape("<script>alert('x') & \"y\"</script>"),
            "&lt;script&gt;alert(&#39;x&#39;) &amp; &quot;y&quot;&lt;/script&gt;");
  EXPECT_EQ(escape_text("a < b & \"c\" 'd'"), "a &lt; b &amp; \"c\" 'd'");
  EXPECT_EQ(html_escape("μ = 0.634"), "μ = 0.634");  // UTF-8 passes through
  EXPECT_EQ(html_escape(std::string("a\0b", 3)), "a\xEF\xBF\xBD" "b");
}

TEST(Escape, NotationMakesSubAndSuperscriptsAndEscapesTheRest) {
  EXPECT_EQ(notation_html("v_{x0}^2"), "v<sub>x0</sub><sup>2</sup>");
  EXPECT_EQ(notation_html("e^{-k t}"), "e<sup>-k t</sup>");
  EXPECT_EQ(notation_html("a_{b^{2}}"), "a<sub>b<sup>2</sup></sub>");
  EXPECT_EQ(notation_html("φ_0 = θ_φ"), "φ<sub>0</sub> = θ<sub>φ</sub>");  // UTF-8 characters
  EXPECT_EQ(notation_html("run\\_01"), "run_01");
  EXPECT_EQ(notation_html("x < y & z_"), "x &lt; y &amp; z_");  // trailing '_' is literal
  EXPECT_EQ(notation_html("_{<b>}"), "<sub>&lt;b&gt;</sub>");
  EXPECT_EQ(notation_html("a_{unclosed"), "a<sub>unclosed</sub>");
  EXPECT_EQ(notation_html("{x}"), "{x}");
}

TEST(Escape, ScriptSafeRemovesEverySequenceThatEndsOrEscapesAScript) {
  const std::string js = "a='</script>';b=\"<!--\";c=/<SCRIPT/i;d='</Script '";
  const std::string safe = script_safe(js);
  EXPECT_EQ(safe, "a='<\\/script>';b=\"<\\x21--\";c=/<\\x53CRIPT/i;d='<\\/Script '");
  EXPECT_EQ(script_safe("if (a < b) c = a <= b;"), "if (a < b) c = a <= b;");
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

TEST(Escape, EmbeddedPlotlyIsScriptSafeAfterRewriting) {
  const std::string safe = lower(script_safe(plotly_js()));
  EXPECT_EQ(safe.find("</script"), std::string::npos);
  EXPECT_EQ(safe.find("<script"), std::string::npos);
  EXPECT_EQ(safe.find("<!--"), std::string::npos);
}

TEST(Escape, JsonForScriptCannotCloseItsBlockAndParsesBack) {
  const nlohmann::json j = {{"s", "</script><!-- & >"}, {"x", 0.1}};
  const std::string text = json_for_script(j);
  EXPECT_EQ(text.find('<'), std::string::npos);
  EXPECT_EQ(text.find('>'), std::string::npos);
  EXPECT_EQ(text.find('&'), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(text), j);
}

TEST(Escape, JsonForScriptWritesNaNAsNullAndReplacesInvalidUtf8) {
  const nlohmann::json j = {{"v", {1.0, kNaN, std::numeric_limits<double>::infinity()}},
                            {"name", std::string("bad \xFF byte")}};
  const auto back = nlohmann::json::parse(json_for_script(j));
  EXPECT_TRUE(back["v"][1].is_null());
  EXPECT_TRUE(back["v"][2].is_null());
  EXPECT_EQ(back["name"], "bad \xEF\xBF\xBD byte");
}

TEST(Slugify, AsciiWordsJoinedByDashes) {
  EXPECT_EQ(slugify("Incline: x–t & y–t"), "incline-x-t-y-t");
  EXPECT_EQ(slugify("  About this report "), "about-this-report");
  EXPECT_EQ(slugify("斜面"), "section");
  EXPECT_EQ(slugify("", "plot"), "plot");
}

TEST(Base64, RfcTestVectors) {
  // RFC 4648, section 10: every padding case.
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
}

TEST(Base64, HighBytesUseTheWholeAlphabetAndDecodeBack) {
  // Bytes >= 0x80 must not be sign-extended: FF FF FF is "////", FB FF is "+/8=".
  EXPECT_EQ(base64("\xFF\xFF\xFF"), "////");
  EXPECT_EQ(base64("\xFB\xFF"), "+/8=");
  // Every byte value once, decoded back by an independent reading of the alphabet.
  std::string all;
  for (int b = 0; b < 256; ++b) all += static_cast<char>(b);
  const std::string enc = base64(all);
  ASSERT_EQ(enc.size(), 344u);  // ceil(256 / 3) * 4
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string dec;
  unsigned bits = 0;
  int n = 0;
  for (char c : enc) {
    if (c == '=') break;
    bits = (bits << 6) | static_cast<unsigned>(alphabet.find(c));
    n += 6;
    if (n >= 8) {
      n -= 8;
      dec += static_cast<char>((bits >> n) & 0xFF);
    }
  }
  EXPECT_EQ(dec, all);
}

TEST(Embedded, PlotlyLibraryAndVersionAreInTheBinary) {
  // The vendored file begins with its licence banner naming the bundle and the version.
  const std::string_view js = plotly_js();
  EXPECT_GT(js.size(), 1'000'000u);
  EXPECT_NE(js.substr(0, 200).find("plotly.js (cartesian - minified) v" + std::string(plotly_version())),
            std::string_view::npos);
  EXPECT_NE(js.find("newPlot"), std::string_view::npos);
  EXPECT_FALSE(tribolab_version().empty());
}

}  // namespace
}  // namespace tribolab::report
