#!/usr/bin/env python3
"""Independent rigid-ellipse contact for the seed-001 map errata (docs/theory.md, errata).

Written from the equations only (docs/theory.md#bounce-contact), sharing no code with
tribolab: support depth Y = sqrt(a^2 sin^2 + b^2 cos^2), support offset X = -dY/dtheta,
d = Y - y, d_dot = -(vy + omega X), N = max(0, K d^n (1 + chi d_dot)),
m x'' = f, m y'' = N - m g, I theta'' = X N + Y f; exact Coulomb stick-slip (slip:
f = -mu N sign(v_t), v_t = vx + omega Y; stick: the force keeping v_t = 0,
f = X (omega^2 - Y N / I) / (1/m + Y^2/I), while |f| <= mu N). Classical RK4 with a fixed
step; each event (separation, slip reversal, stick limit) located by bisection on the step
length. The cell of the seed's map: collision angle chi (rear tip taken for motion to +x),
v_x = 0, v_y = -4 m/s, spin -|omega| (clockwise: drives the support point into the floor).

  python3 ellipse_contact.py cell CHI SPIN D     # one cell (SPIN signed, rad/s)
  python3 ellipse_contact.py map D [SIGN]       # 71 x 21 map, SIGN -1 (default) or +1

Output (2026-11-29; step halving 4e-6 -> 1e-6 s changes e by < 1e-10):
  map 0            largest e = 1.3778518156 at (126 deg, -50 rad/s)
  cell 125.72 -50 0        e = 1.3778540135
  cell 100 50 0            e = 1.3095906138 (largest of the map with SIGN +1)
  cell 104.664 -50 11749.272  e = 0.9999999995;  D -0.1 %: 1.000257, +0.1 %: 0.999743
"""
import math
import sys

A, B, M, I = 0.145, 0.095, 0.435, 4.1e-3
K, N_EXP = 101054.0, 1.51


def geom(th):
    s, c = math.sin(th), math.cos(th)
    y = math.sqrt(A * A * s * s + B * B * c * c)
    return -(A * A - B * B) * s * c / y, y


def collision_angle(th):
    x, y = geom(th)
    tip = (-A * math.cos(th), -A * math.sin(th)) if math.cos(th) > 0 else (A * math.cos(th), A * math.sin(th))
    dot = x * tip[0] - y * tip[1]
    return math.degrees(math.acos(max(-1.0, min(1.0, dot / math.hypot(x, y) / A))))


def theta_for_collision(chi_deg):
    lo, hi = -math.pi / 2 + 1e-12, math.pi / 2 - 1e-12  # the angle falls from 180 to 0 here
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if collision_angle(mid) > chi_deg:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def simulate(theta, vx, vy, w, D=0.0, mu=0.5, g=9.8, h=4e-6):
    chi = D / K
    st = [0.0, geom(theta)[1], theta, vx, vy, w]

    def forces(s, mode):
        _, y, th, vx_, vy_, w_ = s
        x_, y_s = geom(th)
        d = y_s - y
        n = max(K * d ** N_EXP * (1 + chi * (-(vy_ + w_ * x_))), 0.0) if d > 0 else 0.0
        f = x_ * (w_ * w_ - y_s * n / I) / (1 / M + y_s * y_s / I) if mode == 0 else -mode * mu * n
        return n, f, x_, y_s, d

    def rhs(s, mode):
        n, f, x_, y_s, _ = forces(s, mode)
        return [s[3], s[4], s[5], f / M, n / M - g, (x_ * n + y_s * f) / I]

    def step(s, hh, mode):
        k1 = rhs(s, mode)
        k2 = rhs([s[i] + hh / 2 * k1[i] for i in range(6)], mode)
        k3 = rhs([s[i] + hh / 2 * k2[i] for i in range(6)], mode)
        k4 = rhs([s[i] + hh * k3[i] for i in range(6)], mode)
        return [s[i] + hh / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]) for i in range(6)]

    def v_t(s):
        return s[3] + s[5] * geom(s[2])[1]

    def guards(s, mode):
        n, f, _, _, d = forces(s, mode)
        return {"sep": d, "stick": mu * n - abs(f)} if mode == 0 else {"sep": d, "slip": mode * v_t(s)}

    mode, t = (1 if v_t(st) > 0 else -1), 0.0
    while t < 0.2:
        s1 = step(st, h, mode)
        early = t < 10 * h  # d starts at 0: ignore the separation guard for the first steps
        hit = [k for k, v in guards(s1, mode).items() if v < 0 and not (k == "sep" and early)]
        if not hit:
            st, t = s1, t + h
            continue
        lo, hi = 0.0, h
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            gm = guards(step(st, mid, mode), mode)
            if any(gm[k] < 0 for k in hit):
                hi = mid
            else:
                lo = mid
        st, t = step(st, hi, mode), t + hi
        gm = guards(st, mode)
        k = min(hit, key=lambda kk: gm[kk])
        if k == "sep":
            return {"e": -st[4] / vy, "vx": st[3], "vy": st[4], "omega": st[5], "T": t}
        _, f, _, _, _ = forces(st, 0)
        if k == "slip":  # v_t reached 0: stick if the required force fits in the cone
            st[3] = -st[5] * geom(st[2])[1]
            mode = 0 if abs(f) <= mu * forces(st, 0)[0] else (1 if f < 0 else -1)
        else:  # stick limit: slip against the excess of the required force
            mode = -1 if f > 0 else 1
    return None


def cell(chi_deg, spin, D):
    return simulate(theta_for_collision(chi_deg), 0.0, -4.0, spin, D=D)


if __name__ == "__main__":
    if sys.argv[1] == "cell":
        print(cell(float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])))
    else:
        D = float(sys.argv[2])
        sign = float(sys.argv[3]) if len(sys.argv) > 3 else -1.0
        best = max((cell(100 + i, sign * (30 + j), D)["e"], 100 + i, sign * (30 + j))
                   for i in range(71) for j in range(21))
        print("largest e = %.10f at (%g deg, %g rad/s)" % best)
