// The bounce table of `bounce fit` and `bounce synth-table`: CSV with the header
//   theta_deg,vx_in,vy_in,omega_in,vx_out,vy_out,omega_out
// (columns in any order, extra columns ignored, '#' comment lines and blank lines skipped;
// cells may be double-quoted as RFC 4180 writes them, so a quoted `file` cell may hold commas),
// one measured bounce per row, SI units and degrees. docs/cli.md#bounce-fit.
#pragma once

#include "analysis/bounce_fit.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace tribolab::io {

/// Parses a table; `source` names it in errors ("file.csv:12: ..."). Throws InputError for a
/// missing column, a malformed or non-finite number, a wrong field count or no rows.
std::vector<analysis::BounceRow> parse_bounce_table(std::string_view text, const std::string& source);

/// Reads and parses `path`.
std::vector<analysis::BounceRow> read_bounce_table(const std::string& path);

/// The table as CSV text (header and one line per row, shortest round-trip numbers). With
/// `files` (one per row) a last column `file` names each row's source (quoted where needed):
/// a plain table a spreadsheet opens, with no comment line (docs/design.md#spreadsheets).
std::string write_bounce_table(const std::vector<analysis::BounceRow>& rows,
                               const std::vector<std::string>& files = {});

}  // namespace tribolab::io
