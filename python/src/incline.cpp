// tribolab._tribolab.incline: the `tribolab incline` commands of the application layer
// (src/app/incline_*.hpp) through the mechanism of bind.hpp.
#include "bind.hpp"

#include "app/incline_forward.hpp"
#include "app/incline_stop.hpp"

namespace tribolab::python {
namespace {

using incline::State;

/// A trajectory in seed 000's frame (x across the slope, y up it).
py::dict states(const std::vector<State>& v) {
  return columns(v, field("t", &State::t), field("x", &State::x), field("y", &State::y),
                 field("vx", &State::vx), field("vy", &State::vy), field("ax", &State::ax),
                 field("ay", &State::ay));
}

/// --mu --phi-deg --v0 --g --mu-static.
template <class C>
void launch_options(C& c) {
  TRIBOLAB_OPT(c, launch.mu);
  TRIBOLAB_OPT(c, launch.phi_deg);
  TRIBOLAB_OPT(c, launch.v0);
  TRIBOLAB_OPT(c, launch.g);
  TRIBOLAB_OPT(c, launch.mu_static);
}

constexpr const char* kStates =
    "t (s), x, y (m; x across the slope, y up it), vx, vy (m/s), ax, ay (m/s^2)";

}  // namespace

void bind_incline(py::module_& m) {
  {
    Command<app::InclinePredictOptions> c(m, "predict",
        "A launch across the incline in closed form (`tribolab incline predict`, model B, seed 000 "
        "eqs 七-九): regime, stop point and time, accelerations.");
    launch_options(c);
    TRIBOLAB_OPT(c, report);
    c.def(&app::incline_predict,
          [](const app::InclinePredictResult& r, py::dict& d) { d["trajectory"] = states(r.trajectory); },
          std::string("trajectory: dict of arrays ") + kStates + ", 401 samples (none if the duration is infinite)");
  }
  {
    Command<app::InclineSimulateOptions> c(m, "simulate",
        "A slide across the incline, model B or A, closed form or numeric (`tribolab incline simulate`).");
    launch_options(c);
    TRIBOLAB_OPT(c, model);
    TRIBOLAB_OPT(c, normal_accel);
    TRIBOLAB_OPT(c, method);
    TRIBOLAB_OPT(c, dt);
    TRIBOLAB_OPT(c, t_end);
    TRIBOLAB_OPT(c, out);
    TRIBOLAB_OPT(c, report);
    c.def(&app::incline_simulate,
          [](const app::InclineSimulateResult& r, py::dict& d) { d["trajectory"] = states(r.trajectory); },
          std::string("trajectory: dict of arrays ") + kStates);
  }
  {
    Command<app::InclineFamiliesOptions> c(m, "families",
        "Curves for several values of one launch parameter (`tribolab incline families`).");
    launch_options(c);
    TRIBOLAB_OPT(c, vary);
    TRIBOLAB_OPT(c, values);
    TRIBOLAB_OPT(c, samples);
    TRIBOLAB_OPT(c, t_end);
    TRIBOLAB_OPT(c, out);
    TRIBOLAB_OPT(c, report);
    c.def(&app::incline_families,
          [](const app::InclineFamiliesResult& r, py::dict& d) {
            const auto& members = r.family.members;
            d["curves"] = columns_2d(members, [](const incline::FamilyMember& mb) -> const auto& { return mb.trajectory; },
                                     {std::pair{"t", &State::t}, std::pair{"x", &State::x}, std::pair{"y", &State::y},
                                      std::pair{"vx", &State::vx}, std::pair{"vy", &State::vy},
                                      std::pair{"ax", &State::ax}, std::pair{"ay", &State::ay}});
          },
          std::string("curves: dict of 2-D arrays (len(values), samples) ") + kStates);
  }
  {
    Command<app::InclineMuFromStopOptions> c(m, "mu_from_stop",
        "The friction coefficient from the stopping point alone (`tribolab incline mu-from-stop`, "
        "seed 000 eq 十A), with its uncertainty and the best-angle advice.");
    TRIBOLAB_OPT(c, phi_deg);
    TRIBOLAB_OPT(c, x_stop);
    TRIBOLAB_OPT(c, y_stop);
    TRIBOLAB_OPT(c, sigma_phi_deg);
    TRIBOLAB_OPT(c, sigma_pos);
    TRIBOLAB_OPT(c, g);
    TRIBOLAB_OPT(c, plate_size);
    TRIBOLAB_OPT(c, report);
    c.def(&app::incline_mu_from_stop, [](const app::InclineMuFromStopResult&, py::dict&) {}, "");
  }
}

}  // namespace tribolab::python
