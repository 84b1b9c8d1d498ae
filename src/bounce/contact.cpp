#include "bounce/contact.hpp"

#include "numerics/cpu_dispatch.hpp"
#include "numerics/error.hpp"
#include "numerics/message_number.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace tribolab::bounce {

std::string ContactOptions::validate() const {
  if (!std::isfinite(g) || !(g >= 0)) return "g: gravitational acceleration must be >= 0";
  if (auto e = integrator.validate(); !e.empty()) return e;
  if (!std::isfinite(max_duration) || !(max_duration > 0)) return "max contact duration must be positive";
  if (max_phases == 0) return "max phases must be positive";
  return {};
}

ContactOptions contact_options_with_tolerance(double tol) {
  ContactOptions o;
  o.integrator.abs_tol = tol;
  o.integrator.rel_tol = tol;
  return o;
}

std::string_view to_string(PhaseKind k) {
  switch (k) {
    case PhaseKind::slip_positive: return "slip+";
    case PhaseKind::slip_negative: return "slip-";
    case PhaseKind::stick: return "stick";
    case PhaseKind::smooth: return "smooth";
  }
  return "?";
}

std::string_view to_string(ContactStatus s) {
  switch (s) {
    case ContactStatus::separated: return "separated";
    case ContactStatus::max_duration: return "max_duration";
    case ContactStatus::failed: return "failed";
  }
  return "?";
}

KineticEnergy kinetic_energy(const Ball& ball, const BodyState& s) {
  return {0.5 * ball.mass * s.vx * s.vx, 0.5 * ball.mass * s.vy * s.vy,
          0.5 * ball.inertia * s.omega * s.omega};
}

namespace {

// State: x, y, theta, vx, vy, omega, u (tangential spring elongation), W_n, W_f, and the
// support point's depth Y(theta) and slope Y'(theta), integrated along with theta
// (docs/theory.md#bounce-integrator, "The support point as state").
constexpr std::size_t kN = 11;
using State = Vec<kN>;
enum : std::size_t { iX, iY, iTh, iVx, iVy, iW, iU, iWn, iWf, iSY, iSYp };

// Y and Y' are held to 1/kSupportErrorWeight of the tolerances: the penetration d = Y - y of a
// grazing contact is small for a long time, and an error of Y as large as y's moved its
// lift-off (largest error over the seed's map at tol 1e-6, exact Coulomb: 1.5e-5 m/s with Y
// computed from theta; 7.1e-5 with the weight 1, 1.4e-5 with 100, 5.6e-6 with 300 for 7 % more
// right-hand-side calls; docs/benchmarks.md#issue-15-fifth-pass-the-support-point-as-state).
// Y and Y' are smooth in time, so this costs few steps.
constexpr double kSupportErrorWeight = 300;
constexpr State kErrorWeights = {1, 1, 1, 1, 1, 1, 1, 1, 1, kSupportErrorWeight, kSupportErrorWeight};

enum class Mode { free, coulomb_slip, coulomb_stick, regularized, spring_elastic, spring_slip };

struct Eval {
  Support sp;
  double d = 0, d_dot = 0, v_t = 0;
  double N = 0, elastic = 0;  // normal force and its elastic part K d^n, N
  double f = 0;       // tangential force, N
  double f_req = 0;   // Coulomb: force that keeps v_t = 0, N
  double ax = 0, ay = 0, alpha = 0;
};

struct Model {
  const Ball& ball;
  const NormalLaw& law;
  const FrictionModel& fr;
  double g;
  double inv_m, inv_I;
  double inv_vs = 1 / fr.slip_scale;  // 1 / v_s: a product instead of a division on every call
  double a2 = ball.a * ball.a, b2 = ball.b * ball.b, a2_b2 = a2 * b2;

  // The support point from the state's Y and Y' (geometry.cpp's support() without sin, cos
  // and sqrt: this runs on every right-hand-side call); Y'' = a^2 b^2 / Y^3 - Y.
  Support support_point(const State& x) const {
    Support sp;
    sp.Y = x[iSY];
    const double inv_Y = 1 / sp.Y;
    sp.dY = x[iSYp];
    sp.X = -sp.dY;
    sp.d2Y = a2_b2 * (inv_Y * inv_Y * inv_Y) - sp.Y;
    return sp;
  }

  Eval eval(const State& x, Mode mode, double s) const {
    Eval e;
    e.sp = support_point(x);
    const double w = x[iW];
    e.d = e.sp.Y - x[iY];
    e.d_dot = -(x[iVy] + w * e.sp.X);
    e.v_t = x[iVx] + w * e.sp.Y;
    // The partial derivatives of N are left out (only force_rate needs them): with eval
    // inlined (normal_law.hpp) their division is not computed.
    const NormalLaw::Force nf = law.eval(e.d, e.d_dot);
    e.N = nf.N;
    e.elastic = nf.elastic;
    const double N = e.N;
    const double mu = fr.mu;
    switch (mode) {
      case Mode::free: e.f = 0; break;
      case Mode::coulomb_slip:
      case Mode::spring_slip: e.f = -s * mu * N; break;
      case Mode::coulomb_stick: e.f = required_force(e.sp, w, N); break;
      case Mode::regularized: e.f = -mu * N * std::tanh(e.v_t * inv_vs); break;
      case Mode::spring_elastic: e.f = -(fr.k_t * x[iU] + fr.c_t * e.v_t); break;
    }
    if (mode == Mode::coulomb_stick) e.f_req = required_force(e.sp, w, N);
    e.ax = e.f * inv_m;
    e.ay = N * inv_m - g;
    e.alpha = (e.sp.X * N + e.sp.Y * e.f) * inv_I;
    return e;
  }

  // Tangential force that keeps v_t = vx + omega Y constant: d/dt v_t = f/m + alpha Y +
  // omega^2 Y' = 0 with alpha = (X N + Y f)/I and Y' = -X (docs/theory.md#bounce-friction).
  double required_force(const Support& sp, double w, double N) const {
    return sp.X * (w * w - sp.Y * N * inv_I) / (inv_m + sp.Y * sp.Y * inv_I);
  }

  // Rate of change of N along the motion (clamped parts give 0).
  double force_rate(const Eval& e, double w) const {
    const double d_ddot = -(e.ay + e.alpha * e.sp.X - w * w * e.sp.d2Y);
    const NormalLaw::Force nf = law.eval(e.d, e.d_dot);
    return nf.dN_dd * e.d_dot + nf.dN_ddot * d_ddot;
  }

  // Acceleration of the slip velocity.
  double slip_accel(const Eval& e, double w) const { return e.ax + e.alpha * e.sp.Y + w * w * e.sp.dY; }
};

PhaseKind kind_of(Mode m, double s) {
  switch (m) {
    case Mode::coulomb_slip:
    case Mode::spring_slip: return s > 0 ? PhaseKind::slip_positive : PhaseKind::slip_negative;
    case Mode::coulomb_stick:
    case Mode::spring_elastic: return PhaseKind::stick;
    default: return PhaseKind::smooth;
  }
}

double sign_of(double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }

/// Running peak of N(t) from samples, refined by the parabola through a local maximum.
struct PeakTracker {
  double t0 = 0, n0 = -1, t1 = 0, n1 = -1;
  double peak = 0, t_peak = 0;
  void add(double t, double n) {
    if (n1 >= 0 && t <= t1) return;  // duplicate sample at a phase boundary
    if (n > peak) {
      peak = n;
      t_peak = t;
    }
    if (n0 >= 0 && n1 >= n0 && n1 >= n && n1 > 0) {
      const double h0 = t0 - t1, h2 = t - t1;
      const double d0 = (n0 - n1) / h0, d2 = (n - n1) / h2;
      const double c = (d2 - d0) / (h2 - h0);
      const double b = d0 - c * h0;
      if (c < 0) {
        const double tau = -b / (2 * c);
        if (tau >= h0 && tau <= h2) {
          const double v = n1 - b * b / (4 * c);
          if (v > peak) {
            peak = v;
            t_peak = t1 + tau;
          }
        }
      }
    }
    t0 = t1;
    n0 = n1;
    t1 = t;
    n1 = n;
  }
};

/// Throws InputError unless the ball, the friction model, the options, the resolved law and
/// the incoming state are valid (docs/theory.md#bounce-contact).
void validate_contact(const Ball& ball, const NormalLaw& law, const FrictionModel& friction,
                      const BodyState& touch, const ContactOptions& options) {
  if (auto e = ball.validate(); !e.empty()) throw InputError(e);
  if (auto e = friction.validate(); !e.empty()) throw InputError(e);
  if (auto e = options.validate(); !e.empty()) throw InputError(e);
  if (!(law.K > 0) || !(law.n >= 1) || !(law.D >= 0) || !std::isfinite(law.K + law.n + law.D))
    throw InputError("normal law: need K > 0, n >= 1, D >= 0");
  for (double v : {touch.x, touch.theta, touch.vx, touch.vy, touch.omega})
    require_finite(v, "incoming state");
}

/// The state at first touch (y = Y(theta): gap 0) and the contact point's velocity there
/// into r.in, r.v_in_normal, r.v_t_in; throws InputError unless the contact point approaches
/// the floor (docs/theory.md#bounce-contact).
State state_at_touch(const Ball& ball, const BodyState& touch, ContactResult& r) {
  r.in = touch;
  r.in.y = support(ball, touch.theta).Y;
  const PointVelocity pv = contact_point_velocity(ball, touch.theta, touch.vx, touch.vy, touch.omega);
  r.v_in_normal = -pv.vy;
  r.v_t_in = pv.vx;
  if (!(pv.vy < 0)) {
    throw InputError("incoming state", "the contact point must approach the floor at first touch "
                                       "(vy + omega X = " + message_number(pv.vy) + " m/s, need < 0)");
  }
  State x{};
  x[iX] = r.in.x;
  x[iY] = r.in.y;
  x[iTh] = r.in.theta;
  const Support sp = support(ball, r.in.theta);
  x[iSY] = sp.Y;
  x[iSYp] = sp.dY;
  x[iVx] = r.in.vx;
  x[iVy] = r.in.vy;
  x[iW] = r.in.omega;
  return x;
}

/// The friction regime of one smooth phase (docs/theory.md#bounce-friction): its mode and slip
/// direction s (+-1; 0 unset).
struct FrictionPhase {
  Mode mode = Mode::free;
  double s = 0;
};

/// Coulomb with v_t = 0 (docs/theory.md#bounce-friction): stick if the required force fits
/// in the cone mu N, else slip against it. Stick keeps the previous s (`before`).
FrictionPhase coulomb_at_rest(const Model& model, const FrictionModel& friction, const State& x,
                              FrictionPhase before) {
  const Eval e = model.eval(x, Mode::coulomb_stick, 0);
  if (std::abs(e.f_req) <= friction.mu * e.N) return {Mode::coulomb_stick, before.s};
  return {Mode::coulomb_slip, -sign_of(e.f_req)};
}

/// The friction regime at first touch (docs/theory.md#bounce-friction, "phase selection");
/// for the spring model starting in slip, puts the elongation x[iU] on the cap.
FrictionPhase initial_friction_phase(const Model& model, const NormalLaw& law, const FrictionModel& friction,
                                     double v_t_in, State& x) {
  if (friction.mu == 0) return {Mode::free, 0};
  if (friction.kind == FrictionKind::regularized) return {Mode::regularized, 0};
  if (friction.kind == FrictionKind::coulomb) {
    if (v_t_in != 0) return {Mode::coulomb_slip, sign_of(v_t_in)};
    return coulomb_at_rest(model, friction, x, {Mode::free, 0});
  }
  // Decide with the load just after touch, N(0+): a Hooke dashpot jumps to D d_dot there,
  // and a spring put on that cap would gain energy from nothing.
  const Eval e = model.eval(x, Mode::spring_elastic, 0);
  const double N0 = law.eval(std::numeric_limits<double>::min(), e.d_dot).N;
  const double trial = friction.k_t * x[iU] + friction.c_t * e.v_t;
  if (friction.mu * N0 - std::abs(trial) > 0 || e.v_t == 0) return {Mode::spring_elastic, 0};
  const double s = trial != 0 ? sign_of(trial) : sign_of(e.v_t);
  x[iU] = (s * friction.mu * e.N - friction.c_t * e.v_t) / friction.k_t;
  return {Mode::spring_slip, s};
}

/// The first trial step (docs/theory.md#bounce-integrator, "First step"): the contact's time
/// scale tau = (m / (K v_in^(n-1)))^(1/(n+1)) (the time in which the law's force stops the
/// ball: ~1/3 of the contact duration) times tol^(1/5), the 5th-order step of that
/// tolerance: e.g. 3.5e-4 s for the seed's law at 4 m/s and tol 1e-6; initial_step when
/// that is not a positive number.
double first_step(const Ball& ball, const NormalLaw& law, double v_in_normal, const PhaseOptions& integrator) {
  double h = integrator.initial_step;
  const double tau = std::pow(ball.mass / (law.K * std::pow(v_in_normal, law.n - 1)), 1 / (law.n + 1));
  const double h_scale = tau * std::pow(integrator.abs_tol, 0.2);
  if (std::isfinite(h_scale) && h_scale > 0) h = h_scale;
  return h;
}

/// The equations of motion of one smooth phase for integrate_phase (docs/theory.md#bounce-contact):
/// the right-hand side, the guards (separation d; the friction regime's end) with their
/// rates, and the observer (peaks, history). Allocation-free; inlined into the phase loop.
struct PhaseSystem {
  const Model& model;
  const FrictionModel& friction;
  std::vector<ContactSample>* history;
  FrictionPhase cur;  ///< the regime being integrated
  PeakTracker peak;   ///< of N
  PeakTracker peak_d; ///< of the penetration d

  // The integrator asks for the same state three times per accepted step (the FSAL rhs
  // at the step end, the guards there, the observer): the guards and the observer reuse the
  // last evaluation when state and mode are bitwise the same (eval is a pure function of them).
  struct EvalCache {
    State x{};
    Mode mode = Mode::free;
    double s = 0;
    Eval e;
    bool valid = false;
  } cache;

  // Bitwise equality of two doubles (NaN of the same bits equal, +0 and -0 not), inline:
  // a memcmp call here took ~8 % of the solver's time (perf, docs/benchmarks.md#issue-15),
  // and the states of successive stages already differ in their first component.
  static bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
  }
  bool cached(const State& st) const {
    if (!(cache.valid && cache.mode == cur.mode && same_bits(cache.s, cur.s))) return false;
    for (std::size_t i = 0; i < kN; ++i)
      if (!same_bits(cache.x[i], st[i])) return false;
    return true;
  }

  const Eval& eval_at(const State& st) {
    if (!cached(st)) {
      cache.e = model.eval(st, cur.mode, cur.s);
      cache.x = st;
      cache.mode = cur.mode;
      cache.s = cur.s;
      cache.valid = true;
    }
    return cache.e;
  }

  // The right-hand side evaluates into a local and then fills the cache: reading the
  // evaluation back from the cache put a store and a load on the chain from one stage to the
  // next (7 % of the solver's time, docs/benchmarks.md, "Issue 15, sixth pass"); a stage state
  // is new anyway, so the cache is not looked at here.
  void rhs(const State& st, State& dx) {
    const Eval e = model.eval(st, cur.mode, cur.s);
    cache.e = e;
    cache.x = st;
    cache.mode = cur.mode;
    cache.s = cur.s;
    cache.valid = true;
    dx[iX] = st[iVx];
    dx[iY] = st[iVy];
    dx[iTh] = st[iW];
    dx[iVx] = e.ax;
    dx[iVy] = e.ay;
    dx[iW] = e.alpha;
    dx[iU] = cur.mode == Mode::spring_elastic ? e.v_t : 0.0;
    dx[iWn] = (e.N - e.elastic) * e.d_dot;
    dx[iWf] = -e.f * e.v_t;
    dx[iSY] = st[iW] * e.sp.dY;
    dx[iSYp] = st[iW] * e.sp.d2Y;
  }

  // Guards and their rates (NaN = not supplied): the rates of the separation guard d and
  // of the slip guard let the integrator find a brief dip below zero inside one step.
  void guards(const State& st, std::array<double, 2>& gv, std::array<double, 2>& rate) {
    constexpr double kNoRate = std::numeric_limits<double>::quiet_NaN();
    const Eval& e = eval_at(st);
    gv[0] = e.d;  // separation
    rate[0] = e.d_dot;
    rate[1] = kNoRate;
    const double muN = friction.mu * e.N;
    switch (cur.mode) {
      case Mode::coulomb_slip:
        gv[1] = cur.s * e.v_t;
        rate[1] = cur.s * model.slip_accel(e, st[iW]);
        break;
      case Mode::coulomb_stick: gv[1] = muN - std::abs(e.f_req); break;
      case Mode::spring_elastic:
        gv[1] = muN - std::abs(friction.k_t * st[iU] + friction.c_t * e.v_t);
        break;
      case Mode::spring_slip:
        gv[1] = cur.s * (friction.k_t * e.v_t + friction.c_t * model.slip_accel(e, st[iW])) -
                friction.mu * model.force_rate(e, st[iW]);
        break;
      default: gv[1] = 1.0; break;
    }
  }

  void observe(double tt, const State& st) {
    const Eval& e = eval_at(st);
    peak.add(tt, e.N);
    peak_d.add(tt, std::max(e.d, 0.0));
    if (history) {
      ContactSample smp;
      smp.t = tt;
      smp.state = {st[iX], st[iY], st[iTh], st[iVx], st[iVy], st[iW]};
      smp.d = e.d;
      smp.d_dot = e.d_dot;
      smp.N = e.N;
      smp.f = e.f;
      smp.v_t = e.v_t;
      smp.phase = kind_of(cur.mode, cur.s);
      history->push_back(smp);
    }
  }
};

/// The friction regime after the friction guard of `cur` reached zero at x
/// (docs/theory.md#bounce-friction, the events of each model); may put x on the new
/// regime's constraint (v_t = 0 for Coulomb stick, u on the cap for spring slip).
FrictionPhase next_friction_phase(const Model& model, const FrictionModel& friction, FrictionPhase cur, State& x) {
  const Eval e = model.eval(x, cur.mode, cur.s);
  FrictionPhase next = cur;
  switch (cur.mode) {
    case Mode::coulomb_slip:
      x[iVx] = -x[iW] * e.sp.Y;  // v_t = 0 exactly (the event is located to rounding)
      next = coulomb_at_rest(model, friction, x, cur);
      if (next.mode == Mode::coulomb_slip && next.s == cur.s) next.s = -cur.s;  // must reverse
      break;
    case Mode::coulomb_stick:
      next.mode = Mode::coulomb_slip;
      next.s = -sign_of(e.f_req);
      if (next.s == 0) next.s = 1;
      break;
    case Mode::spring_elastic: {
      const double trial = friction.k_t * x[iU] + friction.c_t * e.v_t;
      next.mode = Mode::spring_slip;
      // The slip goes the way the trial force points. When it is zero to rounding (no
      // load: N clamped to 0, cap 0), the way it is about to point: its rate
      // k_t v_t + c_t a_t, or failing that the slip velocity.
      const double scale = friction.k_t * std::abs(x[iU]) + friction.c_t * std::abs(e.v_t);
      if (std::abs(trial) > 1e-9 * scale && trial != 0) {
        next.s = sign_of(trial);
      } else {
        const double rate = friction.k_t * e.v_t + friction.c_t * model.slip_accel(e, x[iW]);
        next.s = rate != 0 ? sign_of(rate) : (e.v_t != 0 ? sign_of(e.v_t) : 1.0);
      }
      break;
    }
    case Mode::spring_slip:
      next.mode = Mode::spring_elastic;
      x[iU] = (cur.s * friction.mu * e.N - friction.c_t * e.v_t) / friction.k_t;
      break;
    default: break;
  }
  return next;
}

/// How a phase that ended on `end` ends the contact (docs/theory.md#bounce-contact): true (and
/// r.status, r.message set) at separation (guard 0: d = 0), at max_duration or on an
/// integrator failure; false at the friction guard (a stick/slip change follows).
bool contact_ends(const PhaseEnd<kN>& end, ContactResult& r) {
  switch (end.status) {
    case PhaseStatus::reached_end:
      r.status = ContactStatus::max_duration;
      r.message = "still in contact after max_duration";
      return true;
    case PhaseStatus::max_steps:
    case PhaseStatus::non_finite:
    case PhaseStatus::step_underflow:
      r.status = ContactStatus::failed;
      r.message = end.status == PhaseStatus::max_steps ? "integrator step budget exhausted"
                                                       : "integrator failed (non-finite state or step underflow)";
      return true;
    case PhaseStatus::guard: break;
  }
  if (end.guard == 0) {
    r.status = ContactStatus::separated;
    r.message = "separated";
    return true;
  }
  return false;
}

/// The outgoing state at time t and what follows from it (docs/theory.md#bounce-contact):
/// e, peaks, impulses from momentum, energies and the energy balance's residual.
void finish_contact(const Ball& ball, const NormalLaw& law, const ContactOptions& options, const State& x,
                    double t, const PhaseSystem& sys, ContactResult& r) {
  r.out = {x[iX], x[iY], x[iTh], x[iVx], x[iVy], x[iW]};
  r.contact_duration = t;
  r.restitution = r.in.vy != 0 ? -r.out.vy / r.in.vy : std::numeric_limits<double>::quiet_NaN();
  r.peak_force = sys.peak.peak;
  r.t_peak = sys.peak.t_peak;
  r.max_penetration = sys.peak_d.peak;
  r.impulse_normal = ball.mass * (r.out.vy - r.in.vy) + ball.mass * options.g * t;
  r.impulse_tangential = ball.mass * (r.out.vx - r.in.vx);
  const Support sp_out = support(ball, r.out.theta);
  r.v_t_out = r.out.vx + r.out.omega * sp_out.Y;
  r.energy_in = kinetic_energy(ball, r.in);
  r.energy_out = kinetic_energy(ball, r.out);
  r.work_gravity = -ball.mass * options.g * (r.out.y - r.in.y);
  r.dissipated_normal = x[iWn];
  r.dissipated_friction = x[iWf];
  const double d_end = std::max(0.0, sp_out.Y - r.out.y);
  r.energy_residual = r.energy_in.total() + r.work_gravity - r.energy_out.total() -
                      r.dissipated_normal - r.dissipated_friction - law.potential(d_end);
}

/// The solver (docs/theory.md#bounce-contact), inlined into one function per CPU level below
/// (numerics/cpu_dispatch.hpp): with FMA and no vectorisation of the 11-component stage sums
/// (CMakeLists.txt) a right-hand-side call is ~8 % faster (docs/benchmarks.md, "Issue 15, sixth
/// pass"); the integrator's hot templates are always-inline for this.
[[gnu::always_inline]] inline ContactResult solve_contact(const Ball& ball, const NormalLaw& law,
                                                          const FrictionModel& friction, const BodyState& touch,
                                                          const ContactOptions& options,
                                                          std::vector<ContactSample>* history) {
  validate_contact(ball, law, friction, touch, options);
  const Model model{ball, law, friction, options.g, 1 / ball.mass, 1 / ball.inertia};
  ContactResult r;
  r.law = law;
  State x = state_at_touch(ball, touch, r);
  FrictionPhase phase = initial_friction_phase(model, law, friction, r.v_t_in, x);
  double t = 0;
  double h = first_step(ball, law, r.v_in_normal, options.integrator);
  PhaseSystem sys{model, friction, history, phase, {}, {}, {}};
  auto rhs = [&sys](const State& st, State& dx, double) { sys.rhs(st, dx); };
  auto guards = [&sys](double, const State& st, std::array<double, 2>& gv, std::array<double, 2>& rate) {
    sys.guards(st, gv, rate);
  };
  auto observer = [&sys](double tt, const State& st) { sys.observe(tt, st); };
  if (history) history->clear();

  // Phases that ended at once at the same time, in a row: two such (stick ends at once,
  // then slip ends at once) mean a point where neither friction phase can go on (e.g. the
  // spring model as the load vanishes, both guards negative to rounding). The next phase
  // then keeps its friction guard waiting until it becomes positive instead of ending at
  // once again, so that time moves on (docs/theory.md#bounce-integrator, "Zero-progress chatter").
  int immediate_run = 0;
  while (true) {
    if (r.n_phases >= options.max_phases) {
      r.status = ContactStatus::failed;
      r.message = "too many stick/slip phase changes";
      break;
    }
    sys.cur = phase;
    const unsigned patient = immediate_run >= 2 ? 2u : 0u;  // guard 1: friction
    const PhaseEnd<kN> end = integrate_phase<kN, 2>(rhs, guards, observer, t, x,
                                                    options.max_duration, h, options.integrator,
                                                    patient, &kErrorWeights);
    immediate_run = end.immediate ? immediate_run + 1 : 0;
    r.steps += end.steps;
    r.rhs_calls += end.rhs_calls;
    if (r.n_phases < kMaxStoredPhases) r.phases[r.n_phases] = {kind_of(sys.cur.mode, sys.cur.s), t, end.t};
    ++r.n_phases;
    t = end.t;
    x = end.x;
    if (end.next_step > 0) h = end.next_step;
    if (contact_ends(end, r)) break;
    phase = next_friction_phase(model, friction, sys.cur, x);
  }
  finish_contact(ball, law, options, x, t, sys, r);
  return r;
}

}  // namespace

namespace detail {

ContactResult simulate_contact_baseline(const Ball& ball, const NormalLaw& law, const FrictionModel& friction,
                                        const BodyState& touch, const ContactOptions& options,
                                        std::vector<ContactSample>* history) {
  return solve_contact(ball, law, friction, touch, options, history);
}

#if TRIBOLAB_HAVE_X86_64_V3
TRIBOLAB_TARGET_X86_64_V3 ContactResult simulate_contact_x86_64_v3(const Ball& ball, const NormalLaw& law,
                                                                   const FrictionModel& friction,
                                                                   const BodyState& touch,
                                                                   const ContactOptions& options,
                                                                   std::vector<ContactSample>* history) {
  return solve_contact(ball, law, friction, touch, options, history);
}
#else
ContactResult simulate_contact_x86_64_v3(const Ball& ball, const NormalLaw& law, const FrictionModel& friction,
                                         const BodyState& touch, const ContactOptions& options,
                                         std::vector<ContactSample>* history) {
  return solve_contact(ball, law, friction, touch, options, history);  // no such build: the baseline
}
#endif

}  // namespace detail

ContactResult simulate_contact(const Ball& ball, const NormalLaw& law, const FrictionModel& friction,
                               const BodyState& touch, const ContactOptions& options,
                               std::vector<ContactSample>* history) {
  if (options.kernel == ContactKernel::fastest && numerics::cpu_level() == numerics::CpuLevel::x86_64_v3)
    return detail::simulate_contact_x86_64_v3(ball, law, friction, touch, options, history);
  return detail::simulate_contact_baseline(ball, law, friction, touch, options, history);
}

ContactResult simulate_contact(const Ball& ball, const NormalLawSpec& spec,
                               const FrictionModel& friction, const BodyState& touch,
                               const ContactOptions& options, std::vector<ContactSample>* history) {
  if (auto e = ball.validate(); !e.empty()) throw InputError(e);
  const PointVelocity pv = contact_point_velocity(ball, touch.theta, touch.vx, touch.vy, touch.omega);
  const NormalLaw law = resolve(spec, -pv.vy, ball.mass);
  return simulate_contact(ball, law, friction, touch, options, history);
}

}  // namespace tribolab::bounce
