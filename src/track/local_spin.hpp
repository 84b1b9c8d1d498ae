// Local spin rates of an angle track: the slope of theta(t) over a sliding window with its
// standard error, the noise pooled over all windows (docs/theory.md#rigid-body). Shared by two
// points of one body (track/rigid_body.hpp) and one point about a pivot (track/pivot.hpp).
#pragma once

#include "track/rigid_body.hpp"

#include <vector>

namespace tribolab::track {

/// Sets omega and sigma_omega of every row from the slope of theta(t) over `window` rows about
/// it (shifted at the ends: there it is the spin at the window's middle); rows keep their
/// values when fewer than 3 rows exist. Only t and theta are read.
void local_spins(std::vector<RigidBodyRow>& rows, int window);

}  // namespace tribolab::track
