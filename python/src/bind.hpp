// The one mechanism that makes a command of the application layer (src/app) a Python function
// (docs/python.md, docs/design.md "Python"): keyword arguments named as the command line's
// options in snake_case, defaults read from a default-constructed Options struct, the call
// without the GIL, result.json as a dict with exactly the CLI's --json keys and numbers, the
// arrays beside it as numpy arrays, InputError as ValueError with the CLI's message.
//
// Each command registers a spec (the module's `_specs` list) from which tribolab/_commands.py
// builds the Python function with its signature and docstring (help from the `///` comments
// of the option structs, collected at build time by python/option_help.py).
#pragma once

#include "app/common/option_fields.hpp"
#include "app/sweep/sweep_text.hpp"
#include "numerics/error.hpp"
#include "report/plotly_script.hpp"
#include "track/track.hpp"

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

// `plotly="embed"|"cdn"|"file"` (report::PlotlyMode, --plotly): a str in Python; another
// string is a ValueError with the command line's message.
namespace pybind11::detail {
template <>
struct type_caster<tribolab::report::PlotlyMode> {
  PYBIND11_TYPE_CASTER(tribolab::report::PlotlyMode, const_name("str"));
  bool load(handle src, bool) {
    if (!isinstance<str>(src)) return false;
    value = tribolab::report::parse_plotly_mode(src.cast<std::string>());  // InputError -> ValueError
    return true;
  }
  static handle cast(tribolab::report::PlotlyMode m, return_value_policy, handle) {
    return str(std::string(tribolab::report::to_string(m))).release();
  }
};
}  // namespace pybind11::detail

// A sweep axis (a range field of a declaration, `bounce sweep` theta_deg): (lo, hi, count), as
// the command line's LO:HI:N; a quantity that is one value or an axis (speed, mu): a number or
// (lo, hi, count); a shard: (index, count) or the command line's "i/N" (read by
// app::parse_shard, so a malformed one is the command line's message). Here, beside the
// mechanism, because Command::declared instantiates every type a declaration may hold.
namespace pybind11::detail {
template <>
struct type_caster<tribolab::sweep::Axis> {
  PYBIND11_TYPE_CASTER(tribolab::sweep::Axis, const_name("tuple[float, float, int]"));
  bool load(handle src, bool) {
    if (!isinstance<sequence>(src) || isinstance<str>(src)) return false;
    const auto seq = reinterpret_borrow<sequence>(src);
    if (seq.size() != 3) return false;
    try {
      value.lo = seq[0].cast<double>();
      value.hi = seq[1].cast<double>();
      value.count = seq[2].cast<std::int64_t>();
    } catch (const cast_error&) {
      return false;
    }
    return true;
  }
  static handle cast(const tribolab::sweep::Axis& a, return_value_policy, handle) {
    return make_tuple(a.lo, a.hi, a.count).release();
  }
};
template <>
struct type_caster<tribolab::sweep::Shard> {
  PYBIND11_TYPE_CASTER(tribolab::sweep::Shard, const_name("tuple[int, int] or str"));
  bool load(handle src, bool) {
    if (isinstance<str>(src)) {
      value = tribolab::app::parse_shard(src.cast<std::string>(), tribolab::field("shard"));  // InputError -> ValueError
      return true;
    }
    if (!isinstance<sequence>(src)) return false;
    const auto seq = reinterpret_borrow<sequence>(src);
    if (seq.size() != 2) return false;
    try {
      value.index = seq[0].cast<std::int64_t>();
      value.count = seq[1].cast<std::int64_t>();
    } catch (const cast_error&) {
      return false;
    }
    return true;
  }
  static handle cast(const tribolab::sweep::Shard& s, return_value_policy, handle) {
    return make_tuple(s.index, s.count).release();
  }
};
template <>
struct type_caster<tribolab::sweep::ValueOrAxis> {
  PYBIND11_TYPE_CASTER(tribolab::sweep::ValueOrAxis, const_name("float or tuple[float, float, int]"));
  bool load(handle src, bool convert) {
    if (isinstance<float_>(src) || isinstance<int_>(src)) {
      value.value = src.cast<double>();
      value.axis.reset();
      return true;
    }
    make_caster<tribolab::sweep::Axis> axis;
    if (!axis.load(src, convert)) return false;
    value.axis = cast_op<tribolab::sweep::Axis>(axis);
    return true;
  }
  static handle cast(const tribolab::sweep::ValueOrAxis& v, return_value_policy p, handle h) {
    if (v.axis) return make_caster<tribolab::sweep::Axis>::cast(*v.axis, p, h);
    return float_(v.value).release();
  }
};
}  // namespace pybind11::detail

namespace tribolab::python {

namespace py = pybind11;

/// A JSON value as Python objects: null -> None, integers -> int, numbers -> float (the same
/// double, so `json.loads` of the CLI's output compares equal to the last digit), strings,
/// lists, dicts. A non-finite number becomes None, as nlohmann's dump() prints it.
py::object to_python(const nlohmann::json& j);

/// A copy of `v` as a 1-D float64 array.
py::array_t<double> array_1d(const std::vector<double>& v);

/// A copy of `v` (row-major, v.size() == rows * cols) as a 2-D float64 array (rows, cols).
py::array_t<double> array_2d(const std::vector<double>& v, std::size_t rows, std::size_t cols);

/// A field of a sample struct to make a column of: field("t", &State::t).
template <class S, class M>
std::pair<const char*, M S::*> field(const char* name, M S::*member) { return {name, member}; }

/// One column of a table of samples as a 1-D array of the field's type (float64, int, bool).
template <class S, class M>
py::array_t<M> column(const std::vector<S>& samples, M S::*member) {
  py::array_t<M> a(static_cast<py::ssize_t>(samples.size()));
  auto out = a.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < samples.size(); ++i) out(static_cast<py::ssize_t>(i)) = samples[i].*member;
  return a;
}

/// One computed column: of_each(samples, [](const S& s) { return s.state.x; }) as float64.
template <class S, class F>
py::array_t<double> of_each(const std::vector<S>& samples, F value) {
  py::array_t<double> a(static_cast<py::ssize_t>(samples.size()));
  auto out = a.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < samples.size(); ++i) out(static_cast<py::ssize_t>(i)) = value(samples[i]);
  return a;
}

/// A table of samples as a dict of 1-D arrays, one per named field:
/// columns(trajectory, field("t", &State::t), field("x", &State::x)) -> {"t": array, "x": array}.
template <class S, class... M>
py::dict columns(const std::vector<S>& samples, std::pair<const char*, M S::*>... fields) {
  py::dict d;
  ((d[fields.first] = column(samples, fields.second)), ...);
  return d;
}

/// A track's points as a dict of arrays frame, t, x, y (the columns every command that
/// returns tracked or synthetic points gives).
inline py::dict point_columns(const std::vector<track::TrackPoint>& points) {
  using track::TrackPoint;
  return columns(points, field("frame", &TrackPoint::frame), field("t", &TrackPoint::t), field("x", &TrackPoint::x),
                 field("y", &TrackPoint::y));
}

/// Rows of equally long sample tables (the members of a family) as a dict of 2-D float64
/// arrays (rows, samples), one per named field; `samples_of(row)` returns a row's samples.
template <class Row, class SamplesOf, class S>
py::dict columns_2d(const std::vector<Row>& rows, SamplesOf samples_of,
                    std::initializer_list<std::pair<const char*, double S::*>> fields) {
  const std::size_t n = rows.empty() ? 0 : samples_of(rows.front()).size();
  for (const auto& r : rows) {
    if (samples_of(r).size() != n) throw std::logic_error("columns_2d: rows of different lengths");
  }
  py::dict d;
  for (const auto& [name, member] : fields) {
    py::array_t<double> a({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(n)});
    auto out = a.template mutable_unchecked<2>();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto& s = samples_of(rows[i]);
      for (std::size_t j = 0; j < n; ++j) {
        out(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = s[j].*member;
      }
    }
    d[name] = std::move(a);
  }
  return d;
}

namespace detail {

/// The Python type a C++ option type takes, for docstrings.
/// (A type with its own caster, as sweep::Axis, says its Python spelling: "tuple[float, float, int]".)
template <class T> struct TypeName { static std::string get() { return py::detail::make_caster<T>::name.text; } };
template <> struct TypeName<double> { static std::string get() { return "float"; } };
template <> struct TypeName<float> { static std::string get() { return "float"; } };
template <> struct TypeName<bool> { static std::string get() { return "bool"; } };
template <> struct TypeName<int> { static std::string get() { return "int"; } };
template <> struct TypeName<unsigned> { static std::string get() { return "int"; } };
template <> struct TypeName<long> { static std::string get() { return "int"; } };
template <> struct TypeName<unsigned long> { static std::string get() { return "int"; } };
template <> struct TypeName<long long> { static std::string get() { return "int"; } };
template <> struct TypeName<unsigned long long> { static std::string get() { return "int"; } };
template <> struct TypeName<std::string> { static std::string get() { return "str"; } };
template <> struct TypeName<report::PlotlyMode> { static std::string get() { return "str"; } };
template <class T> struct TypeName<std::optional<T>> {
  static std::string get() { return TypeName<T>::get() + " or None"; }
};
template <class T> struct TypeName<std::vector<T>> {
  static std::string get() { return "list of " + TypeName<T>::get(); }
};

/// "tribolab::app::InclinePredictOptions" -> "InclinePredictOptions".
std::string unqualified(const std::string& name);

template <class T> struct IsNumber : std::bool_constant<std::is_arithmetic_v<T> && !std::is_same_v<T, bool>> {};
template <class T> struct IsNumber<std::optional<T>> : IsNumber<T> {};
template <class T> struct IsNumber<std::vector<T>> : IsNumber<T> {};
template <class T> struct IsText : std::is_same<T, std::string> {};
template <class T> struct IsText<std::optional<T>> : IsText<T> {};
template <class T> struct IsText<std::vector<T>> : IsText<T> {};

/// The Python side of the command line's rule for option values (docs/python.md, "Keyword
/// values"; cli/command_line_check.hpp, empty_value_problem): a number keyword refuses a bool
/// (True is not 1.0; TypeError), a str keyword refuses a NUL character (a path would be cut
/// at it; ValueError). Applies to the items of a list keyword as well.
template <class T>
void check_keyword_value(const std::string& command, const std::string& keyword, py::handle value) {
  auto check_one = [&](py::handle v) {
    if constexpr (IsNumber<T>::value) {
      if (py::isinstance<py::bool_>(v))
        throw py::type_error(command + "(): " + keyword + " must be " + TypeName<T>::get() + ", got bool");
    }
    if constexpr (IsText<T>::value) {
      if (py::isinstance<py::str>(v) && v.cast<std::string>().find('\0') != std::string::npos)
        throw py::value_error(command + "(): " + keyword + " contains a NUL character");
    }
  };
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    for (py::handle v : value) check_one(v);
  } else {
    check_one(value);
  }
}

/// Adds `spec` to the `_specs` list of module `m` (created on first use).
void add_spec(py::module_& m, const py::dict& spec);

}  // namespace detail

/// A command being bound: `Command<O>(m, "simulate", "Simulates ...").opt(...).def(fn, arrays)`.
template <class O>
class Command {
 public:
  Command(py::module_ m, std::string name, std::string summary)
      : module_(std::move(m)), name_(std::move(name)), summary_(std::move(summary)) {}

  /// An option: `path` is the field of O ("launch.mu", a nested group's field after a dot), its
  /// last part the keyword (as the command line's option in snake_case); `get` returns the field.
  template <class Get>
  Command& opt(const std::string& path, Get get) { return add(path, keyword_of(path), std::move(get), false); }
  /// An option whose keyword is not the field's name.
  template <class Get>
  Command& opt_as(const std::string& keyword, const std::string& path, Get get) {
    return add(path, keyword, std::move(get), false);
  }
  /// Every declared field of O (src/app/common/option_fields.hpp) as a keyword named as the field, its
  /// Python type, default (from a default-constructed O), help and unit from the declaration;
  /// the input files (FieldRole::input_files) positional or keyword.
  Command& declared(const app::Fields<O>& fields) {
    O defaults;
    for (const app::Field<O>& f : fields) {
      std::visit(
          [&](auto* p) {
            using T = std::remove_cvref_t<decltype(*p)>;
            auto ref = f.ref;
            add(f.name, f.name, [ref](O& o) -> T& { return *std::get<T*>(ref(o)); },
                f.role == app::FieldRole::input_files, &f);
          },
          f.ref(defaults));
    }
    return *this;
  }
  /// A positional argument of the command line (e.g. the input files): positional or keyword.
  template <class Get>
  Command& arg(const std::string& path, Get get) { return add(path, keyword_of(path), std::move(get), true); }

  /// Defines the function `_<name>` in the module (tribolab/_commands.py wraps it as `<name>`):
  /// options from the keywords, `run` without the GIL, the dict of result.json, then
  /// `arrays(result, dict)` adds the arrays.
  template <class Result, class Arrays>
  void def(Result (*run)(const O&), Arrays arrays, const std::string& returns) {
    auto setters = setters_;
    std::string name = name_;
    module_.def(("_" + name_).c_str(), [setters, name, run, arrays](py::kwargs kwargs) {
      O options;
      for (const auto& [key, value] : kwargs) {
        const auto k = py::str(key).cast<std::string>();
        auto it = setters.find(k);
        if (it == setters.end()) {
          throw py::type_error(name + "() got an unexpected keyword argument '" + k + "'");
        }
        it->second(options, value);
      }
      std::optional<Result> result;
      {
        py::gil_scoped_release unlocked;
        result.emplace(run(options));
      }
      py::object out = to_python(result->json);
      if (!py::isinstance<py::dict>(out)) throw std::logic_error(name + ": result.json is not an object");
      py::dict d = out;
      py::dict extra;
      arrays(*result, extra);
      for (const auto& [k, v] : extra) {
        if (d.contains(k)) throw std::logic_error(name + ": array key clashes with a JSON key");
        d[k] = v;
      }
      return d;
    });
    py::dict spec;
    spec["name"] = name_;
    spec["summary"] = summary_;
    spec["returns"] = returns;
    spec["options_struct"] = detail::unqualified(py::type_id<O>());
    spec["options"] = options_;
    detail::add_spec(module_, spec);
  }

 private:
  static std::string keyword_of(const std::string& path) {
    const auto dot = path.rfind('.');
    return dot == std::string::npos ? path : path.substr(dot + 1);
  }

  template <class Get>
  Command& add(const std::string& path, const std::string& keyword, Get get, bool positional,
               const app::FieldDecl* decl = nullptr) {
    using T = std::remove_cvref_t<decltype(get(std::declval<O&>()))>;
    O defaults;
    py::dict o;
    o["keyword"] = keyword;
    o["path"] = path;
    o["type"] = detail::TypeName<T>::get();
    o["default"] = py::cast(get(defaults));  // the ONE source of the default: the struct
    o["positional"] = positional;
    if (decl) {  // declared: the help and unit of the declaration, not the struct's comment
      std::string help = decl->help;
      if (!decl->choices.empty()) {
        help += ":";
        for (const auto& c : decl->choices) help += " " + c;
      }
      o["help"] = help;
      o["unit"] = decl->unit;
      o["required"] = decl->required;
    }
    options_.append(o);
    std::string name = name_;
    setters_[keyword] = [get, name, keyword](O& options, py::handle value) {
      detail::check_keyword_value<T>(name, keyword, value);
      try {
        get(options) = value.cast<T>();
      } catch (const py::cast_error&) {
        throw py::type_error(name + "(): " + keyword + " must be " + detail::TypeName<T>::get() +
                             ", got " + Py_TYPE(value.ptr())->tp_name);
      }
    };
    return *this;
  }

  py::module_ module_;
  std::string name_, summary_;
  py::list options_;
  std::map<std::string, std::function<void(O&, py::handle)>> setters_;
};

/// `OPT(cmd, launch.mu)`: binds the field `launch.mu` of the command's options as keyword `mu`.
#define TRIBOLAB_OPT(cmd, field) (cmd).opt(#field, [](auto& o) -> auto& { return o.field; })
/// A positional argument of the command line (the input files): `TRIBOLAB_ARG(cmd, files)`.
#define TRIBOLAB_ARG(cmd, field) (cmd).arg(#field, [](auto& o) -> auto& { return o.field; })

/// The areas, one file each.
void bind_selftest(py::module_& m);
void bind_incline(py::module_& m);
void bind_bounce(py::module_& m);
void bind_track(py::module_& m);

}  // namespace tribolab::python
