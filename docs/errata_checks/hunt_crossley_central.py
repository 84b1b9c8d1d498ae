#!/usr/bin/env python3
"""Independent check of seed 001's fitted law in a central impact (docs/theory.md, errata).

N = K d^n (1 + chi d_dot), K = 101054 N/m^1.51, n = 1.51, chi = D/K = 60423/101054 s/m.
Method 1: the exact relation 1 - e z = (1 + z) exp(-z (1 + e)), z = chi v_in, solved by
bisection for the root e in (0, 1/z) (e = -1 is the trivial root).
Method 2: m d'' = -N + m g (d = penetration), classical RK4 with a fixed step, from d = 0,
d' = v_in to the return of d to 0 (linear interpolation inside the last step).
Standard library only. Output (2026-11-29):
  exact   v=4: e = 0.363766008178637   v=8: e = 0.205265577348193
  RK4 v=4 (h = 1e-7 s): g = 0: e = 0.363766008179 (21.497 ms); g = 9.8: e = 0.344376093372
"""
import math

K, N_EXP, D, M = 101054.0, 1.51, 60423.0, 0.435


def exact_restitution(z):
    f = lambda e: 1 - e * z - (1 + z) * math.exp(-z * (1 + e))
    lo, hi = 1e-15, min(1.0, 1 / z) - 1e-15
    flo = f(lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return 0.5 * (lo + hi)


def rk4_central(v_in, g=0.0, h=1e-7):
    def rhs(d, w):
        n = K * d ** N_EXP * (1 + D / K * w) if d > 0 else 0.0
        return w, -max(n, 0.0) / M + g
    d, w, t = 0.0, v_in, 0.0
    while True:
        k1 = rhs(d, w)
        k2 = rhs(d + h / 2 * k1[0], w + h / 2 * k1[1])
        k3 = rhs(d + h / 2 * k2[0], w + h / 2 * k2[1])
        k4 = rhs(d + h * k3[0], w + h * k3[1])
        dn = d + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        wn = w + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        t += h
        if dn <= 0 and t > 10 * h:
            s = d / (d - dn)
            return -(w + s * (wn - w)) / v_in, t - h + s * h
        d, w = dn, wn


if __name__ == "__main__":
    for v in (4.0, 8.0):
        print(f"exact   v={v:g}: e = {exact_restitution(D / K * v):.15f}")
    for g in (0.0, 9.8):
        e, T = rk4_central(4.0, g)
        print(f"RK4 g={g:g} v=4: e = {e:.12f}, contact {T * 1e3:.3f} ms")
