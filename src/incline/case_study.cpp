#include "incline/case_study.hpp"

#include "incline/inverse.hpp"
#include "numerics/units.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace tribolab::incline {
namespace {

constexpr double kG = kDefaultG;  // the seed's g, m/s^2

Parameters setup(double mu, double phi_deg, double v0) {
  Parameters p;
  p.mu = mu;
  p.phi = to_rad(phi_deg);
  p.v0 = v0;
  p.g = kG;
  return p;
}

PrintedCheck check(std::string where, double printed, double computed, double tolerance,
                   std::string note) {
  PrintedCheck c;
  c.where = std::move(where);
  c.printed = printed;
  c.computed = computed;
  c.tolerance = tolerance;
  c.agrees = std::abs(printed - computed) <= tolerance;
  c.note = std::move(note);
  return c;
}

}  // namespace

double mu_from_slide_acceleration(double phi, double a, double g) {
  return (g * std::sin(phi) - a) / (g * std::cos(phi));  // seed 000, eq (a)
}

namespace {

/// Table 1 (表一), seed 000 陸-四-5: mu_A from each column's stop, and its printed-number checks.
void add_table1(CaseStudy& cs) {
  struct Col { double phi, x, y, mu_a, diff; };
  const Col cols[] = {{4.82, 0.478, 0.034, 0.601, -5.21}, {10.37, 0.214, 0.036, 0.588, -7.26},
                      {14.48, 0.594, 0.142, 0.624, -1.58}, {20.96, 0.659, 0.273, 0.648, 2.21},
                      {23.20, 0.506, 0.277, 0.636, 0.32}};
  for (const Col& c : cols) {
    StopMeasurement m;
    m.phi = to_rad(c.phi);
    m.x_stop = c.x;
    m.y_stop = -c.y;
    Table1Row row;
    row.phi_deg = c.phi;
    row.x_stop = c.x;
    row.y_stop = -c.y;
    row.mu_printed = c.mu_a;
    row.mu = mu_from_stop(m).mu;
    row.diff_percent_printed = c.diff;
    row.diff_percent = 100 * (row.mu - cs.mu_o) / cs.mu_o;
    cs.table1.push_back(row);
    char label[64];
    std::snprintf(label, sizeof label, "table 1 (表一) mu_A at phi = %.2f deg", c.phi);
    cs.checks.push_back(check(label,
                              c.mu_a, row.mu, 0.0005, "eq 10A (十A) solved by bracketing the cubic"));
  }
}

/// Figure 八 (phi = 10.37 deg, mu = 0.585): slopes per unit v_x0 (t_f) and v_x0^2 (x_f, y_f).
void add_figure8_checks(CaseStudy& cs) {
  const Prediction p8 = ClosedForm(setup(0.585, 10.37, 1.0)).predict();
  cs.checks.push_back(check("figure 8-2 (圖八-2) theory slope t_f / v_x0 (phi 10.37 deg, mu 0.585), s^2/m",
                            0.2242, *p8.t_stop, 0.00005, "eq 7 (七) at v_x0 = 1 m/s"));
  cs.checks.push_back(check("figure 8-4 (圖八-4) theory slope x_f / v_x0^2, s^2/m", 0.0948, *p8.x_stop, 0.00005,
                            "eq 8 (八) at v_x0 = 1 m/s"));
  cs.checks.push_back(check("figure 8-4 (圖八-4) theory slope y_f / v_x0^2, s^2/m", -0.0155, *p8.y_stop, 0.00005,
                            "eq 9 (九) at v_x0 = 1 m/s (-0.01554 at phi = 10.46 deg)"));
  const Prediction p85 = ClosedForm(setup(0.585, 10.46, 1.0)).predict();
  cs.checks.push_back(check("figure 8-5 (圖八-5) theory slope y_f / x_f (phi 10.46 deg, mu 0.585)", -0.2123,
                            *p85.y_stop / *p85.x_stop, 0.00005, "eq 10 (十)"));
  // Unlike 圖八-2/4's 7.99 % and 1.02 % (and 伍-一-(三)'s 2.76 %), this difference is taken relative to
  // the measured slope: 0.0129/0.1994 = 6.469 % (relative to the theory slope it would be 6.08 %).
  cs.checks.push_back(check("figure 8-5 (圖八-5) printed difference of -0.1994 from -0.2123, relative to "
                            "-0.1994, %", 6.47, 100 * (0.2123 - 0.1994) / 0.1994, 0.005,
                            "arithmetic on the printed slopes"));
}

/// Figure 五 (phi = 20.96 deg, mu = 0.634): initial and final accelerations; figures 6, 7, 3-2.
void add_figure5_checks(CaseStudy& cs) {
  const Parameters s5 = setup(0.634, 20.96, 2.62);
  const Prediction p5 = ClosedForm(s5).predict();
  cs.checks.push_back(check("figure 5-4X (圖五-4X) a_x0 = -g mu cos phi, m/s^2", -5.80, p5.a_x0, 0.005, "eq 1.1a"));
  // The study never states g. Its -5.80, -3.50 and 2.30 all hold for g between 9.794 and 9.798 m/s^2,
  // its 3.856 (below) for g between 9.787 and 9.789: consistent with g = 9.79, not with 9.8.
  cs.checks.push_back(check("figure 5-4Y (圖五-4Y) a_y0 = -g sin phi with g = 9.795 (the study states no g), m/s^2",
                            -3.50, -9.795 * std::sin(to_rad(20.96)), 0.005,
                            "eq 1.2a at theta = 90 deg; g = 9.8 gives -3.506"));
  cs.checks.push_back(check("figure 5-4Y (圖五-4Y) a_yf = g mu cos phi - g sin phi, m/s^2", 2.30, p5.a_y_final, 0.005,
                            "limit of eq 4 (四)"));
  cs.checks.push_back(check("section 5-1-(3)-1 (伍-一-(三)-1) g sin(23.20 deg) with g = 9.788 (the study states no g), "
                            "m/s^2", 3.856, 9.788 * std::sin(to_rad(23.20)), 0.0005,
                            "direct; g = 9.8 gives 3.861"));
  cs.checks.push_back(check("figure 6 (圖六) boundary atan(0.634), deg", 32.39, to_deg(std::atan(0.634)), 0.005,
                            "k = 1"));
  cs.checks.push_back(check("figure 7 (圖七) boundary tan(20.96 deg)", 0.383, std::tan(to_rad(20.96)), 0.0005,
                            "k = 1"));
  cs.checks.push_back(check("figure 3-2 (圖三-2) 1/slope = 1/1.5746", 0.635, 1 / 1.5746, 0.0005, "direct"));
}

/// Setups of figures 二-八 evaluated with the closed form.
void add_setups(CaseStudy& cs) {
  auto add = [&](std::string fig, const Parameters& p) {
    cs.setups.push_back({std::move(fig), p, ClosedForm(p).predict()});
  };
  add("figures 2/4 (圖二/四) (phi 23.20 deg, mu 0.634, v0 2.30 m/s)", setup(0.634, 23.20, 2.30));
  add("figure 5 (圖五) (phi 20.96 deg, mu 0.634, v0 2.62 m/s)", setup(0.634, 20.96, 2.62));
  add("figure 6 (圖六) (phi = atan 0.634 = 32.37 deg: k = 1, v0 2.62 m/s)",
      [] { Parameters p = setup(0.634, 0, 2.62); p.phi = std::atan(0.634); return p; }());
  add("figure 6 (圖六) (phi 40 deg, mu 0.634, v0 2.62 m/s)", setup(0.634, 40.0, 2.62));
  add("figure 6A (圖六A) (phi 20.0 deg, mu 0.583, v0 2.20 m/s)", setup(0.583, 20.0, 2.20));
  add("figure 7 (圖七) (phi 20.96 deg, mu 0, v0 2.62 m/s: smooth incline)", setup(0.0, 20.96, 2.62));
  add("figure 7A (圖七A) (phi 23.20 deg, mu 0.634, v0 2.30 m/s)", setup(0.634, 23.20, 2.30));
  add("figure 8 (圖八) (phi 10.37 deg, mu 0.585, v0 1 m/s: slopes per unit v0)", setup(0.585, 10.37, 1.0));
}

/// The seed's errata, one line each (also in docs/theory.md).
std::vector<std::string> errata() {
  return {
      "incline study, appendix 11 (十一) (A2): the integral of x cosh(a + b ln x) has denominator b^2 - 4, "
      "not 4 - b^2 (differentiate the result); eq 3.1 uses the correct sign.",
      "incline study, appendix 10 (十): A = 4/(3r) + 512/(27 r^3); the first line prints -512/(27 r^3), and "
      "the discriminant is -16(12 r^4 + 183 r^2 + 768)/(81 r^4), not ...+1280 r^2; it is < 0 "
      "either way, so three real roots.",
      "incline study, section 6-4 (陸-四) (10A (十A)) in the main text puts -2 pi outside the 1/3, which selects the root "
      "k > 2 (mu 16x too small in the first column of table 1 (表一), 6.9-8.5x in the others); the appendix (10.6) is right.",
      "incline study, eq (1.3) in the main text (section 5-2 (伍-二)): tan(theta) = v_x/(-v_y) = xdot/ydot loses the minus "
      "sign of -v_y in its last member; appendix 1 (附錄一) has it right (xdot/(-ydot)).",
      "incline study, eq (1.2a) drops mu: a_y = g mu cos(phi) cos(theta) - g sin(phi).",
      "incline study, figure 8-2 (圖八-2): theory slope t_f/v_x0 at phi = 10.37 deg, mu = 0.585 is 0.1966 s^2/m "
      "(eq 7 (七)), not 0.2242.",
      "incline study, figure 8-4 (圖八-4): x_f/v_x0^2 is 0.0909 s^2/m (eq 8 (八)), not 0.0948; y_f/v_x0^2 is -0.0154 "
      "(-0.0155 at 10.46 deg).",
      "incline study, figure 8-5 (圖八-5): y_f/x_f at phi = 10.46 deg, mu = 0.585 is -0.1709 (eq 10 (十)), not -0.2123.",
      "incline study, section 5-1-(3) (伍-一-(三)), figure 3-1 (圖三-1): its text gives the angle as 23.02 deg, the "
      "summary of the same figure and the g sin phi = 3.856 23.20 deg. (Not an erratum: 3.856 = g sin(23.20 deg) and figure 5-4 (圖五-4)'s "
      "-5.80, -3.50 and 2.30 m/s^2 are consistent with g = 9.79, not with 9.8 (they hold for g = 9.787-9.789 and "
      "9.794-9.798; 9.8 would give 3.861 and -3.51; the study never states g).)",
      "incline study, table 1 (表一): at phi = 4.82 deg, eq 10A (十A) gives mu_A = 0.6017 (0.602), printed 0.601 "
      "(the other four columns agree to the printed digits).",
      "incline study, figure 6 (圖六): atan(0.634) = 32.37 deg (printed 32.39). section 5-3-(3)-4 (3) (伍-三-(三)-4 (3)), on the v_y of figure 7-3 (圖七-3), reads "
      "mu <= 0.383 where mu < 0.383 is meant (mu = 0.383 is its case (2)); figure 7-4Y (圖七-4Y)'s case (3) rightly reads mu < 0.383.",
      "incline study, at the equality mu = tan(phi) (k = 1): section 5-3-(3)-2 (伍-三-(三)-2) says y comes to rest for mu >= 0.383, but at "
      "mu = 0.383 v_y = (v_x0/2)(u^2 - 1) tends to -v_x0/2 and y falls for ever (the stop needs mu > tan(phi), as "
      "section 6-1 (陸-一) derives); and v_y has no extremum there (sections 5-3-(2)-3 (2) and 5-3-(3)-4 (2) (伍-三-(二)-3 (2), 伍-三-(三)-4 (2))): a_y = -2 alpha u^2/(1 + u^2) < 0 "
      "throughout (closed form and numerical integration).",
      "incline study, figures 6-1 and 7-1 (圖六-1, 圖七-1): x does not always tend to a constant 'stopping position'. x has a finite limit "
      "only for k = tan(phi)/mu < 2 (2 v_x0^2/(alpha (4 - k^2)), eq 8 (八) as t -> infinity), and it is a stop only for "
      "k < 1; for k >= 2 x grows without bound (like t^((k-2)/(k-1))): mu <= 0.192 at figure 7 (圖七)'s 20.96 deg (mu = 0 "
      "gives x = v0 t, as figure 7-1 (圖七-1) itself says), phi >= 51.7 deg at figure 6 (圖六)'s mu = 0.634. Appendices 7-9 (七-九) take the "
      "limits without the conditions k < 1 (七, 九) and k < 2 (八) (numerical integration to 800 s).",
      "incline study, appendix typos: appendix 1 (附錄一) drops a sign (sqrt(alpha^2 - a_x^2)/a_x = -sqrt((alpha/a_x)^2 - 1) for a_x < 0, "
      "so z of (1.8) comes out negative; harmless, only cosh enters (1.10)) and writes -(beta/alpha) dv_x for "
      "-(beta/v_x) dv_x after (1.8); appendix 4 (附錄四) is headed a_x - v_x for equation 4 (式四), which is a_y, and quotes (1.4) as "
      "-beta + sqrt(alpha^2 - xdot^2), with the velocity xdot for the acceleration xddot (appendix 1 (附錄一) has xddot^2, "
      "and the next line substitutes xddot); appendix 5 (附錄五) quotes (2.2) with "
      "denominator alpha^2 - beta^2 instead of (alpha^2 - beta^2)/alpha; appendix 7 (附錄七) puts a minus before the limit that "
      "vanishes in the (right) result; appendix 9 (附錄九) writes (beta-1)/alpha, (beta+1)/alpha for beta/alpha -/+ 1 "
      "(each step checked symbolically).",
      "incline study, figure 8 (圖八): inverted with the correct eqs 7-10 (七-十), the measured slopes give mu = 0.562 (t_f/v_x0 = 0.2063), "
      "0.556 (x_f/v_x0^2 = 0.0958), 0.567 (y_f/v_x0^2 = -0.0165) and 0.514 (y_f/x_f = -0.1994 at 10.46 deg): mean "
      "0.550, sd 0.024, all below the 0.585 the study compares with; against the correct theory slopes at 0.585 "
      "(0.1966, 0.09089, -0.01537, -0.1709) the measurements differ by 5 %, 5 %, 7 % and 17 %.",
      "incline study, section 4-2-(1) (肆-二-(一)), eq b: with cos(theta) = v_y/|v| as printed, a_y sin(theta) - a_x "
      "cos(theta) has the opposite sign of eq b; consistent with eq 1.3 is cos(theta) = -v_y/|v|, "
      "i.e. a_N = (a_x v_y - a_y v_x)/|v| (on simulated model B runs this a_N has slope g sin(phi) through the origin).",
      "incline study, section 4-2-(2) (肆-二-(二)): cos(theta_c) = v_yc/|v| is negative on the way down while eq c makes it "
      "tan(phi)/mu > 0; it is |v_yc|/|v| (on simulated model B runs it equals tan(phi)/mu).",
  };
}

}  // namespace

CaseStudy seed000_case_study() {
  CaseStudy cs;
  cs.mu_o_from_eq_a = mu_from_slide_acceleration(to_rad(41.09), 1.758, kG);

  add_table1(cs);

  cs.checks.push_back(check("section 5-1-(1) (伍-一-(一)) mu_o from eq (a), phi = 41.09 deg, a = 1.758 m/s^2",
                            0.634, cs.mu_o_from_eq_a, 0.0005, "(g sin phi - a)/(g cos phi)"));

  add_figure8_checks(cs);
  add_figure5_checks(cs);
  add_setups(cs);
  cs.errata = errata();
  return cs;
}

}  // namespace tribolab::incline
