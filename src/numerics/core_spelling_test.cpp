// The core names no flag (docs/design.md, "Errors name fields; each front end spells them"):
// no string literal in the libraries below the application layer spells a front end's option
// ("--max-gap", "--plotly"); they name the field (field("max_gap"), numerics/error.hpp) and each
// front end spells it. The sources are read as C++ tokens: comments (which may describe a
// command line) and code such as `--i` are not string literals; raw strings of another
// language (delimiter CSS or JS: a style sheet's `--ink`, a script's `i--`) are left out.
#include "numerics/source_dir_test_util.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace tribolab {
namespace {

namespace fs = std::filesystem;

struct Literal {
  int line = 0;
  std::string text;  ///< between the quotes, escapes as written
};

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// The string literals of a C++ source, but raw strings delimited CSS or JS.
std::vector<Literal> string_literals(const std::string& src) {
  std::vector<Literal> out;
  int line = 1;
  const std::size_t n = src.size();
  std::size_t i = 0;
  const auto advance_to = [&](std::size_t end) {  // counts the lines passed
    for (; i < end && i < n; ++i) line += src[i] == '\n';
  };
  while (i < n) {
    const char c = src[i];
    if (c == '\n') {
      ++line, ++i;
    } else if (src.compare(i, 2, "//") == 0) {
      advance_to(src.find('\n', i) == std::string::npos ? n : src.find('\n', i));
    } else if (src.compare(i, 2, "/*") == 0) {
      const std::size_t end = src.find("*/", i + 2);
      advance_to(end == std::string::npos ? n : end + 2);
    } else if (c == '\'' && i > 0 && std::isxdigit(static_cast<unsigned char>(src[i - 1]))) {
      ++i;  // a digit separator (1'000), unless part of a character literal's prefix (u8'a' is not used)
    } else if (c == '\'') {
      std::size_t j = i + 1;
      while (j < n && src[j] != '\'') j += src[j] == '\\' ? 2 : 1;
      advance_to(j + 1);
    } else if (c == '"' && i > 0 && src[i - 1] == 'R' && (i < 2 || !identifier_char(src[i - 2]) ||
                                                           (i >= 3 && src.compare(i - 3, 2, "u8") == 0) || src[i - 2] == 'L' ||
                                                           src[i - 2] == 'u' || src[i - 2] == 'U')) {
      const std::size_t open = src.find('(', i + 1);
      if (open == std::string::npos) break;
      const std::string delim = src.substr(i + 1, open - i - 1);
      const std::size_t close = src.find(")" + delim + "\"", open + 1);
      const std::size_t end = close == std::string::npos ? n : close;
      if (delim != "CSS" && delim != "JS") out.push_back({line, src.substr(open + 1, end - open - 1)});
      advance_to(end == n ? n : end + delim.size() + 2);
    } else if (c == '"') {
      std::size_t j = i + 1;
      while (j < n && src[j] != '"' && src[j] != '\n') j += src[j] == '\\' ? 2 : 1;
      out.push_back({line, src.substr(i + 1, std::min(j, n) - i - 1)});
      advance_to(j + 1);
    } else {
      ++i;
    }
  }
  return out;
}

/// Whether `text` spells a command-line flag: "--" then a lower-case letter, not inside a word
/// ("a--b" is no flag).
bool spells_a_flag(const std::string& text) {
  for (std::size_t p = text.find("--"); p != std::string::npos; p = text.find("--", p + 1)) {
    const bool starts = p == 0 || !(identifier_char(text[p - 1]) || text[p - 1] == '-');
    if (starts && p + 2 < text.size() && std::islower(static_cast<unsigned char>(text[p + 2]))) return true;
  }
  return false;
}

TEST(CoreSpelling, TheScanFindsFlagsInStringLiteralsOnly) {
  const std::string sample =
      "// a comment: give \"--max-gap\"\n"
      "/* \"--search\" */ const char* a = \"a larger --max-gap\";\n"
      "char q = '\"'; int n = 1'000; --n; const char* b = \"x--y, -- z, --Big\";\n"
      "const char* r = R\"x(--raw \"quoted\")x\"; const char* s = R\"CSS(:root { --ink: #000; })CSS\";\n"
      "const char* e = \"an \\\"--escaped\\\" quote\";\n";
  std::vector<std::string> flagged;
  std::vector<int> lines;
  for (const Literal& l : string_literals(sample)) {
    if (spells_a_flag(l.text)) flagged.push_back(l.text), lines.push_back(l.line);
  }
  EXPECT_EQ(flagged, (std::vector<std::string>{"a larger --max-gap", "--raw \"quoted\"", "an \\\"--escaped\\\" quote"}));
  EXPECT_EQ(lines, (std::vector<int>{2, 4, 5}));
}

TEST(CoreSpelling, NoLibraryBelowTheApplicationLayerSpellsAFlag) {
  const fs::path src = fs::path(test_source_dir()) / "src";
  ASSERT_TRUE(fs::is_directory(src / "video")) << src;
  std::vector<std::string> found;
  int files = 0;
  for (const auto& area : fs::directory_iterator(src)) {
    const std::string name = area.path().filename().string();
    if (!area.is_directory() || name == "app" || name == "studio") continue;  // the front ends' layers
    for (const auto& e : fs::recursive_directory_iterator(area.path())) {
      const std::string file = e.path().filename().string();
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
      if (file.size() > 9 && file.compare(file.size() - 9, 9, "_test.cpp") == 0) continue;  // tests run commands
      ++files;
      std::ifstream in(e.path(), std::ios::binary);
      const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      for (const Literal& l : string_literals(text))
        if (spells_a_flag(l.text))
          found.push_back(fs::relative(e.path(), src).string() + ":" + std::to_string(l.line) + ": \"" + l.text + "\"");
    }
  }
  EXPECT_GT(files, 100);  // the scan read the libraries
  std::string list;
  for (const auto& f : found) list += "\n  " + f;
  EXPECT_TRUE(found.empty()) << "string literals spelling a flag (name the field: field(\"max_gap\")):" << list;
}

}  // namespace
}  // namespace tribolab
