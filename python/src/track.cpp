// tribolab._tribolab.track: the `tribolab track` commands of the application layer
// (src/app/track_*.hpp) through the mechanism of bind.hpp.
#include "bind.hpp"

#include "app/track/track_import.hpp"
#include "app/track/track_kinematics.hpp"
#include "app/track/track_rigid_body.hpp"
#include "app/track/track_rotation.hpp"
#include "app/track/track_video.hpp"

namespace tribolab::python {

void bind_track(py::module_& m) {
  {
    Command<app::TrackImportOptions> c(m, "load",
        "Reads tracked points (`tribolab track import`): a Tracker .trk/.trz, Tracker's exported "
        "data text or a CSV table; lengths in m, times in s after the time scale.");
    c.declared(app::track_import_fields());
    c.def(&app::track_import,
          [](const app::TrackImportResult& r, py::dict& d) {
            py::dict tracks;
            for (const auto& t : r.tracks) {
              tracks[py::str(t.name)] = point_columns(t.points);
            }
            d["points"] = tracks;
          },
          "points: dict track name -> dict of arrays frame (int), t (s), x, y (m, y up)");
  }
  {
    using track::KinematicsRow;
    Command<app::TrackKinematicsOptions> c(m, "kinematics",
        "Velocities and accelerations of one track (`tribolab track kinematics`): Tracker's "
        "finite differences or Savitzky-Golay with standard errors, never across impacts.");
    c.declared(app::track_kinematics_fields());
    c.def(&app::track_kinematics,
          [](const app::TrackKinematicsResult& r, py::dict& d) {
            const auto& k = r.kinematics.rows;
            d["rows"] = columns(k, field("frame", &KinematicsRow::frame), field("t", &KinematicsRow::t),
                                field("x", &KinematicsRow::x), field("y", &KinematicsRow::y),
                                field("vx", &KinematicsRow::vx), field("vy", &KinematicsRow::vy),
                                field("ax", &KinematicsRow::ax), field("ay", &KinematicsRow::ay),
                                field("sigma_vx", &KinematicsRow::sigma_vx),
                                field("sigma_vy", &KinematicsRow::sigma_vy),
                                field("sigma_ax", &KinematicsRow::sigma_ax),
                                field("sigma_ay", &KinematicsRow::sigma_ay),
                                field("segment", &KinematicsRow::segment));
          },
          "rows: dict of arrays frame, t (s), x, y (m), vx, vy (m/s), ax, ay (m/s^2), their "
          "sigma_* (NaN for tracker), segment (int)");
  }
  {
    using track::RigidBodyRow;
    Command<app::TrackRigidBodyOptions> c(m, "rigid_body",
        "The planar motion of a body from two tracked points on it (`tribolab track rigid-body`): "
        "centre, orientation and spin with standard errors, and the A-B distance check.");
    c.declared(app::track_rigid_body_fields());
    c.def(&app::track_rigid_body,
          [](const app::TrackRigidBodyResult& r, py::dict& d) {
            d["rows"] = columns(r.body.rows, field("frame", &RigidBodyRow::frame), field("t", &RigidBodyRow::t),
                                field("xc", &RigidBodyRow::xc), field("yc", &RigidBodyRow::yc),
                                field("theta", &RigidBodyRow::theta), field("length", &RigidBodyRow::length),
                                field("omega", &RigidBodyRow::omega),
                                field("sigma_omega", &RigidBodyRow::sigma_omega));
          },
          "rows: dict of arrays frame, t (s), xc, yc (m), theta (rad, unwrapped), length (m), "
          "omega, sigma_omega (rad/s; NaN where the window does not fit)");
  }
  {
    using track::PivotRow;
    Command<app::TrackRotationOptions> c(m, "rotation",
        "The spin of one tracked point about a fixed, given or uniformly moving pivot (`tribolab "
        "track rotation`): pivot, radius, omega and alpha with standard errors, local spins.");
    c.declared(app::track_rotation_fields());
    c.def(&app::track_rotation,
          [](const app::TrackRotationResult& r, py::dict& d) {
            d["rows"] = columns(r.rotation.rows, field("frame", &PivotRow::frame), field("t", &PivotRow::t),
                                field("x", &PivotRow::x), field("y", &PivotRow::y),
                                field("theta", &PivotRow::theta), field("radius", &PivotRow::radius),
                                field("omega", &PivotRow::omega), field("sigma_omega", &PivotRow::sigma_omega));
          },
          "rows: dict of arrays frame, t (s), x, y (m), theta (rad, unwrapped about the pivot), "
          "radius (m), omega, sigma_omega (rad/s; NaN where the window does not fit)");
  }
  {
    using video::TrackedRow;
    Command<app::TrackVideoOptions> c(m, "video",
        "Follows points and balls through a video or a Tracker project's video (`tribolab track "
        "video`); writes the table to `out` (required).");
    c.declared(app::track_video_fields());
    c.def(&app::track_video,
          [](const app::TrackVideoResult& r, py::dict& d) {
            py::dict tracks;
            for (const auto& s : r.series) {
              py::dict t = columns(s.rows, field("frame", &TrackedRow::frame), field("t", &TrackedRow::t),
                                   field("x", &TrackedRow::x), field("y", &TrackedRow::y),
                                   field("x_px", &TrackedRow::x_px), field("y_px", &TrackedRow::y_px),
                                   field("score", &TrackedRow::score), field("lost", &TrackedRow::lost));
              t["angle_rad"] = array_1d(s.angle_rad);
              tracks[py::str(s.name)] = t;
            }
            d["rows"] = tracks;
          },
          "rows: dict track name -> dict of arrays frame, t (s), x, y (m; px uncalibrated), x_px, "
          "y_px (px), score (0..1), lost (bool), angle_rad (rad)");
  }
}

}  // namespace tribolab::python
