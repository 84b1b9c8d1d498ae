// The errata page of the demo: every erratum of docs/theory.md ("Errata in the seeds"), kept
// here as data. Seed 000's come from incline::seed000_case_study() (one source with its
// checks); seed 001's (bounce, sweep) are listed below with the check that shows each.
#include "app/demo/demo.hpp"

#include "incline/case_study.hpp"

#include <ostream>

namespace tribolab::app {

std::vector<Erratum> seed001_errata() {
  return {
      {"rugby-ball study, experiment 1 (實驗一), group 2 arithmetic",
       "The y–t fit before the impact, −4.05 t² + 0.45 t − 0.06, has derivative −8.10 t + 0.45, but the summary and e "
       "use −8.10 t + 0.50 (e = 1.35 with 0.50, 1.33 with 0.45); the printed Δv_y = 6.98 matches neither (6.91, "
       "6.96). The pre-impact fit itself is suspect: its a = −8.10 m/s² is 17 % below g, and at the impact "
       "(t = 0.425 s) it puts the centre at y = −0.600 m, the post-impact fit at −0.512 m, 8.8 cm apart (group 1's "
       "fits agree to 0.45 cm): e = 1.35 is unreliable beyond the 0.45/0.50 slip. Group 1's e computes to 1.2071 "
       "(1.21; printed ≈ 1.20). Group 3 and all four spins follow from the printed fits and periods.",
       "recomputed from the printed fits and periods"},
      {"rugby-ball study, tables 2 and 3 (表二, 表三), row 3",
       "The centre is printed (0.710, 0.299) but the midpoint of A (0.825, 0.124) and B (0.594, 0.295) is "
       "(0.7095, 0.2095); table 3 (表三) used the wrong centre and gives θ = 0.9868 rad instead of 0.637 rad, which would "
       "reverse the spin seen in rows 1–2.",
       "recomputed from the printed tip coordinates"},
      {"rugby-ball study, eq 15 and the formula for Y (experiment 3 (實驗三) 5–7)",
       "The printed depth of the lowest point, Y = |−b[cos²θ + (a/b)² sin²θ]|, gives a²/b (0.221 m for the default "
       "ball) at θ = 90 deg instead of a (0.145 m). The correct depth is Y = sqrt(a² sin²θ + b² cos²θ), which the "
       "the study's own eq 20 uses (as Y²).",
       "the figure 'Depth of the lowest point' in this report (brute-force minimisation over the ellipse)"},
      {"rugby-ball study, experiment 3 (實驗三) 6–7, eqs 5, 9 and 17",
       "Differentiating eq 4 implicitly gives dy/dx = −(A₁ + A₂)/(B₁ + B₂) (eq 5 drops the minus sign; harmless "
       "where it is set to 0); B₂ = (1/b²)[2y cos²θ + 2x sinθ cosθ] (eq 9 prints −2x sinθ cosθ); the middle member of "
       "eq 17 is r sin(φ+θ) cosθ − r sinθ cos(φ+θ) (printed +; its last member y′ cosθ − x′ sinθ is right).",
       "symbolic differentiation and finite differences on the ellipse"},
      {"rugby-ball study, experiment 3 (實驗三) 10–11 (bounds on the contact time)",
       "With sin²θ = 1 the ball lands on a tip of the major axis (Y = a), not the minor one; the bounds are "
       "sqrt(2(H−a)/g) ≤ t ≤ sqrt(2(H−b)/g), not the reverse.",
       "simulated flights (200 random cases)"},
      {"rugby-ball study, table 4",
       "Row 1 (0.350 s) is reproduced (0.3491 s, clockwise spin). Rows 2 and 3 (0.335, 0.356 s) and all three "
       "measured times exceed the latest possible contact sqrt(2(H−b)/g) from an apex at H, so they are not "
       "times from the apex and the 97–98 % 'similarity' compares inconsistent quantities.",
       "Table 4 in this report"},
      {"rugby-ball study, research methods 6 (研究方法 六): the contact law",
       "F = K δ^n + D δ' is called Hunt–Crossley; that is a nonlinear spring with a linear dashpot. Hunt–Crossley "
       "(1975) is K δ^n + D δ^n δ', which is also the form of the study's own fit (101054 x^1.51 + 60423 x^1.51 v). "
       "δ is the instantaneous, not the maximum, deformation. Its n = 1.51 differs from Hertz's 3/2 by 0.67 % "
       "(printed 0.66 %, which divides by 1.51).",
       "docs/theory.md#bounce-normal-laws (Hunt & Crossley 1975, J. Appl. Mech. 42)"},
      {"rugby-ball study, discussion 4 (討論 四): fitted law vs heat maps",
       "In SI units the fitted law N = 101054 d^1.51 (1 + 0.598 d′) gives a central restitution of 0.364 at 4 m/s "
       "(exact relation 1 − e z = (1 + z) exp(−z(1 + e)), z = 0.598 × 4; 0.344 with gravity during the 22 ms "
       "contact). Over the study's map (collision angle 100–170 deg, spin 30–50 rad/s clockwise — the sense that "
       "drives the contact point into the floor —, v_y = −4 m/s, v_x = 0, μ = 0.5) the contact simulation gives "
       "at most e = 0.516 (0.253 at 8 m/s), never e > 1: the study's figures 53–56 cannot come from the law as "
       "printed. An elastic contact (D = 0) reaches at most e = 1.378 on that map (at 125.7 deg and 50 rad/s, its "
       "edge), and e > 1 occurs somewhere on it only for D < 11749 N s/m^2.51 (1.17e4, a fifth of the study's "
       "60423). With counter-clockwise spin: 0.532, 0.328, 1.310 and D < 10920. (Our earlier 0.44, 1.25 and "
       "about 9e3 were wrong.)",
       "bounce sweep over the whole map, refined between grid points, bisection on D; an independent rigid-ellipse "
       "contact in Python (docs/errata_checks/); the maps 'As the study's figure 53' and '... 54' in this report"},
      {"rugby-ball study (sweep), the energy-ratio threshold 2.56",
       "Rebound above the drop height is said to need about 35 rad/s at v_y = 4 m/s and a rotational to vertical "
       "kinetic energy ratio above 2.56. Since I ≤ m a², the ratio is at most (a ω / v_y)² = 1.61 for a = 0.145 m "
       "at 35 rad/s (0.72 with the default I): the two numbers cannot both hold.",
       "bounce sweep --threshold (energy ratio at each angle's threshold); docs/theory.md#sweeps"},
      {"rugby-ball study (sweep), figure 55's z axis",
       "The text of experiment 4 (section 6-4-(2) 8 (陸、四(二) 8)) calls it initial over final speed; the poster and the z = 1 "
       "discussion of figure 56 use final over initial. tribolab's maps use e = −v_y,out / v_y,in. The slides "
       "also invert its y axis (initial centre speed over spin; the text: spin over speed, ω/|v_y|).",
       "the map 'As the study's figure 55' in this report (e = −v_y,out / v_y,in)"},
      {"rugby-ball study, section 5-2 (2) (伍-二 (二)) 1–3 (figure 32)",
       "Item 1 says e < 1 for 180° > θ > 0°, which contains the 100–160° where item 2 says e > 1 in most throws; "
       "item 3 repeats 170–180°. Item 1 presumably means 100° > θ > 0°.",
       "the three items of section 5-2 (2) (伍-二 (二)) against each other"},
      {"rugby-ball study, section 4-4 (3) (肆-四 (三)) and the slides (e from heights)",
       "e = sqrt(H′/H) with H, H′ the centre's apex heights above the floor is said to equal |v_f|/|v_i|. The "
       "centre is at height Y(θ) (b ≤ Y ≤ a) when the contact starts and ends, so the velocity ratio at touch and "
       "separation is sqrt((H′ − Y_out)/(H − Y_in)): for H = H′ = 0.7 m it is 1.044 or 0.958 when the ball touches "
       "on a tip and leaves on its side or the reverse, a ±4 % difference at the e = 1 boundary of figure 32. "
       "sqrt(H′/H) answers the study's question (does the centre rise higher?) but is not the e of the maps.",
       "centre heights against velocities at touch and separation; bounce analyze reports both (e_velocity, "
       "e_height)"},
  };
}

void add_errata_section(report::Report& r, std::ostream& log) {
  auto& s = r.add_section("Errata found in the two studies");
  s.add_paragraph("Every number or formula of the two studies that tribolab found to be wrong, with the independent "
                  "check that shows it. The same list is in docs/theory.md, section \"Errata in the seeds\".");
  const incline::CaseStudy cs = incline::seed000_case_study();
  report::Table t0;
  t0.caption = "The incline study";
  t0.header = {"#", "erratum", "check"};
  int i = 0;
  for (const std::string& e : cs.errata)
    t0.rows.push_back({std::to_string(++i), e,
                       "recomputed in 'Incline: printed numbers checked' and table 1 above where a number is "
                       "involved; independent scripts in docs/errata_checks/"});
  s.add_table(std::move(t0));
  report::Table t1;
  t1.caption = "The rugby-ball study";
  t1.header = {"#", "where", "erratum", "check"};
  i = 0;
  const auto bounce = seed001_errata();
  for (const Erratum& e : bounce) t1.rows.push_back({std::to_string(++i), e.where, e.text, e.check});
  s.add_table(std::move(t1));
  log << "  errata: " << cs.errata.size() << " in the incline study, " << bounce.size() << " in the rugby-ball study\n";
}

}  // namespace tribolab::app
