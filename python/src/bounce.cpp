// tribolab._tribolab.bounce: the `tribolab bounce` commands of the application layer
// (src/app/bounce_*.hpp) through the mechanism of bind.hpp.
#include "bind.hpp"

#include "app/bounce_simulate.hpp"

namespace tribolab::python {
namespace {

/// --a --b --mass --inertia (the seed's rugby ball by default).
template <class C>
void ball_options(C& c) {
  TRIBOLAB_OPT(c, ball.ball.a);
  TRIBOLAB_OPT(c, ball.ball.b);
  TRIBOLAB_OPT(c, ball.ball.mass);
  TRIBOLAB_OPT(c, ball.ball.inertia);
}

/// --model --K --n --D --restitution --friction --mu --slip-scale --k-t --c-t --tol.
template <class C>
void law_options(C& c) {
  TRIBOLAB_OPT(c, law.model);
  TRIBOLAB_OPT(c, law.K);
  TRIBOLAB_OPT(c, law.n);
  TRIBOLAB_OPT(c, law.D);
  TRIBOLAB_OPT(c, law.restitution);
  TRIBOLAB_OPT(c, law.friction);
  TRIBOLAB_OPT(c, law.mu);
  TRIBOLAB_OPT(c, law.slip_scale);
  TRIBOLAB_OPT(c, law.k_t);
  TRIBOLAB_OPT(c, law.c_t);
  TRIBOLAB_OPT(c, law.tol);
}

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

constexpr const char* kStates = "t (s), x, y (m, centre), theta (rad), vx, vy (m/s), omega (rad/s)";

}  // namespace

void bind_bounce(py::module_& m) {
  {
    Command<app::BounceContactTimeOptions> c(m, "contact_time",
        "First contact of a ball released at an apex (`tribolab bounce contact-time`, seed 001 "
        "table 4): time, collision angle and state at the touch.");
    ball_options(c);
    TRIBOLAB_OPT(c, height);
    TRIBOLAB_OPT(c, omega);
    TRIBOLAB_OPT(c, theta_deg);
    TRIBOLAB_OPT(c, direction);
    TRIBOLAB_OPT(c, g);
    TRIBOLAB_OPT(c, report);
    c.def(&app::bounce_contact_time,
          [](const app::BounceContactTimeResult& r, py::dict& d) {
            py::dict f = body_states(r.samples);
            f["gap"] = of_each(r.samples, [](const app::FlightSample& s) { return s.gap; });
            d["flight"] = f;
          },
          std::string("flight: dict of arrays ") + kStates + ", gap (m, lowest point above the floor)");
  }
  {
    using bounce::ContactSample;
    Command<app::BounceSimulateOptions> c(m, "simulate",
        "One impact from first touch until the ball flies free (`tribolab bounce simulate`, seed "
        "001 exp. 4): restitution, spin change, contact time.");
    ball_options(c);
    law_options(c);
    TRIBOLAB_OPT(c, vx);
    TRIBOLAB_OPT(c, vy);
    TRIBOLAB_OPT(c, omega);
    TRIBOLAB_OPT(c, theta_deg);
    TRIBOLAB_OPT(c, g);
    TRIBOLAB_OPT(c, history);
    TRIBOLAB_OPT(c, report);
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
          std::string("contact: dict of arrays ") + kStates +
              ", d (m, penetration), d_dot (m/s), N, f (N), v_t (m/s, slip)");
  }
  {
    Command<app::BounceDropOptions> c(m, "drop",
        "Release, flight and several bounces until rest (`tribolab bounce drop`).");
    ball_options(c);
    law_options(c);
    TRIBOLAB_OPT(c, height);
    TRIBOLAB_OPT(c, theta_deg);
    TRIBOLAB_OPT(c, omega);
    TRIBOLAB_OPT(c, vx);
    TRIBOLAB_OPT(c, vy);
    TRIBOLAB_OPT(c, bounces);
    TRIBOLAB_OPT(c, rest_height);
    TRIBOLAB_OPT(c, g);
    TRIBOLAB_OPT(c, trajectory);
    TRIBOLAB_OPT(c, sample_dt);
    TRIBOLAB_OPT(c, report);
    TRIBOLAB_OPT(c, keep_trajectory);
    c.def(&app::bounce_drop,
          [](const app::BounceDropResult& r, py::dict& d) { d["samples"] = body_states(r.trajectory); },
          std::string("samples: dict of arrays ") + kStates +
              " (empty unless trajectory, report or keep_trajectory)");
  }
}

}  // namespace tribolab::python
