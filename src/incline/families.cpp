#include "incline/families.hpp"

#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tribolab::incline {

const char* to_string(FamilyParameter p) {
  switch (p) {
    case FamilyParameter::v0: return "v0";
    case FamilyParameter::phi: return "phi";
    case FamilyParameter::mu: return "mu";
  }
  return "?";
}

std::string FamilyOptions::validate() const {
  if (values.empty()) return "the family needs at least one value";
  if (values.size() > 1000) return "at most 1000 values per family";
  if (!std::isfinite(t_end) || t_end < 0) return "t_end must be finite and >= 0";
  if (samples < 2 || samples > 1000000) return "samples must be in [2, 1000000]";
  return base.validate();
}

double default_duration(const Parameters& p) {
  const ClosedForm cf(p);
  const double ts = cf.t_stop();
  if (std::isfinite(ts) && ts > 0) return 1.25 * ts;
  if (p.mu > 0 && p.v0 > 0) return 2 * p.v0 / p.alpha();
  return 1.0;
}

Family make_family(const FamilyOptions& o) {
  const std::string msg = o.validate();
  if (!msg.empty()) throw InputError(msg);
  Family f;
  for (double v : o.values) {
    FamilyMember m;
    m.value = v;
    m.parameters = o.base;
    switch (o.vary) {
      case FamilyParameter::v0: m.parameters.v0 = v; break;
      case FamilyParameter::phi: m.parameters.phi = v; break;
      case FamilyParameter::mu:
        m.parameters.mu = v;
        break;
    }
    const std::string e = m.parameters.validate();
    if (!e.empty()) throw InputError(std::string("family value of ") + to_string(o.vary), e);
    f.members.push_back(std::move(m));
  }
  for (auto& m : f.members) {
    m.t_end = o.t_end > 0 ? o.t_end : default_duration(m.parameters);
    if (!std::isfinite(m.t_end))
      throw InputError("t_end", "the default duration is not finite for these parameters; give t_end");
    f.t_end = std::max(f.t_end, m.t_end);
    std::vector<double> times(o.samples);
    for (int i = 0; i < o.samples; ++i) times[i] = m.t_end * i / (o.samples - 1);
    const ClosedForm cf(m.parameters);
    m.prediction = cf.predict();
    m.trajectory = cf.trajectory(times);
    const double k = m.prediction.k;
    if (std::isfinite(k) && std::abs(k - 1) < 0.02) {
      char buf[240];
      std::snprintf(buf, sizeof buf,
                    "%s = %.6g gives k = tan(phi)/mu = %.4f, near 1: the disc %s (k < 1 stops, k >= 1 never does); "
                    "its curve spans %.4g s",
                    to_string(o.vary), o.vary == FamilyParameter::phi ? to_deg(m.value) : m.value, k,
                    m.prediction.t_stop ? "takes very long to stop" : "never stops", m.t_end);
      f.warnings.push_back(buf);
    }
  }
  return f;
}

}  // namespace tribolab::incline
