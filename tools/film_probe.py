#!/usr/bin/python3
"""Why a marked point on real film is not followed: ten probes held against the human's marks.

issue 24, docs/benchmarks.md#tracking-on-real-film. For one track of a Tracker project whose
video is an image sequence inside the .trz (CarInLoop.trz's `masa A`), each probe places the
point in every marked frame with a method the path tracker could use, in its most favourable
form (searching only near the human's own mark, or told the velocity by the human's marks),
and prints the distance to the human's mark per frame and the number of frames within the
correction distance (4 px per 640 px of image width, 8 px at 1280). A probe that fails even
with that help rules its method out for this clip:

  rotate      the first frame's template (the path tracker's, side --patch) turned in 7.5 deg
              steps, best normalised correlation within 40 px of each human mark;
  deblur      the same, turned to the human's heading and each frame blurred along it by
              shutter * (|v0| - |v|) px (the first frame is the most blurred), shutter 0.5 and 1;
  chain       a template taken anew from every frame at the point found there (frame to
              frame), searched within 80 px on the first step, then 30 px around a
              constant-velocity prediction; fb is the forward-backward error (Kalal et al. 2010);
  chain-mid   the same, started from the human's mark of --mid (a sharper frame), both ways;
  mark-look   the template of the human's mark of --mid kept (not renewed, not turned), searched
              as chain-mid: what a user's mark would add if it gave the path tracker its look;
  reblur      the other direction: the car as seen around the chain's point in a sharper frame k
              (201 px), turned to the start's heading and blurred by shutter * (|v0| - |vk|) along
              it (headings and speeds from the chain), is placed in the start frame; the click's
              offset from where it lands, turned back, gives the point in frame k (shutter 1,
              |v0| 70 px/frame, the human's first step);
  edge        where each mark lies along the motion (the human's heading, 9 px wide) from the
              half-contrast point of the car's white-to-green edge (green minus the larger of red
              and blue): > 0 behind it; a blurred edge is a ramp whose middle is the edge at
              mid-exposure, so a mark kept on one point of the car keeps its distance;
  blob        the foreground (absolute difference from the per-pixel median background above
              35 grey levels) of the first frame's colours (8 levels per channel, those 1.5 times as
              frequent near the click as elsewhere in the foreground; ratio above 0.6), the region with
              most pixels within 100 px of the human's mark: the mark is its centroid plus the
              first frame's offset turned with the region's principal axis;
  grow        the path tracker's template grown about the click (sides 51 to 181 px): for each
              side, the start look's own correlation ridge in the first frame (peak_ridge_px,
              src/video/path_tracker.cpp: the half-length of the line through the peak along
              which the correlation stays within 0.05 of it) and the best placement within 40 px
              of each mark with its ridge; the side a "grow until the start's ridge is at most
              8 px" rule would choose is marked;
  masked      the first frame's template (--patch) with its background pixels left out (those
              within 20 grey levels of the per-pixel median of every third frame: the loop's
              pillar beside the click), masked normalised correlation, best within 40 px of each mark.

Needs Debian's python3-numpy, python3-scipy and python3-pil (run with /usr/bin/python3):
    tools/film_probe.py [--track 'masa A'] [--mid 20] [--probes rotate,chain] ../shared/data/tracker/CarInLoop.trz
"""
import argparse
import io
import re
import sys
import zipfile

import numpy as np
from track_eval import human_marks
from PIL import Image
from scipy import ndimage, signal


def read_project(path, track):
    """The image sequence (RGB, float) and {frame: (x, y)} of the track's marks in image px
    (pixel centres at whole numbers, as the images' indices and `track video` have them)."""
    z = zipfile.ZipFile(path)
    marks = human_marks(path, track)
    images = sorted(n for n in z.namelist() if re.search(r"\d+\.(jpg|jpeg|png)$", n, re.I))
    if not images:
        sys.exit(f"{path}: no image sequence in the project (only image-sequence videos are read)")
    frames = np.stack([np.asarray(Image.open(io.BytesIO(z.read(n))).convert("RGB"), dtype=np.float64) for n in images])
    return frames, marks


def gray(rgb):
    return rgb[..., 0] * 0.299 + rgb[..., 1] * 0.587 + rgb[..., 2] * 0.114  # as cv::cvtColor


def patch(img, x, y, s):
    xi, yi = int(round(x)), int(round(y))
    if yi - s < 0 or xi - s < 0 or yi + s + 1 > img.shape[0] or xi + s + 1 > img.shape[1]:
        return None
    return img[yi - s:yi + s + 1, xi - s:xi + s + 1]


def ncc_map(win, t):
    """TM_CCOEFF_NORMED of template t over window win ('valid' placements)."""
    t = t - t.mean()
    ones = np.ones_like(t)
    num = signal.correlate(win, t, mode="valid")
    s1 = signal.correlate(win, ones, mode="valid")
    s2 = signal.correlate(win * win, ones, mode="valid")
    return num / np.sqrt(np.maximum(s2 - s1 * s1 / t.size, 1e-9) * (t * t).sum())


def masked_ncc_map(win, t, w):
    """TM_CCOEFF_NORMED of template t over window win with pixel weights w (0 or 1): the
    template's and each placement's mean and norm over the weighted pixels only."""
    n = w.sum()
    tz = (t - (t * w).sum() / n) * w
    num = signal.correlate(win, tz, mode="valid")
    s1 = signal.correlate(win, w, mode="valid")
    s2 = signal.correlate(win * win, w, mode="valid")
    return num / np.sqrt(np.maximum(s2 - s1 * s1 / n, 1e-9) * (tz * tz).sum())


def ridge_px(m, i, drop=0.05, steps=64):
    """peak_ridge_px (src/video/path_tracker.cpp) of the correlation map m at its peak i (row, col)."""
    v = m[i]
    longest = 0.0
    for dy, dx in ((0, 1), (1, 0), (1, 1), (-1, 1)):
        total = 0
        for sign in (-1, 1):
            k = 1
            while k <= steps:
                r, c = i[0] + sign * k * dy, i[1] + sign * k * dx
                if r < 0 or c < 0 or r >= m.shape[0] or c >= m.shape[1] or m[r, c] < v - drop:
                    break
                k += 1
            total += k - 1
        longest = max(longest, 0.5 * total * np.hypot(dx, dy))
    return longest


def best_in(img, t, x, y, w):
    """Best placement of t within w px of (x, y): (x, y, correlation) or None at the border."""
    h = t.shape[0] // 2
    win = patch(img, x, y, h + w)
    if win is None:
        return None
    m = ncc_map(win, t)
    i = np.unravel_index(np.argmax(m), m.shape)
    return round(x) + i[1] - w, round(y) + i[0] - w, m[i]


def rotated(big, deg, h):
    b = big.shape[0] // 2
    return ndimage.rotate(big, deg, reshape=False, order=1)[b - h:b + h + 1, b - h:b + h + 1]


def velocity(marks, f):
    fs = sorted(marks)
    i = fs.index(f)
    a, b = fs[max(0, i - 1)], fs[min(len(fs) - 1, i + 1)]
    return (np.array(marks[b]) - np.array(marks[a])) / (b - a)


def probe_rotate(g, marks, p, f0):
    h = p // 2
    big = patch(g[f0], *marks[f0], int(1.5 * h) + 2)
    temps = [rotated(big, a, h) for a in np.arange(-195, 31, 7.5)]
    out = {}
    for f in sorted(marks):
        if f == f0:
            continue
        best = None
        for t in temps:
            r = best_in(g[f], t, *marks[f], 40)
            if r and (best is None or r[2] > best[2]):
                best = r
        if best:
            out[f] = best
    return out


def probe_deblur(g, marks, p, f0, shutter):
    h = p // 2
    big = patch(g[f0], *marks[f0], int(1.5 * h) + 2)
    v0 = velocity(marks, f0)
    th0 = np.arctan2(v0[1], v0[0])
    out = {}
    for f in sorted(marks):
        if f == f0:
            continue
        v = velocity(marks, f)
        th = np.arctan2(v[1], v[0])
        t = rotated(big, -np.degrees(th - th0), h)
        pad = 40
        win = patch(g[f], *marks[f], h + 40 + pad)
        if win is None:
            continue
        win = line_blur(win, shutter * (np.hypot(*v0) - np.hypot(*v)), th)[pad:-pad, pad:-pad]
        m = ncc_map(win, t)
        i = np.unravel_index(np.argmax(m), m.shape)
        out[f] = (round(marks[f][0]) + i[1] - 40, round(marks[f][1]) + i[0] - 40, m[i])
    return out


def chain(g, marks, p, f0, step, last, fixed=False):
    """Frame-to-frame template from f0's mark towards `last` (fixed: f0's template throughout):
    {frame: (x, y, ncc, fb)}."""
    h = p // 2
    x, y = marks[f0]
    vx = vy = 0.0
    out = {}
    f = f0
    first = patch(g[f0], x, y, h)
    while f != last:
        t = first if fixed else patch(g[f], x, y, h)
        r = best_in(g[f + step], t, x + vx, y + vy, 80 if f == f0 else 30) if t is not None else None
        if r is None:
            break
        nx, ny, s = r
        back = best_in(g[f], patch(g[f + step], nx, ny, h), x, y, 30)
        fb = np.hypot(back[0] - x, back[1] - y) if back else float("nan")
        f += step
        out[f] = (nx, ny, s, fb)
        vx, vy, x, y = nx - x, ny - y, nx, ny
    return out


def line_blur(img, length, th):
    """Blur along heading th (rad, image axes) by a line of `length` px."""
    if length <= 1:
        return img
    n = int(np.ceil(length))
    k = np.zeros((2 * n + 1, 2 * n + 1))
    for s in np.linspace(-length / 2, length / 2, 4 * n + 1):
        k[int(round(n + s * np.sin(th))), int(round(n + s * np.cos(th)))] += 1
    return ndimage.convolve(img, k / k.sum(), mode="nearest")


def probe_reblur(g, marks, p, f0, last, shutter=1.0, v0=70.0):
    c = {f0: np.array(marks[f0])}
    c.update({f: np.array(v[:2], float) for f, v in chain(g, marks, p, f0, 1, last).items()})

    def heading(t):
        a, b = max(f0, t - 1), min(max(c), t + 1)
        d = c[b] - c[a]
        return np.arctan2(d[1], d[0]), np.hypot(*d) / (b - a)

    th0, _ = heading(f0)
    out = {}
    for k in range(f0 + 8, min(last, f0 + 30), 2):
        thk, vk = heading(k)
        big = patch(g[k], *c[k], 100)
        if big is None:
            continue
        seen = line_blur(ndimage.rotate(big, np.degrees(thk - th0), reshape=False, order=1), shutter * (v0 - vk), th0)
        r = best_in(g[f0], seen[50:151, 50:151], *c[f0], 60)
        if r is None:
            continue
        a = thk - th0
        pk = c[k] + np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]]) @ (c[f0] - np.array(r[:2], float))
        out[k] = (pk[0], pk[1], r[2])
    return out


def probe_edge(rgb, marks):
    green = rgb[..., 1] - np.maximum(rgb[..., 0], rgb[..., 2])
    s, w = np.arange(-80, 81), np.arange(-4, 5)
    out = []
    for f in sorted(marks):
        v = velocity(marks, f)
        u = v / np.hypot(*v)
        n = np.array([-u[1], u[0]])
        pts = np.array(marks[f])[None, None, :] + s[:, None, None] * u + w[None, :, None] * n
        prof = ndimage.map_coordinates(green[f], [pts[..., 1].ravel(), pts[..., 0].ravel()], order=1)
        prof = prof.reshape(len(s), len(w)).mean(axis=1)
        k = int(np.argmax(prof[:121]))  # the green (rear) at most 40 px ahead of the mark
        half = 0.5 * (prof[k] + prof[80:].min())
        j = k
        while j < len(s) - 1 and prof[j] >= half:
            j += 1
        a, b = prof[j - 1], prof[j]
        out.append(f"{f}:{s[j - 1] + (a - half) / (a - b) if a != b else s[j]:.0f}")
    print("edge (px behind the white-green edge, per frame): " + " ".join(out))


def probe_blob(rgb, marks, f0):
    bg = np.median(rgb[::3], axis=0)
    fg = lambda f: np.abs(rgb[f] - bg).max(axis=2) > 35
    q = lambda im: (im // 32).astype(np.int32) @ np.array([64, 8, 1])
    H, W = rgb.shape[1:3]
    yy, xx = np.mgrid[0:H, 0:W]
    x0, y0 = marks[f0]
    d0 = np.hypot(xx - x0, yy - y0)
    f_0, q0 = fg(f0), q(rgb[f0])
    near = np.bincount(q0[f_0 & (d0 < 90)], minlength=512) + 0.5
    far = np.bincount(q0[f_0 & (d0 >= 150)], minlength=512) + 0.5
    ratio = (near / near.sum()) / (near / near.sum() + far / far.sum())

    def region(f):
        m = ndimage.binary_opening(fg(f) & (ratio[q(rgb[f])] > 0.6))
        lab, n = ndimage.label(ndimage.binary_closing(m, iterations=3))
        inside = (np.hypot(xx - marks[f][0], yy - marks[f][1]) < 100) & (lab > 0)
        k = np.bincount(lab[inside], minlength=n + 1).argmax()
        ys, xs = np.nonzero((lab == k) & m)
        cx, cy = xs.mean(), ys.mean()
        w, v = np.linalg.eigh(np.cov(np.stack([xs - cx, ys - cy])))
        return cx, cy, np.arctan2(v[1, 1], v[0, 1])

    cx0, cy0, th0 = region(f0)
    off = np.array([x0 - cx0, y0 - cy0])
    prev = th0
    out = {}
    for f in sorted(marks):
        if f == f0:
            continue
        cx, cy, th = region(f)
        th = prev + ((th - prev + np.pi / 2) % np.pi - np.pi / 2)  # the axis turns continuously
        prev = th
        a = th - th0
        px, py = np.array([cx, cy]) + np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]]) @ off
        out[f] = (px, py, float("nan"))
    return out


def placed_near_marks(g, marks, f0, h, corr, w=40):
    """{frame: (x, y, correlation, ridge)}: the best placement of a template of half side h within
    w px of each mark but the first frame's, `corr(window)` its correlation map there."""
    out = {}
    for f in sorted(marks):
        win = patch(g[f], *marks[f], h + w) if f != f0 else None
        if win is None:
            continue
        m = corr(win)
        i = np.unravel_index(np.argmax(m), m.shape)
        out[f] = (round(marks[f][0]) + i[1] - w, round(marks[f][1]) + i[0] - w, m[i], ridge_px(m, i))
    return out


def probe_grow(g, marks, f0, sides, bound):
    """{side: (own ridge, {frame: (x, y, ncc, ridge)})} and the side the rule chooses."""
    out, chosen = {}, None
    for p in sides:
        h = p // 2
        t = patch(g[f0], *marks[f0], h)
        win = patch(g[f0], *marks[f0], h + 30)
        if t is None or win is None:
            continue
        m = ncc_map(win, t)
        own = ridge_px(m, (30, 30))
        if chosen is None and own <= bound:
            chosen = p
        out[p] = (own, placed_near_marks(g, marks, f0, h, lambda win, t=t: ncc_map(win, t)))
    return out, chosen


def probe_masked(g, marks, p, f0, level=20.0):
    h = p // 2
    bg = np.median(g[::3], axis=0)
    t = patch(g[f0], *marks[f0], h)
    w = (np.abs(t - patch(bg, *marks[f0], h)) > level).astype(float)
    print(f"masked: {100 * w.mean():.0f} % of the {p} px template differs from the background by more than {level:.0f}")
    return placed_near_marks(g, marks, f0, h, lambda win: masked_ncc_map(win, t, w))


def report(name, placed, marks, bar, tag="fb"):
    """Per frame: distance to the mark and (tag) the placement's fourth figure: fb the
    forward-backward error, r the ridge, px."""
    d = {f: np.hypot(placed[f][0] - marks[f][0], placed[f][1] - marks[f][1]) for f in placed}
    within = sum(v <= bar for v in d.values())
    print(f"{name}: {within} of {len(d)} frames within {bar:.0f} px of the human's mark, "
          f"median {np.median(list(d.values())):.1f} px")
    print("  " + " ".join(f"{f}:{d[f]:.0f}" + (f"/{tag}{placed[f][3]:.0f}" if len(placed[f]) > 3 else "")
                          for f in sorted(d)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("project")
    ap.add_argument("--track", default="masa A")
    ap.add_argument("--patch", type=int, default=51, help="template side, px (the path tracker chose 51 on CarInLoop)")
    ap.add_argument("--mid", type=int, default=20, help="the frame chain-mid starts from")
    ap.add_argument("--probes", default="rotate,deblur,chain,chain-mid,mark-look,reblur,edge,blob,grow,masked")
    a = ap.parse_args()
    rgb, marks = read_project(a.project, a.track)
    marks = {f: xy for f, xy in marks.items() if f < len(rgb)}
    g = gray(rgb)
    f0, last = min(marks), max(marks)
    bar = max(4.0, 4.0 * rgb.shape[2] / 640)
    print(f"{a.project} '{a.track}': {len(rgb)} frames {rgb.shape[2]}x{rgb.shape[1]}, {len(marks)} marks, "
          f"correction distance {bar:.0f} px")
    probes = a.probes.split(",")
    if "rotate" in probes:
        report("rotate", probe_rotate(g, marks, a.patch, f0), marks, bar)
    if "deblur" in probes:
        for s in (0.5, 1.0):
            report(f"deblur (shutter {s})", probe_deblur(g, marks, a.patch, f0, s), marks, bar)
    if "chain" in probes:
        report("chain", chain(g, marks, a.patch, f0, 1, last), marks, bar)
    if "chain-mid" in probes:
        both = chain(g, marks, a.patch, a.mid, 1, last)
        both.update(chain(g, marks, a.patch, a.mid, -1, f0))
        report(f"chain-mid (from frame {a.mid})", both, marks, bar)
    if "mark-look" in probes:
        both = chain(g, marks, a.patch, a.mid, 1, last, fixed=True)
        both.update(chain(g, marks, a.patch, a.mid, -1, f0, fixed=True))
        placed = {f: v for f, v in both.items() if v[2] >= 0.6}  # the path tracker's min_score
        print(f"mark-look: {len(placed)} of {len(both)} frames correlate >= 0.6 with frame {a.mid}'s look")
        report(f"mark-look (frame {a.mid}'s look)", both, marks, bar)
    if "reblur" in probes:
        report("reblur", probe_reblur(g, marks, a.patch, f0, last), marks, bar)
    if "edge" in probes:
        probe_edge(rgb, marks)
    if "blob" in probes:
        report("blob", probe_blob(rgb, marks, f0), marks, bar)
    if "grow" in probes:
        grown, chosen = probe_grow(g, marks, f0, (51, 81, 111, 141, 181), bar)
        for p, (own, placed) in grown.items():
            ridges = [v[3] for v in placed.values()]
            rule = f" (the side a start ridge <= {bar:.0f} px rule chooses)" if p == chosen else ""
            print(f"grow {p} px: the start's own ridge {own:.1f} px, the placements' median ridge "
                  f"{np.median(ridges):.1f} px{rule}")
            report(f"grow {p} px", placed, marks, bar, tag="r")
    if "masked" in probes:
        report(f"masked ({a.patch} px)", probe_masked(g, marks, a.patch, f0), marks, bar, tag="r")


if __name__ == "__main__":
    main()
