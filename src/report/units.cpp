#include "report/units.hpp"

#include <map>
#include <set>

namespace tribolab::report {
namespace {

bool starts(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }
bool ends(std::string_view s, std::string_view p) { return s.size() >= p.size() && s.substr(s.size() - p.size()) == p; }
bool has(std::string_view s, std::string_view p) { return s.find(p) != std::string_view::npos; }

std::string trim(std::string s) {
  while (!s.empty() && s.back() == ' ') s.pop_back();
  while (!s.empty() && s.front() == ' ') s.erase(0, 1);
  return s;
}

/// Units of the symbols and parameter names the reports use in labels, beyond the result
/// keys' rules (those cover v_*, t_*, x_*, omega*, energies, forces, ...). "1": dimensionless.
const std::map<std::string, std::string, std::less<>>& symbol_units() {
  static const std::map<std::string, std::string, std::less<>> m = {
      {"μ", "1"}, {"μ_s", "1"}, {"μ_o", "1"}, {"mu", "1"}, {"e", "1"}, {"e_v", "1"}, {"e_h", "1"}, {"k", "1"},
      {"n", "1"}, {"R^2", "1"}, {"R²", "1"}, {"pull", "1"}, {"tan", "1"}, {"cos", "1"}, {"χ²", "1"},
      {"φ", "deg"}, {"θ", "deg"}, {"θ_c", "deg"}, {"angle", "deg"}, {"theta_deg", "deg"}, {"phi_deg", "deg"},
      {"ω", "rad/s"}, {"omega", "rad/s"}, {"ω_in", "rad/s"}, {"ω_out", "rad/s"},
      {"v_0", "m/s"}, {"v_x", "m/s"}, {"v_y", "m/s"}, {"v_s", "m/s"}, {"vx", "m/s"}, {"vy", "m/s"}, {"speed", "m/s"},
      {"g", "m/s^2"}, {"a", "m"}, {"b", "m"}, {"mass", "kg"}, {"m", "kg"}, {"inertia", "kg m^2"}, {"I", "kg m^2"},
      {"height", "m"}, {"dt", "s"}, {"seed", "1"}, {"tol", "1"}, {"restitution", "1"}, {"spin_sign", "1"},
      {"slip_scale", "m/s"}, {"k_t", "N/m"}, {"c_t", "N s/m"}, {"f_N/m", "m/s^2"}, {"c_0", "1"}, {"c_1", "1"},
      // Slopes of the stop point against the launch speed (seed 000, figure 八): t_stop/v0 is
      // s/(m/s), x_stop/v0² and y_stop/v0² are m/(m/s)², y_stop/x_stop is a pure number.
      {"t_stop_v0", "s^2/m"}, {"x_stop_v0sq", "s^2/m"}, {"y_stop_v0sq", "s^2/m"}, {"y_stop_x_stop", "1"}, {"r", "1"},
  };
  return m;
}

/// Words in a label that make a count or a ratio (dimensionless), as the key rules' `n_`,
/// `_ratio`, `_fraction`, `count`.
bool names_a_pure_number(std::string_view label) {
  for (const char* w : {"tolerance", "fraction", "ratio", "count", "number of", "iterations", "degrees of freedom",
                        "runs", "rows", "frames", "points", "cells", "samples", "coefficient", "restitution",
                        "score", "factor", "consistency", "correlation", "statistic", "p value", "p-value",
                        "χ^2", "χ²", "scale", "after / before", "angles with"})
    if (has(label, w)) return true;
  return false;
}

}  // namespace

std::string unit_of_key(const std::string& key_in, const std::string& parent) {
  std::string key = key_in;
  if (starts(key, "sigma_")) key = key.substr(6);
  if (ends(key, "_ci95")) key = key.substr(0, key.size() - 5);
  if (has(key, "_over_")) return "";  // a ratio of quantities (t_stop_over_v0): units in docs/cli.md
  if (ends(key, "_deg")) return "deg";
  if (ends(key, "_px")) return "px";
  static const std::set<std::string, std::less<>> statistic = {"mean", "sd", "sigma", "sigma_scaled", "median", "min", "max"};
  if (statistic.count(key_in) && !parent.empty()) return unit_of_key(parent);  // mean_normal_force.mean is in N
  if (ends(key, "ratio") || has(key, "_ratio") || ends(key, "factor") || has(key, "_factor") || ends(key, "scale") ||
      ends(key, "score") || ends(key, "fraction") ||
      starts(key, "n_") || starts(key, "cos_") || starts(key, "tan_") || key == "e" || starts(key, "e_") || key == "mu" ||
      starts(key, "mu_") || key == "k" || has(key, "p_value") || has(key, "statistic") || has(key, "correlation") ||
      has(key, "count") || key == "frame" || key == "frames")
    return "";
  if (has(parent, "energy")) return "J";  // translational_x, rotational, total of an energy breakdown
  if (has(key, "energy") || starts(key, "work_") || starts(key, "dissipated_")) return "J";
  if (has(key, "impulse")) return "N s";
  if (has(key, "force") || key == "N" || key == "f") return "N";
  if (starts(key, "omega")) return "rad/s";
  if (has(key, "accel") || key == "g" || key == "ax" || key == "ay" || starts(key, "a_x") || starts(key, "a_y") ||
      starts(key, "ax_") || starts(key, "ay_"))
    return "m/s^2";
  if (key == "v" || key == "v0" || key == "vx" || key == "vy" || starts(key, "v_") || starts(key, "vx_") ||
      starts(key, "vy_") || has(key, "velocity") || has(key, "speed"))
    return "m/s";
  if (key == "t" || key == "t0" || starts(key, "t_") || ends(key, "_duration") || ends(key, "_time"))
    return "s";
  if (key == "x" || key == "y" || key == "x0" || key == "y0" || starts(key, "x_") || starts(key, "y_") ||
      has(key, "height") || has(key, "penetration") || has(key, "distance") || has(key, "length") ||
      key == "contact_point" || ends(key, "_apex"))
    return "m";
  return "";
}

bool looks_like_unit(std::string_view text) {
  static const std::set<std::string, std::less<>> known = {
      "m", "s", "kg", "N", "J", "W", "rad", "deg", "°", "ms", "mm", "cm", "μm", "px", "Hz", "fps", "1", "%", "g"};
  if (text.empty() || text.size() > 24) return false;
  std::string t(text);
  // Drop exponents: "^2", "^n", "^(n+1)", "²".
  for (std::size_t p; (p = t.find('^')) != std::string::npos;) {
    std::size_t q = p + 1;
    if (q < t.size() && t[q] == '(') {
      q = t.find(')', q);
      q = q == std::string::npos ? t.size() : q + 1;
    } else {
      while (q < t.size() && t[q] != ' ' && t[q] != '/') ++q;
    }
    t.erase(p, q - p);
  }
  for (const char* sup : {"²", "³", "⁻¹"})
    for (std::size_t p; (p = t.find(sup)) != std::string::npos;) t.erase(p, std::string_view(sup).size());
  std::size_t start = 0;
  bool any = false;
  for (std::size_t i = 0; i <= t.size(); ++i) {
    if (i == t.size() || t[i] == ' ' || t[i] == '/' || t[i] == '.') {
      if (i > start) {
        if (!known.count(t.substr(start, i - start))) return false;
        any = true;
      }
      start = i + 1;
    }
  }
  return any;
}

std::pair<std::string, std::string> split_unit(const std::string& label_in) {
  const std::string label = trim(label_in);
  // "v_x (m/s)" or "E before (J)": a unit in the last parentheses.
  if (!label.empty() && label.back() == ')') {
    const auto open = label.rfind(" (");
    if (open != std::string::npos) {
      const std::string u = label.substr(open + 2, label.size() - open - 3);
      if (looks_like_unit(u)) return {trim(label.substr(0, open)), u};
      // "(m/s, CCW positive)": the unit first, a note after it.
      const auto comma = u.find(", ");
      if (comma != std::string::npos && looks_like_unit(u.substr(0, comma)))
        return {trim(label.substr(0, open)) + " (" + u.substr(comma + 2) + ")", u.substr(0, comma)};
    }
  }
  // "mass, kg": a unit after the last comma.
  if (const auto comma = label.rfind(", "); comma != std::string::npos && looks_like_unit(label.substr(comma + 2)))
    return {trim(label.substr(0, comma)), label.substr(comma + 2)};
  // The leading symbol or key: "μ (kinetic ...)", "e = −v_y,out / v_y,in", "vx".
  // Words before the symbol ("slope c_1", "weighted μ", "truth f_N/m") are skipped.
  std::string rest = label, symbol;
  for (;;) {
    symbol = rest.substr(0, rest.find_first_of(" ,("));
    const bool qualifier = symbol == "slope" || symbol == "intercept" || symbol == "weighted" || symbol == "truth" ||
                           symbol == "largest" || symbol == "smallest";
    if (!qualifier || rest.size() <= symbol.size() + 1 || rest[symbol.size()] != ' ') break;
    rest = rest.substr(symbol.size() + 1);
  }
  const auto& m = symbol_units();
  if (auto it = m.find(symbol); it != m.end()) return {label, it->second == "1" ? kDimensionless : it->second};
  if (names_a_pure_number(label)) return {label, kDimensionless};
  if (std::string u = unit_of_key(symbol); !u.empty()) return {label, u};
  return {label, ""};
}

bool is_parameter_table(const std::vector<std::string>& header) {
  if (header.size() < 2 || (header[0] != "quantity" && header[0] != "parameter")) return false;
  for (const auto& h : header)
    if (h == "unit") return false;
  return true;
}

}  // namespace tribolab::report
