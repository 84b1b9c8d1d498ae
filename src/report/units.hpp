// Units from names: the rules the text listing (cli/text_listing.hpp) applies to result keys,
// and the unit column every "quantity | value" or "parameter | value" table of a report gets
// (html.cpp), from the unit written in the row's label ("v_x (m/s)", "mass, kg") or else from
// its leading symbol or key ("μ", "e", "vx", "mass"). docs/cli.md#units-in-the-text-listing.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tribolab::report {

/// What the unit cell of a dimensionless quantity says.
inline constexpr const char* kDimensionless = "dimensionless";

/// The unit of a result key from its name ("" when dimensionless or unknown); `parent` is the
/// enclosing object's key (energies inside an `energy_in_parts` object are joules).
std::string unit_of_key(const std::string& key, const std::string& parent = "");

/// True when `text` is a unit made of SI and common units ("m/s^2", "kg m^2", "N s/m^(n+1)",
/// "rad/s", "deg", "ms", "px").
bool looks_like_unit(std::string_view text);

/// A table row label split into the label without its unit and the unit:
/// "v_x (m/s)" -> {"v_x", "m/s"}; "mass, kg" -> {"mass", "kg"}; "μ (kinetic friction
/// coefficient)" -> {"μ (kinetic friction coefficient)", kDimensionless} (from the symbol μ);
/// {label, ""} when no unit is known.
std::pair<std::string, std::string> split_unit(const std::string& label);

/// True for the tables that get a unit column: the first header cell is "quantity" or
/// "parameter" and there is no "unit" column yet.
bool is_parameter_table(const std::vector<std::string>& header);

}  // namespace tribolab::report
