// Error conventions shared by every layer of tribolab (STYLE.md, habit 6; docs/design.md,
// "Errors: input, solver, bug").
//
// * Invalid user input (a parameter out of range, a malformed file, data that cannot
//   support a fit: too few points, parameters the data cannot determine) is reported by
//   throwing InputError: the user changes the input.
// * A solver that fails on input that passed validation (an ODE integration that gives up,
//   a root or a least-squares fit that does not converge, a contact whose integration
//   fails) throws SolverError: not the user's fault, but the message names what failed so
//   the user can try another tolerance, start or method. A solver's own result struct
//   reports such failures as a status (Ceres' Summary, odeint); the code that needs the
//   answer to go on throws.
// * Both derive from Error (where() + message): the command-line layer catches them and
//   prints one line, "tribolab: error: <where>: <message>", exit status 1; library users
//   catch Error, or std::exception.
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

/// An error tribolab reports to its user: what() is the whole message, `where()` names the
/// source ("file.csv:12", "--mu", "model A") when one is known.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
  Error(const std::string& where, const std::string& message)
      : std::runtime_error(where.empty() ? message : where + ": " + message), where_(where) {}
  const std::string& where() const noexcept { return where_; }

 private:
  std::string where_;
};

/// Invalid input from the user: a parameter, an option or a file, or data that cannot
/// support the computation asked for.
class InputError : public Error {
 public:
  using Error::Error;
};

/// A solver failed on valid input: an integration gave up, a root or fit did not converge.
class SolverError : public Error {
 public:
  using Error::Error;
};

/// A message on one line, as the front ends print it ("tribolab: error: ..." and Python's
/// ValueError): line breaks become spaces, trailing spaces go.
inline std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

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
