// tribolab._tribolab.bounce: the `tribolab bounce` commands of the application layer (bind.hpp).
#include "bind.hpp"

namespace tribolab::python {

void bind_bounce(py::module_& m) {}

}  // namespace tribolab::python
