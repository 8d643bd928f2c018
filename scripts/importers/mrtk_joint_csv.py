#!/usr/bin/env python3
"""mrtk_joint_csv.py — HoloLens 2 hand joints logged through MRTK 2 as CSV -> handspring joint CSV v2.

Usage:
    python3 scripts/importers/mrtk_joint_csv.py IN.csv --hand right --out OUT.csv [--from S] [--to S]

Reads (stdlib only) the CSV written by the TrackingLogger Unity scripts of Duke-I3T-Lab's
Hand-gesture-recognition (github.com/Duke-I3T-Lab/Hand-gesture-recognition,
DataCollection/Hololens2/TCP_TrackingLogger.cs, MIT), which run on a HoloLens 2 and call MRTK 2's
HandJointUtils.TryGetJointPose(TrackedHandJoint.X, Handedness.Right/Left) once per logged frame:

  Label,Time,Counter,<26 columns of the right hand>,<26 columns of the left hand>

  * Label: the observer's gesture label (kept in a comment only); Time: the HoloLens wall clock,
    "HH:mm:ss.fff" as logged, or "YYYY-MM-DD HH:mm:ss.fff" in the repository's labeled files;
    Counter: frame number.
  * each joint column holds Unity's Vector3.ToString("F3") with the commas replaced by '/',
    e.g. "(-0.024/ -0.312/ 0.018)", i.e. metres rounded to 1 mm, in Unity world space
    (left-handed: x right, y up, z forward; origin where the app started) — handspring's
    `@frame unity`, `@units m`; or "0" when MRTK had no pose for that joint (hand not tracked).
  * the 26 joint names per hand, in the logger's (alphabetical) column order: IndexDistalJoint,
    IndexKnuckle, IndexMetacarpal, IndexMiddleJoint, IndexTip, the same for Middle, Palm, Pinky,
    Ring, then ThumbDistalJoint, ThumbMetacarpalJoint, ThumbProximalJoint, ThumbTip, Wrist.
    (pandas re-saves duplicate names with a ".1" suffix; the importer goes by position.)

Joint mapping (MediaPipe index <- MRTK TrackedHandJoint, which follows the Windows/OpenXR hand
joint set: ThumbMetacarpalJoint is the thumb's CMC, ThumbProximalJoint its MCP, ThumbDistalJoint
its IP; XKnuckle is a finger's MCP, XMiddleJoint its PIP, XDistalJoint its DIP):
  0 Wrist; 1 ThumbMetacarpalJoint; 2 ThumbProximalJoint; 3 ThumbDistalJoint; 4 ThumbTip;
  5-8 IndexKnuckle, IndexMiddleJoint, IndexDistalJoint, IndexTip; 9-12 Middle...; 13-16 Ring...;
  17-20 Pinky... . Palm and the four finger metacarpal bases (XMetacarpal) are not used.

t is seconds from the first row kept (after --from), from the Time column (1 ms resolution,
irregular, ~40 ms apart). A row where the hand's joints are "0" gets empty cells and tracked = 0
(confidence 0); MRTK gives no confidence, so a tracked row has confidence 1. A time that goes
backwards (a midnight wrap of "HH:mm:ss.fff") is unwrapped by adding a day.
"""
import argparse
import csv
import datetime
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import handcsv  # noqa: E402

JOINTS = [
    "IndexDistalJoint", "IndexKnuckle", "IndexMetacarpal", "IndexMiddleJoint", "IndexTip",
    "MiddleDistalJoint", "MiddleKnuckle", "MiddleMetacarpal", "MiddleMiddleJoint", "MiddleTip",
    "Palm",
    "PinkyDistalJoint", "PinkyKnuckle", "PinkyMetacarpal", "PinkyMiddleJoint", "PinkyTip",
    "RingDistalJoint", "RingKnuckle", "RingMetacarpal", "RingMiddleJoint", "RingTip",
    "ThumbDistalJoint", "ThumbMetacarpalJoint", "ThumbProximalJoint", "ThumbTip", "Wrist",
]
MEDIAPIPE_FROM_MRTK = [
    "Wrist",
    "ThumbMetacarpalJoint", "ThumbProximalJoint", "ThumbDistalJoint", "ThumbTip",
    "IndexKnuckle", "IndexMiddleJoint", "IndexDistalJoint", "IndexTip",
    "MiddleKnuckle", "MiddleMiddleJoint", "MiddleDistalJoint", "MiddleTip",
    "RingKnuckle", "RingMiddleJoint", "RingDistalJoint", "RingTip",
    "PinkyKnuckle", "PinkyMiddleJoint", "PinkyDistalJoint", "PinkyTip",
]
FIRST = 3                       # Label, Time, Counter
BLOCK = {"right": FIRST, "left": FIRST + len(JOINTS)}


def parse_time(s):
    """Seconds since midnight from "HH:mm:ss.fff" or "YYYY-MM-DD HH:mm:ss.fff" (exact in ms)."""
    s = s.strip()
    day = 0
    if " " in s:
        date, s = s.split(" ", 1)
        y, mo, d = (int(x) for x in date.split("-"))
        # days since 2000-01-01 (only differences matter)
        day = (datetime.date(y, mo, d) - datetime.date(2000, 1, 1)).days
    hh, mm, ss = s.split(":")
    sec, _, frac = ss.partition(".")
    ms = (int(hh) * 3600 + int(mm) * 60 + int(sec)) * 1000 + (int((frac + "000")[:3]) if frac else 0)
    return day * 86400000 + ms            # integer milliseconds


def parse_point(cell):
    c = cell.strip()
    if c in ("", "0"):
        return None
    parts = c.strip("()").split("/")
    if len(parts) != 3:
        raise ValueError("bad joint cell %r" % cell)
    return tuple(float(p) for p in parts)


def convert(path, hand, t_from=None, t_to=None):
    with open(path, encoding="utf-8-sig", newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], [r for r in rows[1:] if r and any(x.strip() for x in r)]
    base = BLOCK[hand]
    names = [h.split(".")[0] for h in header[base:base + len(JOINTS)]]
    if names != JOINTS or [h.strip() for h in header[:FIRST]] != ["Label", "Time", "Counter"]:
        raise SystemExit("%s: not the TrackingLogger column layout" % path)
    col = {n: base + i for i, n in enumerate(JOINTS)}
    ms = []
    last = None
    for r in body:
        v = parse_time(r[1])
        if last is not None:
            while v < last - 12 * 3600000:     # "HH:mm:ss.fff" wrapped past midnight
                v += 86400000
        ms.append(v)
        last = v
    ms0 = ms[0]
    kept = [(m, r) for m, r in zip(ms, body)
            if (t_from is None or (m - ms0) / 1000.0 >= t_from - 1e-9)
            and (t_to is None or (m - ms0) / 1000.0 <= t_to + 1e-9)]
    if not kept:
        raise SystemExit("%s: no row in the asked time range" % path)
    k0 = kept[0][0]
    out = []
    labels = {}
    prev = None
    for m, r in kept:
        if len(r) < base + len(JOINTS):
            raise SystemExit("%s: short row (counter %s)" % (path, r[2]))
        if prev is not None and m < prev:
            raise SystemExit("%s: time goes backwards at counter %s" % (path, r[2]))
        prev = m
        pts = [parse_point(r[col[n]]) for n in MEDIAPIPE_FROM_MRTK]
        tracked = all(p is not None for p in pts)
        if not any(p is not None for p in pts):
            pts = None
        lab = r[0].strip()
        labels[lab] = labels.get(lab, 0) + 1
        out.append(((m - k0) / 1000.0, pts, tracked, 1.0 if tracked else 0.0))
    return out, labels


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("input", help="TrackingLogger CSV")
    ap.add_argument("--hand", required=True, choices=("left", "right"))
    ap.add_argument("--out", default="-", help="output CSV (default stdout)")
    ap.add_argument("--from", dest="t_from", type=float, help="first second kept (from the input's first row)")
    ap.add_argument("--to", dest="t_to", type=float, help="last second kept (from the input's first row)")
    ap.add_argument("--source", help="text for the @source directive")
    a = ap.parse_args(argv)
    rows, labels = convert(a.input, a.hand, a.t_from, a.t_to)
    src = a.source or "HoloLens 2 hand joints via MRTK 2 (Duke-I3T-Lab TrackingLogger CSV %s)" % os.path.basename(a.input)
    comments = [
        "converted by scripts/importers/mrtk_joint_csv.py from %s" % os.path.basename(a.input),
        "Unity world space (left-handed, x right, y up, z forward), metres rounded to 1 mm by the logger",
        "observer labels in the rows kept: " + ", ".join(
            "%s x%d" % (k if k else "(none)", labels[k]) for k in sorted(labels)),
    ]
    handcsv.write(a.out, rows, "unity", "m", a.hand, src, comments)


if __name__ == "__main__":
    main()
