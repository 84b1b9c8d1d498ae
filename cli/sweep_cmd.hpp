// `tribolab bounce sweep` and `tribolab bounce merge`: the sweep options (grid, shard,
// threads, resume, derived maps) are parsed here; the physics (ball, contact law,
// friction) comes from the bounce commands through SweepPhysics. See docs/cli.md.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

#include "sweep/runner.hpp"

namespace tribolab::cli {

/// What the bounce commands supply to `bounce sweep`.
struct SweepPhysics {
  /// Adds the physical options of `bounce simulate` (ball, --model, --K/--n/--D or
  /// --restitution, --friction, --slip-scale, --g, --vx, ...) to the sweep command, bound
  /// to state that make_model reads. Must not add the options the sweep owns: --theta-deg,
  /// --omega, --ratio, --speed, --mu, --out, --shard, --threads, --restart, --contour,
  /// --threshold, --contour-tol, --report, --json.
  std::function<void(CLI::App& sweep_command)> add_options;
  /// Builds the cell model after parsing (called once per run); throws InputError naming
  /// the option for invalid values. Per cell, CellInput carries theta_deg, omega, the
  /// incoming speed |vy| (vy = -speed) and mu, swept or fixed.
  std::function<sweep::CellModel()> make_model;
  /// Rebuilds the cell model from the physics description recorded in a sweep file's header
  /// (CellModel::description), for `bounce merge --report`, which has no physical options.
  /// Throws InputError when the description is not one this physics wrote.
  std::function<sweep::CellModel(const std::string& description)> model_from_description;
  double default_mu = 0.5;     ///< --mu when not given (SPEC section 3 default)
  double default_speed = 4.0;  ///< --speed when not given, m/s (seed 001 figure 53)
};

/// Registers `sweep` and `merge` under the `bounce` area command.
void register_sweep_commands(CLI::App& bounce_area, SweepPhysics physics);

}  // namespace tribolab::cli
