#!/usr/bin/env python3
"""Independent checks of seed 000's errata found on the second reading (docs/theory.md).

1. Figure 八: the measured slopes inverted for mu with the printed eqs 七, 八, 九, 十 (bisection).
2. k = 1 and the x limit: model B integrated by RK4 (v-hat = v/|v|, friction g mu cos phi).
3. Appendix steps checked symbolically (needs sympy; skipped without it).
4. Seed 001: e from centre heights vs e from velocities at touch and separation.
5. The referee's rechecks (2026-12-01): 圖八-5's 6.47 %, the g behind 3.856 / 圖五-4, eq 十A's
   wrong root per column, seed 001's group 1 e, group 2's pre-impact fit, n, eqs 5, 9 and 17.
Output (2026-11-29):
  t_f/v0 0.2063 -> mu 0.562381, x_f/v0^2 0.0958 -> 0.556460, y_f/v0^2 -0.0165 -> 0.566662,
  y_f/x_f -0.1994 (10.46 deg) -> 0.514290; mean 0.5499, sd 0.0241; both 八-4 slopes -> 0.5760
  k = 1 (mu = tan 20.96 deg): vy(20 s) = -1.3100 = -v0/2; k = 2.5: x(800)/x(100) = 2.19;
  k = 1.9: x(10) = 5.13 m < limit 19.08 m
  appendix: A1, A3, A4 right, A2 sign wrong; (1.7) sign; (2.2) as quoted in 五 wrong; 九 ok
  e_height / e_velocity for H = H' = 0.7 m, Y_in = a, Y_out = b: 1/1.044
Output of 5 (2026-12-01):
  圖八-5: 0.0129/0.1994 = 6.469 %; g ranges: 3.856 [9.7870, 9.7895], -3.50 [9.7703, 9.7983],
  -5.80 [9.7881, 9.8049], 2.30 [9.7938, 9.8365]; 十A mu ratios 15.988 8.541 7.309 6.928 7.424;
  group 1 e = 1.2071; group 2 a = -8.10 (17.3 % below 9.8), centres 8.84 cm apart at 0.425 s;
  n: 0.667 % (0.662 % relative to 1.51); eq 9 B2 needs +2x sin cos; eq 17 needs -; (1.4) with xdd
"""
import math

G = 9.8


def bisect(f, a, b, it=200):
    fa = f(a)
    for _ in range(it):
        m = 0.5 * (a + b)
        fm = f(m)
        if (fm > 0) == (fa > 0):
            a, fa = m, fm
        else:
            b = m
    return 0.5 * (a + b)


def slopes(mu, phi_deg):
    """Printed eqs 七, 八, 九 per unit v_x0 (t) and v_x0^2 (x, y), and eq 十 (y/x)."""
    p = math.radians(phi_deg)
    c, s, k = math.cos(p), math.sin(p), math.tan(p) / mu
    t = mu * c / (G * (mu * mu * c * c - s * s))
    x = -2 / (G * mu * c * (k * k - 4))
    y = k / (4 * G * mu * c * (k * k - 1))
    return t, x, y, y / x


def figure8():
    meas = [(0, 10.37, 0.2063), (1, 10.37, 0.0958), (2, 10.37, -0.0165), (3, 10.46, -0.1994)]
    mus = []
    for i, phi, m in meas:
        lo = math.tan(math.radians(phi)) * (1 + 1e-7)
        mus.append(bisect(lambda mu: slopes(mu, phi)[i] - m, lo, 5.0))
    mean = sum(mus) / 4
    sd = math.sqrt(sum((u - mean) ** 2 for u in mus) / 3)
    both = bisect(lambda mu: slopes(mu, 10.37)[3] + 0.0165 / 0.0958, math.tan(math.radians(10.37)) * (1 + 1e-7), 5.0)
    print("figure 八: mu =", ["%.6f" % u for u in mus], "mean %.4f sd %.4f; 八-4 ratio -> %.4f" % (mean, sd, both))


def model_b(mu, phi_deg, v0, T, h):
    p = math.radians(phi_deg)
    al, be = G * mu * math.cos(p), G * math.sin(p)

    def f(s):
        v = math.hypot(s[2], s[3])
        return [s[2], s[3], -al * s[2] / v, -al * s[3] / v - be]
    s, t = [0.0, 0.0, v0, 0.0], 0.0
    while t < T - 1e-12:
        k1 = f(s)
        k2 = f([s[i] + h / 2 * k1[i] for i in range(4)])
        k3 = f([s[i] + h / 2 * k2[i] for i in range(4)])
        k4 = f([s[i] + h * k3[i] for i in range(4)])
        s = [s[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]) for i in range(4)]
        t += h
    return s


def limits():
    phi, v0 = 20.96, 2.62
    tp = math.tan(math.radians(phi))
    print("k = 1: vy(20 s) = %.4f (-v0/2 = %.4f)" % (model_b(tp, phi, v0, 20, 1e-3)[3], -v0 / 2))
    a, b = model_b(tp / 2.5, phi, v0, 100, 1e-2)[0], model_b(tp / 2.5, phi, v0, 800, 1e-2)[0]
    print("k = 2.5: x(100) = %.2f m, x(800) = %.2f m, ratio %.3f (t^(1/3): 2)" % (a, b, b / a))
    al = G * tp / 1.9 * math.cos(math.radians(phi))
    print("k = 1.9: x(10) = %.3f m, limit 2 v0^2/(alpha(4-k^2)) = %.3f m" %
          (model_b(tp / 1.9, phi, v0, 10, 1e-3)[0], 2 * v0 * v0 / (al * (4 - 1.9 ** 2))))


def appendix():
    try:
        import sympy as sp
    except ImportError:
        print("appendix: sympy not available, skipped")
        return
    x, a, b, al, be, xd, xd0 = sp.symbols("x a b alpha beta xd xd0", positive=True)
    u = a + b * sp.log(x)
    for name, F, f in [("A1", x * (b * sp.sinh(u) - sp.cosh(u)) / (b ** 2 - 1), sp.cosh(u)),
                       ("A2 printed", x ** 2 * (b * sp.sinh(u) - 2 * sp.cosh(u)) / (4 - b ** 2), x * sp.cosh(u)),
                       ("A2 b^2-4", x ** 2 * (b * sp.sinh(u) - 2 * sp.cosh(u)) / (b ** 2 - 4), x * sp.cosh(u)),
                       ("A3", x * (b * sp.cosh(u) - sp.sinh(u)) / (b ** 2 - 1), sp.sinh(u)),
                       ("A4", x ** 2 * (b * sp.cosh(2 * u) - sp.sinh(2 * u)) / (4 * (b ** 2 - 1)),
                        x * sp.sinh(u) * sp.cosh(u))]:
        print("appendix 十一", name, "right" if sp.simplify((sp.diff(F, x) - f).rewrite(sp.exp)) == 0 else "WRONG")
    xdd = sp.symbols("xdd", negative=True)
    print("附錄一 (1.7): sqrt(al^2 - xdd^2)/xdd + sqrt((al/xdd)^2 - 1) =",
          sp.simplify(sp.sqrt(al ** 2 - xdd ** 2) / xdd + sp.sqrt((al / xdd) ** 2 - 1)), "(so a sign was dropped)")
    k, s = be / al, (be / al) * sp.log(xd / xd0)
    num = xd * (k * sp.sinh(s) - sp.cosh(s)) + xd0
    for name, t in [("(2.2) of 附錄二", num / ((al ** 2 - be ** 2) / al)), ("(2.2) as quoted in 附錄五", num / (al ** 2 - be ** 2))]:
        ok = sp.simplify((sp.diff(t, xd) + sp.cosh(s) / al).rewrite(sp.exp)) == 0
        print(name, "gives dt/dxd = -cosh/alpha (eq 2.1):", ok)
    lhs = xd ** 2 * (k * sp.cosh(2 * s) - sp.sinh(2 * s))
    rhs = sp.Rational(1, 2) * xd ** 2 * ((k - 1) * sp.exp(2 * s) + (k + 1) * sp.exp(-2 * s))
    print("附錄九 expansion with (beta/alpha -/+ 1):", sp.simplify((lhs - rhs).rewrite(sp.exp)) == 0)


def heights():
    H = Hp = 0.7
    a, b = 0.145, 0.095
    print("seed 001 e_height/e_velocity, H = H' = 0.7 m: touch on the tip, leave on the side: 1/%.3f;"
          " the reverse: 1/%.3f" % (math.sqrt((Hp - b) / (H - a)), math.sqrt((Hp - a) / (H - b))))


def referee():
    """Numbers rechecked on the third (referee's) reading: corrections of our own errata."""
    print("圖八-5: 0.0129/0.1994 = %.3f %% (printed 6.47 %%; relative to -0.2123: %.3f %%)" %
          (100 * 0.0129 / 0.1994, 100 * 0.0129 / 0.2123))
    s23, s21, c21 = math.sin(math.radians(23.20)), math.sin(math.radians(20.96)), math.cos(math.radians(20.96))
    for name, lo, hi in [("3.856 = g sin 23.20", 3.8555 / s23, 3.8565 / s23),
                         ("-3.50 = -g sin 20.96", 3.495 / s21, 3.505 / s21),
                         ("-5.80 = -g mu cos 20.96", 5.795 / (0.634 * c21), 5.805 / (0.634 * c21)),
                         ("2.30 = g (mu cos - sin)", 2.295 / (0.634 * c21 - s21), 2.305 / (0.634 * c21 - s21))]:
        print("  %s holds for g in [%.4f, %.4f]" % (name, lo, hi))
    print("十A main text vs appendix, mu ratio per column of 表一:", end="")
    for phi, x, y in [(4.82, 0.478, 0.034), (10.37, 0.214, 0.036), (14.48, 0.594, 0.142),
                      (20.96, 0.659, 0.273), (23.20, 0.506, 0.277)]:
        r, t = abs(y / x), math.tan(math.radians(phi))
        S = 4 / 3 + 64 / 9 * r * r
        th = math.acos((4 / 3 * r + 512 / 27 * r ** 3) / S ** 1.5)
        main = t / (8 / 3 * r + 2 * math.sqrt(S) * math.cos(th / 3 - 2 * math.pi))
        app = t / (8 / 3 * r + 2 * math.sqrt(S) * math.cos((th - 2 * math.pi) / 3))
        print(" %.3f (%.4f vs %.4f)" % (app / main, main, app), end="")
    print()
    t1, t2 = 0.466, 0.425
    print("seed 001 group 1: e = %.4f (printed 1.20)" % abs((-9.50 * t1 + 8.48) / (-9.48 * t1 + 1.06)))
    pre, post = -4.05 * t2 ** 2 + 0.45 * t2 - 0.06, -4.60 * t2 ** 2 + 7.88 * t2 - 3.03
    print("seed 001 group 2: pre-impact a = -8.10 (%.1f %% below 9.8); centre at %.3f s: %.4f m (pre) vs "
          "%.4f m (post), %.2f cm apart" % (100 * (9.8 - 8.10) / 9.8, t2, pre, post, 100 * (post - pre)))
    print("seed 001 n = 1.51 vs 3/2: %.3f %% (relative to 1.51: %.3f %%)" % (100 * 0.01 / 1.5, 100 * 0.01 / 1.51))
    try:
        import sympy as sp
    except ImportError:
        print("seed 001 eqs 5, 9, 17: sympy not available, skipped")
        return
    x, y, th, a, b, r, ph = sp.symbols("x y theta a b r phi", real=True)
    F = ((x * sp.cos(th) - y * sp.sin(th)) / a) ** 2 + ((y * sp.cos(th) + x * sp.sin(th)) / b) ** 2
    s_, c_ = sp.sin(th), sp.cos(th)
    A = (2 * x * c_ ** 2 - 2 * y * s_ * c_) / a ** 2 + (2 * x * s_ ** 2 + 2 * y * s_ * c_) / b ** 2
    B1 = (2 * y * s_ ** 2 - 2 * x * s_ * c_) / a ** 2
    print("seed 001 eq 6-7: A1 + A2 = dF/dx:", sp.simplify(sp.diff(F, x) - A) == 0)
    for name, B2 in [("printed -2x sin cos", (2 * y * c_ ** 2 - 2 * x * s_ * c_) / b ** 2),
                     ("+2x sin cos", (2 * y * c_ ** 2 + 2 * x * s_ * c_) / b ** 2)]:
        print("seed 001 eq 9, B2 %s: B1 + B2 = dF/dy:" % name, sp.simplify(sp.diff(F, y) - B1 - B2) == 0)
    print("seed 001 eq 5: implicit dy/dx = -(dF/dx)/(dF/dy), i.e. -(A1 + A2)/(B1 + B2)")
    middle_printed = r * sp.sin(ph + th) * c_ + r * s_ * sp.cos(ph + th)
    middle_right = r * sp.sin(ph + th) * c_ - r * s_ * sp.cos(ph + th)
    print("seed 001 eq 17, r sin(phi) = r sin(phi+theta) cos theta -/+ r sin theta cos(phi+theta): printed +:",
          sp.simplify(middle_printed - r * sp.sin(ph)) == 0, "; with -:", sp.simplify(middle_right - r * sp.sin(ph)) == 0)
    al, be, xdd, ydd = sp.symbols("alpha beta xdd ydd", positive=True)
    print("附錄一 (1.4): (ydd + beta)^2 + xdd^2 = alpha^2 gives ydd = -beta + sqrt(alpha^2 - xdd^2):",
          sp.simplify(((-be + sp.sqrt(al ** 2 - xdd ** 2)) + be) ** 2 + xdd ** 2 - al ** 2) == 0)


if __name__ == "__main__":
    figure8()
    limits()
    appendix()
    heights()
    referee()
