#include "app/bounce/bounce_cell.hpp"

#include "bounce/contact.hpp"
#include "bounce/impact.hpp"
#include "io/sweep_file.hpp"
#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"
#include "numerics/units.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace tribolab::app {
namespace {

using namespace tribolab::bounce;


const char* kind_word(BounceCellKind k) { return k == BounceCellKind::impact ? "bounce-impact" : "bounce-contact"; }

AngleConvention convention_of(const std::string& angle) {
  if (angle == "collision") return AngleConvention::collision;
  if (angle == "orientation") return AngleConvention::orientation;
  throw InputError(field("angle"), "unknown angle convention '" + angle + "' (collision, orientation)");
}

}  // namespace

std::string_view to_string(AngleConvention c) {
  return c == AngleConvention::collision ? "collision" : "orientation";
}

const std::vector<std::string>& bounce_cell_outputs(BounceCellKind kind) {
  static const std::vector<std::string> impact = {"vx",       "vy",       "omega_out",   "e",
                                                  "contacts", "contact_duration", "vx_first", "vy_first",
                                                  "omega_first", "e_first", "duration_first"};
  static const std::vector<std::string> contact = {"vx", "vy", "omega_out", "e"};
  return kind == BounceCellKind::impact ? impact : contact;
}

BounceCell make_bounce_cell(const BounceCellOptions& o, BounceCellKind kind) {
  BounceCell cell;
  cell.ball = o.ball.get();
  cell.law = o.law.law();
  cell.friction = o.law.friction_model(0.5);  // each cell sets its own mu
  cell.options = o.law.contact(checked_g(o.g, /*zero_allowed=*/true));  // cells start at touch
  // A map is many contacts: the fastest compiled solver (bounce/contact.hpp; a map made on a CPU
  // without FMA differs in the last bits, and by up to ~the tolerance in a few cells).
  cell.options.kernel = bounce::ContactKernel::fastest;
  cell.convention = convention_of(o.angle);
  check_range(o.vx, ranges::velocity, field("vx"));  // docs/cli.md#physical-ranges
  if (o.spin_sign != 1 && o.spin_sign != -1) throw InputError("spin_sign", "must be +1 or -1");
  cell.vx = o.vx;
  cell.direction = o.vx < 0 ? -1 : 1;  // as collision_angle_deg in `bounce simulate`
  cell.spin_sign = o.spin_sign;
  cell.tol = o.law.tol;
  cell.kind = kind;
  return cell;
}

sweep::CellOutputs BounceCell::operator()(const sweep::CellInput& in) const {
  sweep::CellOutputs out;
  out.fill(kNaN);
  BodyState s;
  s.theta = convention == AngleConvention::collision ? theta_for_collision_angle(ball, in.theta_deg, direction)
                                                     : to_rad(in.theta_deg);
  s.vx = vx;
  s.vy = -in.speed;
  s.omega = spin_sign * in.omega;
  if (!(contact_point_velocity(ball, s.theta, s.vx, s.vy, s.omega).vy < 0)) return out;
  FrictionModel f = friction;
  f.mu = in.mu;
  if (kind == BounceCellKind::contact) {
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

std::string BounceCell::description() const {
  auto num = [](double v) { return io::format_number_exact(v); };
  const NormalLawSpec& s = law;
  const FrictionModel& f = friction;
  std::string d = std::string(kind_word(kind)) + " angle=" + std::string(to_string(convention)) + " vx=" + num(vx) +
                  " a=" + num(ball.a) + " b=" + num(ball.b) + " mass=" + num(ball.mass) +
                  " inertia=" + num(ball.inertia) + " law=" + std::string(bounce::to_string(s.model)) +
                  " K=" + num(s.K) + " n=" + num(s.n);
  d += s.restitution ? " restitution=" + num(*s.restitution) : " D=" + num(s.D);
  d += " friction=" + std::string(bounce::to_string(f.kind));
  if (f.kind == FrictionKind::regularized) d += " slip_scale=" + num(f.slip_scale);
  if (f.kind == FrictionKind::spring) d += " k_t=" + num(f.k_t) + " c_t=" + num(f.c_t);
  d += " g=" + num(options.g) + " tol=" + num(tol);
  if (spin_sign == -1) d += " spin_sign=-1";
  return d;
}

sweep::CellModel bounce_cell_model(const BounceCell& cell) {
  sweep::CellModel model;
  model.output_names = bounce_cell_outputs(cell.kind);
  model.description = cell.description();
  model.mass = cell.ball.mass;
  model.inertia = cell.ball.inertia;
  model.evaluate = [cell](const sweep::CellInput& in) { return cell(in); };
  return model;
}

ParsedBounceCell parse_bounce_cell_description(const std::string& description) {
  auto refuse = [&](const std::string& why) {
    return InputError(field("report"), "cannot rebuild the physics of the sweep file (" + why + "): '" +
                                      description.substr(0, 60) + "'");
  };
  ParsedBounceCell p;
  std::string kind;
  for (BounceCellKind k : {BounceCellKind::impact, BounceCellKind::contact}) {
    if (description.rfind(std::string(kind_word(k)) + " ", 0) == 0) {
      kind = kind_word(k);
      p.kind = k;
    }
  }
  if (kind.empty()) throw refuse("not a bounce-impact or bounce-contact sweep");
  BounceCellOptions& o = p.options;
  LawOptions& law = o.law;
  // Each key of the description and the field it sets (the option of the same meaning).
  using Setter = void (*)(BounceCellOptions&, double);
  static const std::pair<const char*, Setter> kNumbers[] = {
      {"vx", [](BounceCellOptions& x, double v) { x.vx = v; }},
      {"a", [](BounceCellOptions& x, double v) { x.ball.ball.a = v; }},
      {"b", [](BounceCellOptions& x, double v) { x.ball.ball.b = v; }},
      {"mass", [](BounceCellOptions& x, double v) { x.ball.ball.mass = v; }},
      {"inertia", [](BounceCellOptions& x, double v) { x.ball.ball.inertia = v; }},
      {"K", [](BounceCellOptions& x, double v) { x.law.K = v; }},
      {"n", [](BounceCellOptions& x, double v) { x.law.n = v; }},
      {"D", [](BounceCellOptions& x, double v) { x.law.D = v; }},
      {"restitution", [](BounceCellOptions& x, double v) { x.law.restitution = v; }},
      {"slip_scale", [](BounceCellOptions& x, double v) { x.law.slip_scale = v; }},
      {"k_t", [](BounceCellOptions& x, double v) { x.law.k_t = v; }},
      {"c_t", [](BounceCellOptions& x, double v) { x.law.c_t = v; }},
      {"g", [](BounceCellOptions& x, double v) { x.g = v; }},
      {"tol", [](BounceCellOptions& x, double v) { x.law.tol = v; }},
      {"spin_sign", [](BounceCellOptions& x, double v) { x.spin_sign = v == -1 ? -1 : (v == 1 ? 1 : 0); }},
  };
  std::size_t pos = kind.size() + 1;
  while (pos < description.size()) {
    const std::size_t q = std::min(description.find(' ', pos), description.size());
    const std::string word = description.substr(pos, q - pos);
    pos = q + 1;
    const auto eq = word.find('=');
    if (eq == std::string::npos) throw refuse("unknown field '" + word.substr(0, 30) + "'");
    const std::string key = word.substr(0, eq), value = word.substr(eq + 1);
    if (key == "angle") {
      o.angle = value;
    } else if (key == "law") {
      law.model = value;
    } else if (key == "friction") {
      law.friction = value;
    } else {
      const auto it = std::find_if(std::begin(kNumbers), std::end(kNumbers),
                                   [&](const auto& k) { return key == k.first; });
      if (it == std::end(kNumbers)) throw refuse("unknown field '" + word.substr(0, 30) + "'");
      try {
        it->second(o, io::parse_double(value, key));
      } catch (const InputError& e) {
        throw refuse(marked_message(e));
      }
    }
  }
  return p;
}

sweep::CellModel bounce_cell_model_from_description(const std::string& description) {
  const ParsedBounceCell p = parse_bounce_cell_description(description);
  sweep::CellModel model = bounce_cell_model(make_bounce_cell(p.options, p.kind));
  if (model.description != description) {
    throw InputError(field("report"), "cannot rebuild the physics of the sweep file (it does not read back to the same "
                                 "options): '" + description.substr(0, 60) + "'");
  }
  return model;
}

}  // namespace tribolab::app
