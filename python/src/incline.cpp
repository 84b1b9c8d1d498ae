// tribolab._tribolab.incline: the `tribolab incline` commands of the application layer (bind.hpp).
#include "bind.hpp"

namespace tribolab::python {

void bind_incline(py::module_& m) {}

}  // namespace tribolab::python
