// The caption of a heat map, computed from what the map holds: the range of the values and
// where they are reached, how they change along each axis, which side of the diverging
// scale's neutral value the cells lie on, the curve drawn over the map (e.g. the e = 1
// boundary) and the blank cells. No prose about a particular map: every number is the data's.
#pragma once

#include "report/report.hpp"

#include <string>

namespace tribolab::app {

/// The description of `f` (which must have a heat map). `quantity` names z in the text
/// ("e", "ω_out"), `unit` its unit ("" when dimensionless). Axis names and units come from
/// the figure's axis titles ("collision angle (deg)" -> "collision angle", "deg").
std::string describe_heat_map(const report::Figure& f, const std::string& quantity, const std::string& unit);

}  // namespace tribolab::app
