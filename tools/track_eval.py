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

    tools/track_eval.py [--tribolab build/bin/tribolab] [--markdown] [--mark-every N] [--corrections]
                        [--frames] [--marks-scatter] [PROJECT...] [-- OPTIONS]

A user's corrections are measured with the human's own marks given as `--mark`:
  --mark-every N   the marks of every Nth frame after the start given; "to correct" and "wrong"
                   then count the frames between them (a marked frame lies on its mark);
  --corrections    a user who corrects the first frame to correct, tracks again and goes on
                   until none is left: "marks" is how many corrections that took (each with its
                   re-tracking, as the studio does).

Which frames (with any of the above):
  --frames         after the table, each track's frames to correct or confidently wrong: the
                   distance to the human's mark, px ("-": no position; "!": confidently wrong,
                   > 10 px, which at 1920 px can lie within the 12 px correction distance).

How far the human's own marks scatter (no tracking):
  --marks-scatter  each mark against the cubic through the marks of the two frames before and
                   the two after it (for an object moving smoothly over five frames that cubic
                   is within a fraction of a px of the path; CarInLoop's car, turning ~20 degrees
                   per frame round a ~200 px loop: ~0.5 px), printed as the median, 90th
                   percentile and largest distance and the frames farthest off. A mark's own
                   error enters 1.39 times (the cubic's weights -1/6, 2/3, 2/3, -1/6).
"""
import argparse
import glob
import json
import os
import csv
import math
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zipfile


# Tracker puts pixel (j, i)'s centre at (j + 0.5, i + 0.5), tribolab (OpenCV) at (j, i):
# src/video/source.hpp, kTrackerPixelOffset.
TRACKER_PIXEL_OFFSET = 0.5
# A position farther than this from the human's mark is confidently wrong (the bar), px.
WRONG_PX = 10


def human_marks(project, track):
    """{frame: (x, y)} in tribolab's image px (as --mark takes them) of a track's marks in a
    Tracker project (.trz or .trk)."""
    if project.endswith(".trz"):
        z = zipfile.ZipFile(project)
        text = z.read([n for n in z.namelist() if n.endswith(".trk")][0])
    else:
        with open(project, "rb") as f:
            text = f.read()
    marks = {}
    for obj in ET.fromstring(text).iter("object"):
        names = [p for p in obj.findall("property") if p.get("name") == "name"]
        if not names or names[0].text != track or "PointMass" not in (obj.get("class") or ""):
            continue
        for fd in obj.iter("property"):
            m = re.fullmatch(r"\[(\d+)\]", fd.get("name") or "")
            inner = fd.find("object")
            if not m or inner is None or "FrameData" not in (inner.get("class") or ""):
                continue
            v = {p.get("name"): float(p.text) for p in inner.findall("property") if p.get("name") in ("x", "y")}
            if "x" in v and "y" in v:
                marks[int(m.group(1))] = (v["x"] - TRACKER_PIXEL_OFFSET, v["y"] - TRACKER_PIXEL_OFFSET)
        break
    return marks


def mark_options(name, marks, frames):
    out = []
    for f in sorted(frames):
        out += ["--mark", f"{name}@{f}={marks[f][0]:.3f},{marks[f][1]:.3f}"]
    return out


def distances(csv_path, name, marks, start, given):
    """{frame: distance to the human's mark, px (None: no position)} over the marked frames
    after the start that were not given."""
    out = {}
    with open(csv_path) as f:
        for r in csv.DictReader(f):
            k = int(r["frame"])
            if r["track"] != name or k <= start or k not in marks or k in given:
                continue
            out[k] = math.hypot(float(r["x_px"]) - marks[k][0], float(r["y_px"]) - marks[k][1]) if r["x_px"] else None
    return out


def between_marks(d, correct_px, given):
    """vs_human's figures over the frames between the given marks (distances d)."""
    placed = sorted(v for v in d.values() if v is not None)
    q = lambda p: placed[min(len(placed) - 1, int(p * len(placed)))] if placed else 0.0
    return {"marks": len(d), "frames": len(placed), "median_px": q(0.5), "p90_px": q(0.9), "given": len(given),
            "to_correct": sum(1 for v in d.values() if v is None or v > correct_px),
            "confidently_wrong": sum(1 for v in placed if v > WRONG_PX)}


def marks_scatter(marks):
    """{frame: distance (px) of the mark from the cubic through the marks two frames either side}."""
    out = {}
    for f, (x, y) in marks.items():
        near = [marks.get(f + d) for d in (-2, -1, 1, 2)]
        if any(q is None for q in near):
            continue
        px = (-near[0][0] + 4 * near[1][0] + 4 * near[2][0] - near[3][0]) / 6
        py = (-near[0][1] + 4 * near[1][1] + 4 * near[2][1] - near[3][1]) / 6
        out[f] = math.hypot(x - px, y - py)
    return out


def print_marks_scatter(projects, tribolab):
    print("{:28} {:12} {:>6} {:>8} {:>8} {:>8}  {}".format("project", "track", "marks", "median", "p90", "max",
                                                         "farthest (frame: px)"))
    for proj in projects:
        imp, err = run_json([tribolab, "track", "import", proj, "--json"])
        if imp is None:
            print(f"{proj}: track import failed: {err}", file=sys.stderr)
            continue
        for name in imp["track_names"]:
            d = marks_scatter(human_marks(proj, name))
            if not d:
                continue
            v = sorted(d.values())
            pick = lambda q: v[min(len(v) - 1, int(q * len(v)))]
            far = sorted(d.items(), key=lambda kv: -kv[1])[:3]
            print("{:28} {:12} {:>6} {:>8.2f} {:>8.2f} {:>8.2f}  {}".format(
                os.path.basename(proj), name, len(v), pick(0.5), pick(0.9), v[-1],
                " ".join(f"{f}: {x:.1f}" for f, x in far)))


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
    ap.add_argument("--mark-every", type=int, default=0, help="give the human's marks of every Nth frame")
    ap.add_argument("--corrections", action="store_true", help="count a user's corrections until none is left")
    ap.add_argument("--marks-scatter", action="store_true", help="how far the human's marks scatter about a smooth path")
    ap.add_argument("--frames", action="store_true", help="list each track's frames to correct after the table")
    ap.add_argument("projects", nargs="*")
    a = ap.parse_args(argv)
    projects = a.projects or sorted(glob.glob(os.path.join(root, "..", "shared", "data", "tracker", "*.trz")))
    if a.marks_scatter:
        print_marks_scatter(projects, a.tribolab)
        return
    rows = []
    listed = []  # (project, track, [(frame, distance or None)]) for --frames
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
                base = os.path.basename(proj)
                cmd = [a.tribolab, "track", "video", proj, "--from-track", name, "--out", out, "--json"] + extra
                marks = human_marks(proj, name) if a.mark_every or a.corrections or a.frames else {}
                start = min(marks) if marks else 0
                given = [k for k in marks if k > start and (k - start) % a.mark_every == 0] if a.mark_every else []
                j, err = run_json(cmd + mark_options(name, marks, given))
                while a.corrections and j is not None:
                    d = distances(out, name, marks, start, given)
                    bad = sorted(k for k, v in d.items() if v is None or v > j["tracks"][name]["vs_human"]["correct_px"])
                    if not bad:
                        break
                    given.append(bad[0])
                    j, err = run_json(cmd + mark_options(name, marks, given))
                correct_px = j["tracks"][name]["vs_human"]["correct_px"] if j is not None else 0
                if j is not None and (a.mark_every or a.corrections):
                    # The given marks lie on the human's: the frames between them are what is measured.
                    j["tracks"][name]["vs_human"] = between_marks(distances(out, name, marks, start, given), correct_px, given)
                if j is None:
                    rows.append((base, name, None, err.splitlines()[-1] if err else "failed"))
                    continue
                rows.append((base, name, j["tracks"][name]["vs_human"], ""))
                if a.frames:
                    d = distances(out, name, marks, start, given)
                    listed.append((base, name, [(k, v) for k, v in sorted(d.items())
                                                if v is None or v > correct_px or v > WRONG_PX]))
    fmt = "| {} | {} | {} | {} | {} | {} | {} | {} |" if a.markdown else "{:28} {:12} {:>6} {:>8} {:>8} {:>8} {:>10} {:>6}"
    head = "marks given" if a.mark_every or a.corrections else "marks"
    print(fmt.format("project", "track", head, "tracked", "median", "p90", "to correct", "wrong"))
    if a.markdown:
        print("|---|---|---|---|---|---|---|---|")
    worst = 0.0
    for base, name, h, err in rows:
        if h is None:
            print(fmt.format(base, name, "-", "refused", "-", "-", "100 %", "-") + ("" if a.markdown else "  " + err))
            worst = 1.0
            continue
        m = max(1, h["marks"])  # frames measured (between the given marks)
        share = h["to_correct"] / m
        worst = max(worst, share)
        # No frame with a position: no distance to show (vs_human's 0 would read as exact).
        dist = (f"{h['median_px']:.2f}", f"{h['p90_px']:.2f}") if h["frames"] > 0 else ("-", "-")
        first = f"{h['given']} of {h['marks'] + h['given']}" if "given" in h else h["marks"]
        print(fmt.format(base, name, first, f"{100 * h['frames'] / m:.0f} %", dist[0], dist[1],
                         f"{100 * share:.1f} %", h["confidently_wrong"]))
    for base, name, bad in listed:
        shown = " ".join(f"{k}: -" if v is None else f"{k}: {v:.1f}{'!' if v > WRONG_PX else ''}" for k, v in bad)
        print(f"{base} {name}: {len(bad)} frame(s) to correct or wrong{' (frame: px) ' + shown if bad else ''}")
    print(f"worst share to correct: {100 * worst:.1f} %", file=sys.stderr)


if __name__ == "__main__":
    main()
