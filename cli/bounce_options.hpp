// The command-line flags of the options every `tribolab bounce` command shares: the ball and
// the contact law (the option structs, their defaults and checks: src/app/bounce_options.hpp).
#pragma once

#include "app/bounce_options.hpp"
#include "app/bounce_truth_law.hpp"

#include <CLI/CLI.hpp>

namespace tribolab::cli {

/// --a --b --mass --inertia (SPEC section 5, "ball options").
void add_ball_options(CLI::App* cmd, bounce::Ball& ball);
inline void add_ball_options(CLI::App* cmd, app::BallOptions& ball) { add_ball_options(cmd, ball.ball); }

/// --model --K --n --D --restitution [--mu] --friction --slip-scale --k-t --c-t --tol; without
/// `with_mu` the command owns --mu itself (e.g. a sweep axis).
void add_law_options(CLI::App* cmd, app::LawOptions& law, bool with_mu = true);

/// --model --K --n --D --restitution --mu --friction --slip-scale of the synthetic generators
/// (`bounce synth-video`, `synth-table`, `render`).
void add_truth_law_options(CLI::App* cmd, app::TruthLawOptions& law);

/// The filmed throw of the synthetic generators (`bounce synth-video`, `bounce render`): the
/// ball, the truth law, the release (--height --theta-deg --omega --vx --vy) and the film
/// (--after --fps); `O` is the command's options struct with those fields.
template <class O>
void add_throw_options(CLI::App* cmd, O& o) {
  add_ball_options(cmd, o.ball);
  add_truth_law_options(cmd, o.law);
  cmd->add_option("--height", o.height, "centre height at release, m");
  cmd->add_option("--theta-deg", o.theta_deg, "orientation at release, deg");
  cmd->add_option("--omega", o.omega, "spin at release, rad/s");
  cmd->add_option("--vx", o.vx, "horizontal speed, m/s");
  cmd->add_option("--vy", o.vy, "vertical speed at release, m/s");
  cmd->add_option("--after", o.after, "seconds of video after the separation");
  cmd->add_option("--fps", o.fps, "camera frame rate, 1/s");
}

}  // namespace tribolab::cli
