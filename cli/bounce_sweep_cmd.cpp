// The physics of `tribolab bounce sweep`: every cell is one whole impact of
// bounce::simulate_impact from first touch (the first contact and any further contact before
// the ball flies free to its apex), with the ball, normal law, friction law, g and tolerance of
// `bounce simulate`. The sweep options themselves (grid, shard, threads, resume, contour) are
// in cli/sweep_cmd.cpp. docs/cli.md#bounce-sweep, docs/theory.md#sweeps.
#include "bounce_sweep_cmd.hpp"

#include "bounce/contact.hpp"
#include "bounce/impact.hpp"
#include "bounce_options.hpp"
#include "io/sweep_command.hpp"
#include "io/sweep_file.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "sweep_cmd.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tribolab::cli {
namespace {

using namespace tribolab::bounce;

constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// How the swept `--theta-deg` values are read (docs/theory.md#sweeps).
enum class AngleConvention {
  collision,    ///< the seed's collision angle (figures 53-56), 0..180 deg
  orientation,  ///< the major axis from the horizontal at first touch, deg (as bounce simulate)
};

/// The physical options of `bounce simulate` except --mu (owned by the sweep, sweepable).
/// Defaults equal those of `bounce simulate` (docs/cli.md#bounce-simulate).
struct BouncePhysicsOptions {
  app::BallOptions ball;
  /// Integrator tolerance 1e-6: the loosest power of ten at which no cell of the seed's map
  /// (figure 53, 1491 cells) is less accurate than the seed's 1-microsecond stepping, against
  /// a 1e-12 reference (docs/benchmarks.md#bounce-sweep-phase-diagram).
  app::LawOptions law{1e-6};
  double g = 9.8;
  double vx = 0;     ///< horizontal centre velocity at first touch, m/s
  std::string angle = "collision";
  CLI::App* command = nullptr;  ///< the sweep command, to check the --theta-deg range once

  void add(CLI::App& cmd) {
    command = &cmd;
    cmd.add_option("--angle", angle,
                   "meaning of --theta-deg: collision (the seed's collision angle, 0..180 deg) | "
                   "orientation (major axis from the horizontal at first touch) (default collision)");
    cmd.add_option("--vx", vx, "horizontal centre velocity at first touch, m/s (default 0)");
    add_ball_options(&cmd, ball);
    add_law_options(&cmd, law, /*with_mu=*/false);  // --mu belongs to the sweep (sweepable)
    cmd.add_option("--g", g, "gravitational acceleration, m/s^2 (default 9.8)");
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
  std::string description(const std::string& kind, const Ball& b, const NormalLawSpec& s,
                          const FrictionModel& f, const ContactOptions& o) const {
    auto num = [](double v) { return io::format_number_exact(v); };
    std::string d = kind + " angle=" + angle + " vx=" + num(vx) + " a=" + num(b.a) + " b=" + num(b.b) +
                    " mass=" + num(b.mass) + " inertia=" + num(b.inertia) + " law=" + std::string(to_string(s.model)) +
                    " K=" + num(s.K) + " n=" + num(s.n);
    d += s.restitution ? " restitution=" + num(*s.restitution) : " D=" + num(s.D);
    d += " friction=" + std::string(to_string(f.kind));
    if (f.kind == FrictionKind::regularized) d += " slip_scale=" + num(f.slip_scale);
    if (f.kind == FrictionKind::spring) d += " k_t=" + num(f.k_t) + " c_t=" + num(f.c_t);
    d += " g=" + num(o.g) + " tol=" + num(law.tol);
    return d;
  }
};

/// The cell's physics, recorded as the first word of the model description: the whole
/// impact (this version), or the first contact phase alone (files written before; read
/// back for `--report` only).
const std::string kImpactKind = "bounce-impact";
const std::string kContactKind = "bounce-contact";

/// Output columns of a whole-impact cell (docs/cli.md#bounce-sweep): the whole impact, then
/// the first contact phase alone.
const std::vector<std::string> kImpactOutputs = {"vx",       "vy",          "omega_out",   "e",
                                                 "contacts", "contact_duration", "vx_first", "vy_first",
                                                 "omega_first", "e_first",  "duration_first"};

/// Everything one cell needs, fixed for the whole sweep (shared read-only by the threads).
struct BounceCell {
  Ball ball;
  NormalLawSpec law;
  FrictionModel friction;
  ContactOptions options;
  AngleConvention convention = AngleConvention::collision;
  double vx = 0;
  int direction = 1;  ///< direction of horizontal motion for the collision angle (sign of vx, +1 at 0)
  bool whole_impact = true;  ///< false: the first contact phase only (kContactKind files)

  /// The kImpactOutputs of one impact (first-phase only: vx, vy, omega_out, e); all NaN
  /// when the contact point does not approach the floor at first touch (no contact) or the
  /// integrator fails; the whole-impact values NaN when a later contact or flight search
  /// fails or the contacts never end (max_contacts).
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
    if (!whole_impact) {
      const ContactResult r = simulate_contact(ball, law, f, s, options);
      if (r.status == ContactStatus::failed) return out;
      out[0] = r.out.vx;
      out[1] = r.out.vy;
      out[2] = r.out.omega;
      out[3] = r.restitution;
      return out;
    }
    ImpactOptions io;
    io.contact = options;
    const ImpactResult r = simulate_impact(ball, law, f, s, io);
    if (r.first.status == ContactStatus::failed) return out;
    if (r.status == ImpactStatus::free_flight || r.status == ImpactStatus::rest) {
      out[0] = r.whole.out.vx;
      out[1] = r.whole.out.vy;
      out[2] = r.whole.out.omega;
      out[3] = r.whole.restitution;
      out[4] = static_cast<double>(r.contacts);
      out[5] = r.whole.contact_duration;
    }
    out[6] = r.first.out.vx;
    out[7] = r.first.out.vy;
    out[8] = r.first.out.omega;
    out[9] = r.first.restitution;
    out[10] = r.first.contact_duration;
    return out;
  }
};

/// The cell model of the parsed options (throws InputError naming an invalid option); `kind`
/// kContactKind rebuilds the first-phase model of older files.
sweep::CellModel build_model(const BouncePhysicsOptions& opts, const std::string& kind = kImpactKind) {
  BounceCell cell;
  cell.ball = opts.ball.get();
  cell.law = opts.law.law();
  cell.friction = opts.law.friction_model(0.5);  // each cell sets its own mu
  cell.options = opts.law.contact(app::checked_g(opts.g, /*zero_allowed=*/true));  // cells start at touch
  cell.convention = opts.convention();
  opts.check_theta_range(cell.convention);
  check_range(opts.vx, ranges::velocity, "--vx");  // docs/cli.md#physical-ranges
  cell.vx = opts.vx;
  cell.direction = opts.vx < 0 ? -1 : 1;  // as collision_angle_deg in `bounce simulate`
  cell.whole_impact = kind == kImpactKind;
  sweep::CellModel model;
  model.output_names = cell.whole_impact ? kImpactOutputs : std::vector<std::string>{"vx", "vy", "omega_out", "e"};
  model.description = opts.description(kind, cell.ball, cell.law, cell.friction, cell.options);
  model.mass = cell.ball.mass;
  model.inertia = cell.ball.inertia;
  model.evaluate = [cell](const sweep::CellInput& in) { return cell(in); };
  return model;
}

/// The inverse of BouncePhysicsOptions::description: each key=value becomes its option and
/// goes through the same parser and checks; the rebuilt model must describe itself with
/// exactly the same line, else the description is refused.
sweep::CellModel model_from_description(const std::string& description) {
  static const std::pair<const char*, const char*> kKeys[] = {
      {"angle", "--angle"}, {"vx", "--vx"},        {"a", "--a"},        {"b", "--b"},
      {"mass", "--mass"},   {"inertia", "--inertia"}, {"law", "--model"}, {"K", "--K"},
      {"n", "--n"},         {"restitution", "--restitution"}, {"D", "--D"}, {"friction", "--friction"},
      {"slip_scale", "--slip-scale"}, {"k_t", "--k-t"}, {"c_t", "--c-t"}, {"g", "--g"}, {"tol", "--tol"}};
  auto refuse = [&](const std::string& why) {
    return InputError("--report", "cannot rebuild the physics of the sweep file (" + why + "): '" +
                                      description.substr(0, 60) + "'");
  };
  std::string kind;
  for (const std::string& k : {kImpactKind, kContactKind}) {
    if (description.rfind(k + " ", 0) == 0) kind = k;
  }
  if (kind.empty()) throw refuse("not a bounce-impact or bounce-contact sweep");
  std::vector<std::string> args;  // CLI11 parses a vector from its back
  std::size_t p = kind.size() + 1;
  while (p < description.size()) {
    const std::size_t q = std::min(description.find(' ', p), description.size());
    const std::string word = description.substr(p, q - p);
    p = q + 1;
    const auto eq = word.find('=');
    const std::string key = word.substr(0, eq);
    const auto it = std::find_if(std::begin(kKeys), std::end(kKeys), [&](const auto& k) { return key == k.first; });
    if (eq == std::string::npos || it == std::end(kKeys)) throw refuse("unknown field '" + word.substr(0, 30) + "'");
    args.push_back(std::string(it->second) + "=" + word.substr(eq + 1));
  }
  std::reverse(args.begin(), args.end());
  BouncePhysicsOptions opts;
  CLI::App app;
  opts.add(app);
  try {
    app.parse(args);
  } catch (const CLI::Error& e) {
    throw refuse(e.what());
  }
  sweep::CellModel model = build_model(opts, kind);
  if (model.description != description) throw refuse("it does not read back to the same options");
  return model;
}

}  // namespace

void register_bounce_sweep(CLI::App& bounce_area) {
  auto opts = std::make_shared<BouncePhysicsOptions>();
  SweepPhysics physics;
  physics.add_options = [opts](CLI::App& cmd) { opts->add(cmd); };
  physics.make_model = [opts]() { return build_model(*opts); };
  physics.model_from_description = model_from_description;
  physics.default_mu = 0.5;
  physics.default_speed = 4.0;
  register_sweep_commands(bounce_area, std::move(physics));
}

}  // namespace tribolab::cli
