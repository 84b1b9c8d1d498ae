// mu from a straight slide (seed 000, eq a) on synthetic slides with known truth.
#include "analysis/incline_slide.hpp"
#include "analysis/incline_synthetic.hpp"
#include "incline/closed_form.hpp"
#include "numerics/error.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tribolab::analysis {
namespace {

/// Disc released from rest at t_release on the incline (mu, phi), filmed at fps with noise,
/// in a camera frame rotated by `frame_deg` from the incline's (x across, y up the slope).
track::Track slide(double mu, double phi_deg, double fps, double noise, std::uint64_t seed,
                   double frame_deg = 0, double t_release = 0.05, double duration = 0.6) {
  incline::Parameters p;
  p.mu = mu;
  p.phi = incline::deg_to_rad(phi_deg);
  p.v0 = 0;
  const incline::ClosedForm cf(p);  // v0 = 0: slides down the fall line (a = beta - alpha)
  PortableNormal normal(seed);
  const double c = std::cos(incline::deg_to_rad(frame_deg)), s = std::sin(incline::deg_to_rad(frame_deg));
  track::Track t{"disc", {}};
  for (int i = 0; i * (1 / fps) <= duration; ++i) {
    const double ti = i / fps;
    incline::State st;
    if (ti > t_release) st = cf.at(ti - t_release);
    const double x = 0.1 + c * st.x - s * st.y, y = 0.3 + s * st.x + c * st.y;
    t.points.push_back({i, ti, x + noise * normal(), y + noise * normal()});
  }
  return t;
}

TEST(MuFromSlide, RecoversTheSeedsSlide) {
  // Seed 000, 伍-一-(一): phi = 41.09 deg, a = 1.758 m/s^2, mu = 0.634.
  const double phi = incline::deg_to_rad(41.09);
  const double mu = (9.8 * std::sin(phi) - 1.758) / (9.8 * std::cos(phi));  // eq (a)
  SlideOptions o;
  o.phi = phi;
  const SlideResult r = mu_from_slide(slide(mu, 41.09, 80, 0.001, 1), o);
  // Truth within 3.3 sigma (a 1-in-1000 miss for a correct interval; fixed seed).
  EXPECT_NEAR(r.a, 1.758, 3.3 * r.sigma_a);
  EXPECT_NEAR(*r.mu, mu, 3.3 * *r.sigma_mu);
  EXPECT_LT(*r.sigma_mu, 0.01);
  EXPECT_GT(r.r_squared, 0.999);
  EXPECT_NEAR(r.direction_deg, -90, 0.5);  // straight down y
  // The seed's v–t line agrees within its (understated) uncertainty times 3.
  EXPECT_NEAR(r.a_velocity_line, r.a, 3 * std::hypot(r.sigma_a, 3 * r.sigma_a_velocity_line));
}

TEST(MuFromSlide, SaysWhatTheSlideShowsOfAWrongAngleOrTimeScale) {
  // Issue 27: 41.09 deg given in radians (0.7172) gave mu < 0 without a word; a slide cannot
  // accelerate faster than g sin(phi), so it shows the angle is at least asin(a / g).
  const track::Track t = slide(0.634, 41.09, 80, 0.001, 1);
  SlideOptions o;
  o.phi = incline::deg_to_rad(0.7172);
  const SlideResult r = mu_from_slide(t, o);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("the incline is at least 10.4"), std::string::npos) << r.warnings[0];  // asin(1.775/9.8), a fitted
  EXPECT_NE(r.warnings[0].find("looks like the angle in radians (0.7172 rad = 41.09 deg)"), std::string::npos) << r.warnings[0];
  // The angle right: nothing to say.
  o.phi = incline::deg_to_rad(41.09);
  EXPECT_TRUE(mu_from_slide(t, o).warnings.empty());
  // Times 1/8 of the real ones (--time-scale 0.125 applied twice): a = 64 x 1.758 > g.
  track::Track fast = t;
  for (auto& p : fast.points) p.t /= 8;
  const SlideResult f = mu_from_slide(fast, o);
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("times must be multiplied by at least 3.4"), std::string::npos) << f.warnings[0];  // sqrt(113.6/9.8)
}

TEST(MuFromSlide, RotatedCameraFrameGivesTheSameResult) {
  // The path is found from the points, so a camera rotated by 12 deg changes nothing but the
  // direction (noise-free: identical to rounding).
  SlideOptions o;
  o.phi = incline::deg_to_rad(41.09);
  const auto a = mu_from_slide(slide(0.634, 41.09, 120, 0, 1, 0), o);
  const auto b = mu_from_slide(slide(0.634, 41.09, 120, 0, 1, 12), o);
  EXPECT_NEAR(a.a, b.a, 1e-9);
  EXPECT_NEAR(*a.mu, 0.634, 1e-9);  // noise-free parabola is exact
  EXPECT_NEAR(b.direction_deg, -78, 1e-6);
}

TEST(MuFromSlide, UncertaintyPropagatesTheAngle) {
  SlideOptions o;
  o.phi = incline::deg_to_rad(41.09);
  const auto exact = mu_from_slide(slide(0.634, 41.09, 120, 0.001, 2), o);
  o.sigma_phi = incline::deg_to_rad(0.5);
  const auto r = mu_from_slide(slide(0.634, 41.09, 120, 0.001, 2), o);
  // dmu/dphi = sec^2(phi) - a sin(phi)/(g cos^2 phi) at phi = 41.09 deg: 1.50 per rad.
  const double phi = *o.phi, a = r.a;
  const double d = 1 / std::pow(std::cos(phi), 2) - a * std::sin(phi) / (9.8 * std::pow(std::cos(phi), 2));
  EXPECT_NEAR(*r.sigma_mu, std::hypot(*exact.sigma_mu, d * o.sigma_phi), 1e-12);
}

TEST(MuFromSlide, WithoutAngleReportsOnlyTheAcceleration) {
  const auto r = mu_from_slide(slide(0.634, 41.09, 80, 0.001, 3), SlideOptions{});
  EXPECT_FALSE(r.mu.has_value());
  EXPECT_GT(r.a, 1.5);
}

TEST(MuFromSlide, RejectsDataThatCannotSupportTheFit) {
  SlideOptions o;
  o.phi = incline::deg_to_rad(20);
  // Stuck: mu = 0.634 > tan(20 deg): the disc never moves.
  EXPECT_THROW(mu_from_slide(slide(0.634, 20, 80, 0.001, 4), o), InputError);
  // Too few points.
  track::Track few{"disc", {{0, 0, 0, 0}, {1, 0.1, 0, -0.01}, {2, 0.2, 0, -0.04}}};
  EXPECT_THROW(mu_from_slide(few, o), InputError);
  // Decelerating: pushed down the slope at 1 m/s with mu > tan(phi).
  track::Track dec{"disc", {}};
  for (int i = 0; i < 40; ++i) {
    const double t = i / 80.0, a = 9.8 * (std::sin(0.35) - 0.634 * std::cos(0.35));  // < 0
    dec.points.push_back({i, t, 0, -(1.0 * t + 0.5 * a * t * t)});
  }
  try {
    mu_from_slide(dec, o);
    FAIL() << "decelerating slide accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not accelerating"), std::string::npos) << e.what();
  }
}

TEST(InclineSynth, SameSeedSameRunDifferentSeedDifferentNoise) {
  InclineSynthOptions o;
  o.params.phi = incline::deg_to_rad(20.96);
  o.seed = 42;
  const auto a = synthesize_incline_run(o), b = synthesize_incline_run(o);
  ASSERT_EQ(a.track.points.size(), b.track.points.size());
  for (std::size_t i = 0; i < a.track.points.size(); ++i) {
    EXPECT_EQ(a.track.points[i].x, b.track.points[i].x);
    EXPECT_EQ(a.track.points[i].y, b.track.points[i].y);
  }
  o.seed = 43;
  const auto c = synthesize_incline_run(o);
  EXPECT_NE(a.track.points[5].x, c.track.points[5].x);
}

TEST(InclineSynth, RestsBeforeTheLaunchAndAfterTheStop) {
  InclineSynthOptions o;
  o.params.phi = incline::deg_to_rad(20.96);
  o.noise = 0;
  o.t_launch = 0.1;
  const auto r = synthesize_incline_run(o);
  ASSERT_TRUE(r.t_stop.has_value());
  // t_stop = v0 / (alpha (1 - k^2)) after the launch (seed eq 七).
  const incline::ClosedForm cf(o.params);
  EXPECT_NEAR(*r.t_stop, 0.1 + cf.t_stop(), 1e-12);
  for (const auto& p : r.track.points) {
    if (p.t <= 0.1) {
      EXPECT_EQ(p.x, o.x0);
      EXPECT_EQ(p.y, o.y0);
    }
  }
  const auto& last = r.track.points.back();
  EXPECT_GT(last.t, *r.t_stop + 0.25);  // 0.3 s of rest recorded by default
  EXPECT_NEAR(last.x, o.x0 + *cf.predict().x_stop, 1e-12);
  EXPECT_NEAR(last.y, o.y0 + *cf.predict().y_stop, 1e-12);
}

TEST(InclineSynth, NoiseHasTheRequestedStandardDeviation) {
  PortableNormal n(7);
  double s = 0, s2 = 0;
  const int N = 200000;
  for (int i = 0; i < N; ++i) {
    const double v = n();
    s += v;
    s2 += v * v;
  }
  // Mean 0 +- 3/sqrt(N) = 0.0067; variance 1 +- 3 sqrt(2/N) = 0.0095.
  EXPECT_NEAR(s / N, 0.0, 0.0067);
  EXPECT_NEAR(s2 / N, 1.0, 0.0095);
}

TEST(InclineSynth, ModelARunUsesTheIntegrator) {
  InclineSynthOptions o;
  o.params.phi = incline::deg_to_rad(20.96);
  o.params.normal_accel = 0.3;
  o.noise = 0;
  const auto a = synthesize_incline_run(o);
  o.params.normal_accel = 0;
  const auto b = synthesize_incline_run(o);
  // f_N pointing up the slope bends the path less: the model A disc ends higher.
  EXPECT_GT(a.track.points.back().y, b.track.points.back().y + 0.005);
}

TEST(InclineSynth, ReleaseFromRestSlidesStraightDownTheFallLine) {
  // v0 = 0 on an incline steeper than atan(mu): y = y0 - (beta - alpha) t^2/2, x = x0.
  InclineSynthOptions o;
  o.params.mu = 0.634;
  o.params.phi = incline::deg_to_rad(41.09);
  o.params.v0 = 0;
  o.noise = 0;
  o.fps = 100;
  o.duration = 0.6;
  const InclineSynthRun run = synthesize_incline_run(o);
  const double a = o.params.beta() - o.params.alpha();  // eq (a): the seed's 1.758 m/s^2
  EXPECT_NEAR(a, 1.758, 0.005);
  EXPECT_FALSE(run.t_stop);
  for (const auto& p : run.track.points) {
    const double tr = std::max(0.0, p.t - o.t_launch);
    EXPECT_EQ(p.x, o.x0);  // exactly: no motion across the slope
    EXPECT_NEAR(p.y, o.y0 - 0.5 * a * tr * tr, 1e-12);
  }
  // And the slide analysis recovers mu exactly from noise-free data (the parabola is exact).
  SlideOptions so;
  so.phi = o.params.phi;
  EXPECT_NEAR(*mu_from_slide(run.track, so).mu, 0.634, 1e-9);
}

TEST(InclineSynth, ReleaseFromRestMustSlideAndBeModelB) {
  InclineSynthOptions o;
  o.params.v0 = 0;
  o.params.mu = 0.634;
  o.params.phi = incline::deg_to_rad(20);  // tan(20 deg) = 0.36 < mu: the disc stays
  EXPECT_NE(o.validate().find("stays"), std::string::npos);
  o.params.phi = incline::deg_to_rad(41);
  EXPECT_TRUE(o.validate().empty());
  o.params.normal_accel = 0.2;
  EXPECT_NE(o.validate().find("normal_accel"), std::string::npos);
  EXPECT_THROW(synthesize_incline_run(o), InputError);
}

}  // namespace
}  // namespace tribolab::analysis
