// tribolab._tribolab._selftest: the mechanism of bind.hpp on a command made for testing it.
#include "selftest.hpp"

#include "bind.hpp"
#include "numerics/error.hpp"

#include <Python.h>

namespace tribolab::python {

SelftestResult selftest_echo(const SelftestOptions& o) {
  if (o.n < 1 || o.n > 100) {
    throw InputError(tribolab::field("n"), "must be in [1, 100], got " + std::to_string(o.n) + "\nsecond line");
  }
  SelftestResult r;
  r.json = nlohmann::json::parse(o.json_text);
  r.json["echo"] = {{"files", o.files}, {"g", o.group.g}, {"n", o.n}, {"model", o.model},
                    {"flag", o.flag}, {"values", o.values},
                    {"mu", o.group.mu ? nlohmann::json(*o.group.mu) : nlohmann::json(nullptr)}};
  r.json["gil_held"] = PyGILState_Check() != 0;  // the call runs without the GIL
  r.rows = o.rows;
  r.cols = o.cols;
  for (std::size_t i = 0; i < o.rows * o.cols; ++i) r.grid.push_back(static_cast<double>(i));
  return r;
}

void bind_selftest(py::module_& m) {
  m.def("to_python", [](const std::string& text) { return to_python(nlohmann::json::parse(text)); },
        "The converter on a JSON text (nlohmann's parse, as the commands' numbers).");
  m.def("dump", [](const std::string& text) { return nlohmann::json::parse(text).dump(); },
        "nlohmann's dump() of a JSON text, as the CLI prints --json.");
  Command<SelftestOptions> c(m, "echo", "Echoes its options; a test of the binding mechanism.");
  TRIBOLAB_ARG(c, files);
  TRIBOLAB_OPT(c, group.g);
  TRIBOLAB_OPT(c, group.mu);
  TRIBOLAB_OPT(c, n);
  TRIBOLAB_OPT(c, model);
  TRIBOLAB_OPT(c, flag);
  TRIBOLAB_OPT(c, values);
  TRIBOLAB_OPT(c, json_text);
  TRIBOLAB_OPT(c, rows);
  TRIBOLAB_OPT(c, cols);
  c.def(&selftest_echo,
        [](const SelftestResult& r, py::dict& d) { d["grid"] = array_2d(r.grid, r.rows, r.cols); },
        "grid: float array (rows, cols)");
}

}  // namespace tribolab::python
