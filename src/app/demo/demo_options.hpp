// The options of `tribolab demo` and their declaration (app/common/option_fields.hpp): the
// command line binds from it; the demo is a program, not a Python function (python/tests/
// test_schema.py, NOT_IN_PYTHON). The workflow is run_demo (app/demo/demo.hpp).
#pragma once

#include "app/common/option_fields.hpp"

#include <string>

namespace tribolab::app {

struct DemoOptions {
  std::string out = "demo-out";  ///< folder for report.html and the data (created if needed)
};

inline const Fields<DemoOptions>& demo_fields() {
  using O = DemoOptions;
  static const Fields<O> f = [] {
    Fields<O> d;
    d.add("out", &O::out, "", "folder for report.html, created if needed").as(FieldRole::output_path);
    return d;
  }();
  return f;
}

}  // namespace tribolab::app
