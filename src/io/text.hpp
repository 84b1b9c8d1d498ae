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

/// Largest |x|, |y| of a tracked point in its file's units (m, cm, mm, px) and largest |t|
/// (s or ms): far beyond any tracked run (1e6 mm is a kilometre, 1e6 px a 1000-megapixel
/// side, 1e8 ms a day), far below where a fit's sums of squares lose every digit. A value
/// beyond them is a typo, a lost decimal point or a glitch that the fits cannot carry (one
/// 1e308 among metres gave mu 0.3996 for 0.3001 and no uncertainty): refused with file:line.
inline constexpr double kMaxTrackCoordinate = 1e6;

/// Frame numbers beyond this are refused by every reader: no video has them (a million
/// seconds at 100 fps), and they would overflow int arithmetic.
inline constexpr long long kMaxFrameNumber = 100'000'000;
inline constexpr double kMaxTrackTime = 1e8;

/// `v`, or InputError(where, "<what> = V is beyond +-MAX, ...") when |v| > max.
double check_track_value(double v, double max, const std::string& where, std::string_view what);

/// Empty when `s` can be a name tribolab passes on (a track name, a unit: into JSON, CSV,
/// reports): valid UTF-8 without control characters (a NUL would cut it short, an invalid
/// byte stops every JSON writer). Else what is wrong, naming the byte and its position:
/// "is not valid UTF-8 (byte 0xff at character 3)". The readers throw it with file:line.
std::string name_text_problem(std::string_view s);

/// A CSV cell for `s`: as it is, or in double quotes (inner quotes doubled) when it holds a
/// comma, a quote or a line break (RFC 4180).
std::string csv_quote(const std::string& s);

/// A CSV cell for the number `v`: its shortest round-trip form ("0.1", "1e-300"), or an empty
/// cell when it is NaN or infinite (undefined: a spreadsheet reads it as missing).
std::string csv_number(double v);

}  // namespace tribolab::io
