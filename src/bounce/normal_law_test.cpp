#include "bounce/friction.hpp"
#include "bounce/normal_law.hpp"

#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <string_view>
#include <vector>

namespace tribolab::bounce {
namespace {

TEST(NormalLaw, EveryModelHasOneRowAndItsNameRoundTrips) {
  // The table is the one list of laws (names, choices, messages): each enumerator has exactly
  // one row, names are distinct and parse back to their model; the undamped laws default to D = 0.
  const NormalModel all[] = {NormalModel::hooke, NormalModel::hertz, NormalModel::hunt_crossley,
                             NormalModel::flores, NormalModel::lankarani_nikravesh, NormalModel::gonthier};
  EXPECT_EQ(std::size(kNormalModels), std::size(all));
  std::set<std::string_view> names;
  for (NormalModel m : all) {
    EXPECT_EQ(std::count_if(std::begin(kNormalModels), std::end(kNormalModels), [m](const auto& r) { return r.model == m; }), 1);
    EXPECT_EQ(parse_normal_model(to_string(m)), m);
    names.insert(to_string(m));
  }
  EXPECT_EQ(names.size(), std::size(all));
  EXPECT_EQ(normal_model_names().size(), std::size(all));
  EXPECT_FALSE(parse_normal_model("Hertz").has_value());
  EXPECT_EQ(info(NormalModel::hertz).default_D, 0);
  EXPECT_EQ(info(NormalModel::hertz).default_n, 1.5);
  EXPECT_EQ(info(NormalModel::hunt_crossley).default_D, Seed001Law::D);
  for (FrictionKind k : {FrictionKind::coulomb, FrictionKind::regularized, FrictionKind::spring})
    EXPECT_EQ(parse_friction_kind(to_string(k)), k);
  EXPECT_EQ(friction_kind_names(), (std::vector<std::string>{"coulomb", "regularized", "spring"}));
}

TEST(NormalLaw, HuntCrossleyRelationRoundTrips) {
  for (double e : {1e-3, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999999}) {
    const double z = hunt_crossley_chi_v(e);
    // Both directions are root solves to the last bits of well-conditioned functions.
    EXPECT_NEAR(hunt_crossley_restitution(z), e, 1e-12 * std::max(1.0, 1 / e)) << e;
    if (e >= 0.1) {
      // The loop integral itself: (1 - e z) = (1 + z) exp(-z (1 + e)). 1 - e z >= 1e-4 here,
      // so its logarithm carries ~eps / 1e-4 ~ 1e-12 rounding.
      EXPECT_NEAR(std::log1p(-e * z), std::log1p(z) - z * (1 + e), 1e-10) << e;
    } else {
      // 1 - e z ~ (1 + z) exp(-1/e) underflows double's spacing near 1: z = 1/e to rounding.
      EXPECT_NEAR(z * e, 1.0, 1e-15) << e;
    }
  }
}

TEST(NormalLaw, HuntCrossleyNearlyElasticLimit) {
  // As e -> 1: z = 3(1-e)/2 + O((1-e)^2) (the classical Hunt–Crossley damping,
  // Hunt & Crossley 1975). For 1 - e = 1e-4 the O((1-e)^2) term is ~1e-8 relative... of z.
  const double e = 1 - 1e-4;
  const double z = hunt_crossley_chi_v(e);
  EXPECT_NEAR(z / (1.5 * (1 - e)), 1.0, 2e-4);
  EXPECT_EQ(hunt_crossley_chi_v(1.0), 0.0);
}

// eval computes d^n as exp(n log d) (cheaper than pow, docs/benchmarks.md#issue-15). Its
// relative error is the absolute error of n log d, up to ~1.5 units of its last place
// (log's 0.5 plus the product's 0.5, both relative to |n log d|), plus exp's and pow's own
// rounding: bound (2 |n log d| + 4) x 1.1e-16, ~2e-14 at d = 1e-12 m, n = 3 (measured worst
// 1.24e-14). A wrong formula (log base 2, n - 1) misses it by many orders.
TEST(NormalLaw, PowerThroughExpLogMatchesPow) {
  for (double n : {1.0, 1.25, 1.5, 1.51, 2.0, 3.0}) {
    NormalLaw law;
    law.K = 1e5;
    law.n = n;
    law.D = 6e4;
    for (double d = 1e-12; d < 0.1; d *= 1.7) {
      const double want = law.K * std::pow(d, n);
      const double bound = (2 * std::abs(n * std::log(d)) + 4) * 1.1e-16 * want;
      EXPECT_NEAR(law.eval(d, 0.0).elastic, want, bound) << "n " << n << " d " << d;
    }
  }
}

TEST(NormalLaw, HookeClampedRestitution) {
  EXPECT_DOUBLE_EQ(hooke_restitution(0), 1.0);
  double prev = 1;
  for (double zeta = 0.05; zeta < 0.99; zeta += 0.05) {
    const double e = hooke_restitution(zeta);
    EXPECT_LT(e, prev);  // monotone decreasing
    EXPECT_NEAR(hooke_damping_ratio(e), zeta, 1e-10);
    // The clamp makes the ball leave when the force vanishes, earlier than d = 0: e is
    // larger than the unclamped exp(-pi zeta / sqrt(1 - zeta^2)).
    EXPECT_GT(e, std::exp(-std::acos(-1.0) * zeta / std::sqrt(1 - zeta * zeta)));
    prev = e;
  }
}

TEST(NormalLaw, NeverPulls) {
  NormalLaw hc{false, 1e5, 1.5, 6e4};
  EXPECT_EQ(hc.eval(0.01, -10).N, 0.0);  // 1 + chi d_dot < 0
  EXPECT_EQ(hc.eval(-0.01, 5).N, 0.0);   // not in contact
  NormalLaw hooke{true, 1e5, 1, 100};
  EXPECT_EQ(hooke.eval(0.001, -5).N, 0.0);
  EXPECT_NEAR(hooke.eval(0.001, 0).N, 100, 1e-12);
}

TEST(NormalLaw, ResolveRestitutionModels) {
  NormalLawSpec s;
  s.K = 1e5;
  s.n = 1.5;
  s.restitution = 0.8;
  const double v = 4;
  s.model = NormalModel::lankarani_nikravesh;
  EXPECT_NEAR(resolve(s, v, 0.4).D, 1e5 * 3 * (1 - 0.64) / (4 * v), 1e-9);
  s.model = NormalModel::flores;
  EXPECT_NEAR(resolve(s, v, 0.4).D, 1e5 * 8 * 0.2 / (5 * 0.8 * v), 1e-9);
  s.model = NormalModel::gonthier;
  EXPECT_NEAR(resolve(s, v, 0.4).D, 1e5 * 0.36 / (0.8 * v), 1e-9);
  s.model = NormalModel::hertz;
  EXPECT_THROW(resolve(s, v, 0.4), InputError);  // Hertz is elastic
  s.restitution.reset();
  s.D = 0;
  EXPECT_EQ(resolve(s, v, 0.4).D, 0.0);
}

TEST(NormalLaw, ModelNamesRoundTrip) {
  for (auto m : {NormalModel::hooke, NormalModel::hertz, NormalModel::hunt_crossley,
                 NormalModel::flores, NormalModel::lankarani_nikravesh, NormalModel::gonthier})
    EXPECT_EQ(parse_normal_model(to_string(m)), m);
  EXPECT_FALSE(parse_normal_model("kelvin"));
}

}  // namespace
}  // namespace tribolab::bounce
