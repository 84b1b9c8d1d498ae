// Small text utilities shared by the file readers: strict number parsing with locations,
// splitting and trimming.
#pragma once

#include <optional>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tribolab::io {

/// Parses a whole field as a finite double ("1.5", "-2e-3"). With decimal_comma, a single
/// ',' is read as the decimal point ("1,5"). Throws InputError(where, ...) naming the text.
double parse_double(std::string_view text, const std::string& where, bool decimal_comma = false);

/// Like parse_double but returns nullopt for an empty (or all-blank) field.
std::optional<double> parse_optional_double(std::string_view text, const std::string& where,
                                            bool decimal_comma = false);

std::string_view trim(std::string_view s);

/// Splits on `delim`; keeps empty fields ("a,,b" -> {"a", "", "b"}).
std::vector<std::string> split(std::string_view line, char delim);

/// The largest text input read whole (a .trk, a track table), bytes: 512 MiB, 30x the
/// 20,000-frame projects we have. The same bound applies to a .trk inside a .trz.
inline constexpr std::uint64_t kMaxTextInputBytes = 512ull << 20;

/// Reads a whole file, with memory of its size (not the 3-4x of a growing buffer); throws
/// InputError naming the path when it cannot be read or holds more than max_bytes (also
/// for a pipe or device, which is read until its end).
std::string read_file(const std::string& path, std::uint64_t max_bytes = kMaxTextInputBytes);

/// Formats a double with up to 12 significant digits, shortest form ("0.1", "1e-09").
std::string format_number(double v);

/// A CSV cell for `s`: as it is, or in double quotes (inner quotes doubled) when it holds a
/// comma, a quote or a line break (RFC 4180).
std::string csv_quote(const std::string& s);

}  // namespace tribolab::io
