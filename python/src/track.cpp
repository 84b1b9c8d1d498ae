// tribolab._tribolab.track: the `tribolab track` commands of the application layer (bind.hpp).
#include "bind.hpp"

namespace tribolab::python {

void bind_track(py::module_& m) {}

}  // namespace tribolab::python
