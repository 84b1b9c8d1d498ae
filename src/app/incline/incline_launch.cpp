#include "app/incline/incline_launch.hpp"

#include "io/text.hpp"
#include "numerics/error.hpp"
#include "numerics/physical_range.hpp"

namespace tribolab::app {

double check_incline_angle_deg(double deg, const std::string& option, bool allow_zero) {
  if (!(deg >= 0 && deg < 90) || (!allow_zero && deg == 0))
    throw InputError(option, std::string("must be in ") + (allow_zero ? "[0, 90)" : "(0, 90)") +
                                 " degrees, got " + io::format_number(deg));
  return deg;
}

incline::Parameters incline_launch_parameters(const InclineLaunchOptions& o, const std::string& skip) {
  incline::Parameters p;
  auto need = [&](const std::optional<double>& v, const std::string& option) {
    if (!v) {
      if (option == skip) return 0.0;
      throw MissingOptionError(option, "is required");
    }
    return *v;
  };
  // Physical ranges: numerics/physical_range.hpp (docs/cli.md#physical-ranges).
  p.mu = check_range(need(o.mu, field("mu")), ranges::friction, field("mu"));
  const double phi_deg = need(o.phi_deg, field("phi_deg"));
  if (!(phi_deg >= 0 && phi_deg < 90))
    throw InputError(field("phi_deg"), "must be in [0, 90), got " + io::format_number(phi_deg));
  p.phi = to_rad(phi_deg);
  p.v0 = check_range(need(o.v0, field("v0")), ranges::speed, field("v0"));
  p.g = check_range(o.g, ranges::gravity, field("g"));
  if (o.mu_static) p.mu_static = check_range(*o.mu_static, ranges::friction, field("mu_static"));
  p.check();
  return p;
}

const Fields<InclineLaunchOptions>& incline_launch_fields(bool required) {
  auto make = [](bool req) {
    using O = InclineLaunchOptions;
    Fields<O> d;
    auto need = [req](FieldDecl& f) -> FieldDecl& { return req ? f.needed() : f; };
    need(d.add("mu", &O::mu, "", "kinetic friction coefficient (>= 0)")).in(ranges::friction);
    need(d.add("phi_deg", &O::phi_deg, "deg", "incline angle, in [0, 90)"));
    need(d.add("v0", &O::v0, "m/s", "launch speed along +x (>= 0)")).in(ranges::speed);
    d.add("g", &O::g, "m/s^2", "gravitational acceleration").in(ranges::gravity);
    d.add("mu_static", &O::mu_static, "", "static friction coefficient deciding whether a disc at rest stays (unset: mu)")
        .in(ranges::friction);
    return d;
  };
  static const Fields<InclineLaunchOptions> with_required = make(true), optional = make(false);
  return required ? with_required : optional;
}

}  // namespace tribolab::app
