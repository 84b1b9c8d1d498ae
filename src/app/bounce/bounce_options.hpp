// Options shared by every bounce workflow: the ball, the normal contact law, the friction
// law and the integrator tolerance (docs/cli.md#bounce). One definition so that defaults and
// error messages agree across simulate, drop, contact-time, sweep, analyze and fit, and
// across the front ends (the command line binds these fields in cli/bounce_options.hpp; the
// Python module takes them as keywords). Errors name the field (field("mu"),
// numerics/error.hpp), which each front end spells: "--mu: ..." on the command line.
#pragma once

#include "bounce/contact.hpp"
#include "bounce/friction.hpp"
#include "bounce/geometry.hpp"
#include "bounce/normal_law.hpp"

#include "app/common/option_fields.hpp"

#include <optional>
#include <string>

namespace tribolab::app {

/// The normal law named `name`; InputError naming --model with the list of laws otherwise.
bounce::NormalModel parsed_model(const std::string& name);

/// The friction law named `name`; InputError naming --friction with the list otherwise.
bounce::FrictionKind parsed_friction(const std::string& name);

/// Throws InputError naming `option` unless v is finite.
void check_finite(double v, const std::string& option);

/// Turns "field: message" from a validate() into an InputError naming the field (input_error_of).
[[noreturn]] void invalid(const std::string& message);

/// g within the physical range, else an InputError naming --g: [0.01, 1000] m/s^2 where a
/// flight needs gravity (contact-time, drop, synth-video), [0, 1000] with `zero_allowed` where
/// the command starts at first touch (simulate, sweep): a contact without gravity is the
/// idealisation of the exact central Hunt-Crossley restitution (docs/theory.md).
double checked_g(double g, bool zero_allowed = false);

/// The ball after checking every field; InputError naming the option otherwise.
bounce::Ball checked_ball(const bounce::Ball& ball);

/// --a --b --mass --inertia: the ball (defaults: the seed's rugby ball, bounce::Ball).
struct BallOptions {
  bounce::Ball ball;
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

  bounce::NormalLawSpec law() const;
  bounce::FrictionModel friction_model(double mu_value) const;
  bounce::FrictionModel friction_model() const { return friction_model(mu); }
  bounce::ContactOptions contact(double g) const;
};

/// The declarations of --a --b --mass --inertia (group "ball"; app/common/option_fields.hpp).
const Fields<BallOptions>& ball_fields();
/// The declarations of the contact-law options (group "law"; a command that owns --mu itself,
/// as the sweep's axis, leaves it out with Fields::group's `except`).
const Fields<LawOptions>& law_fields();
/// The declarations of the key `law` {model, K, n, D} every contact result carries, under `prefix`.
ResultKeys law_result_keys(const std::string& prefix);

}  // namespace tribolab::app
