// Plausibility checks of one analysed bounce and of a bounce fit: results that no passive
// bounce can give (a rebound with more kinetic energy than the arrival, a contact that ends
// before it starts, non-finite energies), frames far off the fitted flights (a hand or another
// object tracked), fitted contact-law parameters pinned at their bounds. Each adds a
// plain-language warning saying what is implausible and what to check.
// docs/theory.md#plausibility-checks.
#pragma once

#include "analysis/bounce_analyze.hpp"
#include "analysis/bounce_fit.hpp"

#include <array>
#include <string>
#include <vector>

namespace tribolab::analysis {

/// Energy balance, contact order and wild frames of `r` (analysed with `ball`): appends to
/// r.warnings. Thresholds and their reasons: docs/theory.md#plausibility-checks.
void check_bounce_plausibility(const bounce::Ball& ball, BounceAnalysis& r);

/// The kinetic-energy gain E_post - E_pre of `r` (J) and its standard uncertainty from the
/// fitted velocities and spins (pre and post flights independent).
struct EnergyGain {
  double gain = 0, sigma = 0;  ///< J
  double e_allowed = 0;        ///< largest e_velocity the energy before impact allows
};
EnergyGain energy_gain(const bounce::Ball& ball, const BounceAnalysis& r);

/// The warning for flights that fall at g +- sigma_g (m/s^2) instead of 9.8, empty when they
/// agree (3 sd, and beyond the 9.78-9.83 m/s^2 of the Earth's surface); a gross g (25 % off)
/// names the factor the file's times need (docs/theory.md#plausibility-checks).
std::string gravity_warning(double g, double sigma_g);

/// Gravity read off a centre track before any impact is found: y(t) parabolas fitted on either
/// side of its lowest frame (two frames next to it left out); {g, sigma}, m/s^2, or {NaN, NaN}
/// when neither side has 5 points. For the hint when the impact detector finds nothing.
std::array<double, 2> rough_gravity(const track::Track& centre);

/// Free parameters of a bounce fit sitting at a bound of the search (e = 1, mu = 3, n = 1 or
/// 3, K or D at the ends of their ranges): the data want a value the law cannot take.
/// `names` are the shown names (K, n, D or e, mu), `values` the fitted values in the
/// solver's variables, `lower`/`upper` its bounds, `free` whether the parameter was fitted.
std::vector<std::string> bound_warnings(const std::vector<std::string>& names, const std::vector<double>& values,
                                        const std::vector<double>& lower, const std::vector<double>& upper,
                                        const std::vector<bool>& free);

}  // namespace tribolab::analysis
