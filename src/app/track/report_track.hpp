// Report page of `track kinematics`: positions, velocities and accelerations of one track
// against time, with standard-error bars (savgol) and the detected impacts marked.
#pragma once

#include "report/report.hpp"
#include "track/free_flight.hpp"
#include "track/kinematics.hpp"

#include <string>
#include <vector>

namespace tribolab::app {

/// `track kinematics --report`: six figures (x, y, vx, vy, ax, ay against t), an impacts
/// table, the constant-acceleration fit of each segment and the warnings; `source` names the
/// input file.
report::Report track_kinematics_report(const track::Kinematics& k, const track::KinematicsOptions& options,
                                       const std::string& source,
                                       const std::vector<track::SegmentAcceleration>& segment_fits = {},
                                       const std::vector<std::string>& warnings = {});

}  // namespace tribolab::app
