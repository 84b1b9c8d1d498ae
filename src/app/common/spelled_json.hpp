// A result's JSON with the fields the core names in its texts (field("floor_y") in a warning,
// numerics/error.hpp) spelled by one front end: the command line's flags (--floor-y,
// cli::spelled_for_cli), the studio's field names (floor_y). Python spells them while it
// converts the JSON (python/src/module.cpp, to_python). CLI11-free.
#pragma once

#include "numerics/error.hpp"

#include <nlohmann/json.hpp>

namespace tribolab::app {

/// `j` with every string's field marks spelled by `spell(name)`; keys, numbers and the rest as they are.
template <class Spell>
nlohmann::json spelled_json(const nlohmann::json& j, const Spell& spell) {
  if (j.is_string()) return spell_fields(j.get_ref<const std::string&>(), spell);
  if (!j.is_array() && !j.is_object()) return j;
  nlohmann::json out = j;
  for (auto& v : out) v = spelled_json(v, spell);
  return out;
}

/// `j` with its fields named as the option structs name them (floor_y): what the studio shows.
inline nlohmann::json plain_fields_json(const nlohmann::json& j) {
  return spelled_json(j, [](std::string_view name) { return std::string(name); });
}

}  // namespace tribolab::app
