// Error conventions shared by every layer of tribolab (STYLE.md, habit 6).
//
// * Invalid user input (a parameter out of range, a malformed file, data that cannot
//   support a fit) is reported by throwing InputError. The command-line layer catches it
//   and prints one line; library users catch it like any std::exception.
// * Internal invariants are checked with TRIBOLAB_ASSERT, which prints both the
//   condition and the values involved and aborts: such a failure is a bug in tribolab.
// * Non-finite numbers are never passed on silently: require_finite() turns them into
//   an InputError naming the quantity.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tribolab {

/// Invalid input from the user: a parameter, an option or a file. `where()` names the
/// source ("file.csv:12", "--mu") when one is known; what() is the whole message.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
  InputError(const std::string& where, const std::string& message)
      : std::runtime_error(where.empty() ? message : where + ": " + message), where_(where) {}
  const std::string& where() const noexcept { return where_; }

 private:
  std::string where_;
};

/// Throws InputError("<name> must be finite, got <value>") when value is NaN or infinite.
inline double require_finite(double value, std::string_view name) {
  if (!std::isfinite(value)) {
    throw InputError(std::string(name) + " must be a finite number, got " + std::to_string(value));
  }
  return value;
}

namespace detail {
[[noreturn]] inline void assertion_failed(const char* expr, const char* file, int line,
                                          const std::string& detail) {
  std::fprintf(stderr, "tribolab internal error: %s:%d: assertion `%s` failed%s%s\n", file, line,
               expr, detail.empty() ? "" : ": ", detail.c_str());
  std::abort();
}
}  // namespace detail

}  // namespace tribolab

/// Internal invariant; `message` is a std::string expression describing the values.
#define TRIBOLAB_ASSERT(cond, message)                                                 \
  do {                                                                                 \
    if (!(cond)) ::tribolab::detail::assertion_failed(#cond, __FILE__, __LINE__, (message)); \
  } while (false)
