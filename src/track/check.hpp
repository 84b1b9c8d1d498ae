// Internal invariant check for the track area. Same behaviour as TRIBOLAB_ASSERT
// (numerics/error.hpp), whose macro parameter `detail` currently collides with the
// namespace name `detail` it expands to; reported to the lead, used here until fixed.
#pragma once

#include "numerics/error.hpp"

#define TRACK_CHECK(cond, message)                                                      \
  do {                                                                                  \
    if (!(cond)) ::tribolab::detail::assertion_failed(#cond, __FILE__, __LINE__, (message)); \
  } while (false)
