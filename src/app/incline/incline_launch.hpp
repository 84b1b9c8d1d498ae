// The launch options shared by `incline predict`, `simulate` and `families` (the application
// layer's one definition of them, docs/design.md "Application layer: incline") and the small
// helpers every incline workflow uses: JSON of optional numbers, option checks that name the
// option as the command line spells it.
#pragma once

#include "app/common/option_fields.hpp"
#include "incline/params.hpp"
#include "numerics/units.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace tribolab::app {

/// The launch of a disc across the incline (seed 000): `--mu`, `--phi-deg`, `--v0`, `--g`,
/// `--mu-static`. An unset required value is an error naming its option.
struct InclineLaunchOptions {
  std::optional<double> mu;         ///< kinetic friction coefficient, >= 0 (required)
  std::optional<double> phi_deg;    ///< incline angle, degrees, in [0, 90) (required)
  std::optional<double> v0;         ///< launch speed along +x, m/s, >= 0 (required)
  double g = kDefaultG;             ///< gravitational acceleration, m/s^2
  /// Static friction coefficient deciding whether a disc at rest stays; unset = mu.
  std::optional<double> mu_static;
};

/// The declarations of --mu --phi-deg --v0 --g --mu-static (app/common/option_fields.hpp); `required`:
/// mu, phi_deg and v0 must be given (predict, simulate; not families, which varies one). The
/// ranges are checked by incline_launch_parameters (phi in [0, 90) has an open end).
const Fields<InclineLaunchOptions>& incline_launch_fields(bool required);

/// The checked core parameters of a launch; `skip` names the one option ("--v0", "--phi-deg"
/// or "--mu") that may be unset because a family varies it. Throws InputError naming the option.
incline::Parameters incline_launch_parameters(const InclineLaunchOptions& o, const std::string& skip = "");

/// An angle option in degrees checked to lie in [0, 90) (`allow_zero`) or (0, 90); returns it.
double check_incline_angle_deg(double deg, const std::string& option, bool allow_zero);

}  // namespace tribolab::app
