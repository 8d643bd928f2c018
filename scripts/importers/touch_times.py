#!/usr/bin/env python3
"""touch_times.py — when a recorded hand's two fingertips reach an object's width, and let it go.

Reads a handspring joint CSV (version 2) and, for two landmarks (MediaPipe numbering: 4 the thumb
tip, 8 the index tip, 12 the middle tip), prints the first time their distance falls to
`width + 2 * radius` (the fingers' surfaces, `radius` from the joint centres, touch an object
`width` across held between them) and the first later time it rises above that again (they let
it go), each interpolated between samples, with the midpoint of the two landmarks at the touch in
handspring's frame (x forward, y left, z up; metres). These are the real hand's close and open
times that the catalog's real-recording scenarios compare the model's grasp with.

  python3 scripts/importers/touch_times.py FILE.csv --pair 4 12 --width 0.05 [--radius 0.008]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analyse  # noqa: E402
import handcsv  # noqa: E402


def crossing(t0, d0, t1, d1, level):
    return t0 + (t1 - t0) * (level - d0) / (d1 - d0)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv")
    ap.add_argument("--pair", type=int, nargs=2, required=True)
    ap.add_argument("--width", type=float, required=True)
    ap.add_argument("--radius", type=float, default=0.008)
    a = ap.parse_args(argv)
    directives, rows = handcsv.read(a.csv)
    frame, units = directives.get("frame", "z_up"), directives.get("units", "m")
    level = a.width + 2 * a.radius
    prev = None
    touch = None
    for t, pts, tracked, _ in rows:
        p, q = pts[a.pair[0]], pts[a.pair[1]]
        if not tracked or p is None or q is None:
            continue
        p, q = analyse.to_zup_m(p, frame, units), analyse.to_zup_m(q, frame, units)
        d = math.dist(p, q)
        if prev is not None:
            t0, d0, p0, q0 = prev
            if touch is None and d0 > level >= d:
                touch = crossing(t0, d0, t, d, level)
                f = (touch - t0) / (t - t0)
                mid = [(p0[k] + f * (p[k] - p0[k]) + q0[k] + f * (q[k] - q0[k])) / 2 for k in range(3)]
                print("touch %.4f s at (%.4f, %.4f, %.4f) m" % (touch, *mid))
            elif touch is not None and d0 <= level < d:
                print("let go %.4f s" % crossing(t0, d0, t, d, level))
                return 0
        prev = (t, d, p, q)
    print("touch never" if touch is None else "let go never")
    return 0


if __name__ == "__main__":
    sys.exit(main())
