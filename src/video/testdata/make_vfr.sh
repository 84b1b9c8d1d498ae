#!/bin/sh
# Makes vfr.mkv (source_test.cpp, FrameReader.VariableFrameRateTakesTheTimestamps): 14 frames
# of 32x24 px MJPEG in Matroska, nominally 30 fps: frames 0-10 at k/30 s, then every 2/30 s
# (a phone dropping every other frame): timestamps 0, 0.033, ..., 0.333, 0.400, 0.467, 0.533
# (Matroska rounds them to 1 ms). Needs ffmpeg (Debian package ffmpeg); the test does not.
set -e
cd "$(dirname "$0")"
ffmpeg -hide_banner -loglevel error -y -f lavfi -i "testsrc=size=32x24:rate=30:duration=1" \
  -vf "setpts='if(lt(N\,10)\,N\,10+(N-10)*2)/30/TB'" -fps_mode vfr \
  -c:v mjpeg -q:v 31 -frames:v 14 vfr.mkv
