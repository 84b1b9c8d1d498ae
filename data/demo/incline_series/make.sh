#!/bin/sh
# A series of synthetic tracked runs of the disc on the incline (seed 000 launched many discs:
# table 1, figures 五A-八) for `tribolab demo`'s "incline-series" case study: seven discs at the
# seed's figure-八 angle, 10.37 deg, with the launch speed varied from 1.2 to 2.4 m/s (so the
# stop point's scaling with v0 can be fitted), and three more at 6, 14 and 18 deg (so the
# cos(theta_c)-tan(phi) test has several angles). mu = 0.585 (the seed's figure-八 value), model
# B, 1 mm noise, 120 fps, Tracker export text. See data/demo/README.md.
set -eu
: "${TRIBOLAB:=tribolab}"
: "${OUT:=$(dirname "$0")}"
"$TRIBOLAB" incline synth --mu 0.585 --phi-deg 10.37 --v0 1.2 --fps 120 --seed 101 --out "$OUT/disc01_10.37deg.txt"
"$TRIBOLAB" incline synth --mu 0.585 --phi-deg 10.37 --v0 1.4 --fps 120 --seed 102 --out "$OUT/disc02_10.37deg.txt"
"$TRIBOLAB" incline synth --mu 0.585 --phi-deg 10.37 --v0 1.6 --fps 120 --seed 103 --out "$OUT/disc03_10.37deg.txt"
"$TRIBOLAB" incline synth --mu 0.585 --phi-deg 10.37 --v0 1.8 --fps 120 --seed 104 --out "$OUT/disc04_10.37deg.txt"
"$TRIBOLAB" incline synth --mu 0.585 --phi-deg 10.37 --v0 2 --fps 120 --seed 105 --out "$OUT/disc05_10.37deg.txt"
"$TRIBOLAB" incline synth --mu 0.585 --phi-deg 10.37 --v0 2.2 --fps 120 --seed 106 --out "$OUT/disc06_10.37deg.txt"
"$TRIBOLAB" incline synth --mu 0.585 --phi-deg 10.37 --v0 2.4 --fps 120 --seed 107 --out "$OUT/disc07_10.37deg.txt"
"$TRIBOLAB" incline synth --mu 0.585 --phi-deg 6 --v0 2 --fps 120 --seed 108 --out "$OUT/disc08_6deg.txt"
"$TRIBOLAB" incline synth --mu 0.585 --phi-deg 14 --v0 2 --fps 120 --seed 109 --out "$OUT/disc09_14deg.txt"
"$TRIBOLAB" incline synth --mu 0.585 --phi-deg 18 --v0 2 --fps 120 --seed 110 --out "$OUT/disc10_18deg.txt"
