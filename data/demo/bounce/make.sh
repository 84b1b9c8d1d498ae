#!/bin/sh
# Demo data of seed 001's bounce analyses (data/demo/README.md): three filmed bounces of the
# default rugby ball as a team records them (240 fps slow motion played at 30 fps, tips A and
# B tracked with 1 mm noise, floor at y = 0) and a table of 40 measured bounces for
# `bounce fit`, all from tribolab's own contact simulation.
#   higher.txt    low-damping law (D = 6000, the demo's), moving to +x with clockwise spin
#                 (topspin): rises above its release height, the seed's headline (e ~ 1.2 as
#                 in its experiment 1)
#   ordinary.txt  the seed's fitted law (K 101054, n 1.51, D 60423, mu 0.5), backspin: an
#                 ordinary bounce (the seed's law never rises above the release height here)
#   backspin.txt  low-damping law, the throw of higher.txt spinning the other way: no rise
#   table.csv     the seed's fitted law, 40 bounces, noise 0.02 m/s and 0.5 rad/s
set -eu
: "${TRIBOLAB:=tribolab}"
: "${OUT:=$(dirname "$0")}"
"$TRIBOLAB" bounce synth-video --D 6000 --height 0.8 --theta-deg 20 --omega -45 --vx 1.5 --fps 240 --noise 0.001 --time-factor 8 --seed 1 --out "$OUT/higher.txt"
"$TRIBOLAB" bounce synth-video --height 0.8 --theta-deg 20 --omega 45 --vx 1.5 --fps 240 --noise 0.001 --time-factor 8 --seed 2 --out "$OUT/ordinary.txt"
"$TRIBOLAB" bounce synth-video --D 6000 --height 0.8 --theta-deg 20 --omega 45 --vx 1.5 --fps 240 --noise 0.001 --time-factor 8 --seed 3 --out "$OUT/backspin.txt"
"$TRIBOLAB" bounce synth-table --rows 40 --noise-v 0.02 --noise-omega 0.5 --seed 1 --out "$OUT/table.csv"
