// One vocabulary of value placeholders in every command's help. CLI11 names a value by its
// C++ type (FLOAT, INT, UINT, TEXT), which reads as noise beside the hand-written NUM,
// FILE.html or A|B of other options. After all commands are registered this pass renames:
// FLOAT -> NUM, UINT -> INT, a TEXT that names a file -> FILE, a TEXT whose help lists its
// choices (a|b|c) -> those choices (NAME when too many to list), NAME=VALUE, I/N and a range
// lo:hi:count -> LO:HI:N as their help says, a track name -> NAME, and drops the placeholder
// of a positional argument whose name already says what it is (FILE, not FILE FILE).
// Defaults are captured from the option structs (app.cpp) and shown as `--g NUM=9.8`; this
// pass hides them where there is none to show (a required option, an empty list).
#pragma once

#include <CLI/CLI.hpp>

namespace tribolab::cli {

/// Applies the renaming above to every option of `app` and its subcommands.
void tidy_placeholders(CLI::App& app);

}  // namespace tribolab::cli
