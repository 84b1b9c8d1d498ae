// Binding the incline commands' options to the application layer's option structs
// (src/app/incline_*.hpp): each CLI11 option writes straight into its struct field, so the
// field's initializer is the default the help shows (`--g NUM=9.8`). A number is read with
// io::parse_double first, so a bad one fails as before: one line naming the option.
#pragma once

#include "io/text.hpp"
#include "numerics/error.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace tribolab::cli {

namespace detail {
template <class T> struct number_of { using type = T; };
template <class T> struct number_of<std::optional<T>> { using type = T; };
template <class T> struct number_of<std::vector<T>> { using type = T; };
}  // namespace detail

/// Adds option `name` bound to `field` (double, int, unsigned, or an optional or vector of
/// them). Each value is parsed by io::parse_double (errors name `name`, exit 1), an integer
/// field must get a whole number; a vector takes comma-separated values.
template <class T>
CLI::Option* add_number(CLI::App& cmd, const std::string& name, T& field, const std::string& help) {
  using N = typename detail::number_of<T>::type;
  CLI::Option* opt = cmd.add_option(name, field, help);
  opt->transform(CLI::Validator(
      [name](std::string& text) {
        const double v = io::parse_double(text, name);
        if constexpr (std::is_integral_v<N>) {
          const double lo = std::is_signed_v<N> ? -9.007199254740992e15 : 0;
          if (!(v == std::floor(v) && v >= lo && v <= 9.007199254740992e15))
            throw InputError(name, std::string("must be an integer") + (std::is_signed_v<N> ? "" : " >= 0") +
                                       ", got " + text);
          text = fmt::format("{}", static_cast<long long>(v));
        } else {
          text = fmt::format("{:.17g}", v);  // the parsed value, exactly
        }
        return std::string();
      },
      "", "number"));
  if constexpr (!std::is_same_v<T, N>) {
    // One token per use, split at commas: `--phi-deg 12,16 a.csv b.csv` keeps the files.
    if constexpr (std::is_same_v<T, std::vector<N>>) opt->delimiter(',')->allow_extra_args(false);
  }
  return opt;
}

}  // namespace tribolab::cli
