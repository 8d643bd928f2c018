#!/usr/bin/env python3
"""leap_json.py — Leap Motion frame recordings (leapjs-playback JSON) -> handspring joint CSV v2.

Usage:
    python3 scripts/importers/leap_json.py IN.json --hand right --out OUT.csv [--from S] [--to S]

Reads (stdlib only, plain JSON; decompress a `.json.lz` once with lz-string's decompressFromBase64)
the recordings written by Leap Motion's leapjs-playback (github.com/leapmotion/leapjs-playback,
src/recording.js), which hold frames of the Leap WebSocket JSON protocol (protocol version 6,
leapjs/Leap_JSON.rst):

  * {"metadata": {...}, "frames": [frame, ...]}     formatVersion 0.1 / 1: each frame a JSON object
  * {"metadata": {...}, "frames": [packing, [...]]} formatVersion 2: frames[0] is the packing
    structure (a list of key names, where {"hands": [[keys]]} / {"pointables": [[keys]]} name the
    fields of each hand / pointable array) and every later element is one frame packed as arrays
  * a bare list of frame objects

A frame has "timestamp" (device clock, microseconds), "hands" (id, type "left"/"right",
palmPosition, direction, palmNormal, confidence, and from Leap SDK 2.1 on also wrist/elbow) and
"pointables" (handId, type 0-4 = thumb..pinky — or, when "type" is absent, id - 10 * handId —,
carpPosition, mcpPosition, pipPosition, dipPosition, btipPosition, tipPosition, tool). Positions
are millimetres in the Leap frame: right-handed, origin at the device, x right, y up, z toward
the user — handspring's `@frame y_up`; the CSV keeps mm.

Joint mapping (MediaPipe index <- Leap field):
  0 wrist     <- hand.wrist when recorded (SDK >= 2.1); else the mean carpPosition of the index,
                 middle, ring and little fingers (the bases of their metacarpals); else, for
                 recordings that have neither (SDK 2.0 era, like most leapjs-playback samples),
                 estimated as  m - w * (0.994 * direction + 0.141 * palmNormal)  where m is the
                 mean mcpPosition of those four fingers and w the index-to-little MCP distance.
                 The two coefficients are the mean metacarpal-base offset measured on
                 leapjs-playback's pinch-57fps recording, which has carpPosition (the Leap v2
                 palm skeleton is rigid, so the offset is a constant in hand units).
  1 thumb CMC <- thumb carpPosition, or its mcpPosition (the same point: Leap models the thumb
                 with a zero-length metacarpal, so its "proximal" bone is the anatomical
                 metacarpal and Leap's thumb mcp/pip/dip are the anatomical CMC/MCP/IP)
  2 thumb MCP <- thumb pipPosition
  3 thumb IP  <- thumb dipPosition
  4 thumb tip <- thumb btipPosition (end of the distal bone) when recorded, else tipPosition
                 (which Leap places ~4 mm short of btip, ~77 % along the distal bone)
  5-8, 9-12, 13-16, 17-20 (index, middle, ring, little) <- mcpPosition, pipPosition,
                 dipPosition, btipPosition (else tipPosition)

t is seconds from the first frame kept (after --from), from the device timestamps, irregular
as recorded. A frame without a hand of the asked type, or with a finger missing, gets empty
cells and tracked = 0 (confidence 0). confidence is Leap's hand.confidence. If several hands of
the asked type are in a frame, the one with the highest confidence is used (--hand-id picks one).
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import handcsv  # noqa: E402

# carp-mean = mcp-mean + w * (A_DIR * direction + A_NORMAL * palmNormal), see the header
A_DIR = -0.994
A_NORMAL = -0.141


def unpack(structure, data):
    """Undo leapjs-playback's packing (formatVersion 2) for one frame or sub-array."""
    out = {}
    for key, value in zip(structure, data):
        if isinstance(key, str):
            out[key] = value
        else:
            (name, sub), = key.items()
            if sub and isinstance(sub[0], list):
                out[name] = [unpack(sub[0], v) for v in (value or [])]
            else:
                out[name] = unpack(sub, value) if value is not None else None
    return out


def load_frames(path):
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    meta = {}
    frames = doc
    if isinstance(doc, dict):
        meta = doc.get("metadata") or {}
        frames = doc["frames"]
    if frames and isinstance(frames[0], list):
        packing = frames[0]
        frames = [unpack(packing, fr) for fr in frames[1:]]
    return meta, frames


def vec(v):
    if v is None or len(v) != 3 or any(x is None for x in v):
        return None
    return (float(v[0]), float(v[1]), float(v[2]))


def finger_type(p, hand_id):
    t = p.get("type")
    if t is not None:
        return int(t)
    return int(p["id"]) - 10 * int(hand_id)


def tip_of(p):
    return vec(p.get("btipPosition")) or vec(p.get("tipPosition"))


def wrist_of(hand, fingers):
    """(point, method) — see the header comment for the three methods."""
    w = vec(hand.get("wrist"))
    if w is not None:
        return w, "hand.wrist"
    carps = [vec(fingers[i].get("carpPosition")) for i in (1, 2, 3, 4) if i in fingers]
    if len(carps) == 4 and all(c is not None for c in carps):
        return tuple(sum(c[k] for c in carps) / 4.0 for k in range(3)), "mean carpPosition"
    mcps = [vec(fingers[i].get("mcpPosition")) for i in (1, 2, 3, 4) if i in fingers]
    d = vec(hand.get("direction"))
    n = vec(hand.get("palmNormal"))
    if len(mcps) != 4 or any(m is None for m in mcps) or d is None or n is None:
        return None, "none"
    m = tuple(sum(c[k] for c in mcps) / 4.0 for k in range(3))
    w = math.dist(mcps[0], mcps[3])
    return tuple(m[k] + w * (A_DIR * d[k] + A_NORMAL * n[k]) for k in range(3)), "estimated from MCPs"


def landmarks(hand, pointables):
    fingers = {}
    for p in pointables:
        if p.get("tool") or p.get("handId") != hand["id"]:
            continue
        fingers.setdefault(finger_type(p, hand["id"]), p)
    pts = [None] * 21
    pts[0], method = wrist_of(hand, fingers)
    th = fingers.get(0)
    if th is not None:
        pts[1] = vec(th.get("carpPosition")) or vec(th.get("mcpPosition"))
        pts[2] = vec(th.get("pipPosition"))
        pts[3] = vec(th.get("dipPosition"))
        pts[4] = tip_of(th)
    for f in (1, 2, 3, 4):
        p = fingers.get(f)
        if p is None:
            continue
        b = 1 + 4 * f
        pts[b] = vec(p.get("mcpPosition"))
        pts[b + 1] = vec(p.get("pipPosition"))
        pts[b + 2] = vec(p.get("dipPosition"))
        pts[b + 3] = tip_of(p)
    return pts, method


def convert(path, hand_type, t_from=None, t_to=None, hand_id=None):
    meta, frames = load_frames(path)
    if not frames:
        raise SystemExit("%s: no frames" % path)
    ts0 = frames[0]["timestamp"]
    kept = []
    for fr in frames:
        t = (fr["timestamp"] - ts0) / 1e6
        if t_from is not None and t < t_from - 1e-9:
            continue
        if t_to is not None and t > t_to + 1e-9:
            continue
        kept.append(fr)
    if not kept:
        raise SystemExit("%s: no frame in the asked time range" % path)
    t0 = kept[0]["timestamp"]
    rows = []
    methods = {}
    prev_ts = None
    for fr in kept:
        if prev_ts is not None and fr["timestamp"] <= prev_ts:
            raise SystemExit("%s: timestamps not increasing at frame id %s" % (path, fr.get("id")))
        prev_ts = fr["timestamp"]
        t = (fr["timestamp"] - t0) / 1e6
        cands = [h for h in fr.get("hands") or [] if h.get("type") == hand_type
                 and (hand_id is None or h.get("id") == hand_id)]
        if not cands:
            rows.append((t, None, False, 0.0))
            continue
        hand = max(cands, key=lambda h: (h.get("confidence") or 0.0, -int(h["id"])))
        pts, method = landmarks(hand, fr.get("pointables") or [])
        tracked = all(p is not None for p in pts)
        methods[method] = methods.get(method, 0) + 1
        conf = hand.get("confidence")
        rows.append((t, pts, tracked, (float(conf) if conf is not None else 1.0) if tracked else 0.0))
    return meta, rows, methods


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("input", help="leapjs-playback recording, plain JSON")
    ap.add_argument("--hand", required=True, choices=("left", "right"))
    ap.add_argument("--out", default="-", help="output CSV (default stdout)")
    ap.add_argument("--from", dest="t_from", type=float, help="first second kept (from the input's first frame)")
    ap.add_argument("--to", dest="t_to", type=float, help="last second kept (from the input's first frame)")
    ap.add_argument("--hand-id", type=int, help="use only the Leap hand with this id")
    ap.add_argument("--source", help="text for the @source directive (default: built from the metadata)")
    a = ap.parse_args(argv)
    meta, rows, methods = convert(a.input, a.hand, a.t_from, a.t_to, a.hand_id)
    src = a.source
    if not src:
        title = meta.get("title") or os.path.splitext(os.path.basename(a.input))[0]
        src = 'leapjs-playback recording "%s" (Leap Motion Controller)' % title
        if a.t_from is not None or a.t_to is not None:
            src += ", cut %s-%s s" % ("" if a.t_from is None else handcsv.fmt_t(a.t_from),
                                       "" if a.t_to is None else handcsv.fmt_t(a.t_to))
    comments = [
        "converted by scripts/importers/leap_json.py from %s" % os.path.basename(a.input),
        "Leap frame (right-handed, y up, z toward the user, origin at the device), millimetres",
        "wrist (landmark 0): " + (", ".join("%s in %d frames" % (k, methods[k]) for k in sorted(methods)) or "none"),
        "thumb: Leap carp/mcp -> CMC, pip -> MCP, dip -> IP, btip (else tip) -> tip",
    ]
    handcsv.write(a.out, rows, "y_up", "mm", a.hand, src, comments)


if __name__ == "__main__":
    main()
