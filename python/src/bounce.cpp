// tribolab._tribolab.bounce: the `tribolab bounce` commands of the application layer
// (src/app/bounce_*.hpp) through the mechanism of bind.hpp.
#include "bind.hpp"

#include "app/bounce/bounce_analyze.hpp"
#include "app/bounce/bounce_series.hpp"
#include "app/bounce/bounce_simulate.hpp"
#include "app/bounce/bounce_sweep.hpp"
#include "app/bounce/bounce_synth.hpp"
#include "numerics/error.hpp"

#include <stdlib.h>  // mkdtemp (POSIX)

#include <filesystem>
#include <string>
#include <system_error>


namespace tribolab::python {
namespace {

/// Samples with a t and a bounce::BodyState `state` as arrays t, x, y, theta, vx, vy, omega.
template <class S>
py::dict body_states(const std::vector<S>& v) {
  py::dict d;
  d["t"] = of_each(v, [](const S& s) { return s.t; });
  d["x"] = of_each(v, [](const S& s) { return s.state.x; });
  d["y"] = of_each(v, [](const S& s) { return s.state.y; });
  d["theta"] = of_each(v, [](const S& s) { return s.state.theta; });
  d["vx"] = of_each(v, [](const S& s) { return s.state.vx; });
  d["vy"] = of_each(v, [](const S& s) { return s.state.vy; });
  d["omega"] = of_each(v, [](const S& s) { return s.state.omega; });
  return d;
}

constexpr const char* kBounceStates = "t (s), x, y (m, centre), theta (rad), vx, vy (m/s), omega (rad/s)";

/// `bounce contact-time`: first contact of a ball released at an apex.
void bind_contact_time(py::module_& m) {
  Command<app::BounceContactTimeOptions> c(m, "contact_time",
      "First contact of a ball released at an apex (`tribolab bounce contact-time`, the rugby-ball study's "
      "table 4): time, collision angle and state at the touch.");
  c.declared(app::bounce_contact_time_fields());
  c.def(&app::bounce_contact_time,
        [](const app::BounceContactTimeResult& r, py::dict& d) {
          py::dict f = body_states(r.samples);
          f["gap"] = of_each(r.samples, [](const app::FlightSample& s) { return s.gap; });
          d["flight"] = f;
        },
        std::string("flight: dict of arrays ") + kBounceStates + ", gap (m, lowest point above the floor)");
}

/// `bounce simulate`: one impact, with the contact history as arrays.
void bind_simulate(py::module_& m) {
  using bounce::ContactSample;
  Command<app::BounceSimulateOptions> c(m, "simulate",
      "One impact from first touch until the ball flies free (`tribolab bounce simulate`, seed "
      "001 exp. 4): restitution, spin change, contact time.");
  c.declared(app::bounce_simulate_fields());
  c.def(&app::bounce_simulate,
        [](const app::BounceSimulateResult& r, py::dict& d) {
          py::dict h = body_states(r.history);
          const auto& v = r.history;
          h["d"] = of_each(v, [](const ContactSample& s) { return s.d; });
          h["d_dot"] = of_each(v, [](const ContactSample& s) { return s.d_dot; });
          h["N"] = of_each(v, [](const ContactSample& s) { return s.N; });
          h["f"] = of_each(v, [](const ContactSample& s) { return s.f; });
          h["v_t"] = of_each(v, [](const ContactSample& s) { return s.v_t; });
          d["contact"] = h;
        },
        std::string("contact: dict of arrays ") + kBounceStates +
            ", d (m, penetration), d_dot (m/s), N, f (N), v_t (m/s, slip)");
}

/// `bounce drop`: release, flight and bounces until rest, with the samples as arrays.
void bind_drop(py::module_& m) {
  Command<app::BounceDropOptions> c(m, "drop",
      "Release, flight and several bounces until rest (`tribolab bounce drop`).");
  c.declared(app::bounce_drop_fields());
  c.def(&app::bounce_drop,
        [](const app::BounceDropResult& r, py::dict& d) { d["samples"] = body_states(r.trajectory); },
        std::string("samples: dict of arrays ") + kBounceStates +
            " (empty unless trajectory, report or keep_trajectory)");
}

/// `bounce analyze`: tracked bounces, with each run's body and fitted flights as arrays.
void bind_analyze(py::module_& m) {
  Command<app::BounceAnalyzeSeriesOptions> c(m, "analyze",
      "Tracked bounces from the two tips of the ball (`tribolab bounce analyze`, the rugby-ball study's "
      "experiment 1): velocities, spin, e and energies before and after, with uncertainties; "
      "several files: a series with a summary (the rugby-ball study's experiment 2).");
  c.declared(app::bounce_analyze_series_fields());
  TRIBOLAB_OPT(c, series.threads);  // a notebook may limit the cores; the command line uses them all
  c.def(&app::bounce_analyze_series,
        [](const app::BounceAnalyzeSeriesResult& r, py::dict& d) {
          using track::RigidBodyRow;
          py::list fits;
          for (const auto& run : r.runs) {
            if (!run.result) {
              fits.append(py::none());
              continue;
            }
            const auto& a = run.result->analysis;
            py::dict f, body;
            const auto& rows = a.body.rows;
            body["t"] = of_each(rows, [](const RigidBodyRow& b) { return b.t; });
            body["x"] = of_each(rows, [](const RigidBodyRow& b) { return b.xc; });
            body["y"] = of_each(rows, [](const RigidBodyRow& b) { return b.yc; });
            body["theta"] = of_each(rows, [](const RigidBodyRow& b) { return b.theta; });
            body["length"] = of_each(rows, [](const RigidBodyRow& b) { return b.length; });
            body["omega"] = of_each(rows, [](const RigidBodyRow& b) { return b.omega; });
            body["sigma_omega"] = of_each(rows, [](const RigidBodyRow& b) { return b.sigma_omega; });
            f["body"] = body;
            for (const auto& [name, seg] : {std::pair{"flight_pre", &a.pre}, {"flight_post", &a.post}}) {
              py::dict g;
              g["t"] = array_1d(seg->grid_t);
              g["x"] = array_1d(seg->grid_x);
              g["y"] = array_1d(seg->grid_y);
              g["theta"] = array_1d(seg->grid_theta);
              f[name] = g;
            }
            fits.append(f);
          }
          d["fits"] = fits;
        },
        "fits: one per file (None where it failed), dicts of body: arrays t (s), x, y (m, centre), "
        "theta (rad, A to B, unwrapped), length (m, A-B), omega, sigma_omega (rad/s, local spin); "
        "flight_pre, flight_post: the fitted flights sampled over their spans, arrays t (s), x, y "
        "(m), theta (rad)");
}

/// `bounce synth-video`: a synthetic Tracker export of one bounce, tips as arrays.
void bind_synth_video(py::module_& m) {
  Command<app::BounceSynthVideoOptions> c(m, "synth_video",
      "A synthetic Tracker export of one bounce, tips A and B, with its truth (`tribolab bounce synth-video`).");
  c.declared(app::bounce_synth_video_fields());
  c.def(&app::bounce_synth_video,
        [](const app::BounceSynthVideoResult& r, py::dict& d) {
          for (const auto* t : {&r.video.tip_a, &r.video.tip_b}) {
            d[py::str("tip_" + t->name)] = point_columns(t->points);
          }
        },
        "tip_A, tip_B: dicts of arrays frame, t (s, file time), x, y (m, with noise)");
}

/// `bounce render`: a filmed throw, with its truth tracks as arrays.
void bind_render(py::module_& m) {
  Command<app::BounceRenderOptions> c(m, "render",
      "Films a simulated throw (flight, bounce, flight) to a video with its truth (`tribolab bounce render`).");
  c.declared(app::bounce_render_fields());
  c.def(&app::bounce_render,
        [](const app::BounceRenderResult& r, py::dict& d) {
          py::dict tracks;
          for (const auto& t : r.truth.tracks) {
            tracks[py::str(t.name)] = point_columns(t.points);
          }
          d["truth_tracks"] = tracks;
        },
        "truth_tracks: dict track name (ball, ball.A, ball.B) -> dict of arrays frame, t (s, video time), x, y (m)");
}

/// `bounce synth-table`: a synthetic bounce table as arrays.
void bind_synth_table(py::module_& m) {
  using analysis::BounceRow;
  Command<app::BounceSynthTableOptions> c(m, "synth_table",
      "A synthetic bounce table for `bounce fit` with known truth (`tribolab bounce synth-table`).");
  c.declared(app::bounce_synth_table_fields());
  c.def(&app::bounce_synth_table,
        [](const app::BounceSynthTableResult& r, py::dict& d) {
          d["table"] = columns(r.rows, field("theta_deg", &BounceRow::theta_deg), field("vx_in", &BounceRow::vx_in),
                               field("vy_in", &BounceRow::vy_in), field("omega_in", &BounceRow::omega_in),
                               field("vx_out", &BounceRow::vx_out), field("vy_out", &BounceRow::vy_out),
                               field("omega_out", &BounceRow::omega_out));
        },
        "table: dict of arrays theta_deg, vx_in, vy_in, omega_in, vx_out, vy_out, omega_out (deg, m/s, rad/s)");
}

/// `bounce fit`: the contact law fitted to a table, with the table and predictions as arrays.
void bind_fit(py::module_& m) {
  Command<app::BounceFitOptions> c(m, "fit",
      "The contact law (K, n, D or e, mu) fitted to a table of measured bounces (`tribolab bounce fit`).");
  c.declared(app::bounce_fit_fields());
  c.def(&app::bounce_fit,
        [](const app::BounceFitResult& r, py::dict& d) {
          using analysis::BounceRow;
          using analysis::BounceFitRow;
          py::dict t = columns(r.rows, field("theta_deg", &BounceRow::theta_deg), field("vx_in", &BounceRow::vx_in),
                               field("vy_in", &BounceRow::vy_in), field("omega_in", &BounceRow::omega_in),
                               field("vx_out", &BounceRow::vx_out), field("vy_out", &BounceRow::vy_out),
                               field("omega_out", &BounceRow::omega_out));
          const auto& f = r.fit.rows;
          t["vx_pred"] = column(f, &BounceFitRow::vx_pred);
          t["vy_pred"] = column(f, &BounceFitRow::vy_pred);
          t["omega_pred"] = column(f, &BounceFitRow::omega_pred);
          d["table"] = t;
        },
        "table: dict of arrays, the bounces as read (theta_deg, vx_in, vy_in, omega_in, vx_out, "
        "vy_out, omega_out; deg, m/s, rad/s) and the fitted law's predictions vx_pred, vy_pred, "
        "omega_pred");
}

/// `bounce merge`: joins a sweep's shard files.
void bind_merge(py::module_& m) {
  Command<app::BounceMergeOptions> c(m, "merge",
      "Joins the shard files of one sweep into the full map, exactly (`tribolab bounce merge`).");
  c.declared(app::bounce_merge_fields());
  c.def(&app::bounce_merge, [](const app::BounceMergeResult&, py::dict&) {}, "");
}

/// `bounce sweep`: the rebound map, as arrays shaped by the axes when no shard.
void bind_sweep(py::module_& m) {
  Command<app::BounceSweepOptions> c(m, "sweep",
      "The rebound over a grid of impact angle x spin (and speed, mu) (`tribolab bounce sweep`, "
      "the rugby-ball study's figure 53): the map as arrays shaped by the axes, resumable, in parallel.");
  c.declared(app::bounce_sweep_fields());
  c.def(+[](const app::BounceSweepOptions& o) {
          app::BounceSweepOptions with_map = o;
          with_map.return_map = o.shard.count == 1;  // a notebook wants the arrays; a shard is not the map
          if (!o.out.empty()) return app::bounce_sweep(with_map);
          if (o.shard.count != 1) throw InputError(::tribolab::field("out"), "a shard is kept only in its file: give out=");
          // No out=: the map is returned as arrays, so the CSV (which the sweep writes as it
          // goes) lives in a private temporary folder, removed afterwards even on an error.
          std::string dir = (std::filesystem::temp_directory_path() / "tribolab-sweep-XXXXXX").string();
          if (!::mkdtemp(dir.data())) throw InputError(::tribolab::field("out"), "cannot create a temporary folder for the map");
          struct Remove {
            std::string dir;
            ~Remove() {
              std::error_code ignored;
              std::filesystem::remove_all(dir, ignored);
            }
          } remove{dir};
          with_map.out = dir + "/map.csv";
          app::BounceSweepResult r = app::bounce_sweep(with_map);
          r.json["out"] = nullptr;  // nothing was kept
          return r;
        },
        [](const app::BounceSweepResult& r, py::dict& d) {
          if (!r.map) return;
          const app::SweepMap& m = *r.map;
          std::vector<py::ssize_t> shape;
          py::dict axes;
          for (std::size_t k = 0; k < m.axis_names.size(); ++k) {
            axes[py::str(m.axis_names[k])] = array_1d(m.axis_values[k]);
            shape.push_back(static_cast<py::ssize_t>(m.axis_values[k].size()));
          }
          py::dict maps;
          for (std::size_t j = 0; j < m.output_names.size(); ++j) {
            maps[py::str(m.output_names[j])] = array_1d(m.outputs[j]).attr("reshape")(py::tuple(py::cast(shape)));
          }
          d["axes"] = axes;
          d["map"] = maps;
        },
        "axes: dict of 1-D arrays, the values of each swept quantity (grid order); map: dict of "
        "arrays, one per output of a cell (e, vx_out, vy_out, omega_out, ...), shaped by the axes "
        "(the last axis fastest, as in the CSV); none for a shard (merge the shards, then read the file)");
}

}  // namespace

void bind_bounce(py::module_& m) {
  bind_contact_time(m);
  bind_simulate(m);
  bind_drop(m);
  bind_analyze(m);
  bind_synth_video(m);
  bind_render(m);
  bind_synth_table(m);
  bind_fit(m);
  bind_merge(m);
  bind_sweep(m);
}

}  // namespace tribolab::python
