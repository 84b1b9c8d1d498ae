#!/usr/bin/env python3
"""Runs every tribolab command with each numeric option at extreme values and checks that it
either refuses with one error line (exit status 1-2, no crash, no output file) or succeeds
with finite numbers only (no inf/nan in stdout or in the files it writes).

    tools/probe_ranges.py BUILD/bin/tribolab [--values v1,v2,...] [--only SUBSTRING]

Prints one line per problem and a summary; exit status 1 when a problem was found.
docs/cli.md#physical-ranges lists the ranges this checks against (the script needs none:
a value is either refused cleanly or computed to finite numbers).
"""
import os
import re
import subprocess
import sys
import tempfile

DEMO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "demo")
INC = os.path.join(DEMO, "incline")
BOU = os.path.join(DEMO, "bounce")

# (command, base arguments, numeric options probed). OUT is replaced by a fresh file.
CASES = [
    ("incline predict", ["--mu", "0.5", "--phi-deg", "20", "--v0", "2"], ["--mu", "--phi-deg", "--v0", "--g", "--mu-static"]),
    ("incline simulate", ["--mu", "0.5", "--phi-deg", "20", "--v0", "2", "--out", "OUT"],
     ["--mu", "--phi-deg", "--v0", "--g", "--mu-static", "--dt", "--t-end"]),
    ("incline simulate", ["--mu", "0.5", "--phi-deg", "20", "--v0", "2", "--model", "A", "--out", "OUT"],
     ["--normal-accel"]),
    ("incline families", ["--mu", "0.5", "--phi-deg", "20", "--vary", "v0", "--values", "1,2", "--out", "OUT"],
     ["--mu", "--phi-deg", "--g", "--samples", "--t-end", "--values"]),
    ("incline families", ["--v0", "2", "--phi-deg", "20", "--vary", "mu", "--values", "0.4,0.6", "--out", "OUT"], ["--values"]),
    ("incline families", ["--v0", "2", "--mu", "0.5", "--vary", "phi", "--values", "10,20", "--out", "OUT"], ["--values"]),
    ("incline synth", ["--mu", "0.634", "--phi-deg", "20.96", "--v0", "2.62", "--out", "OUT"],
     ["--mu", "--phi-deg", "--v0", "--g", "--normal-accel", "--fps", "--noise", "--seed", "--t-offset", "--x0", "--y0",
      "--duration"]),
    ("incline mu-from-stop", ["--phi-deg", "20", "--x-stop", "0.5", "--y-stop", "-0.2"],
     ["--phi-deg", "--x-stop", "--y-stop", "--sigma-phi-deg", "--sigma-pos", "--g"]),
    ("incline mu-from-stop", ["--phi-deg", "20", "--x-stop", "0.5", "--y-stop", "-0.2", "--sigma-pos", "0.001"],
     ["--plate-size"]),
    ("incline mu-from-slide", [os.path.join(INC, "slide_41.09deg.txt"), "--phi-deg", "41.09"],
     ["--phi-deg", "--sigma-phi-deg", "--g", "--time-scale"]),
    ("incline analyze", [os.path.join(INC, "run_20.96deg.txt"), "--phi-deg", "20.96"],
     ["--phi-deg", "--g", "--block", "--time-scale"]),
    ("bounce contact-time", ["--height", "0.5"], ["--height", "--omega", "--theta-deg", "--g", "--a", "--b", "--mass", "--inertia"]),
    ("bounce simulate", ["--vy", "-4", "--omega", "40", "--theta-deg", "30"],
     ["--vx", "--vy", "--omega", "--theta-deg", "--g", "--a", "--b", "--mass", "--inertia", "--K", "--n", "--D",
      "--restitution", "--mu", "--slip-scale", "--k-t", "--c-t", "--tol"]),
    ("bounce simulate", ["--vy", "-4", "--omega", "40", "--theta-deg", "30", "--friction", "spring"], ["--k-t", "--c-t"]),
    ("bounce simulate", ["--vy", "-4", "--omega", "40", "--theta-deg", "30", "--friction", "regularized"], ["--slip-scale"]),
    ("bounce drop", ["--height", "0.5", "--bounces", "2"],
     ["--height", "--theta-deg", "--omega", "--vx", "--vy", "--bounces", "--rest-height", "--g", "--K", "--D", "--mu"]),
    ("bounce sweep", ["--theta-deg", "100:170:2", "--omega", "30:50:2", "--threads", "1", "--out", "OUT", "--restart"],
     ["--vx", "--g", "--K", "--D", "--contour-tol", "--tol"]),
    ("bounce synth-video", ["--out", "OUT"],
     ["--height", "--theta-deg", "--omega", "--vx", "--vy", "--after", "--fps", "--noise", "--time-factor", "--mu", "--K"]),
    ("bounce synth-table", ["--rows", "3", "--out", "OUT"],
     ["--rows", "--speed-min", "--speed-max", "--vx-max", "--omega-max", "--noise-v", "--noise-omega"]),
    ("bounce analyze", [os.path.join(BOU, "higher.txt"), "--track-a", "A", "--track-b", "B", "--time-scale", "0.125"],
     ["--time-scale", "--floor-y", "--contact-duration", "--a", "--b", "--mass", "--inertia"]),
    ("bounce fit", [os.path.join(BOU, "table.csv"), "--fix", "n=1.51"],
     ["--slip-scale", "--loss-scale", "--K0", "--n0", "--D0", "--mu0"]),
    ("track kinematics", [os.path.join(INC, "run_20.96deg.txt"), "--out", "OUT"], ["--time-scale"]),
    ("track import", [os.path.join(INC, "run_20.96deg.txt")], ["--time-scale"]),
]

VALUES = ["0", "-1", "1e-300", "1e-9", "1e3", "-1e3", "1e6", "1e308", "-1e308"]
BAD = re.compile(r"(?<![A-Za-z_])(-?inf(inity)?|nan)(?![A-Za-z_])", re.I)


def run(tribolab, cmd, args, timeout):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "out.csv")
        argv = [tribolab] + cmd.split() + [out if a == "OUT" else a for a in args] + ["--json"]
        try:
            p = subprocess.run(argv, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return "timeout", "", "", ""
        files = ""
        for f in os.listdir(d):
            with open(os.path.join(d, f), errors="replace") as h:
                files += h.read()
        return p.returncode, p.stdout, p.stderr, files


def numeric_keys(text, prefix=""):
    """Paths of the JSON numbers in text (one JSON object), for the null check."""
    import json
    try:
        obj = json.loads(text)
    except ValueError:
        return set()
    keys = set()

    def walk(o, path):
        if isinstance(o, dict):
            for k, v in o.items():
                walk(v, path + "." + k)
        elif isinstance(o, (int, float)) and not isinstance(o, bool):
            keys.add(path)
    walk(obj, prefix)
    return keys


def null_keys(text):
    import json
    try:
        obj = json.loads(text)
    except ValueError:
        return set()
    keys = set()

    def walk(o, path):
        if isinstance(o, dict):
            for k, v in o.items():
                walk(v, path + "." + k)
        elif o is None:
            keys.add(path)
    walk(obj, "")
    return keys


def main():
    tribolab = sys.argv[1]
    values, only, timeout = VALUES, "", 60
    if "--values" in sys.argv:
        values = sys.argv[sys.argv.index("--values") + 1].split(",")
    if "--only" in sys.argv:
        only = sys.argv[sys.argv.index("--only") + 1]
    problems = runs = 0
    for cmd, base, options in CASES:
        if only and only not in cmd:
            continue
        rc, out, err, files = run(tribolab, cmd, base, timeout)
        numbers = numeric_keys(out) if rc == 0 else set()
        for opt in options:
            for v in values:
                args = list(base)
                if opt in args:
                    args[args.index(opt) + 1] = v
                else:
                    args += [opt, v]
                rc, out, err, files = run(tribolab, cmd, args, timeout)
                runs += 1
                what = f"{cmd} {opt} {v}"
                if rc == "timeout":
                    print(f"TIMEOUT  {what}")
                    problems += 1
                elif rc == 0:
                    m = BAD.search(out) or BAD.search(files)
                    if m:
                        problems += 1
                        print(f"NONFINITE {what}: '{m.group(0)}' in {'stdout' if BAD.search(out) else 'file'}")
                    nulls = sorted(null_keys(out) & numbers)
                    if nulls:  # a number at the base point became null: review (may be legitimate)
                        print(f"NULL?    {what}: {', '.join(nulls)}")
                elif rc < 0 or rc > 2:
                    problems += 1
                    print(f"CRASH({rc}) {what}: {err.strip()[:200]}")
                elif len(err.strip().splitlines()) != 1 or files:
                    problems += 1
                    print(f"MESSY    {what}: {len(err.strip().splitlines())} error lines, output file {'written' if files else 'absent'}")
                elif "--" in opt and BAD.search(err) and "outside" not in err:
                    pass
    print(f"{runs} runs, {problems} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
