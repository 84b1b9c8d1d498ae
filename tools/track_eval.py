#!/usr/bin/env python3
"""Tracking on real film, measured as a new user would (issue 24, docs/benchmarks.md#tracking-on-real-film).

For every Tracker project given (default: ../shared/data/tracker/*.trz beside the repository)
and every track in it with human marks, runs
    tribolab track video PROJECT --from-track NAME --out TMP.csv --json [extra options]
and prints one row per track: the share of marked frames tracked, the median and 90th
percentile distance to the human marks (px), the share of marked frames a user must correct
(no position, or farther than 4 px per 640 px of image width from the mark) and the frames
that are confidently wrong (a position > 10 px from the mark). The figures come from
`track video`'s own `vs_human` (src/video/track_video.cpp, compare_with_human).

    tools/track_eval.py [--tribolab build/bin/tribolab] [--markdown] [PROJECT...] [-- OPTIONS]
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile


def run_json(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    try:
        return json.loads(p.stdout), p.stderr.strip()
    except json.JSONDecodeError:
        return None, p.stderr.strip()


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        k = argv.index("--")
        argv, extra = argv[:k], argv[k + 1:]
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tribolab", default=os.path.join(root, "build", "bin", "tribolab"))
    ap.add_argument("--markdown", action="store_true", help="print a Markdown table")
    ap.add_argument("projects", nargs="*")
    a = ap.parse_args(argv)
    projects = a.projects or sorted(glob.glob(os.path.join(root, "..", "shared", "data", "tracker", "*.trz")))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "t.csv")
        for proj in projects:
            imp, err = run_json([a.tribolab, "track", "import", proj, "--json"])
            if imp is None:
                print(f"{proj}: track import failed: {err}", file=sys.stderr)
                continue
            for name in imp["track_names"]:
                if imp["tracks"][name]["points"] < 2:
                    continue
                j, err = run_json([a.tribolab, "track", "video", proj, "--from-track", name, "--out", out, "--json"] + extra)
                base = os.path.basename(proj)
                if j is None:
                    rows.append((base, name, None, err.splitlines()[-1] if err else "failed"))
                    continue
                rows.append((base, name, j["tracks"][name]["vs_human"], ""))
    fmt = "| {} | {} | {} | {} | {} | {} | {} | {} |" if a.markdown else "{:28} {:12} {:>6} {:>8} {:>8} {:>8} {:>10} {:>6}"
    print(fmt.format("project", "track", "marks", "tracked", "median", "p90", "to correct", "wrong"))
    if a.markdown:
        print("|---|---|---|---|---|---|---|---|")
    worst = 0.0
    for base, name, h, err in rows:
        if h is None:
            print(fmt.format(base, name, "-", "refused", "-", "-", "100 %", "-") + ("" if a.markdown else "  " + err))
            worst = 1.0
            continue
        m = max(1, h["marks"])
        share = h["to_correct"] / m
        worst = max(worst, share)
        # No frame with a position: no distance to show (vs_human's 0 would read as exact).
        dist = (f"{h['median_px']:.2f}", f"{h['p90_px']:.2f}") if h["frames"] > 0 else ("-", "-")
        print(fmt.format(base, name, h["marks"], f"{100 * h['frames'] / m:.0f} %", dist[0], dist[1],
                         f"{100 * share:.1f} %", h["confidently_wrong"]))
    print(f"worst share to correct: {100 * worst:.1f} %", file=sys.stderr)


if __name__ == "__main__":
    main()
