#include "help_wrap.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace tribolab::cli {
namespace {

/// The code point starting at s[i] and its length in bytes (a stray byte counts as one).
char32_t decode(std::string_view s, std::size_t i, std::size_t& len) {
  const auto c = static_cast<unsigned char>(s[i]);
  len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 1;
  if (i + len > s.size()) len = 1;
  if (len == 1) return c;
  char32_t cp = c & (0x3F >> (len - 1));
  for (std::size_t k = 1; k < len; ++k) cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
  return cp;
}

bool is_wide(char32_t c) {
  return (c >= 0x1100 && c <= 0x115F) || (c >= 0x2E80 && c <= 0xA4CF) || (c >= 0xAC00 && c <= 0xD7A3) ||
         (c >= 0xF900 && c <= 0xFAFF) || (c >= 0xFE30 && c <= 0xFE4F) || (c >= 0xFF00 && c <= 0xFF60) ||
         (c >= 0xFFE0 && c <= 0xFFE6) || (c >= 0x20000 && c <= 0x3FFFD);
}

/// The words of `line`, each with whether a space precedes it; a word wider than `width`
/// (a list such as a|b|c or x,y,z) is split after its | and , to break there.
std::vector<std::pair<std::string_view, bool>> words_of(std::string_view line, std::size_t width) {
  std::vector<std::pair<std::string_view, bool>> words;
  std::size_t pos = 0;
  while (pos <= line.size()) {
    const std::size_t end = std::min(line.find(' ', pos), line.size());
    std::string_view word = line.substr(pos, end - pos);
    bool space = true;
    while (display_width(word) > width) {
      const std::size_t cut = word.find_first_of("|,");
      if (cut == std::string_view::npos || cut + 1 >= word.size()) break;
      words.emplace_back(word.substr(0, cut + 1), space);
      word.remove_prefix(cut + 1);
      space = false;
    }
    words.emplace_back(word, space);
    pos = end + 1;
  }
  return words;
}

void wrap_line(std::string_view line, std::size_t width, std::string& out) {
  std::size_t used = 0;
  bool first = true;
  for (const auto& [word, space] : words_of(line, width)) {
    const std::size_t w = display_width(word);
    const std::size_t gap = space ? 1 : 0;
    if (!first && used + gap + w > width) {
      out += '\n';
      used = 0;
    } else if (!first && space) {
      out += ' ';
      ++used;
    }
    out += word;
    used += w;
    first = false;
  }
}

}  // namespace

std::size_t display_width(std::string_view text) {
  std::size_t cols = 0;
  for (std::size_t i = 0, len = 0; i < text.size(); i += len) cols += is_wide(decode(text, i, len)) ? 2 : 1;
  return cols;
}

std::string wrap_text(std::string_view text, std::size_t width) {
  std::string out;
  std::size_t start = 0;
  while (true) {
    const std::size_t nl = text.find('\n', start);
    wrap_line(text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start), width, out);
    if (nl == std::string_view::npos) break;
    out += '\n';
    start = nl + 1;
  }
  return out;
}

void wrap_help(CLI::App& app) {
  const std::size_t column = app.get_formatter()->get_column_width();
  const std::size_t width = kHelpWidth > column + 20 ? kHelpWidth - column : 20;
  // A description is shown both at the top of its own help (column 0) and in its parent's
  // list of subcommands (at the column): wrapped for the narrower place.
  app.description(wrap_text(app.get_description(), width));
  if (!app.get_footer().empty()) app.footer(wrap_text(app.get_footer(), kHelpWidth));
  for (CLI::Option* o : app.get_options()) o->description(wrap_text(o->get_description(), width));
  for (CLI::App* sub : app.get_subcommands({})) wrap_help(*sub);
}

}  // namespace tribolab::cli
