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
// * The core names an option by its field (field("time_scale")), never by a front end's
//   spelling: the command line shows it as --time-scale, Python as time_scale.
// * Internal invariants are checked with TRIBOLAB_ASSERT, which prints both the
//   condition and the values involved and aborts: such a failure is a bug in tribolab.
// * Non-finite numbers are never passed on silently: require_finite() turns them into
//   an InputError naming the quantity.
#pragma once

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tribolab {

/// A field of an option struct named in a message, as the core spells it: its snake_case
/// name between two control characters, field("time_scale"), written where the message
/// names the input (`InputError(field("time_scale"), "must be positive")`, `field("order") +
/// " must be 1..6"`). Each front end spells it its own way (Error::message): the command line
/// `--time-scale`, Python (and what()) `time_scale` (docs/design.md, "Errors").
inline constexpr char kFieldOpen = '\x1e', kFieldClose = '\x1f';
inline std::string field(std::string_view name) {
  return kFieldOpen + std::string(name) + kFieldClose;
}

/// `text` with every field(...) in it spelled by `spell(name)`; other text unchanged.
template <class Spell>
std::string spell_fields(std::string_view text, Spell spell) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t open = text.find(kFieldOpen, i);
    const std::size_t close = open == std::string_view::npos ? open : text.find(kFieldClose, open + 1);
    if (close == std::string_view::npos) {
      out.append(text.substr(i));
      break;
    }
    out.append(text.substr(i, open - i));
    out += spell(text.substr(open + 1, close - open - 1));
    i = close + 1;
  }
  return out;
}

/// `text` with its fields named as the option structs name them (time_scale).
inline std::string plain_fields(std::string_view text) {
  return spell_fields(text, [](std::string_view name) { return std::string(name); });
}

/// An error tribolab reports to its user: what() is the whole message, `where()` names the
/// source ("file.csv:12", "time_scale", "model A") when one is known. Fields named with
/// field() read as their plain names in what() and where(); message(spell) spells them as a
/// front end does.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(plain_fields(message)), text_(message) {}
  Error(const std::string& where, const std::string& message)
      : std::runtime_error(plain_fields(where.empty() ? message : where + ": " + message)),
        where_(plain_fields(where)),
        text_(where.empty() ? message : where + ": " + message) {}
  const std::string& where() const noexcept { return where_; }
  /// The whole message with each field spelled by `spell(name)` (the command line: "--" and
  /// dashes for underscores).
  template <class Spell>
  std::string message(Spell spell) const { return spell_fields(text_, spell); }

 private:
  std::string where_;
  std::string text_;  ///< the message with its field() marks
};

/// Invalid input from the user: a parameter, an option or a file, or data that cannot
/// support the computation asked for.
class InputError : public Error {
 public:
  using Error::Error;
};

/// A required input is missing ("give --start, --ellipse or --from-track"): to the command
/// line a malformed command line (exit 2, as a missing required option), to Python a ValueError.
class MissingOptionError : public InputError {
 public:
  using InputError::InputError;
};

/// A solver failed on valid input: an integration gave up, a root or fit did not converge.
class SolverError : public Error {
 public:
  using Error::Error;
};

/// The InputError of a validate() message. "name: what", name a field as the option structs
/// spell it (range_error(v, r, "slip_scale") writes that), names field(name); a message that
/// already names its field with field(), or names none, is kept whole.
inline InputError input_error_of(const std::string& message) {
  const auto colon = message.find(':');
  if (colon == std::string::npos || colon == 0 || colon >= 24 || message.compare(colon, 2, ": ") != 0)
    return InputError(message);
  std::string name = message.substr(0, colon);
  for (char& c : name) {
    if (c == '-') c = '_';  // the older spelling of a few validate() messages
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return InputError(message);
  }
  return InputError(field(name), message.substr(colon + 2));
}

/// The message of `e` with its fields still marked (an Error's), else what(): for passing a
/// caught error's text on inside another message or between processes.
inline std::string marked_message(const std::exception& e) {
  if (const auto* err = dynamic_cast<const Error*>(&e)) return err->message(field);
  return e.what();
}

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
