#!/bin/sh
# Opens a tribolab HTML report in Debian's headless Chromium, as a person would, and checks
# that every plot rendered without a script error: the page's hidden status element
# (<div id="tribolab-status">) must read "ok N", N = the number of plot elements in the file
# (and = EXPECTED when given). Name resolution is disabled, so a report that needed the
# network would fail; a script may only come from a relative path that exists (`--plotly
# file`). Then what a reader sees, in the rendered page: no caption numbered twice ("Figure 3.
# Figure 2 (二)"), no table label holding a unit in its middle ("θ_c (deg), at t_c" over the
# unit "s"), no subscript of one letter run into more letters ("ω_out" drawn as "ω" + "o" +
# "ut"), no internal names (test files, "truth (make.sh)"). Saves a screenshot to SCREENSHOT.PNG.
#
#   sh tests/browser/check_report.sh REPORT.html SCREENSHOT.png [EXPECTED_PLOTS]
set -eu
if [ $# -lt 2 ]; then
  echo "usage: $0 REPORT.html SCREENSHOT.png [EXPECTED_PLOTS]" >&2
  exit 2
fi
html=$1
png=$2
expected=${3:-}

fail() {
  echo "FAIL: $html: $*" >&2
  exit 1
}

command -v chromium >/dev/null 2>&1 ||
  fail "chromium is not installed (Debian package 'chromium'; 'make deps' installs it)"
[ -s "$html" ] || fail "report missing or empty"

plots=$(grep -o 'class="tribolab-plot"' "$html" | wc -l | tr -d ' ')
if [ -n "$expected" ] && [ "$plots" -ne "$expected" ]; then
  fail "the file has $plots plot elements, expected $expected"
fi
# Offline: no stylesheet link, and a script only from a relative path that exists beside the
# report (`--plotly file`: plotly-VERSION.min.js shared by the reports of a folder).
if grep -Eiq '<link[^>]*[[:space:]]href=' "$html"; then
  fail "the report loads an external stylesheet"
fi
for src in $(grep -Eio '<script[^>]*[[:space:]]src="[^"]*"' "$html" | sed 's/.*src="//; s/"$//'); do
  case $src in
    *:* | /* | '') fail "the report loads the script '$src' from outside its folder" ;;
  esac
  [ -s "$(dirname "$html")/$src" ] || fail "the script '$src' is missing beside the report"
done

profile=$(mktemp -d)
log=$(mktemp)
trap 'rm -rf "$profile" "$log"' EXIT INT TERM
case $html in
  /*) url="file://$html" ;;
  *) url="file://$(pwd)/$html" ;;
esac
browse() {
  timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --host-resolver-rules="MAP * ~NOTFOUND" --user-data-dir="$profile" \
    --virtual-time-budget=10000 "$@" "$url" 2>>"$log"
}

dom=$(browse --dump-dom) || { cat "$log" >&2; fail "chromium failed"; }
status=$(printf '%s\n' "$dom" | grep -o 'id="tribolab-status"[^>]*>[^<]*' | sed 's/^[^>]*>//')
if [ "$status" != "ok $plots" ]; then
  fail "status is '$status', expected 'ok $plots'"
fi
if printf '%s\n' "$dom" | grep -q 'data-title="Share chart'; then
  fail "Plotly's 'share chart' (upload) button is shown; the report must work offline"
fi
# What a reader sees. Captions: ours number the figures; a study's figure is "the study's figure".
bad=$(printf '%s\n' "$dom" | grep -Eo '<figcaption>Figure [0-9]+\. [Ff]igure [0-9][^<]{0,40}' | head -n 1)
[ -z "$bad" ] || fail "a caption is numbered twice: '$bad'"
# Units: a parameter table's label "q (unit), more" puts the unit in the middle of the label,
# and the unit column then shows the unit of the last quantity only.
bad=$(printf '%s\n' "$dom" | grep -Eo '<tr><td>[^<]*\([^()<]*\), [^<]*</td><td>[^<]+</td>' | head -n 1)
[ -z "$bad" ] || fail "a table label holds a unit in its middle: '$bad'"
# Labels: tribolab's notation subscripts one character (x_N); a longer subscript needs braces
# (ω_{out}). Plotly titles, axis and colour-bar labels carry the notation as <sub> in the file
# (inside the figures' JSON as \u003csub\u003e).
bad=$(sed 's/\\u003c/</g; s/\\u003e/>/g' "$html" | grep -Eo '.{0,12}<sub>[^<]</sub>[a-z]{2}.{0,12}' | head -n 1)
[ -z "$bad" ] || fail "a one-letter subscript runs into letters (use braces): '$bad'"
for internal in '_test\.cpp' 'truth \(make\.sh\)' 'src/[a-z]*/[a-z_]*\.cpp'; do
  bad=$(printf '%s\n' "$dom" | sed 's/<script[^>]*>.*<\/script>//' | grep -Eo ".{0,30}$internal" | head -n 1)
  [ -z "$bad" ] || fail "the report shows an internal name: '$bad'"
done

rm -f "$png"
browse --screenshot="$png" --window-size=1280,2000 >/dev/null ||
  { cat "$log" >&2; fail "chromium could not take a screenshot"; }
[ -s "$png" ] || fail "no screenshot written to $png"
echo "PASS: $html: status '$status', screenshot $png"
