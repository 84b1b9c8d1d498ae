// A command that exists only to test the binding mechanism (python/tests/test_mechanism.py):
// options of every kind the application layer uses, nested like its shared groups.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace tribolab::python {

/// A shared group, like app::BallOptions.
struct SelftestGroup {
  double g = 9.81;            ///< an acceleration with a default, m/s^2
  std::optional<double> mu;   ///< an optional number, 1; unset = none
};

struct SelftestOptions {
  std::vector<std::string> files;  ///< positional input files
  SelftestGroup group;             ///< --g, --mu
  int n = 3;                       ///< a count, in [1, 100]
  std::string model = "B";         ///< a word
  bool flag = false;               ///< a switch
  std::vector<double> values;      ///< a list of numbers
  std::string json_text = "{}";    ///< a JSON object returned as the result, as text
  std::size_t rows = 2;            ///< rows of the returned grid
  std::size_t cols = 3;            ///< columns of the returned grid
};

struct SelftestResult {
  nlohmann::json json;        ///< json_text parsed, plus "echo" (the options) and "gil_held"
  std::vector<double> grid;   ///< rows * cols numbers 0, 1, 2... row-major
  std::size_t rows = 0, cols = 0;
};

/// Throws InputError("--n: ...") for n outside [1, 100], as a command checks an option.
SelftestResult selftest_echo(const SelftestOptions& o);

}  // namespace tribolab::python
