// A number for a command's JSON result: JSON has no NaN or infinity, so an undefined value
// (e when vy_in = 0, a sigma without degrees of freedom) is written as null.
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>

namespace tribolab::app {

/// `v`, or null when it is NaN or infinite.
inline nlohmann::json json_number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

/// `*v`, or null when unset, NaN or infinite.
inline nlohmann::json json_number(const std::optional<double>& v) { return v ? json_number(*v) : nlohmann::json(nullptr); }

}  // namespace tribolab::app
