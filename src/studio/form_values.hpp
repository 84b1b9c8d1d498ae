// A form's values (JSON, keyed by the declared field names) into an options struct, through
// the same declaration the command line and Python are bound from (app/common/option_fields.hpp).
#pragma once

#include "app/common/option_fields.hpp"
#include "numerics/error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace tribolab::studio {

/// Sets each field of `o` named in `values` (an object): a number for a number (null unsets an
/// optional one), a whole number for an integer, a number or an array of numbers for a list, text for text (one of the declared words when
/// the field has them), true/false for a flag. Only fields of role `value` may be set: the
/// files a command reads and writes are the studio's. InputError naming the field otherwise;
/// the declared ranges are checked afterwards (app::check_ranges).
template <class O>
void apply_form_values(O& o, const app::Fields<O>& fields, const nlohmann::json& values) {
  for (auto it = values.begin(); it != values.end(); ++it) {
    const std::string name = it.key();
    const nlohmann::json& v = it.value();
    const app::Field<O>* f = fields.find(name);
    if (!f) throw InputError("the form has no field '" + name + "'");
    if (f->role != app::FieldRole::value) throw InputError(field(name), "is set by the studio, not by the form");
    const auto bad = [&](const char* what) { return InputError(field(name), std::string("must be ") + what); };
    std::visit(
        [&](auto* p) {
          using T = std::remove_cvref_t<decltype(*p)>;
          if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>) {
            if constexpr (std::is_same_v<T, std::optional<double>>) {
              if (v.is_null()) {
                p->reset();
                return;
              }
            }
            if (!v.is_number() || !std::isfinite(v.get<double>())) throw bad("a finite number");
            *p = v.get<double>();
          } else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>) {
            if constexpr (std::is_same_v<T, std::optional<int>>) {
              if (v.is_null()) {
                p->reset();
                return;
              }
            }
            if (!v.is_number_integer() || std::abs(v.get<long long>()) > 1000000000LL) throw bad("a whole number");
            *p = static_cast<int>(v.get<long long>());
          } else if constexpr (std::is_same_v<T, std::string>) {
            if (!v.is_string()) throw bad("text");
            const std::string s = v.get<std::string>();
            if (!f->choices.empty() && std::find(f->choices.begin(), f->choices.end(), s) == f->choices.end())
              throw bad("one of the offered words");
            *p = s;
          } else if constexpr (std::is_same_v<T, std::vector<double>>) {
            // A list of numbers (one incline angle per file): one number, or an array of them.
            const nlohmann::json list = v.is_array() ? v : nlohmann::json::array({v});
            if (list.empty() || list.size() > 10000) throw bad("a number or a list of numbers");
            std::vector<double> numbers;
            for (const nlohmann::json& e : list) {
              if (!e.is_number() || !std::isfinite(e.get<double>())) throw bad("a number or a list of finite numbers");
              numbers.push_back(e.get<double>());
            }
            *p = std::move(numbers);
          } else if constexpr (std::is_same_v<T, bool>) {
            if (!v.is_boolean()) throw bad("true or false");
            *p = v.get<bool>();
          } else {
            throw InputError(field(name), "cannot be set from the studio");
          }
        },
        f->ref(o));
  }
  app::check_ranges(o, fields);
}

}  // namespace tribolab::studio
