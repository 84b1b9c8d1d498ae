// Sane physical ranges of the inputs (docs/cli.md#physical-ranges), in one place, with one
// message style: "1e+308 m/s is outside the physical range [0, 1000] m/s". Every option
// struct's validate() checks its numbers with range_error(); the front ends prefix the option
// ("--v0: ..."). The bounds keep every command's arithmetic finite (no inf/NaN outputs) while
// leaving room far beyond any table-top experiment.
#pragma once

#include "numerics/error.hpp"
#include "numerics/message_number.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace tribolab {

/// A closed interval [lo, hi] of a physical quantity (lo_open: (lo, hi]).
struct PhysicalRange {
  double lo = 0, hi = 0;
  std::string_view unit;  ///< SI unit as printed ("m/s"); empty for pure numbers
  bool lo_open = false;   ///< exclude lo (a length or mass must be > 0)
};

namespace ranges {
inline constexpr PhysicalRange speed{0, 1e3, "m/s"};                 ///< |v| of a launch
inline constexpr PhysicalRange velocity{-1e3, 1e3, "m/s"};           ///< a signed velocity component
inline constexpr PhysicalRange gravity{0.01, 1e3, "m/s^2"};          ///< g > 0 (a flight needs it)
inline constexpr PhysicalRange gravity_or_zero{0, 1e3, "m/s^2"};     ///< g >= 0 (from touch)
inline constexpr PhysicalRange friction{0, 10, ""};                  ///< a friction coefficient
inline constexpr PhysicalRange accel{-1e3, 1e3, "m/s^2"};            ///< a signed acceleration
inline constexpr PhysicalRange position{-1e3, 1e3, "m"};             ///< a coordinate
inline constexpr PhysicalRange size{1e-3, 10, "m"};                  ///< a body's dimension
inline constexpr PhysicalRange height{0, 1e3, "m", true};            ///< a release height
inline constexpr PhysicalRange mass{1e-6, 1e3, "kg"};
inline constexpr PhysicalRange inertia{1e-12, 1e3, "kg m^2"};
inline constexpr PhysicalRange stiffness{0, 1e12, "N/m^n", true};    ///< contact stiffness K
inline constexpr PhysicalRange damping{0, 1e12, "N s/m^(n+1)"};      ///< contact damping D
inline constexpr PhysicalRange tangential_stiffness{0, 1e12, "N/m", true};
inline constexpr PhysicalRange tangential_damping{0, 1e12, "N s/m"};
inline constexpr PhysicalRange tolerance{1e-14, 1e-2, ""};           ///< integrator tolerance
inline constexpr PhysicalRange spin{-1e5, 1e5, "rad/s"};             ///< an angular velocity
inline constexpr PhysicalRange angle_deg{-360, 360, "deg"};          ///< an orientation
inline constexpr PhysicalRange duration{0, 1e4, "s"};                ///< a time span
inline constexpr PhysicalRange noise{0, 1, "m"};                     ///< a position noise
inline constexpr PhysicalRange frame_rate{1, 1e5, "1/s"};
inline constexpr PhysicalRange distance{0, 1e3, "m", true};          ///< a positive length on the table
inline constexpr PhysicalRange step{0, 1e4, "s", true};              ///< a time step or span > 0
inline constexpr PhysicalRange angle_sigma_deg{0, 10, "deg"};        ///< uncertainty of an angle
inline constexpr PhysicalRange time_scale{1e-5, 1e3, ""};            ///< real seconds per file second
}  // namespace ranges

/// Shortest round-trip-ish form of v for messages ("1e+308", "1000", "0.5").
inline std::string range_number(double v) { return message_number(v); }

/// Empty when v is a normal number or zero; else why not ("is subnormal ..."). A subnormal
/// (0 < |v| < 2.2e-308) keeps fewer than 53 bits and turns into inf or NaN at the first
/// division (a stiffness of 1e-320 N/m^n makes every sweep cell NaN, a scale of 1e-320 m/px
/// an origin of -inf px): no physical input is that small, so it is refused rather than
/// carried (docs/cli.md#physical-ranges).
inline std::string subnormal_error(double v) {
  if (v == 0 || !std::isfinite(v) || std::isnormal(v)) return {};
  char typed[16];  // 3 digits: what was typed (1e-320 is stored as 9.99989e-321)
  std::snprintf(typed, sizeof typed, "%.3g", v);
  return std::string(typed) + " is subnormal (closer to 0 than 2.2e-308, where doubles lose their "
                           "precision): give 0 or a normal number";
}

/// Empty when v is finite, not subnormal and within r; else "V UNIT is outside the physical
/// range [LO, HI] UNIT" (or the subnormal_error).
inline std::string range_error(double v, const PhysicalRange& r) {
  if (std::string e = subnormal_error(v); !e.empty()) return e;
  const std::string unit = r.unit.empty() ? "" : " " + std::string(r.unit);
  if (std::isfinite(v) && (r.lo_open ? v > r.lo : v >= r.lo) && v <= r.hi) return {};
  return range_number(v) + unit + " is outside the physical range " + (r.lo_open ? "(" : "[") +
         range_number(r.lo) + ", " + range_number(r.hi) + "]" + unit;
}

/// "name: <range_error>" when out of range, else empty: the validate() building block.
inline std::string range_error(double v, const PhysicalRange& r, std::string_view name) {
  std::string e = range_error(v, r);
  return e.empty() ? e : std::string(name) + ": " + e;
}

/// Throws InputError(where, range_error(v, r)) when v is out of range; returns v.
inline double check_range(double v, const PhysicalRange& r, const std::string& where) {
  if (std::string e = range_error(v, r); !e.empty()) throw InputError(where, e);
  return v;
}

}  // namespace tribolab
