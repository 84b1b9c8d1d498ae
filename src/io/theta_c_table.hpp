// The table `incline normal-friction-test --table` reads (docs/cli.md#incline-normal-friction-test):
// CSV with a header naming the columns phi_deg and cos_theta_c, optionally sigma_cos_theta_c, in
// any order; blank lines and lines starting with # are skipped. One row per run at an angle.
#pragma once

#include "analysis/incline_diagnostics.hpp"

#include <string>
#include <vector>

namespace tribolab::io {

/// Parses the table's text; `name` (the file) names errors as "name:line: ...". Each point's
/// phi is in rad, its source is "name:line". Throws InputError on a missing header column, a
/// short row, a bad number or phi_deg outside (0, 90).
std::vector<analysis::ThetaCPoint> parse_theta_c_table(const std::string& text, const std::string& name);

/// Reads and parses the file at `path`.
std::vector<analysis::ThetaCPoint> read_theta_c_table(const std::string& path);

}  // namespace tribolab::io
