#!/usr/bin/env python3
"""Analyses a grid of `bounce synth-video` throws with `bounce analyze` and reports, per throw,
whether it was analysed and how far e_velocity lies from the truth in its own sigma
(issue 27: every throw the simulator makes must be analysable).

    tools/bounce_grid.py BUILD/bin/tribolab [--noise 0.001] [--height 0.7] [--floor given|duration]

Grid: release orientation 0..165 deg (step 15) x spin -50..50 rad/s (7 values), seed = index.
Prints failures and a summary (analysed, |z| <= 1, <= 2, <= 3); exit status 1 when any failed.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ap = argparse.ArgumentParser()
ap.add_argument("tribolab")
ap.add_argument("--noise", type=float, default=0.001)
ap.add_argument("--height", type=float, default=0.7)
ap.add_argument("--floor", choices=["given", "duration"], default="given")
ap.add_argument("--sigma-floor-y", type=float, default=0.0)
args = ap.parse_args()

thetas = range(0, 166, 15)
omegas = [-50, -30, -10, 0, 10, 30, 50]
failed, z = [], []
with tempfile.TemporaryDirectory() as d:
    video = os.path.join(d, "v.txt")
    seed = 0
    for th in thetas:
        for om in omegas:
            seed += 1
            throw = ["--theta-deg", str(th), "--omega", str(om), "--height", str(args.height),
                     "--noise", str(args.noise), "--seed", str(seed)]
            truth = json.loads(subprocess.run([args.tribolab, "bounce", "synth-video", "--out", video, "--json"] + throw,
                                              check=True, capture_output=True, text=True).stdout)
            e_true = -truth["vy_out"] / truth["vy_in"]
            floor = (["--floor-y", "0", "--sigma-floor-y", str(args.sigma_floor_y)] if args.floor == "given" else
                     ["--contact-duration", str(round((truth["t_separation"] - truth["t_touch"]) * 240) / 240)])
            p = subprocess.run([args.tribolab, "bounce", "analyze", video, "--track-a", "A", "--track-b", "B",
                                "--time-scale", "0.125", "--json"] + floor, capture_output=True, text=True)
            if p.returncode != 0:
                failed.append((" ".join(throw), p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "?"))
                continue
            r = json.loads(p.stdout)
            e, s = r["e_velocity"], r["sigma_e_velocity"]
            zz = (e - e_true) / s if s else math.inf
            z.append(zz)
            if abs(zz) > 3:
                print(f"|z| > 3: {' '.join(throw)}: e {e:.4f} +- {s:.4f}, truth {e_true:.4f} (z {zz:+.2f})")
n = len(thetas) * len(omegas)
for t, m in failed:
    print(f"FAILED {t}: {m}")
within = [sum(abs(v) <= k for v in z) for k in (1, 2, 3)]
print(f"noise {args.noise * 1e3:g} mm: analysed {len(z)}/{n}; |z|<=1 {within[0]}, <=2 {within[1]}, <=3 {within[2]}")
sys.exit(1 if failed else 0)
