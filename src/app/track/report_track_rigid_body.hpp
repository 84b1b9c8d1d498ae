// Report page of `track rigid-body`: the centre's path, the orientation and the spin against
// time with the global spin fit, the distance between the two points against time.
#pragma once

#include "app/track/track_rigid_body.hpp"
#include "report/report.hpp"

#include <string>

namespace tribolab::app {

/// `track rigid-body --report`: summary table, warnings and four figures; `source` names the file.
report::Report track_rigid_body_report(const TrackRigidBodyResult& result, const std::string& source);

}  // namespace tribolab::app
