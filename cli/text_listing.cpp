#include "text_listing.hpp"

#include "report/format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string_view>
#include <vector>

namespace tribolab::cli {
namespace {

using nlohmann::json;

bool starts(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }
bool ends(std::string_view s, std::string_view p) { return s.size() >= p.size() && s.substr(s.size() - p.size()) == p; }

/// Columns a terminal gives `s` (UTF-8: one per code point; "±" is two bytes, one column).
std::size_t columns(std::string_view s) {
  return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

std::string pad(const std::string& s, std::size_t width) {
  const std::size_t w = columns(s);
  return w >= width ? s : s + std::string(width - w, ' ');
}

/// What a null means, by the key that holds it (docs/cli.md: null is "does not happen").
std::string null_meaning(const std::string& key) {
  static const std::map<std::string, std::string, std::less<>> meaning = {
      {"t_stop", "does not stop"},          {"x_stop", "does not stop"},       {"y_stop", "does not stop"},
      {"v_terminal", "none (no terminal speed)"},
      {"e", "undefined (no vertical speed at touch)"},
      {"first_above_release", "never"},     {"t_above_release", "never"},      {"t_cross_release", "never"},
  };
  if (auto it = meaning.find(key); it != meaning.end()) return it->second;
  for (const char* stop : {"t_stop", "x_stop", "y_stop"}) {
    if (starts(key, stop)) return "does not stop";  // and the ratios made from a stop
  }
  return "none";
}

std::string number(const json& v) {
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  return report::format_value(v.get<double>(), 6);
}

/// A bound of a 95 % interval, to the decimal place of the value's uncertainty when known
/// (two significant digits of sigma, as format_uncertain rounds), else 4 significant digits.
/// A bound of a 95 % interval, to the place of 2 significant digits of `scale` (the value's
/// standard uncertainty; without one, the interval's half-width over 1.96, so that the two
/// bounds of a narrow interval differ: "0.39998 to 0.39999", not "0.4 to 0.4").
std::string bound(const json& b, double scale) {
  const double v = b.get<double>();
  if (scale > 0 && std::isfinite(scale) && std::isfinite(v)) {
    const int decimals = 1 - static_cast<int>(std::floor(std::log10(scale)));
    if (decimals >= 0 && decimals <= 12) {
      std::string s = fmt::format("{:.{}f}", v, decimals);
      if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);  // no "-0.00"
      return s;
    }
  }
  return report::format_value(v, 4);
}

std::string with_unit(std::string value, const std::string& unit) {
  return unit.empty() ? value : value + " " + unit;
}

/// Numbers and nulls inline: "0.19, 0.13" (nulls as "—"); nested lists in parentheses.
std::string inline_list(const json& a, std::size_t max_items = 10) {
  std::string out;
  std::size_t n = 0;
  for (const json& v : a) {
    if (n == max_items) {
      out += ", … (" + std::to_string(a.size()) + " values)";
      break;
    }
    if (n++) out += ", ";
    if (v.is_number()) {
      out += number(v);
    } else if (v.is_null()) {
      out += "—";
    } else if (v.is_array()) {
      out += "(" + inline_list(v, max_items) + ")";
    } else if (v.is_string()) {
      out += v.get<std::string>();
    } else if (v.is_boolean()) {
      out += v.get<bool>() ? "yes" : "no";
    } else {
      out += v.dump();
    }
  }
  return out;
}

bool is_number_pair(const json& j) { return j.is_array() && j.size() == 2 && j[0].is_number() && j[1].is_number(); }

/// The companions of a number `key` in object `o`: its standard uncertainty and 95 % interval.
struct Companions {
  const json* sigma = nullptr;
  const json* ci = nullptr;
  std::vector<std::string> names;  ///< the keys (or "ci95.<key>") they were found under
};

Companions companions(const json& o, const std::string& key) {
  Companions c;
  if (auto it = o.find("sigma_" + key); it != o.end() && it->is_number()) {
    c.sigma = &*it;
    c.names.push_back("sigma_" + key);
  }
  std::vector<std::string> ci_names = {key + "_ci95"};
  if (ends(key, "_deg")) ci_names.push_back(key.substr(0, key.size() - 4) + "_ci95_deg");
  for (const std::string& n : ci_names) {
    if (auto it = o.find(n); it != o.end() && is_number_pair(*it)) {
      c.ci = &*it;
      c.names.push_back(n);
    }
  }
  if (auto it = o.find("ci95"); !c.ci && it != o.end() && it->is_object()) {
    if (auto jt = it->find(key); jt != it->end() && is_number_pair(*jt)) {
      c.ci = &*jt;
      c.names.push_back("ci95." + key);
    }
  }
  return c;
}

class Listing {
 public:
  explicit Listing(const app::ResultKeys& keys) : keys_(keys) {}
  std::string str() const { return out_; }

  /// The declared unit of the key at `path` ("law.K", "bounces.vx_in"), "" when undeclared.
  std::string unit(const std::string& path) const {
    const app::ResultKey* k = app::find_result_key(keys_, path);
    return k ? k->unit : "";
  }

  void object(const json& o, std::size_t indent, const std::string& prefix = "") {
    // Companions are shown on their value's row, not on rows of their own.
    std::set<std::string> shown_with_value;
    for (const auto& [k, v] : o.items()) {
      if (!v.is_number()) continue;
      for (const std::string& n : companions(o, k).names) shown_with_value.insert(n);
    }
    auto is_companion_block = [&](const std::string& k, const json& v) {
      if (k != "ci95" || !v.is_object()) return false;
      for (const auto& [ck, cv] : v.items())
        if (!shown_with_value.count("ci95." + ck)) return false;
      return true;
    };
    std::size_t width = 0;
    for (const auto& [k, v] : o.items()) {
      if (!shown_with_value.count(k) && !is_companion_block(k, v)) width = std::max(width, columns(k));
    }
    for (const auto& [k, v] : o.items()) {
      if (shown_with_value.count(k) || is_companion_block(k, v)) continue;
      const std::string lead = std::string(indent, ' ');
      if (v.is_object() && !v.empty()) {
        line(lead + k + ":");
        object(v, indent + 2, prefix + k + ".");
      } else if (v.is_array() && !v.empty() && std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_object(); })) {
        line(lead + k + ":");
        table(v, k, indent + 2, prefix + k + ".");
      } else if (v.is_array() && !v.empty() && std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_string(); })) {
        for (std::size_t i = 0; i < v.size(); ++i)
          line(lead + pad(i == 0 ? k : "", width) + "  " + v[i].get<std::string>());
      } else {
        line(lead + pad(k, width) + "  " + value(o, k, v, unit(prefix + k)));
      }
    }
  }

 private:
  void line(const std::string& s) {
    std::string t = s;
    while (!t.empty() && t.back() == ' ') t.pop_back();
    out_ += t + '\n';
  }

  std::string value(const json& o, const std::string& k, const json& v, const std::string& unit) const {
    if (v.is_null()) return null_meaning(k);
    if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
    if (v.is_string()) return v.get<std::string>();
    if (v.is_array()) return v.empty() ? "none" : with_unit(is_number_pair(v) && ends(k, "ci95") ? "[" + inline_list(v) + "]" : inline_list(v), unit);
    if (!v.is_number()) return v.dump();
    const Companions c = companions(o, k);
    std::string s = c.sigma ? report::format_uncertain(v.get<double>(), c.sigma->get<double>()) : number(v);
    s = with_unit(s, unit);
    if (c.ci) {
      const double lo = (*c.ci)[0].get<double>(), hi = (*c.ci)[1].get<double>();
      const double scale = c.sigma ? c.sigma->get<double>() : (hi - lo) / (2 * 1.96);
      s += "  (95 % interval " + bound((*c.ci)[0], scale) + " to " + bound((*c.ci)[1], scale) + ")";
    }
    return s;
  }

  /// Flattens an element of a list of objects to (column, cell) pairs; nested objects as a.b.
  static void flatten(const json& e, const std::string& prefix, std::vector<std::pair<std::string, const json*>>& out) {
    for (const auto& [k, v] : e.items()) {
      const std::string name = prefix.empty() ? k : prefix + "." + k;
      if (v.is_object()) {
        flatten(v, name, out);
      } else {
        out.emplace_back(name, &v);
      }
    }
  }

  static std::string cell(const std::string& column, const json& v) {
    if (v.is_null()) return null_meaning(column.substr(column.rfind('.') + 1));
    if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
    if (v.is_string()) return v.get<std::string>();
    if (v.is_array()) return v.empty() ? "none" : inline_list(v, 4);
    if (v.is_number_float()) return report::format_value(v.get<double>(), 5);
    return number(v);
  }

  /// A list of objects: few elements side by side (one column each, one row per field), many
  /// elements one row each (one column per field); units beside the field names.
  void table(const json& list, const std::string& key, std::size_t indent, const std::string& prefix) {
    std::vector<std::string> fields;
    std::vector<std::map<std::string, std::string>> cells(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
      std::vector<std::pair<std::string, const json*>> flat;
      flatten(list[i], "", flat);
      for (const auto& [name, v] : flat) {
        if (std::find(fields.begin(), fields.end(), name) == fields.end()) fields.push_back(name);
        cells[i][name] = cell(name, *v);
      }
    }
    auto label = [&](const std::string& f) { return column_label(f, unit(prefix + f)); };
    const std::string lead(indent, ' ');
    std::string item = key;  // "bounces" -> "bounce 1", "contact_list" -> "contact 1"
    if (ends(item, "_list")) {
      item.resize(item.size() - 5);
    } else if (ends(item, "s") && item.size() > 1) {
      item.pop_back();
    }
    if (list.size() <= 8) {
      std::size_t w0 = 0;
      for (const auto& f : fields) w0 = std::max(w0, columns(label(f)));
      std::vector<std::size_t> w(list.size());
      for (std::size_t i = 0; i < list.size(); ++i) {
        w[i] = columns(item + " " + std::to_string(i + 1));
        for (const auto& f : fields) w[i] = std::max(w[i], columns(cells[i][f]));
      }
      std::string head = lead + pad("", w0);
      for (std::size_t i = 0; i < list.size(); ++i) head += "  " + pad(item + " " + std::to_string(i + 1), w[i]);
      line(head);
      for (const auto& f : fields) {
        std::string row = lead + pad(label(f), w0);
        for (std::size_t i = 0; i < list.size(); ++i) row += "  " + pad(cells[i].count(f) ? cells[i][f] : "", w[i]);
        line(row);
      }
      return;
    }
    std::vector<std::size_t> w;
    for (const auto& f : fields) {
      std::size_t wf = columns(label(f));
      for (auto& c : cells) wf = std::max(wf, columns(c.count(f) ? c[f] : ""));
      w.push_back(wf);
    }
    const std::size_t wi = std::to_string(list.size()).size();
    std::string head = lead + pad("#", wi);
    for (std::size_t j = 0; j < fields.size(); ++j) head += "  " + pad(label(fields[j]), w[j]);
    line(head);
    for (std::size_t i = 0; i < list.size(); ++i) {
      std::string row = lead + pad(std::to_string(i + 1), wi);
      for (std::size_t j = 0; j < fields.size(); ++j) row += "  " + pad(cells[i].count(fields[j]) ? cells[i][fields[j]] : "", w[j]);
      line(row);
    }
  }

  const app::ResultKeys& keys_;
  std::string out_;
};

}  // namespace

std::string column_label(const std::string& name, const std::string& unit) {
  return unit.empty() || ends(name, "_deg") || ends(name, "_px") ? name : name + " (" + unit + ")";
}

std::string text_listing(const json& result, const app::ResultKeys& keys) {
  if (!result.is_object()) return result.dump() + "\n";
  Listing l(keys);
  l.object(result, 0);
  return l.str();
}

}  // namespace tribolab::cli
