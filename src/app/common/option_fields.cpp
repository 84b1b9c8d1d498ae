#include "app/common/option_fields.hpp"

namespace tribolab::app {
namespace {

bool ends_with(const std::string& s, std::string_view p) {
  return s.size() >= p.size() && s.compare(s.size() - p.size(), p.size(), p) == 0;
}

const ResultKey* find_exact(const ResultKeys& keys, const std::string& path) {
  for (const ResultKey& k : keys)
    if (k.key == path) return &k;
  for (const ResultKey& k : keys) {
    const auto star = k.key.find(".*");
    if (star == std::string::npos) continue;
    const std::string prefix = k.key.substr(0, star + 1);  // with the dot
    const std::string suffix = k.key.substr(star + 2);     // "" or ".median_score"
    if (path.size() <= prefix.size() + suffix.size() || path.compare(0, prefix.size(), prefix) != 0) continue;
    // "energy_in_parts.*" covers every key below; "tracks.*.median_score" that key of every
    // element of an object keyed by names (which may hold dots: "ball.A").
    if (suffix.empty() || ends_with(path, suffix)) return &k;
  }
  return nullptr;
}

const char* role_name(FieldRole r) {
  switch (r) {
    case FieldRole::value: return "value";
    case FieldRole::input_files: return "input_files";
    case FieldRole::output_path: return "output_path";
    case FieldRole::report: return "report";
    case FieldRole::plotly: return "plotly";
    case FieldRole::notebook: return "notebook";
  }
  return "value";
}

}  // namespace

FieldType field_type(const FieldRef& r) {
  return std::visit(
      [](auto* p) -> FieldType {
        using T = std::remove_cvref_t<decltype(*p)>;
        if constexpr (std::is_same_v<T, double>) return {"number"};
        else if constexpr (std::is_same_v<T, bool>) return {"flag"};
        else if constexpr (std::is_integral_v<T>) return {"integer"};
        else if constexpr (std::is_same_v<T, std::optional<double>>) return {"number", true};
        else if constexpr (std::is_same_v<T, std::optional<int>>) return {"integer", true};
        else if constexpr (std::is_same_v<T, std::string>) return {"text"};
        else if constexpr (std::is_same_v<T, std::optional<std::string>>) return {"text", true};
        else if constexpr (std::is_same_v<T, std::vector<std::string>>) return {"texts"};
        else if constexpr (std::is_same_v<T, std::vector<double>>) return {"numbers"};
        else if constexpr (std::is_same_v<T, std::optional<sweep::Axis>>) return {"range", true};
        else if constexpr (std::is_same_v<T, sweep::ValueOrAxis>) return {"number or range"};
        else if constexpr (std::is_same_v<T, sweep::Shard>) return {"shard"};
        else return {"choice"};  // report::PlotlyMode
      },
      r);
}

nlohmann::json field_value(const FieldRef& r) {
  return std::visit(
      [](auto* p) -> nlohmann::json {
        using T = std::remove_cvref_t<decltype(*p)>;
        const auto range = [](const sweep::Axis& a) { return nlohmann::json::array({a.lo, a.hi, a.count}); };
        if constexpr (std::is_same_v<T, report::PlotlyMode>) {
          return std::string(report::to_string(*p));
        } else if constexpr (std::is_same_v<T, std::optional<sweep::Axis>>) {
          return *p ? range(**p) : nlohmann::json(nullptr);
        } else if constexpr (std::is_same_v<T, sweep::ValueOrAxis>) {
          return p->axis ? range(*p->axis) : nlohmann::json(p->value);
        } else if constexpr (std::is_same_v<T, sweep::Shard>) {
          return nlohmann::json::array({p->index, p->count});
        } else if constexpr (std::is_same_v<T, std::optional<double>> || std::is_same_v<T, std::optional<int>> ||
                             std::is_same_v<T, std::optional<std::string>>) {
          return *p ? nlohmann::json(**p) : nlohmann::json(nullptr);
        } else {
          return nlohmann::json(*p);
        }
      },
      r);
}

nlohmann::json field_schema(const FieldDecl& f, const FieldRef& in_defaults) {
  const FieldType t = field_type(in_defaults);
  nlohmann::json j = {{"name", f.name},         {"type", t.name},
                      {"nullable", t.nullable}, {"unit", f.unit},
                      {"help", f.help},         {"default", field_value(in_defaults)},
                      {"required", f.required}, {"role", role_name(f.role)},
                      {"choices", f.choices},   {"group", f.group}};
  if (f.range) j["range"] = {{"lo", f.range->lo}, {"hi", f.range->hi}, {"lo_open", f.range->lo_open}};
  else j["range"] = nullptr;
  return j;
}

nlohmann::json result_keys_schema(const ResultKeys& keys) {
  nlohmann::json a = nlohmann::json::array();
  for (const ResultKey& k : keys) a.push_back({{"key", k.key}, {"unit", k.unit}, {"help", k.help}});
  return a;
}

const ResultKey* find_result_key(const ResultKeys& keys, const std::string& path) {
  if (const ResultKey* k = find_exact(keys, path)) return k;
  // A value's companions carry its unit: sigma_X, X_ci95 (X_deg: X_ci95_deg), ci95.X.
  const auto dot = path.rfind('.');
  const std::string parent = dot == std::string::npos ? "" : path.substr(0, dot + 1);
  const std::string leaf = dot == std::string::npos ? path : path.substr(dot + 1);
  if (leaf.rfind("sigma_", 0) == 0) return find_exact(keys, parent + leaf.substr(6));
  if (ends_with(leaf, "_ci95")) return find_exact(keys, parent + leaf.substr(0, leaf.size() - 5));
  if (ends_with(leaf, "_ci95_deg")) return find_exact(keys, parent + leaf.substr(0, leaf.size() - 9) + "_deg");
  if (ends_with(parent, "ci95.")) {
    const std::string up = parent.substr(0, parent.size() - 5);
    return find_exact(keys, up + leaf);
  }
  return nullptr;
}

}  // namespace tribolab::app
