// The bounce cell model: what one cell of `bounce sweep` computes from its inputs (one whole
// impact of bounce::simulate_impact from first touch, or for files of older versions the
// first contact phase alone), its one-line description (the physics line of a sweep file's
// header) and the parse of that line back into the model, without any command-line parser.
// One definition used by `bounce sweep`/`merge`, the demo's maps and bench/bounce_bench.cpp.
// docs/cli.md#bounce-sweep, docs/theory.md#sweeps.
#pragma once

#include "app/bounce/bounce_options.hpp"
#include "numerics/units.hpp"
#include "sweep/runner.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tribolab::app {

/// How the swept theta_deg values are read (docs/theory.md#sweeps).
enum class AngleConvention {
  collision,    ///< the seed's collision angle (figures 53-56), 0..180 deg
  orientation,  ///< the major axis from the horizontal at first touch, deg (as bounce simulate)
};
std::string_view to_string(AngleConvention c);  ///< "collision", "orientation"

/// What a cell computes, recorded as the first word of the description.
enum class BounceCellKind {
  impact,   ///< the whole impact ("bounce-impact", this version)
  contact,  ///< the first contact phase alone ("bounce-contact", files of older versions)
};

/// The physical options of a cell: those of `bounce simulate` except --mu, which is a sweep
/// axis or fixed value per cell. Defaults equal those of `bounce sweep`.
struct BounceCellOptions {
  BallOptions ball;  ///< --a --b --mass --inertia
  /// Integrator tolerance 1e-6: the loosest power of ten at which no cell of the seed's map
  /// (figure 53, 1491 cells) is less accurate than the seed's 1-microsecond stepping, against
  /// a 1e-12 reference (docs/benchmarks.md#bounce-sweep-phase-diagram). law.mu is unused.
  LawOptions law{1e-6};
  double g = kDefaultG;  ///< --g, gravitational acceleration, m/s^2 (0 allowed: cells start at touch)
  double vx = 0;         ///< --vx, horizontal centre velocity at first touch, m/s
  /// --angle: meaning of --theta-deg, "collision" (the seed's collision angle, 0..180 deg) or
  /// "orientation" (major axis from the horizontal at first touch)
  std::string angle = "collision";
  /// Sense of the swept spin: +1 omega as given (counter-clockwise positive, as `bounce
  /// simulate`), -1 omega = -spin (the demo's clockwise maps). Not a command-line option;
  /// recorded in the description only when -1.
  int spin_sign = 1;
};

/// Everything one cell needs, checked, fixed for the whole sweep (shared read-only by the
/// threads).
struct BounceCell {
  bounce::Ball ball;
  bounce::NormalLawSpec law;
  bounce::FrictionModel friction;  ///< mu set per cell
  bounce::ContactOptions options;
  AngleConvention convention = AngleConvention::collision;
  double vx = 0;      ///< m/s
  int direction = 1;  ///< direction of horizontal motion for the collision angle (sign of vx, +1 at 0)
  int spin_sign = 1;
  double tol = 1e-6;  ///< the integrator tolerance the options were made from
  BounceCellKind kind = BounceCellKind::impact;

  /// The outputs of one cell (bounce_cell_outputs(kind)); all NaN when the contact point
  /// does not approach the floor at first touch (no contact) or the integrator fails; the
  /// whole-impact values NaN when a later contact or flight search fails or the contacts
  /// never end.
  sweep::CellOutputs operator()(const sweep::CellInput& in) const;
  /// The one line recording every physical option (a sweep file's header; a resume or
  /// merge with other physics is refused).
  std::string description() const;
};

/// The output columns of a cell: impact: vx, vy, omega_out, e, contacts, contact_duration
/// (the whole impact), then vx_first, vy_first, omega_first, e_first, duration_first (the
/// first contact phase); contact: vx, vy, omega_out, e.
const std::vector<std::string>& bounce_cell_outputs(BounceCellKind kind);

/// The checked cell of the options; InputError naming the field (field("vx")) otherwise.
BounceCell make_bounce_cell(const BounceCellOptions& options, BounceCellKind kind = BounceCellKind::impact);

/// The sweep's cell model of a cell (outputs, description, mass and inertia for the energy
/// ratio of thresholds).
sweep::CellModel bounce_cell_model(const BounceCell& cell);

/// The options and kind a description line records (the inverse of
/// BounceCell::description). Throws InputError(field("report"), ...) naming the problem when the
/// line is not one this version writes or reads (unknown kind or field, malformed number).
struct ParsedBounceCell {
  BounceCellOptions options;
  BounceCellKind kind = BounceCellKind::impact;
};
ParsedBounceCell parse_bounce_cell_description(const std::string& description);

/// The cell model that wrote a sweep file whose header holds `description`: parsed, checked,
/// and refused unless it describes itself with exactly the same line.
sweep::CellModel bounce_cell_model_from_description(const std::string& description);

}  // namespace tribolab::app
