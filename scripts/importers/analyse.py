#!/usr/bin/env python3
"""analyse.py — timing, grip aperture events and bone lengths of handspring joint CSVs (v2).

Usage:
    python3 scripts/importers/analyse.py --title NAME --out events.md HAND1.csv [HAND2.csv ...]

The CSVs are the hands of one recording (same time origin). For each file it reports:
  * frames, duration, mean rate, gaps between timestamps (min / median / max ms), frames with
    tracked = 0;
  * two apertures over time, in mm:
      pinch = |thumb tip (4) - index tip (8)|,
      grip  = mean distance of the five fingertips (4, 8, 12, 16, 20) from the centroid of the
              palm landmarks 0, 5, 9, 13, 17;
  * for each aperture its open level (90th percentile over tracked frames) and closed level
    (10th percentile); "closes" when it falls through the middle of the two levels and "opens"
    when it rises through it again (a hysteresis of 15 % of the span keeps jitter from making
    events; the time is linearly interpolated at the middle crossing; no event is reported when
    the two levels are less than 20 mm apart). For each event: the extreme value since the
    previous event ("before": the highest before a close, the lowest before an open) and the
    extreme until the next event ("after"), the wrist (landmark 0) and the thumb-index midpoint
    ((4 + 8) / 2) at the crossing, and the time, wrist and midpoint when the hand has "settled"
    (the first frame after the crossing within 10 % of the span of the "after" extreme: where
    the hand has essentially finished closing / opening), all positions in handspring's z-up metres (x forward,
    y left, z up);
  * median bone lengths (mm) of the 15 finger segments and of wrist-5, 5-9, 9-13, 13-17.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import handcsv  # noqa: E402

UNIT = {"m": 1.0, "cm": 0.01, "mm": 0.001}
TIPS = (4, 8, 12, 16, 20)
PALM = (0, 5, 9, 13, 17)
FINGER_NAMES = ("thumb", "index", "middle", "ring", "little")
SEGMENT_NAMES = {0: ("CMC-MCP", "MCP-IP", "IP-tip")}


def to_zup_m(p, frame, units):
    s = UNIT[units]
    x, y, z = (c * s for c in p)
    if frame == "y_up":          # x right, y up, z toward the viewer
        return (-z, -x, y)
    if frame == "unity":         # x right, y up, z forward (left-handed)
        return (z, -x, y)
    if frame == "mediapipe":     # x right, y down, z away from the camera
        return (z, -x, -y)
    if frame == "z_up":
        return (x, y, z)
    raise ValueError("unknown @frame %r" % frame)


def median(v):
    v = sorted(v)
    n = len(v)
    if n == 0:
        return float("nan")
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def percentile(v, q):
    v = sorted(v)
    if not v:
        return float("nan")
    k = (len(v) - 1) * q
    i = int(math.floor(k))
    j = min(i + 1, len(v) - 1)
    return v[i] + (v[j] - v[i]) * (k - i)


def pinch(pts):
    return math.dist(pts[4], pts[8])


def grip(pts):
    c = [sum(pts[i][k] for i in PALM) / len(PALM) for k in range(3)]
    return sum(math.dist(pts[i], c) for i in TIPS) / len(TIPS)


MIN_SPAN_MM = 20.0


def events(ts, vals):
    """ts, vals (mm): tracked frames only. Returns (open level, closed level, [(kind, t, i0, i1)])."""
    hi, lo = percentile(vals, 0.9), percentile(vals, 0.1)
    mid = 0.5 * (hi + lo)
    h = 0.15 * (hi - lo)
    out = []
    if len(vals) < 2 or hi - lo < MIN_SPAN_MM:
        return hi, lo, out
    state = "open" if vals[0] >= mid else "closed"
    for i in range(1, len(vals)):
        a = vals[i]
        if state == "open" and a < mid - h:
            j = i
            while j > 0 and vals[j - 1] < mid:
                j -= 1
            # crossing of mid between j-1 (>= mid) and j (< mid)
            j0 = max(j - 1, 0)
            out.append(("closes", cross_time(ts, vals, j0, j, mid), j0, j))
            state = "closed"
        elif state == "closed" and a > mid + h:
            j = i
            while j > 0 and vals[j - 1] > mid:
                j -= 1
            j0 = max(j - 1, 0)
            out.append(("opens", cross_time(ts, vals, j0, j, mid), j0, j))
            state = "open"
    return hi, lo, out


def cross_time(ts, vals, i, j, mid):
    if i == j or vals[i] == vals[j]:
        return ts[j]
    f = (mid - vals[i]) / (vals[j] - vals[i])
    f = min(max(f, 0.0), 1.0)
    return ts[i] + f * (ts[j] - ts[i])


def lerp_point(a, b, f):
    return tuple(a[k] + f * (b[k] - a[k]) for k in range(3))


def at_time(ts, pts_list, t, idx):
    """Landmark idx (or 'mid' for the thumb-index midpoint) interpolated at time t."""
    def get(p):
        if idx == "mid":
            return tuple(0.5 * (p[4][k] + p[8][k]) for k in range(3))
        return p[idx]
    for i in range(len(ts) - 1):
        if ts[i] <= t <= ts[i + 1]:
            f = 0.0 if ts[i + 1] == ts[i] else (t - ts[i]) / (ts[i + 1] - ts[i])
            return lerp_point(get(pts_list[i]), get(pts_list[i + 1]), f)
    return get(pts_list[-1] if t > ts[-1] else pts_list[0])


def f3(p):
    return "(%+.3f, %+.3f, %+.3f)" % p


def analyse_file(path, lines, summary):
    d, rows = handcsv.read(path)
    frame, units, hand = d.get("frame"), d.get("units"), d.get("hand")
    mm = UNIT[units] * 1000.0
    ts_all = [r[0] for r in rows]
    gaps = [(b - a) * 1000.0 for a, b in zip(ts_all, ts_all[1:])]
    dur = ts_all[-1] - ts_all[0]
    untracked = [r[0] for r in rows if not r[2]]
    tr = [r for r in rows if r[2]]
    tr_index = [i for i, r in enumerate(rows) if r[2]]
    # gap_after[k]: untracked rows lie between tracked frames k and k + 1
    gap_after = [b - a > 1 for a, b in zip(tr_index, tr_index[1:])] + [False]
    ts = [r[0] for r in tr]
    P = [r[1] for r in tr]
    lines.append("## %s hand — `%s`" % (hand, os.path.basename(path)))
    lines.append("")
    lines.append("- source: %s" % d.get("source", ""))
    lines.append("- frame `%s`, units `%s`; z-up positions below are in metres (x forward, y left, z up)" % (frame, units))
    lines.append("- frames: %d, duration %.3f s, mean rate %.1f frames/s" % (len(rows), dur, (len(rows) - 1) / dur if dur > 0 else float("nan")))
    if gaps:
        lines.append("- timestamp gaps: min %.2f ms, median %.2f ms, max %.2f ms" % (min(gaps), median(gaps), max(gaps)))
    if untracked:
        spans = []
        start = prev = None
        for r in rows:
            if not r[2]:
                if start is None:
                    start = r[0]
                prev = r[0]
            elif start is not None:
                spans.append((start, prev))
                start = None
        if start is not None:
            spans.append((start, prev))
        lines.append("- frames with the hand missing (tracked = 0): %d, at %s" % (
            len(untracked), ", ".join("%.3f-%.3f s" % s if s[0] != s[1] else "%.3f s" % s[0] for s in spans[:12])
            + (" ..." if len(spans) > 12 else "")))
    else:
        lines.append("- frames with the hand missing (tracked = 0): none")
    lines.append("")
    if not tr:
        lines.append("(no tracked frame)")
        lines.append("")
        return
    ap = {"pinch": [pinch(p) * mm for p in P], "grip": [grip(p) * mm for p in P]}
    summ = {"hand": hand, "file": os.path.basename(path), "frames": len(rows), "duration": dur,
            "rate": (len(rows) - 1) / dur if dur > 0 else float("nan"), "untracked": len(untracked),
            "gaps": (min(gaps), median(gaps), max(gaps)) if gaps else None, "events": {}}
    for name, desc in (("pinch", "thumb tip - index tip distance"),
                       ("grip", "mean fingertip distance from the palm centroid (0, 5, 9, 13, 17)")):
        vals = ap[name]
        hi, lo, ev = events(ts, vals)
        lines.append("### %s aperture (%s)" % (name, desc))
        lines.append("")
        lines.append("- range %.1f-%.1f mm; open level (p90) %.1f mm, closed level (p10) %.1f mm, middle %.1f mm"
                     % (min(vals), max(vals), hi, lo, 0.5 * (hi + lo)))
        if not ev:
            lines.append("- no close/open event%s" % (
                " (open and closed levels less than %g mm apart)" % MIN_SPAN_MM if hi - lo < MIN_SPAN_MM else ""))
        else:
            lines.append("")
            lines.append("| event | t (s) | aperture before (mm) | aperture after (mm) | wrist z-up (m) | thumb-index midpoint z-up (m) "
                         "| t settled (s) | wrist there (m) | thumb-index midpoint there (m) |")
            lines.append("|---|---|---|---|---|---|---|---|---|")
        evs = []
        for k, (kind, t, i0, i1) in enumerate(ev):
            prev_i = ev[k - 1][3] if k > 0 else 0
            next_i = ev[k + 1][2] if k + 1 < len(ev) else len(vals) - 1
            before = vals[prev_i:i1]
            after = vals[i0:next_i + 1]
            pick = max if kind == "opens" else min
            b = (max if kind == "closes" else min)(before)
            a = pick(after)
            # "settled": the first frame after the crossing within 10 % of the span of that extreme
            tol = 0.1 * (hi - lo)
            k_after = i1
            while k_after < next_i and not (vals[k_after] <= a + tol if kind == "closes" else vals[k_after] >= a - tol):
                k_after += 1
            w = to_zup_m(at_time(ts, P, t, 0), frame, units)
            m = to_zup_m(at_time(ts, P, t, "mid"), frame, units)
            w2 = to_zup_m(P[k_after][0], frame, units)
            m2 = to_zup_m(tuple(0.5 * (P[k_after][4][c] + P[k_after][8][c]) for c in range(3)), frame, units)
            label = kind + (" (across a tracking loss: time and positions interpolated over it)"
                            if i0 != i1 and gap_after[i0] else "")
            lines.append("| %s | %.3f | %.1f | %.1f | %s | %s | %.3f | %s | %s |" % (
                label, t, b, a, f3(w), f3(m), ts[k_after], f3(w2), f3(m2)))
            evs.append((kind, t, b, a, w, m, ts[k_after], w2, m2))
        summ["events"][name] = (hi, lo, evs)
        lines.append("")
    # aperture over time, at most ~60 rows
    step = max(1, int(math.ceil(len(ts) / 60.0)))
    lines.append("### apertures over time (every %d%s tracked frame)" % (step, "th" if step > 1 else "st"))
    lines.append("")
    lines.append("| t (s) | pinch (mm) | grip (mm) | wrist z-up (m) | thumb-index midpoint z-up (m) |")
    lines.append("|---|---|---|---|---|")
    for i in range(0, len(ts), step):
        w = to_zup_m(P[i][0], frame, units)
        m = to_zup_m(tuple(0.5 * (P[i][4][k] + P[i][8][k]) for k in range(3)), frame, units)
        lines.append("| %.3f | %.1f | %.1f | %s | %s |" % (ts[i], ap["pinch"][i], ap["grip"][i], f3(w), f3(m)))
    lines.append("")
    # bone lengths
    lines.append("### median bone lengths (mm, over %d tracked frames)" % len(P))
    lines.append("")
    lines.append("| finger | segment 1 | segment 2 | segment 3 |")
    lines.append("|---|---|---|---|")
    bones = {}
    for f in range(5):
        b = 1 + 4 * f
        segs = []
        for s in range(3):
            L = median([math.dist(p[b + s], p[b + s + 1]) * mm for p in P])
            segs.append(L)
        names = ("CMC-MCP", "MCP-IP", "IP-tip") if f == 0 else ("MCP-PIP", "PIP-DIP", "DIP-tip")
        lines.append("| %s (%d-%d-%d-%d) | %s %.1f | %s %.1f | %s %.1f |" % (
            FINGER_NAMES[f], b, b + 1, b + 2, b + 3, names[0], segs[0], names[1], segs[1], names[2], segs[2]))
        bones[FINGER_NAMES[f]] = segs
    palm = []
    for a, b in ((0, 5), (5, 9), (9, 13), (13, 17)):
        palm.append(median([math.dist(p[a], p[b]) * mm for p in P]))
    lines.append("")
    lines.append("palm: wrist-5 %.1f, 5-9 %.1f, 9-13 %.1f, 13-17 %.1f mm" % tuple(palm))
    lines.append("")
    summ["bones"] = bones
    summ["palm"] = palm
    summary.append(summ)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv", nargs="+")
    ap.add_argument("--title", required=True)
    ap.add_argument("--out", default="-")
    ap.add_argument("--note", action="append", default=[], help="a paragraph put under the title")
    a = ap.parse_args(argv)
    lines = ["# %s — events" % a.title, "",
             "Written by `scripts/importers/analyse.py` (see its header for the definitions).", ""]
    for n in a.note:
        lines += [n, ""]
    summary = []
    for p in a.csv:
        analyse_file(p, lines, summary)
    text = "\n".join(lines).rstrip("\n") + "\n"
    if a.out == "-":
        sys.stdout.write(text)
    else:
        with open(a.out, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)


if __name__ == "__main__":
    main()
