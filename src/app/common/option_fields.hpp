// One declaration per option and per result key (docs/design.md, "Options and results:
// declared once"; STYLE.md habit 11). Beside each options struct of the application layer,
// `<area>_<cmd>_fields()` lists its fields once: name, member, unit, help, range, whether
// required, the words a text field takes, the shared group it belongs to. Every front end is
// derived from that list:
//
//   * the command line (cli/declared_options.hpp): one CLI11 option per field, flag
//     "--" + the name with dashes, help "<help>, <unit>", the default from the member initializer;
//   * Python (python/src/bind.hpp, Command::declared): one keyword per field, its Python type,
//     default and docstring line;
//   * the schema (`tribolab schema --json`): what a form needs, and what docs/cli.md is checked
//     against (cli/schema_test.cpp);
//   * validation: check_ranges() checks each declared range and names the field
//     (field(name), numerics/error.hpp), which each front end spells its way.
//
// `<area>_<cmd>_result_keys()` declares the result's JSON keys with their units: the text
// listing prints those units (cli/text_listing.hpp) and a test requires every number a
// converted command prints to be declared. No CLI11 and no pybind11 here.
#pragma once

#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "report/plotly_script.hpp"
#include "sweep/grid.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace tribolab::app {

/// The field of one options object a declaration names, by its C++ type.
using FieldRef = std::variant<double*, int*, unsigned*, std::int64_t*, std::uint64_t*, std::optional<double>*,
                              std::optional<int>*, std::string*, std::optional<std::string>*, bool*,
                              std::vector<std::string>*, std::vector<double>*, report::PlotlyMode*,
                              std::optional<sweep::Axis>*, sweep::ValueOrAxis*, sweep::Shard*>;

/// What a field is to a form: a value, the input files (positional on the command line), a
/// path written by the command, the report pair (`--report`, `--plotly`), or a value only a
/// notebook wants (keep arrays in memory: a Python keyword, no command-line flag).
enum class FieldRole { value, input_files, output_path, report, plotly, notebook };

/// The declaration of one option, independent of the struct it lives in.
struct FieldDecl {
  std::string name;   ///< snake_case, as messages name it (field(name)) and Python's keyword; CLI: "--" + dashes
  std::string unit;   ///< SI unit as printed ("m/s", "kg m^2", "deg"); "" for pure numbers, words and flags
  std::string help;   ///< one line for people, without the unit
  std::optional<PhysicalRange> range;  ///< valid values (numerics/physical_range.hpp); checked by check_ranges
  bool required = false;               ///< must be given (no meaningful default)
  FieldRole role = FieldRole::value;
  std::vector<std::string> choices;    ///< the words a text field accepts; empty = any text
  std::string group;                   ///< shared group ("ball", "law", "truth law") or "" for the command's own
  std::string cli_alias;               ///< a second command-line spelling kept for old scripts ("--from" of t_from); "" = none

  FieldDecl& in(const PhysicalRange& r) { range = r; return *this; }
  FieldDecl& needed() { required = true; return *this; }
  FieldDecl& as(FieldRole r) { role = r; return *this; }
  FieldDecl& one_of(std::vector<std::string> words) { choices = std::move(words); return *this; }
  FieldDecl& also_spelled(std::string flag) { cli_alias = std::move(flag); return *this; }
};

/// One declared field of options struct O: the declaration and how to reach the member.
template <class O>
struct Field : FieldDecl {
  std::function<FieldRef(O&)> ref;
};

/// The declared fields of options struct O, in the order the help lists them.
template <class O>
class Fields {
 public:
  /// Declares `member` as option `name` with `unit` and `help`; chain .in(range), .needed(),
  /// .as(role), .one_of({...}) on the result.
  template <class T>
  FieldDecl& add(std::string name, T O::*member, std::string unit, std::string help) {
    Field<O> f;
    f.name = std::move(name);
    f.unit = std::move(unit);
    f.help = std::move(help);
    f.ref = [member](O& o) -> FieldRef { return &(o.*member); };
    fields_.push_back(std::move(f));
    return fields_.back();
  }

  /// Every field of a group's declaration (`BallOptions ball;` -> --a --b --mass --inertia),
  /// reached through `member`; `except` leaves out fields the command owns itself.
  template <class G>
  Fields& group(G O::*member, const Fields<G>& inner, const std::vector<std::string>& except = {}) {
    for (const Field<G>& g : inner) {
      if (std::find(except.begin(), except.end(), g.name) != except.end()) continue;
      add_from(member, g);
    }
    return *this;
  }

  /// One field of another struct's declaration, reached through `member` (a command over
  /// several files declares its shared options as the one-file command's, one by one).
  template <class G>
  FieldDecl& add_from(G O::*member, const Field<G>& g) {
    Field<O> f;
    static_cast<FieldDecl&>(f) = g;
    f.ref = [member, r = g.ref](O& o) -> FieldRef { return r(o.*member); };
    fields_.push_back(std::move(f));
    return fields_.back();
  }

  /// `--report FILE.html` and `--plotly MODE` (cli/report_option.hpp), every command's pair.
  Fields& add_report(std::string O::*path, report::PlotlyMode O::*plotly) {
    add("report", path, "", "write an HTML report to this file").as(FieldRole::report);
    add("plotly", plotly, "", "how the report gets Plotly.js").as(FieldRole::plotly).one_of({"embed", "cdn", "file"});
    return *this;
  }

  auto begin() const { return fields_.begin(); }
  auto end() const { return fields_.end(); }
  std::size_t size() const { return fields_.size(); }
  /// The field named `name`, or nullptr.
  const Field<O>* find(std::string_view name) const {
    for (const auto& f : fields_)
      if (f.name == name) return &f;
    return nullptr;
  }

 private:
  std::vector<Field<O>> fields_;
};

/// The value of a numeric field as a double (nullopt: unset optional, or not a number).
inline std::optional<double> numeric_value(const FieldRef& r) {
  return std::visit(
      [](auto* p) -> std::optional<double> {
        using T = std::remove_cvref_t<decltype(*p)>;
        if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
          return static_cast<double>(*p);
        } else if constexpr (std::is_same_v<T, std::optional<double>> || std::is_same_v<T, std::optional<int>>) {
          if (*p) return static_cast<double>(**p);
          return std::nullopt;
        } else {
          return std::nullopt;
        }
      },
      r);
}

/// Checks every declared range of `o`: InputError(field(name), "V UNIT is outside the physical
/// range [LO, HI] UNIT") for the first value outside it (an unset optional is not checked).
template <class O>
void check_ranges(const O& o, const Fields<O>& fields) {
  O& obj = const_cast<O&>(o);  // the references are only read
  for (const Field<O>& f : fields) {
    if (!f.range) continue;
    if (auto v = numeric_value(f.ref(obj))) check_range(*v, *f.range, field(f.name));
  }
}

/// The type of a field as the schema names it: "number", "integer", "text", "flag", "numbers",
/// "texts" (lists), "choice" for PlotlyMode; a sweep's "range" (sweep::Axis: lo, hi, count; the
/// command line's LO:HI:COUNT), "number or range" (sweep::ValueOrAxis) and "shard" (index,
/// count; i/N); `nullable` when unset means automatic (std::optional).
struct FieldType {
  std::string name;
  bool nullable = false;
};
FieldType field_type(const FieldRef& r);

/// The field's current value as JSON (null: an unset optional; a range [lo, hi, count], a shard
/// [index, count], a number or range its value or its range).
nlohmann::json field_value(const FieldRef& r);

/// The schema of one declared field, its default read from `defaults`: name, type, nullable,
/// unit, help, default, range {lo, hi, lo_open}, required, role, choices, group.
nlohmann::json field_schema(const FieldDecl& f, const FieldRef& in_defaults);

/// The schema of every field of O (defaults from a default-constructed O).
template <class O>
nlohmann::json fields_schema(const Fields<O>& fields) {
  O defaults;
  nlohmann::json a = nlohmann::json::array();
  for (const Field<O>& f : fields) a.push_back(field_schema(f, f.ref(defaults)));
  return a;
}

/// One declared key of a command's JSON result: `key` is its path, nested objects and the
/// elements of a list of objects joined by dots ("law.K", "bounces.vx_in"); a path ending in
/// ".*" covers every key below it ("energy_in_parts.*"), and "tracks.*.rows" the key `rows` of
/// every member of an object keyed by names. `sigma_X`, `X_ci95` and `ci95.X` carry X's unit
/// without a declaration of their own.
struct ResultKey {
  std::string key;
  std::string unit;  ///< as printed ("m/s"); "" for pure numbers, words, flags, counts
  std::string help;  ///< optional one line
};
using ResultKeys = std::vector<ResultKey>;

/// [{key, unit, help}] of `keys`.
nlohmann::json result_keys_schema(const ResultKeys& keys);

/// The declaration of `path` in `keys` (with the companion and ".*" rules above), or nullptr.
const ResultKey* find_result_key(const ResultKeys& keys, const std::string& path);

}  // namespace tribolab::app
