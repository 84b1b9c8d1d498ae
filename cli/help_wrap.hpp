// Help that reads at 80 columns. CLI11 2.1 prints every description on one line, however
// long (paragraph wrapping came in CLI11 2.4), and starts option and subcommand descriptions
// at its column width (30). This pass, run after every command is registered, breaks each
// description at spaces so that no help line is wider than kHelpWidth terminal columns: CLI11
// indents the continuation lines of an option's or subcommand's description to its column,
// and footers (the plain-language explanations of models and diagnostics) start at column 0.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace tribolab::cli {

/// The width every help line fits in (a terminal's default).
inline constexpr std::size_t kHelpWidth = 80;

/// Terminal columns of UTF-8 text: CJK ideographs and fullwidth forms take two, others one.
std::size_t display_width(std::string_view text);

/// `text` broken at spaces into lines of at most `width` columns; its own line breaks are
/// kept. A word wider than `width` is broken after its | and , (a list of choices or
/// columns), else stands alone on its line.
std::string wrap_text(std::string_view text, std::size_t width);

/// Wraps the description, option help and footer of `app` and of all its subcommands.
void wrap_help(CLI::App& app);

}  // namespace tribolab::cli
