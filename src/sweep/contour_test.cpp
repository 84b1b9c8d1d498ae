#include "sweep/contour.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sweep/synthetic.hpp"

namespace tribolab::sweep {
namespace {

GridSpec seed_grid(std::int64_t n_theta, std::int64_t n_omega) {
  GridSpec g;
  g.axes = {Axis{Quantity::theta_deg, 100, 170, n_theta}, Axis{Quantity::omega, 30, 50, n_omega}};
  return g;
}

/// Plain bisection on the cell function along one coordinate, independent of TOMS748.
double bisect(const std::function<double(double)>& f, double a, double b, double tol) {
  double fa = f(a);
  while (std::abs(b - a) > tol) {
    const double m = 0.5 * (a + b);
    const double fm = f(m);
    if ((fm >= 0) == (fa >= 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

TEST(Contour, WaveBoundaryIsTheKnownCurveAndAgreesWithBisection) {
  const GridSpec g = seed_grid(15, 9);
  const CellModel m = synthetic::wave_model();
  const std::vector<double> v = evaluate_grid(g, m);
  ContourOptions o;
  o.x_tol_rel = 1e-10;
  const ContourResult c = trace_contour(g, m, v, o);
  ASSERT_EQ(c.lines.size(), 1u);  // the curve omega = 40 + 5 sin(2 theta) crosses the map once
  EXPECT_FALSE(c.lines[0].closed);
  EXPECT_EQ(c.unrefined, 0);
  EXPECT_GT(c.evaluations, 0);
  // Points are ordered along the curve: theta moves monotonically from one end to the other.
  const auto& pts = c.lines[0].points;
  ASSERT_GT(pts.size(), 14u);
  const double dir = pts.back().theta_deg - pts.front().theta_deg;
  EXPECT_NEAR(std::abs(dir), 70, 1e-12);
  for (std::size_t k = 1; k < pts.size(); ++k) {
    EXPECT_GE((pts[k].theta_deg - pts[k - 1].theta_deg) * dir, 0);
  }
  const double spacing_theta = 5, spacing_omega = 2.5;
  for (const ContourPoint& p : pts) {
    EXPECT_TRUE(p.refined);
    // The root lies on a grid edge: either theta or omega is a grid value.
    const bool on_theta_line = std::abs(std::remainder(p.theta_deg - 100, spacing_theta)) < 1e-9;
    const bool on_omega_line = std::abs(std::remainder(p.spin - 30, spacing_omega)) < 1e-9;
    ASSERT_TRUE(on_theta_line || on_omega_line);
    // Independent check: bisection on single cells along the same edge. TOMS748 stops when
    // its bracket is below x_tol_rel * spacing; bisection to 1e-13 of the spacing; their
    // roots agree to the larger of the two (plus rounding).
    // A point whose spin is a grid value lies on an edge along theta (theta was solved
    // for); otherwise on an edge along spin.
    if (!on_omega_line) {
      auto f = [&](double w) { return m.evaluate(g.at({p.theta_deg, w}))[3] - 1; };
      const double lo = 30 + spacing_omega * std::floor((p.spin - 30) / spacing_omega);
      const double r = bisect(f, lo, std::min(50.0, lo + spacing_omega), 1e-13 * spacing_omega);
      EXPECT_NEAR(p.spin, r, 1e-10 * spacing_omega + 1e-12);
    } else {
      auto f = [&](double t) { return m.evaluate(g.at({t, p.spin}))[3] - 1; };
      const double lo = 100 + spacing_theta * std::floor((p.theta_deg - 100) / spacing_theta);
      const double r = bisect(f, lo, std::min(170.0, lo + spacing_theta), 1e-13 * spacing_theta);
      EXPECT_NEAR(p.theta_deg, r, 1e-10 * spacing_theta + 1e-12);
    }
    // And the analytic curve, whose e = 1 exactly: |omega - c(theta)| within the root
    // tolerance times the slope |d omega / d theta| <= 5 * pi/90 per degree.
    EXPECT_NEAR(p.spin, synthetic::wave_threshold(p.theta_deg, 4, 0.5), 1e-9);
  }
}

TEST(Contour, UnrefinedPointsAreLinearInterpolation) {
  const GridSpec g = seed_grid(15, 9);
  const CellModel m = synthetic::wave_model();
  ContourOptions o;
  o.refine = false;
  const ContourResult c = trace_contour(g, m, evaluate_grid(g, m), o);
  ASSERT_EQ(c.lines.size(), 1u);
  EXPECT_EQ(c.evaluations, 0);
  EXPECT_EQ(c.unrefined, static_cast<std::int64_t>(c.lines[0].points.size()));
  // Linear interpolation of an exponential over a 2.5 rad/s cell: error below
  // (2.5/2)^2/2 * max|f''/f'| = 0.78 * 0.2 ~ 0.16 rad/s; well within a cell, never exact.
  for (const ContourPoint& p : c.lines[0].points) {
    EXPECT_NEAR(p.spin, synthetic::wave_threshold(p.theta_deg, 4, 0.5), 0.2);
  }
}

TEST(Contour, EllipseGivesOneClosedLoop) {
  const GridSpec g = seed_grid(36, 41);
  const CellModel m = synthetic::ellipse_model();
  const ContourResult c = trace_contour(g, m, evaluate_grid(g, m), ContourOptions{});
  ASSERT_EQ(c.lines.size(), 1u);
  const Polyline& loop = c.lines[0];
  EXPECT_TRUE(loop.closed);
  EXPECT_EQ(loop.points.front().theta_deg, loop.points.back().theta_deg);
  EXPECT_EQ(loop.points.front().spin, loop.points.back().spin);
  for (const ContourPoint& p : loop.points) {
    const double u = (p.theta_deg - 135) / 20, w = (p.spin - 40) / 5;
    // On the ellipse u^2 + w^2 = 0.5 to the root tolerance (1e-9 of a 2-deg or 0.5-rad/s
    // cell) times |grad| <= 2*0.71/5 per unit: 1e-9 is ample.
    EXPECT_NEAR(u * u + w * w, 0.5, 1e-9);
  }
}

TEST(Contour, SaddleSquaresAreResolvedByTheCentreValue) {
  const GridSpec g = seed_grid(15, 9);
  const CellModel m = synthetic::saddle_model();
  const ContourResult c = trace_contour(g, m, evaluate_grid(g, m), ContourOptions{});
  // theta = 131.3 and omega = 41.7 cross inside one square. Marching squares cannot draw
  // a crossing: the centre value pairs the four half-lines into two bent open curves,
  // each made of part of both lines, meeting nowhere.
  ASSERT_EQ(c.lines.size(), 2u);
  for (const Polyline& l : c.lines) {
    EXPECT_FALSE(l.closed);
    bool on_theta = false, on_omega = false;
    for (const ContourPoint& p : l.points) {
      const double dt = std::abs(p.theta_deg - 131.3), dw = std::abs(p.spin - 41.7);
      EXPECT_LT(std::min(dt, dw), 1e-9);  // on the union of the two lines
      on_theta = on_theta || dt < 1e-9;
      on_omega = on_omega || dw < 1e-9;
    }
    EXPECT_TRUE(on_theta && on_omega);
  }
  // The saddle square is [130, 135] x [40, 42.5]; its centre (132.5, 41.25) has
  // e - 1 = 1.2 * (-0.45) / 100 < 0, so the two e >= 1 corners are cut off and each curve
  // links an end on theta = 131.3 with an end on omega = 41.7 in the same e >= 1 quadrant
  // (theta < 131.3 with omega < 41.7, or theta > 131.3 with omega > 41.7).
  for (const Polyline& l : c.lines) {
    const ContourPoint &a = l.points.front(), &b = l.points.back();
    const bool a_on_theta = std::abs(a.theta_deg - 131.3) < 1e-9;
    const bool b_on_theta = std::abs(b.theta_deg - 131.3) < 1e-9;
    EXPECT_NE(a_on_theta, b_on_theta);
    const ContourPoint& t_end = a_on_theta ? a : b;  // end on the theta = 131.3 line
    const ContourPoint& w_end = a_on_theta ? b : a;  // end on the omega = 41.7 line
    EXPECT_EQ(t_end.spin > 41.7, w_end.theta_deg > 131.3);  // same quadrant
  }
}

TEST(Contour, ThreadCountDoesNotChangeThePoints) {
  const GridSpec g = seed_grid(36, 41);
  const CellModel m = synthetic::ellipse_model();
  const std::vector<double> v = evaluate_grid(g, m);
  ContourOptions o1, o7;
  o1.threads = 1;
  o7.threads = 7;
  const ContourResult a = trace_contour(g, m, v, o1), b = trace_contour(g, m, v, o7);
  ASSERT_EQ(a.lines.size(), b.lines.size());
  for (std::size_t l = 0; l < a.lines.size(); ++l) {
    ASSERT_EQ(a.lines[l].points.size(), b.lines[l].points.size());
    for (std::size_t k = 0; k < a.lines[l].points.size(); ++k) {
      EXPECT_EQ(a.lines[l].points[k].theta_deg, b.lines[l].points[k].theta_deg);
      EXPECT_EQ(a.lines[l].points[k].spin, b.lines[l].points[k].spin);
    }
  }
}

TEST(Contour, NaNCellsAreSkipped) {
  const GridSpec g = seed_grid(15, 9);
  const CellModel m = synthetic::wave_model();
  std::vector<double> v = evaluate_grid(g, m);
  v[(7 * 9 + 4) * 4 + 3] = std::nan("");  // one failed cell in the middle of the curve
  const ContourResult c = trace_contour(g, m, v, ContourOptions{});
  for (const Polyline& l : c.lines) {
    for (const ContourPoint& p : l.points) {
      EXPECT_NEAR(p.spin, synthetic::wave_threshold(p.theta_deg, 4, 0.5), 1e-9);
    }
  }
  EXPECT_GE(c.lines.size(), 1u);
}

TEST(Contour, SlicesOfSpeedAndMuAreTracedSeparately) {
  GridSpec g;
  g.axes = {Axis{Quantity::speed, 4, 5, 2}, Axis{Quantity::mu, 0.3, 0.7, 2},
            Axis{Quantity::theta_deg, 100, 170, 15}, Axis{Quantity::omega, 30, 55, 11}};
  const CellModel m = synthetic::wave_model();
  const ContourResult c = trace_contour(g, m, evaluate_grid(g, m), ContourOptions{});
  ASSERT_EQ(c.slice_values.size(), 4u);
  ASSERT_EQ(c.slice_quantities.size(), 2u);
  ASSERT_EQ(c.lines.size(), 4u);
  for (const Polyline& l : c.lines) {
    const double speed = c.slice_values[static_cast<std::size_t>(l.slice)][0];
    const double mu = c.slice_values[static_cast<std::size_t>(l.slice)][1];
    for (const ContourPoint& p : l.points) {
      EXPECT_NEAR(p.spin, synthetic::wave_threshold(p.theta_deg, speed, mu), 1e-9);
    }
  }
}

TEST(Thresholds, SpinThresholdAndEnergyRatioPerAngle) {
  const GridSpec g = seed_grid(15, 21);
  const CellModel m = synthetic::wave_model();
  const std::vector<Threshold> t = spin_thresholds(g, m, evaluate_grid(g, m), ContourOptions{});
  ASSERT_EQ(t.size(), 15u);
  for (const Threshold& r : t) {
    ASSERT_EQ(r.status, Threshold::Status::found) << r.theta_deg;
    const double w = synthetic::wave_threshold(r.theta_deg, 4, 0.5);
    EXPECT_NEAR(r.omega, w, 1e-9 * 20);  // root tolerance: 1e-9 of the 1 rad/s spacing
    EXPECT_DOUBLE_EQ(r.ratio, r.omega / 4);
    // (I w^2 / 2) / (m vy^2 / 2), the seed's rotational / vertical kinetic energy.
    EXPECT_DOUBLE_EQ(r.energy_ratio, 4.1e-3 * r.omega * r.omega / (0.435 * 16));
  }
}

TEST(Thresholds, BelowGridAndNoneAreReported) {
  GridSpec g = seed_grid(3, 5);
  g.axes[1] = Axis{Quantity::omega, 50, 60, 5};  // e > 1 everywhere: threshold below the grid
  const CellModel m = synthetic::wave_model();
  for (const Threshold& r : spin_thresholds(g, m, evaluate_grid(g, m), ContourOptions{})) {
    EXPECT_EQ(r.status, Threshold::Status::below_grid);
    EXPECT_TRUE(std::isnan(r.omega));
  }
  g.axes[1] = Axis{Quantity::omega, 0, 20, 5};  // e < 1 everywhere
  for (const Threshold& r : spin_thresholds(g, m, evaluate_grid(g, m), ContourOptions{})) {
    EXPECT_EQ(r.status, Threshold::Status::none);
    EXPECT_TRUE(std::isnan(r.energy_ratio));
  }
}

TEST(Thresholds, RatioAxisGivesTheSeedsRatioMap) {
  GridSpec g;
  g.fixed_speed = 8;  // seed figure 54/55: |vy| = 8 m/s, spin/speed on the y axis
  g.axes = {Axis{Quantity::theta_deg, 100, 170, 8}, Axis{Quantity::ratio, 3, 8, 11}};
  const CellModel m = synthetic::wave_model();
  for (const Threshold& r : spin_thresholds(g, m, evaluate_grid(g, m), ContourOptions{})) {
    ASSERT_EQ(r.status, Threshold::Status::found);
    EXPECT_NEAR(r.omega, synthetic::wave_threshold(r.theta_deg, 8, 0.5), 1e-8);
    EXPECT_NEAR(r.ratio * 8, r.omega, 1e-12);
  }
}

}  // namespace
}  // namespace tribolab::sweep
