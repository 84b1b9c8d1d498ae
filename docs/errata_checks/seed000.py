#!/usr/bin/env python3
"""Independent checks of seed 000's errata found on the second reading (docs/theory.md).

1. Figure 八: the measured slopes inverted for mu with the printed eqs 七, 八, 九, 十 (bisection).
2. k = 1 and the x limit: model B integrated by RK4 (v-hat = v/|v|, friction g mu cos phi).
3. Appendix steps checked symbolically (needs sympy; skipped without it).
4. Seed 001: e from centre heights vs e from velocities at touch and separation.
Output (2026-11-29):
  t_f/v0 0.2063 -> mu 0.562381, x_f/v0^2 0.0958 -> 0.556460, y_f/v0^2 -0.0165 -> 0.566662,
  y_f/x_f -0.1994 (10.46 deg) -> 0.514290; mean 0.5499, sd 0.0241; both 八-4 slopes -> 0.5760
  k = 1 (mu = tan 20.96 deg): vy(20 s) = -1.3100 = -v0/2; k = 2.5: x(800)/x(100) = 2.19;
  k = 1.9: x(10) = 5.13 m < limit 19.08 m
  appendix: A1, A3, A4 right, A2 sign wrong; (1.7) sign; (2.2) as quoted in 五 wrong; 九 ok
  e_height / e_velocity for H = H' = 0.7 m, Y_in = a, Y_out = b: 1/1.044
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


if __name__ == "__main__":
    figure8()
    limits()
    appendix()
    heights()
