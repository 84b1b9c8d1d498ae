// The extension module `tribolab._tribolab`: the JSON converter, the error translation and one
// submodule per area (incline, bounce, track, _selftest). See bind.hpp.
#include "bind.hpp"

#include "numerics/error.hpp"

#include <glog/logging.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace tribolab::python {

py::object to_python(const nlohmann::json& j) {
  using T = nlohmann::json::value_t;
  switch (j.type()) {
    case T::null: return py::none();
    case T::boolean: return py::bool_(j.get<bool>());
    case T::number_integer: return py::int_(j.get<std::int64_t>());
    case T::number_unsigned: return py::int_(j.get<std::uint64_t>());
    case T::number_float: {
      const double v = j.get<double>();
      return std::isfinite(v) ? py::object(py::float_(v)) : py::object(py::none());
    }
    case T::string: return py::str(plain_fields(j.get_ref<const std::string&>()));  // field("floor_y") -> floor_y
    case T::array: {
      py::list l;
      for (const auto& e : j) l.append(to_python(e));
      return l;
    }
    case T::object: {
      py::dict d;
      for (const auto& [k, v] : j.items()) d[py::str(k)] = to_python(v);
      return d;
    }
    case T::binary:
    case T::discarded: break;
  }
  throw std::logic_error("to_python: a JSON value of a type the commands never produce");
}

py::array_t<double> array_1d(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(double));
  return a;
}

py::array_t<double> array_2d(const std::vector<double>& v, std::size_t rows, std::size_t cols) {
  if (v.size() != rows * cols) throw std::logic_error("array_2d: size is not rows * cols");
  py::array_t<double> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
  if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(double));
  return a;
}

namespace detail {

std::string unqualified(const std::string& name) {
  const auto colons = name.rfind("::");
  return colons == std::string::npos ? name : name.substr(colons + 2);
}

void add_spec(py::module_& m, const py::dict& spec) {
  if (!py::hasattr(m, "_specs")) m.attr("_specs") = py::list();
  m.attr("_specs").cast<py::list>().append(spec);
}

}  // namespace detail


}  // namespace tribolab::python

namespace py = pybind11;

PYBIND11_MODULE(_tribolab, m) {
  namespace tp = tribolab::python;
  // Ceres logs through glog to stderr; the results carry every failure, as in cli/main.cpp.
  FLAGS_minloglevel = google::GLOG_FATAL;
  m.doc() = "tribolab's C++ extension; use the package `tribolab` (tribolab.incline, .bounce, .track).";
  // numpy's C API now, while the import of this module serialises us. pybind11 2.10 looks it
  // up lazily in a function-local static (npy_api::get); a first lookup in one thread while
  // another waits on that static holding the GIL deadlocked (issue 26: two threads calling
  // tribolab before anyone imported numpy).
  py::module_::import("numpy");
  py::array_t<double> warm_up(0);
  (void)warm_up;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const tribolab::InputError& e) {  // the input: the caller changes it
      PyErr_SetString(PyExc_ValueError, tribolab::one_line(e.what()).c_str());
    } catch (const tribolab::SolverError& e) {  // a solver gave up on valid input (docs/design.md)
      PyErr_SetString(PyExc_RuntimeError, tribolab::one_line(e.what()).c_str());
    }
  });
  auto selftest = m.def_submodule("_selftest", "Checks of the binding mechanism itself (python/tests).");
  tp::bind_selftest(selftest);
  auto incline = m.def_submodule("incline", "The disc on a rough incline (incline study).");
  tp::bind_incline(incline);
  auto bounce = m.def_submodule("bounce", "The spinning rugby ball bouncing on a floor (rugby-ball study).");
  tp::bind_bounce(bounce);
  auto track = m.def_submodule("track", "Tracked data: Tracker files, kinematics, video.");
  tp::bind_track(track);
}
