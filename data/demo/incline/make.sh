#!/bin/sh
# Synthetic tracked runs of the disc on the incline (seed 000) for `tribolab demo`: what a team
# would film. Launches across the incline at five angles with the seed's mu = 0.634 (20.96 deg
# is the seed's run, v0 = 2.62 m/s), one launch with a normal friction component (model A,
# f_N/m = 0.3 m/s^2) so the verdict is shown both ways, and a straight slide released from rest
# at the seed's 41.09 deg for eq (a). 1 mm noise, 80-240 fps, Tracker export text and CSV.
# See data/demo/README.md.
set -eu
: "${TRIBOLAB:=tribolab}"
: "${OUT:=$(dirname "$0")}"
"$TRIBOLAB" incline synth --mu 0.634 --phi-deg 12 --v0 2.62 --fps 120 --seed 12 --format csv --out "$OUT/run_12deg.csv"
"$TRIBOLAB" incline synth --mu 0.634 --phi-deg 16 --v0 2.62 --fps 240 --seed 16 --out "$OUT/run_16deg.txt"
"$TRIBOLAB" incline synth --mu 0.634 --phi-deg 20.96 --v0 2.62 --fps 80 --seed 21 --out "$OUT/run_20.96deg.txt"
"$TRIBOLAB" incline synth --mu 0.634 --phi-deg 25 --v0 2.3 --fps 120 --seed 25 --out "$OUT/run_25deg.txt"
"$TRIBOLAB" incline synth --mu 0.634 --phi-deg 28 --v0 2 --fps 120 --seed 28 --out "$OUT/run_28deg.txt"
"$TRIBOLAB" incline synth --mu 0.634 --phi-deg 20.96 --v0 2.62 --normal-accel 0.3 --fps 120 --seed 30 --out "$OUT/run_20.96deg_normal.txt"
"$TRIBOLAB" incline synth --mu 0.634 --phi-deg 41.09 --v0 0 --fps 240 --duration 0.7 --seed 41 --out "$OUT/slide_41.09deg.txt"
