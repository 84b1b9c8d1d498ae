// tribolab._tribolab.incline: the `tribolab incline` commands of the application layer
// (src/app/incline_*.hpp) through the mechanism of bind.hpp.
#include "bind.hpp"

#include "app/incline/incline_analysis.hpp"
#include "app/incline/incline_analyze.hpp"
#include "app/incline/incline_forward.hpp"
#include "app/incline/incline_render.hpp"
#include "app/incline/incline_stop.hpp"

namespace tribolab::python {
namespace {

using incline::State;

/// A trajectory in seed 000's frame (x across the slope, y up it).
py::dict states(const std::vector<State>& v) {
  return columns(v, field("t", &State::t), field("x", &State::x), field("y", &State::y),
                 field("vx", &State::vx), field("vy", &State::vy), field("ax", &State::ax),
                 field("ay", &State::ay));
}

constexpr const char* kInclineStates =
    "t (s), x, y (m; x across the slope, y up it), vx, vy (m/s), ax, ay (m/s^2)";

}  // namespace

void bind_incline(py::module_& m) {
  {
    Command<app::InclinePredictOptions> c(m, "predict",
        "A launch across the incline in closed form (`tribolab incline predict`, model B, the incline study's "
        "eqs 7-9 (七-九)): regime, stop point and time, accelerations.");
    c.declared(app::incline_predict_fields());
    c.def(&app::incline_predict,
          [](const app::InclinePredictResult& r, py::dict& d) { d["trajectory"] = states(r.trajectory); },
          std::string("trajectory: dict of arrays ") + kInclineStates + ", 401 samples (none if the duration is infinite)");
  }
  {
    Command<app::InclineSimulateOptions> c(m, "simulate",
        "A slide across the incline, model B or A, closed form or numeric (`tribolab incline simulate`).");
    c.declared(app::incline_simulate_fields());
    c.def(&app::incline_simulate,
          [](const app::InclineSimulateResult& r, py::dict& d) { d["trajectory"] = states(r.trajectory); },
          std::string("trajectory: dict of arrays ") + kInclineStates);
  }
  {
    Command<app::InclineFamiliesOptions> c(m, "families",
        "Curves for several values of one launch parameter (`tribolab incline families`).");
    c.declared(app::incline_families_fields());
    c.def(&app::incline_families,
          [](const app::InclineFamiliesResult& r, py::dict& d) {
            const auto& members = r.family.members;
            d["curves"] = columns_2d(members, [](const incline::FamilyMember& mb) -> const auto& { return mb.trajectory; },
                                     {std::pair{"t", &State::t}, std::pair{"x", &State::x}, std::pair{"y", &State::y},
                                      std::pair{"vx", &State::vx}, std::pair{"vy", &State::vy},
                                      std::pair{"ax", &State::ax}, std::pair{"ay", &State::ay}});
          },
          std::string("curves: dict of 2-D arrays (len(values), samples) ") + kInclineStates);
  }
  {
    Command<app::InclineMuFromStopOptions> c(m, "mu_from_stop",
        "The friction coefficient from the stopping point alone (`tribolab incline mu-from-stop`, "
        "incline study eq 10A (十A)), with its uncertainty and the best-angle advice.");
    c.declared(app::incline_mu_from_stop_fields());
    c.def(&app::incline_mu_from_stop, [](const app::InclineMuFromStopResult&, py::dict&) {}, "");
  }
  {
    Command<app::InclineNormalFrictionTestOptions> c(m, "normal_friction_test",
        "cos theta_c against tan phi over runs at several angles (`tribolab incline normal-friction-test`, the "
        "incline study's figure 3-2 (圖三-2), eq c): a line through the origin with slope 1/mu without normal friction.");
    c.declared(app::incline_normal_friction_test_fields());
    c.def(&app::incline_normal_friction_test,
          [](const app::InclineNormalFrictionTestResult& r, py::dict& d) {
            py::dict p;
            p["tan_phi"] = array_1d(r.tan_phi);
            p["cos_theta_c"] = array_1d(r.cos_theta_c);
            d["points"] = p;
          },
          "points: dict of arrays tan_phi, cos_theta_c (one per run)");
  }
  {
    Command<app::InclineSynthOptions> c(m, "synth",
        "A synthetic tracked run from the simulators, with noise (`tribolab incline synth`): the file a "
        "tracked disc would give, and the truth beside it.");
    c.declared(app::incline_synth_fields());
    c.def(&app::incline_synth,
          [](const app::InclineSynthResult& r, py::dict& d) {
            d["track_points"] = point_columns(r.run.track.points);
            d["truth"] = states(r.run.truth);
          },
          std::string("track_points: dict of arrays frame, t (s, file time), x, y (m, with noise); truth: dict of "
                      "arrays ") + kInclineStates + " (noise-free, at each point)");
  }
  {
    Command<app::InclineRenderOptions> c(m, "render",
        "A disc launched across the incline (model B) filmed face-on to a video with its true path "
        "(`tribolab incline render`).");
    c.declared(app::incline_render_fields());
    c.def(&app::incline_render,
          [](const app::InclineRenderResult& r, py::dict& d) { d["truth_track"] = point_columns(r.truth.tracks.front().points); },
          "truth_track: dict of arrays frame, t (s, video time), x, y (m, origin at the launch point) of the disc's centre");
  }
  {
    Command<app::InclineAnalyzeOptions> c(m, "analyze",
        "Models B and A fitted to tracked runs of the disc (`tribolab incline analyze`, the incline study's "
        "eqs a-c): mu, v0, the normal-friction test with its p-value; several files: a series "
        "with a summary.");
    c.declared(app::incline_analyze_fields());
    TRIBOLAB_OPT(c, series.threads);  // a notebook may limit the cores; the command line uses them all
    c.def(&app::incline_analyze,
          [](const app::InclineAnalyzeResult& r, py::dict& d) {
            py::list fits;
            for (const auto& run : r.runs) {
              if (!run.analysis) {
                fits.append(py::none());
                continue;
              }
              const auto& a = *run.analysis;
              py::dict f;
              f["data"] = columns(a.data, field("t", &track::TrackPoint::t), field("x", &track::TrackPoint::x),
                                  field("y", &track::TrackPoint::y));
              f["model_b"] = states(a.model_b_fine);
              f["model_a"] = states(a.model_a_fine);
              f["residual_x_b"] = array_1d(a.residual_x_b);
              f["residual_y_b"] = array_1d(a.residual_y_b);
              fits.append(f);
            }
            d["fits"] = fits;
          },
          std::string("fits: one per file (None where it failed), dicts of the measured points "
                      "data (t, x, y; s, m), the fitted models model_b and model_a on a fine grid (") +
              kInclineStates + "), residual_x_b, residual_y_b (m)");
  }
  {
    Command<app::InclineMuFromSlideOptions> c(m, "mu_from_slide",
        "The friction coefficient from a straight slide down the incline (`tribolab incline "
        "mu-from-slide`, the incline study's eq a).");
    c.declared(app::incline_mu_from_slide_fields());
    TRIBOLAB_OPT(c, series.threads);  // a notebook may limit the cores; the command line uses them all
    c.def(&app::incline_mu_from_slide,
          [](const app::InclineMuFromSlideResult& r, py::dict& d) {
            py::list slides;
            for (const auto& run : r.runs) {
              if (!run.result) {
                slides.append(py::none());
                continue;
              }
              py::dict f;
              f["t"] = array_1d(run.result->t);
              f["s"] = array_1d(run.result->s);
              f["v_t"] = array_1d(run.result->v_t);
              f["v"] = array_1d(run.result->v);
              slides.append(f);
            }
            d["slides"] = slides;
          },
          "slides: one per file (None where it failed), dicts of arrays t (s), s (m, along the "
          "path), v_t, v (m/s, speeds along the path)");
  }
}

}  // namespace tribolab::python
