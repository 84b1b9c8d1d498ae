// How a message echoes a number (docs/cli.md#errors): six significant digits, "1e+308",
// "0.5", "-inf" -- never std::to_string's fixed six decimals (1e308 as 309 digits, 1e-7 as
// "0.000000").
#pragma once

#include <cstdio>
#include <string>

namespace tribolab {

/// `v` with %.6g: the form every message that echoes a number uses; `digits` significant
/// digits where a message rounds a result for people ("mu 0.398", three or four digits).
inline std::string message_number(double v, int digits = 6) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

}  // namespace tribolab
