// Checks of the words users read (help texts, reports), shared by the tests: a Chinese
// numeral in English text must stand beside its English reading, written one way everywhere:
// the Arabic reading first and the Chinese in parentheses after it, so a reader can
// cross-check against the paper: "equation 10A (十A)", "figures 5-7 (五-七)",
// "figure 3-2 (圖三-2)", "discussion 2 (討論 (二))".
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace tribolab::cli::testing {

/// Unicode code points of UTF-8 text (a stray byte is kept as itself).
inline std::u32string code_points(std::string_view s) {
  std::u32string out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 1;
    if (i + len > s.size()) len = 1;
    char32_t cp = len == 1 ? c : c & (0x3F >> (len - 1));
    for (std::size_t k = 1; k < len; ++k) cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
    out += cp;
    i += len;
  }
  return out;
}

inline std::string utf8(std::u32string_view s) {
  std::string out;
  for (char32_t c : s) {
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xE0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (c >> 18));
      out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  return out;
}

/// Chinese numerals, plain and formal (the formal ones number the papers' sections).
inline bool is_cjk_numeral(char32_t c) {
  return std::u32string_view(U"〇零一二三四五六七八九十百壹貳參肆伍陸柒捌玖拾").find(c) != std::u32string_view::npos;
}

inline bool is_ideograph(char32_t c) { return (c >= 0x3400 && c <= 0x9FFF) || (c >= 0xF900 && c <= 0xFAFF); }

/// Characters that put a number after them: figure 圖, table 表, equation 式, experiment
/// 實驗, appendix 附錄, the ordinal 第.
inline bool is_number_marker(char32_t c) { return std::u32string_view(U"圖表式驗錄第").find(c) != std::u32string_view::npos; }

inline bool is_ascii_letter(char32_t c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

/// Every Chinese numeral of `text` that names a number (not one inside a Chinese word, as
/// 二 in 斜面二維運動, "two-dimensional motion on an incline") and is not inside parentheses
/// that directly follow a word with an Arabic digit, e.g. "10A (十A)". The parentheses may
/// hold only Chinese, digits and punctuation besides the numeral (no English words), and may
/// nest: "discussion 2 (討論 (二))". Returns each offence with 30 characters of context.
inline std::vector<std::string> unread_cjk_numerals(std::string_view text) {
  const std::u32string t = code_points(text);
  std::vector<std::string> offences;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!is_cjk_numeral(t[i])) continue;
    const char32_t prev = i > 0 ? t[i - 1] : U' ';
    const char32_t next = i + 1 < t.size() ? t[i + 1] : U' ';
    const bool in_word = (is_ideograph(prev) && !is_cjk_numeral(prev) && !is_number_marker(prev)) ||
                         (is_ideograph(next) && !is_cjk_numeral(next));
    if (in_word) continue;
    bool read = false;
    int depth = 0;
    bool letters = false;  // an English word (two letters or more) before the numeral
    for (std::size_t j = i; j-- > 0 && i - j < 80 && !read;) {
      const char32_t c = t[j];
      if (c == U')') {
        ++depth;
      } else if (c == U'(' && depth > 0) {
        --depth;
      } else if (c == U'(') {
        if (letters) break;
        // The word before "(": it must hold an Arabic digit ("10A", "5-7", "3-2").
        if (j >= 2 && t[j - 1] == U' ') {
          std::size_t k = j - 1;
          while (k > 0 && t[k - 1] != U' ' && t[k - 1] != U'(') --k;
          for (std::size_t m = k; m < j - 1; ++m) read = read || (t[m] >= U'0' && t[m] <= U'9');
        }
      } else if (is_ascii_letter(c) && (is_ascii_letter(t[j + 1]) || (j > 0 && is_ascii_letter(t[j - 1])))) {
        letters = true;  // a word, not the letter of a reference like 十A
      }
    }
    if (!read) {
      const std::size_t from = i > 30 ? i - 30 : 0;
      offences.push_back(utf8(t.substr(from, std::min<std::size_t>(t.size(), i + 30) - from)));
    }
  }
  return offences;
}

}  // namespace tribolab::cli::testing
