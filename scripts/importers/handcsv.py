"""handcsv.py — shared writer/reader for handspring joint CSV, version 2 (stdlib only).

The format (one file per hand):

    # comment lines start with '#', allowed anywhere; blank lines are skipped
    @frame y_up | z_up | unity | mediapipe     (directives "@key value", before the header only)
    @units m | cm | mm
    @hand left | right
    @source free text
    t,x0,y0,z0,...,x20,y20,z20,tracked,confidence
    0,12.5,180.2,...,1,1

Landmarks are in MediaPipe order (0 wrist; 1-4 thumb CMC, MCP, IP, tip; 5-8 index MCP, PIP, DIP,
tip; 9-12 middle; 13-16 ring; 17-20 little). A missing landmark is an empty cell; a frame without
the hand has all 63 cells empty and tracked = 0. Numbers are printed with fmt() / fmt_t() so that
re-running an importer on the same input gives byte-identical output.
"""
import math

N_LANDMARKS = 21
HEADER = ["t"] + ["%s%d" % (a, i) for i in range(N_LANDMARKS) for a in "xyz"] + ["tracked", "confidence"]


def fmt(v):
    """A coordinate or confidence: 6 significant digits, no trailing noise, '' for missing."""
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return ""
    s = "%.6g" % v
    if s == "-0":
        s = "0"
    return s


def fmt_t(t):
    """A time in seconds: microsecond resolution, trailing zeros stripped."""
    s = "%.6f" % t
    s = s.rstrip("0").rstrip(".")
    return "0" if s in ("", "-0") else s


def write(path, rows, frame, units, hand, source, comments=()):
    """rows: iterable of (t, points, tracked, confidence); points is a list of 21 (x, y, z) or None."""
    out = []
    for c in comments:
        for line in str(c).splitlines():
            out.append("# " + line if line else "#")
    out.append("@frame " + frame)
    out.append("@units " + units)
    out.append("@hand " + hand)
    out.append("@source " + " ".join(str(source).split()))
    out.append(",".join(HEADER))
    for t, pts, tracked, conf in rows:
        cells = [fmt_t(t)]
        for i in range(N_LANDMARKS):
            p = pts[i] if pts is not None else None
            if p is None:
                cells += ["", "", ""]
            else:
                cells += [fmt(p[0]), fmt(p[1]), fmt(p[2])]
        cells.append("1" if tracked else "0")
        cells.append(fmt(conf))
        out.append(",".join(cells))
    data = "\n".join(out) + "\n"
    if path in (None, "-"):
        import sys
        sys.stdout.write(data)
    else:
        with open(path, "w", encoding="utf-8", newline="\n") as f:
            f.write(data)


def read(path):
    """Returns (directives dict, list of (t, points or None per landmark, tracked, confidence))."""
    directives = {}
    rows = []
    header_seen = False
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if not header_seen:
                if line.startswith("@"):
                    key, _, val = line[1:].partition(" ")
                    directives[key] = val.strip()
                    continue
                if line.split(",")[0] != "t":
                    raise ValueError("%s: expected the header line, got %r" % (path, line[:40]))
                header_seen = True
                continue
            c = line.split(",")
            if len(c) != len(HEADER):
                raise ValueError("%s: %d cells, expected %d" % (path, len(c), len(HEADER)))

            def num(s):
                s = s.strip()
                if s == "" or s.lower() == "nan":
                    return None
                return float(s)
            pts = []
            for i in range(N_LANDMARKS):
                x, y, z = (num(c[1 + 3 * i + k]) for k in range(3))
                pts.append(None if x is None or y is None or z is None else (x, y, z))
            rows.append((float(c[0]), pts, c[-2].strip() == "1", num(c[-1])))
    return directives, rows
