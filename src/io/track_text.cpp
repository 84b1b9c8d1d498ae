#include "io/track_text.hpp"

#include "io/text.hpp"

#include <cctype>
#include <charconv>

namespace tribolab::io::tracktext {

std::vector<Line> lines(std::string_view text) {
  std::vector<Line> out;
  std::size_t start = 0;
  int number = 1;
  while (start <= text.size()) {
    std::size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) {
      if (start < text.size()) out.push_back({text.substr(start), number});
      break;
    }
    out.push_back({text.substr(start, end - start), number++});
    if (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n') ++end;
    start = end + 1;
  }
  return out;
}

namespace {
std::string_view clean(std::string_view c) {
  c = trim(c);
  if (c.size() >= 2 && c.front() == '"' && c.back() == '"') c = c.substr(1, c.size() - 2);
  return c;
}
}  // namespace

std::vector<std::string_view> cells(std::string_view line, char delim, std::size_t expected) {
  std::vector<std::string_view> out;
  // quote-aware split: a field starting with '"' runs to its closing quote, so names such as
  // "tip, B" survive (doubled quotes inside stay doubled; names rarely hold quotes)
  auto split_single = [&] {
    out.clear();
    std::size_t start = 0;
    while (true) {
      std::size_t scan = start;
      while (scan < line.size() && line[scan] == ' ' && delim != ' ') ++scan;
      if (scan < line.size() && line[scan] == '"') {
        std::size_t q = scan + 1;
        while (q < line.size()) {
          if (line[q] == '"' && q + 1 < line.size() && line[q + 1] == '"') {
            q += 2;
          } else if (line[q] == '"') {
            break;
          } else {
            ++q;
          }
        }
        scan = std::min(q + 1, line.size());
      }
      const auto pos = line.find(delim, scan);
      if (pos == std::string_view::npos) {
        out.push_back(clean(line.substr(start)));
        return;
      }
      out.push_back(clean(line.substr(start, pos - start)));
      start = pos + 1;
    }
  };
  if (delim != ' ') {
    split_single();
    return out;
  }
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.remove_suffix(1);
  if (expected > 0) {  // Tracker's one space per cell keeps empty cells
    split_single();
    while (out.size() > expected && out.back().empty()) out.pop_back();
    if (out.size() <= expected) return out;
  }
  out.clear();  // hand-aligned text: runs of blanks separate cells
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t s = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > s) out.push_back(clean(line.substr(s, i - s)));
  }
  return out;
}

ColumnName column_name(std::string_view cell) {
  cell = clean(cell);
  ColumnName c;
  std::string_view base = cell, unit;
  for (const auto& [open, close] : {std::pair{'(', ')'}, std::pair{'[', ']'}}) {
    const auto o = cell.find(open);
    if (o != std::string_view::npos && !cell.empty() && cell.back() == close) {
      base = trim(cell.substr(0, o));
      unit = trim(cell.substr(o + 1, cell.size() - o - 2));
      break;
    }
  }
  for (char ch : base) c.base += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  c.unit = std::string(unit);
  return c;
}

bool is_time_name(const ColumnName& c) { return c.base == "t" || c.base == "time"; }

std::optional<double> seconds_per_unit(const std::string& unit) {
  if (unit.empty() || unit == "s") return 1.0;
  if (unit == "ms") return 1e-3;
  return std::nullopt;
}

std::string exact(double v, bool decimal_comma) {
  if (v == 0) v = 0;  // no "-0" in tables
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, ptr);
  if (decimal_comma) {
    for (char& c : s) {
      if (c == '.') c = ',';
    }
  }
  return s;
}

std::string at(const std::string& source, int line) { return source + ":" + std::to_string(line); }

}  // namespace tribolab::io::tracktext
