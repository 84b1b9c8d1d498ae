// Helpers shared by the tracked-data text readers and writers (tracker_export, track_csv):
// lines with their numbers, cells, column names with units, exact number formatting.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tribolab::io::tracktext {

struct Line {
  std::string_view text;  ///< without the line break
  int number = 0;         ///< 1-based
};

/// Splits on \n, \r\n or \r.
std::vector<Line> lines(std::string_view text);

/// Cells of a line split on `delim`, each trimmed and stripped of surrounding double quotes.
/// With delim ' ', runs of spaces separate cells unless `expected` cells result from single
/// spaces (Tracker writes one space per cell, so empty cells survive).
std::vector<std::string_view> cells(std::string_view line, char delim, std::size_t expected = 0);

/// A column name split into its lower-case base and unit: "x (cm)" -> {"x", "cm"},
/// "T[ms]" -> {"t", "ms"}, "vx" -> {"vx", ""}.
struct ColumnName {
  std::string base, unit;
};
ColumnName column_name(std::string_view cell);

bool is_time_name(const ColumnName& c);

/// Seconds per time unit ("" and "s": 1, "ms": 1e-3); nullopt for anything else.
std::optional<double> seconds_per_unit(const std::string& unit);

/// Shortest text that reads back to the same double ("0.1", "1.2345678901234567e-05").
std::string exact(double v, bool decimal_comma = false);

/// "file:line".
std::string at(const std::string& source, int line);

}  // namespace tribolab::io::tracktext
