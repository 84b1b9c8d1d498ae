// Report page of `track kinematics`: positions, velocities and accelerations of one track
// against time, with standard-error bars (savgol) and the detected impacts marked.
#pragma once

#include "report/report.hpp"
#include "track/kinematics.hpp"

namespace tribolab::app {

/// `track kinematics --report`: six figures (x, y, vx, vy, ax, ay against t) and an impacts
/// table; `source` names the input file.
report::Report track_kinematics_report(const track::Kinematics& k, const track::KinematicsOptions& options,
                                       const std::string& source);

}  // namespace tribolab::app
