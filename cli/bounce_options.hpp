// Command-line options shared by every `tribolab bounce` command: the ball, the normal
// contact law, the friction law and the integrator tolerance (docs/cli.md#bounce). One
// definition so that defaults, help texts and error messages agree across simulate, drop,
// contact-time, sweep, analyze and fit.
#pragma once

#include "bounce/contact.hpp"
#include "bounce/friction.hpp"
#include "bounce/geometry.hpp"
#include "bounce/normal_law.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace tribolab::cli {

/// Throws InputError naming `option` unless v is finite.
void check_finite(double v, const char* option);

/// Turns "field: message" from a validate() into an InputError naming the option --field.
[[noreturn]] void invalid(const std::string& message);

/// g within the physical range, else an InputError naming --g: [0.01, 1000] m/s^2 where a
/// flight needs gravity (contact-time, drop, synth-video), [0, 1000] with `zero_allowed` where
/// the command starts at first touch (simulate, sweep): a contact without gravity is the
/// idealisation of the exact central Hunt-Crossley restitution (docs/theory.md).
double checked_g(double g, bool zero_allowed = false);

/// --a --b --mass --inertia (SPEC section 5, "ball options").
void add_ball_options(CLI::App* cmd, bounce::Ball& ball);
/// The ball after checking every field; InputError naming the option otherwise.
bounce::Ball checked_ball(const bounce::Ball& ball);

struct BallOptions {
  bounce::Ball ball;
  void add(CLI::App* cmd) { add_ball_options(cmd, ball); }
  bounce::Ball get() const { return checked_ball(ball); }
};

/// --model --K --n --D --restitution [--mu] --friction --slip-scale --k-t --c-t --tol.
/// Defaults: the seed's fitted Hunt–Crossley law (K = 101054, n = 1.51, D = 60423), exact
/// Coulomb stick–slip with mu = 0.5.
struct LawOptions {
  std::string model = "hunt-crossley";
  std::optional<double> K, n, D, restitution;
  std::string friction = "coulomb";
  double mu = 0.5, slip_scale = 0.01, k_t = 2.0e4, c_t = 0.0;
  double tol = 1e-10;  ///< integrator tolerance, absolute and relative

  LawOptions() = default;
  explicit LawOptions(double default_tol) : tol(default_tol) {}

  /// Adds the options; without `with_mu` the command owns --mu itself (e.g. a sweep axis).
  void add(CLI::App* cmd, bool with_mu = true);
  bounce::NormalLawSpec law() const;
  bounce::FrictionModel friction_model(double mu_value) const;
  bounce::FrictionModel friction_model() const { return friction_model(mu); }
  bounce::ContactOptions contact(double g) const;
};

}  // namespace tribolab::cli
