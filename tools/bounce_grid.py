#!/usr/bin/env python3
"""Analyses a grid of `bounce synth-video` throws with `bounce analyze` and reports, per throw,
whether it was analysed, refused or failed, and how far e_velocity lies from the truth in its
own sigma (issue 27: every throw the simulator makes must be analysable).

    tools/bounce_grid.py BUILD/bin/tribolab [--noise 0.001 0.003 0.005] [--height 0.7]
        [--omegas -50 -30 -10 0 10 30 50] [--seeds 1] [--floor given|duration] [--jobs 2]

Grid: release orientation 0..165 deg (step 15) x the spins x the seeds; with one seed (the
default) the seed is the throw's index, as in src/analysis/bounce_grid_test.cpp; with
--seeds N each throw is drawn with seeds 1..N.
Outcomes: "analysed" (e and its sigma), "refused" (an error that says the data cannot show a
rebound: no rebound flight, or too short a post-impact flight) and "failed" (any other error,
or |z| > 3). Prints failures and refusals, then one summary line per noise level; exit status 1
when any throw failed.
"""
import argparse
import concurrent.futures
import json
import math
import os
import subprocess
import sys
import tempfile

ap = argparse.ArgumentParser()
ap.add_argument("tribolab")
ap.add_argument("--noise", type=float, nargs="+", default=[0.001])
ap.add_argument("--height", type=float, default=0.7)
ap.add_argument("--omegas", type=float, nargs="+", default=[-50, -30, -10, 0, 10, 30, 50])
ap.add_argument("--thetas", type=float, nargs="+", default=list(range(0, 166, 15)))
ap.add_argument("--seeds", type=int, default=1)
ap.add_argument("--floor", choices=["given", "duration"], default="given")
ap.add_argument("--sigma-floor-y", type=float, default=0.0)
ap.add_argument("--jobs", type=int, default=2)
args = ap.parse_args()

# Words of the refusals that name why the data cannot carry e (analyze_bounce's messages).
REFUSALS = ("no rebound flight the track can show", "cannot carry the rebound")


def run(job):
    noise, th, om, seed = job
    throw = ["--theta-deg", f"{th:g}", "--omega", f"{om:g}", "--height", str(args.height),
             "--noise", str(noise), "--seed", str(seed)]
    with tempfile.TemporaryDirectory() as d:
        video = os.path.join(d, "v.txt")
        truth = json.loads(subprocess.run([args.tribolab, "bounce", "synth-video", "--out", video, "--json"] + throw,
                                          check=True, capture_output=True, text=True).stdout)
        e_true = -truth["vy_out"] / truth["vy_in"]
        floor = (["--floor-y", "0", "--sigma-floor-y", str(args.sigma_floor_y)] if args.floor == "given" else
                 ["--contact-duration", str(round((truth["t_separation"] - truth["t_touch"]) * 240) / 240)])
        p = subprocess.run([args.tribolab, "bounce", "analyze", video, "--track-a", "A", "--track-b", "B",
                            "--time-scale", "0.125", "--json"] + floor, capture_output=True, text=True)
    name = " ".join(throw)
    if p.returncode != 0:
        msg = p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "?"
        return noise, name, ("refused" if any(w in msg for w in REFUSALS) else "failed"), msg, None
    r = json.loads(p.stdout)
    e, s = r["e_velocity"], r["sigma_e_velocity"]
    z = (e - e_true) / s if s else math.inf
    return noise, name, "analysed", f"e {e:.4f} +- {s:.4f}, truth {e_true:.4f} (z {z:+.2f})", z


jobs, seed = [], 0
for noise in args.noise:
    seed = 0
    for th in args.thetas:
        for om in args.omegas:
            seed += 1
            for k in range(args.seeds):
                jobs.append((noise, th, om, seed if args.seeds == 1 else k + 1))
with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
    results = list(pool.map(run, jobs))
any_failed = False
for noise in args.noise:
    rows = [r for r in results if r[0] == noise]
    z = [r[4] for r in rows if r[2] == "analysed"]
    for _, name, kind, msg, zz in rows:
        if kind != "analysed" or abs(zz) > 3:
            print(f"{kind.upper() if kind != 'analysed' else '|z| > 3'} {name}: {msg}")
    failed = sum(r[2] == "failed" for r in rows) + sum(abs(v) > 3 for v in z)
    any_failed |= failed > 0
    within = [sum(abs(v) <= k for v in z) for k in (1, 2, 3)]
    rms = math.sqrt(sum(v * v for v in z) / len(z)) if z else math.nan
    print(f"noise {noise * 1e3:g} mm: {len(rows)} throws, analysed {len(z)}, refused "
          f"{sum(r[2] == 'refused' for r in rows)}, failed {failed}; |z|<=1 {within[0]}, <=2 {within[1]}, "
          f"<=3 {within[2]}, beyond 2 {len(z) - within[1]} ({100 * (len(z) - within[1]) / max(len(z), 1):.1f} %), "
          f"rms z {rms:.2f}")
sys.exit(1 if any_failed else 0)
