// Units and constants shared by every layer: one definition of the default g and of the
// degree (docs/theory.md, "Conventions"). Quantities are SI inside tribolab; angles are
// radians inside the core and degrees only where a name ends in `_deg`.
#pragma once

#include <limits>
#include <numbers>

namespace tribolab {

/// Gravitational acceleration both studies use, m/s^2: the default of every `--g` and of
/// every option struct with a `g` field (seed 000 eq. 3, seed 001 section 3).
inline constexpr double kDefaultG = 9.8;

/// pi, for the files that use it often (std::numbers::pi).
inline constexpr double kPi = std::numbers::pi;

/// The value of an optional field that was not given, and of a result that does not exist.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Degrees per radian: angle_deg = angle_rad * kDegPerRad.
inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;
/// Radians per degree: angle_rad = angle_deg * kRadPerDeg.
inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;

/// Radians to degrees.
constexpr double to_deg(double rad) { return rad * kDegPerRad; }
/// Degrees to radians.
constexpr double to_rad(double deg) { return deg * kRadPerDeg; }

}  // namespace tribolab
