// The command-line flags of the options every `tribolab bounce` command shares: the ball and
// the contact law (the option structs, their defaults and checks: src/app/bounce/bounce_options.hpp).
#pragma once

#include "app/bounce/bounce_options.hpp"

#include <CLI/CLI.hpp>

namespace tribolab::cli {

/// --a --b --mass --inertia (SPEC section 5, "ball options").
void add_ball_options(CLI::App* cmd, bounce::Ball& ball);
inline void add_ball_options(CLI::App* cmd, app::BallOptions& ball) { add_ball_options(cmd, ball.ball); }

/// --model --K --n --D --restitution [--mu] --friction --slip-scale --k-t --c-t --tol; without
/// `with_mu` the command owns --mu itself (e.g. a sweep axis).
void add_law_options(CLI::App* cmd, app::LawOptions& law, bool with_mu = true);

}  // namespace tribolab::cli
