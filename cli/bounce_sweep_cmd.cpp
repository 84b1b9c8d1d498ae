// The physics of `tribolab bounce sweep`: every cell is one contact of bounce::simulate_contact
// from first touch (no flight), with the ball, normal law, friction law, g and tolerance of
// `bounce simulate`. The sweep options themselves (grid, shard, threads, resume, contour) are
// in cli/sweep_cmd.cpp. docs/cli.md#bounce-sweep, docs/theory.md#sweeps.
#include "bounce_sweep_cmd.hpp"

#include "bounce/contact.hpp"
#include "io/sweep_command.hpp"
#include "io/sweep_file.hpp"
#include "numerics/error.hpp"
#include "sweep_cmd.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

namespace tribolab::cli {
namespace {

using namespace tribolab::bounce;

constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void check_finite(double v, const char* option) {
  if (!std::isfinite(v)) throw InputError(option, "must be a finite number");
}

/// Turns "field: message" from a validate() into an error naming the option --field.
[[noreturn]] void invalid(const std::string& message) {
  const auto colon = message.find(':');
  if (colon != std::string::npos && colon < 24 && message.find(' ') > colon) {
    throw InputError("--" + message.substr(0, colon), message.substr(colon + 2));
  }
  throw InputError(message);
}

/// How the swept `--theta-deg` values are read (docs/theory.md#sweeps).
enum class AngleConvention {
  collision,    ///< the seed's collision angle (figures 53-56), 0..180 deg
  orientation,  ///< the major axis from the horizontal at first touch, deg (as bounce simulate)
};

/// The physical options of `bounce simulate` except --mu (owned by the sweep, sweepable).
/// Defaults equal those of `bounce simulate` (docs/cli.md#bounce-simulate).
struct BouncePhysicsOptions {
  Ball ball;
  std::string model = "hunt-crossley";
  std::optional<double> K, n, D, restitution;
  std::string friction = "coulomb";
  double slip_scale = 0.01, k_t = 2.0e4, c_t = 0.0;
  double g = 9.8;
  double vx = 0;     ///< horizontal centre velocity at first touch, m/s
  /// Integrator tolerance. 1e-8: every cell of the seed's map within 1e-6 m/s of a 1e-12
  /// reference; looser tolerances can step over a brief lift-off near grazing
  /// (docs/benchmarks.md#bounce-sweep-phase-diagram).
  double tol = 1e-8;
  std::string angle = "collision";
  CLI::App* command = nullptr;  ///< the sweep command, to check the --theta-deg range once

  void add(CLI::App& cmd) {
    command = &cmd;
    cmd.add_option("--angle", angle,
                   "meaning of --theta-deg: collision (the seed's collision angle, 0..180 deg) | "
                   "orientation (major axis from the horizontal at first touch) (default collision)");
    cmd.add_option("--vx", vx, "horizontal centre velocity at first touch, m/s (default 0)");
    cmd.add_option("--a", ball.a, "semi-major axis, m (default 0.145)");
    cmd.add_option("--b", ball.b, "semi-minor axis, m (default 0.095)");
    cmd.add_option("--mass", ball.mass, "mass, kg (default 0.435)");
    cmd.add_option("--inertia", ball.inertia, "moment of inertia about the centre, kg m^2 (default 4.1e-3)");
    cmd.add_option("--model", model,
                   "normal law: hooke|hertz|hunt-crossley|flores|lankarani-nikravesh|gonthier (default hunt-crossley)");
    cmd.add_option("--K", K, "stiffness, N/m^n (default 101054, the seed's fit)");
    cmd.add_option("--n", n, "exponent (default 1.51; hertz 1.5; hooke 1)");
    cmd.add_option("--D", D, "damping, N s/m^(n+1) (hooke: N s/m) (default 60423; hertz, hooke 0)");
    cmd.add_option("--restitution", restitution, "target central-impact restitution in (0, 1], instead of --D");
    cmd.add_option("--friction", friction, "friction model: coulomb|regularized|spring (default coulomb)");
    cmd.add_option("--slip-scale", slip_scale, "v_s of the regularized law, m/s (default 0.01)");
    cmd.add_option("--k-t", k_t, "tangential stiffness of the spring model, N/m (default 2e4)");
    cmd.add_option("--c-t", c_t, "tangential damping of the spring model, N s/m (default 0)");
    cmd.add_option("--g", g, "gravitational acceleration, m/s^2 (default 9.8)");
    cmd.add_option("--tol", tol, "integrator tolerance, absolute and relative (default 1e-8)");
  }

  Ball checked_ball() const {
    check_finite(ball.a, "--a");
    check_finite(ball.b, "--b");
    check_finite(ball.mass, "--mass");
    check_finite(ball.inertia, "--inertia");
    if (auto e = ball.validate(); !e.empty()) invalid(e);
    return ball;
  }

  NormalLawSpec law() const {
    const auto m = parse_normal_model(model);
    if (!m) {
      throw InputError("--model", "unknown model '" + model +
                                      "' (hooke, hertz, hunt-crossley, flores, lankarani-nikravesh, gonthier)");
    }
    if (D && restitution) throw InputError("--D", "give either --D or --restitution, not both");
    if (K) check_finite(*K, "--K");
    if (n) check_finite(*n, "--n");
    if (D) check_finite(*D, "--D");
    if (restitution) check_finite(*restitution, "--restitution");
    if (*m == NormalModel::hooke && n && *n != 1) throw InputError("--n", "the hooke law is linear (n = 1)");
    NormalLawSpec s;
    s.model = *m;
    s.K = K.value_or(101054);
    s.n = n.value_or(*m == NormalModel::hertz ? 1.5 : (*m == NormalModel::hooke ? 1.0 : 1.51));
    s.D = D.value_or((*m == NormalModel::hertz || *m == NormalModel::hooke) ? 0.0 : 60423);
    s.restitution = restitution;
    if (auto e = s.validate(); !e.empty()) invalid(e);
    return s;
  }

  /// The friction model with the sweep's default mu; each cell sets its own mu.
  FrictionModel friction_model(double mu) const {
    const auto k = parse_friction_kind(friction);
    if (!k) throw InputError("--friction", "unknown friction model '" + friction + "' (coulomb, regularized, spring)");
    check_finite(slip_scale, "--slip-scale");
    check_finite(k_t, "--k-t");
    check_finite(c_t, "--c-t");
    FrictionModel f;
    f.kind = *k;
    f.mu = mu;
    f.slip_scale = slip_scale;
    f.k_t = k_t;
    f.c_t = c_t;
    if (auto e = f.validate(); !e.empty()) invalid(e);
    return f;
  }

  ContactOptions contact() const {
    if (!std::isfinite(g) || !(g > 0)) throw InputError("--g", "gravitational acceleration must be positive");
    if (!(tol > 0) || !(tol < 1e-2) || !std::isfinite(tol)) throw InputError("--tol", "must lie in (0, 0.01)");
    ContactOptions o = contact_options_with_tolerance(tol);
    o.g = g;
    return o;
  }

  AngleConvention convention() const {
    if (angle == "collision") return AngleConvention::collision;
    if (angle == "orientation") return AngleConvention::orientation;
    throw InputError("--angle", "unknown angle convention '" + angle + "' (collision, orientation)");
  }

  /// The collision angle is defined on [0, 180] deg: checks the swept range once.
  void check_theta_range(AngleConvention c) const {
    if (c != AngleConvention::collision || command == nullptr) return;
    const CLI::Option* opt = command->get_option_no_throw("--theta-deg");
    if (opt == nullptr || opt->count() == 0) return;  // the sweep reports the missing option
    const sweep::Axis axis = io::parse_axis(opt->as<std::string>(), sweep::Quantity::theta_deg, "--theta-deg");
    for (double v : {axis.lo, axis.hi}) {
      if (!(v >= 0 && v <= 180)) {
        throw InputError("--theta-deg", "a collision angle lies in 0..180 deg, got " + io::format_number_exact(v) +
                                            " (use --angle orientation for the orientation at impact)");
      }
    }
  }

  /// One line recording every physical option (the sweep file header; a resume or merge
  /// with other physics is refused).
  std::string description(const Ball& b, const NormalLawSpec& s, const FrictionModel& f,
                          const ContactOptions& o) const {
    auto num = [](double v) { return io::format_number_exact(v); };
    std::string d = "bounce-contact angle=" + angle + " vx=" + num(vx) + " a=" + num(b.a) + " b=" + num(b.b) +
                    " mass=" + num(b.mass) + " inertia=" + num(b.inertia) + " law=" + std::string(to_string(s.model)) +
                    " K=" + num(s.K) + " n=" + num(s.n);
    d += s.restitution ? " restitution=" + num(*s.restitution) : " D=" + num(s.D);
    d += " friction=" + std::string(to_string(f.kind));
    if (f.kind == FrictionKind::regularized) d += " slip_scale=" + num(f.slip_scale);
    if (f.kind == FrictionKind::spring) d += " k_t=" + num(f.k_t) + " c_t=" + num(f.c_t);
    d += " g=" + num(o.g) + " tol=" + num(tol);
    return d;
  }
};

/// Everything one cell needs, fixed for the whole sweep (shared read-only by the threads).
struct BounceCell {
  Ball ball;
  NormalLawSpec law;
  FrictionModel friction;
  ContactOptions options;
  AngleConvention convention = AngleConvention::collision;
  double vx = 0;
  int direction = 1;  ///< direction of horizontal motion for the collision angle (sign of vx, +1 at 0)

  /// vx, vy, omega_out, e of one contact; all NaN when the contact point does not approach
  /// the floor at first touch (no contact) or the integrator fails.
  sweep::CellOutputs operator()(const sweep::CellInput& in) const {
    sweep::CellOutputs out;
    out.fill(kNaN);
    BodyState s;
    s.theta = convention == AngleConvention::collision ? theta_for_collision_angle(ball, in.theta_deg, direction)
                                                       : in.theta_deg / kDeg;
    s.vx = vx;
    s.vy = -in.speed;
    s.omega = in.omega;
    if (!(contact_point_velocity(ball, s.theta, s.vx, s.vy, s.omega).vy < 0)) return out;
    FrictionModel f = friction;
    f.mu = in.mu;
    const ContactResult r = simulate_contact(ball, law, f, s, options);
    if (r.status == ContactStatus::failed) return out;
    out[0] = r.out.vx;
    out[1] = r.out.vy;
    out[2] = r.out.omega;
    out[3] = r.restitution;
    return out;
  }
};

}  // namespace

void register_bounce_sweep(CLI::App& bounce_area) {
  auto opts = std::make_shared<BouncePhysicsOptions>();
  SweepPhysics physics;
  physics.add_options = [opts](CLI::App& cmd) { opts->add(cmd); };
  physics.make_model = [opts]() {
    BounceCell cell;
    cell.ball = opts->checked_ball();
    cell.law = opts->law();
    cell.friction = opts->friction_model(0.5);
    cell.options = opts->contact();
    cell.convention = opts->convention();
    opts->check_theta_range(cell.convention);
    check_finite(opts->vx, "--vx");
    cell.vx = opts->vx;
    cell.direction = opts->vx < 0 ? -1 : 1;  // as collision_angle_deg in `bounce simulate`
    sweep::CellModel model;
    model.output_names = {"vx", "vy", "omega_out", "e"};
    model.description = opts->description(cell.ball, cell.law, cell.friction, cell.options);
    model.mass = cell.ball.mass;
    model.inertia = cell.ball.inertia;
    model.evaluate = [cell](const sweep::CellInput& in) { return cell(in); };
    return model;
  };
  physics.default_mu = 0.5;
  physics.default_speed = 4.0;
  register_sweep_commands(bounce_area, std::move(physics));
}

}  // namespace tribolab::cli
