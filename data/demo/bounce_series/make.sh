#!/bin/sh
# Demo data of seed 001's experiment 2 (120 throws, figure 32), in small: twelve filmed bounces
# of the default rugby ball with the low-damping law of the demo's bounce section (D = 6000),
# released at 0.8 m moving to +x at 1.5 m/s with orientations from -50 to 50 deg and spin
# +-45 rad/s, filmed as a team records them (240 fps slow motion played at 30 fps, tips A and
# B with 1 mm noise, floor at y = 0). Analysed together by
#   tribolab bounce analyze throw*.txt --track-a A --track-b B --time-scale 0.125 --floor-y 0
set -eu
: "${TRIBOLAB:=tribolab}"
: "${OUT:=$(dirname "$0")}"
i=0
for theta in -50 -30 -10 10 30 50; do
  for omega in -45 45; do
    i=$((i + 1))
    name=$(printf 'throw%02d.txt' "$i")
    "$TRIBOLAB" bounce synth-video --D 6000 --height 0.8 --theta-deg "$theta" --omega "$omega" --vx 1.5 --fps 240 --noise 0.001 --time-factor 8 --seed $((100 + i)) --out "$OUT/$name" >/dev/null
  done
done
