#!/usr/bin/env python3
"""scale_hand.py — a joint recording of a hand k times the size, doing the same thing.

Reads a handspring joint CSV (MediaPipe layout, version 2) and writes the same recording with every
landmark scaled by k about the hand's grip point in that sample (the midpoint between the thumb tip,
landmark 4, and the mean of the index and middle tips, 8 and 12): a smaller or larger hand whose
fingertips close on the same place, as a person with that hand would hold the same object.
Directives and comments are kept; rows without all three landmarks are copied unchanged.

  python3 scripts/scale_hand.py IN.csv K OUT.csv
"""
import sys


def main(argv):
    src, k, dst = argv[1], float(argv[2]), argv[3]
    out = ["# %s scaled by %s about each sample's grip point (scripts/scale_hand.py)" % (src, argv[2])]
    for line in open(src, encoding="utf-8"):
        line = line.rstrip("\n")
        if not line or line.startswith("#") or line.startswith("@") or line.startswith("t,"):
            out.append(line)
            continue
        c = line.split(",")
        try:
            p = [[float(c[1 + 3 * i + j]) for j in range(3)] for i in range(21)]
        except ValueError:
            out.append(line)
            continue
        g = [(p[4][j] + 0.5 * (p[8][j] + p[12][j])) / 2.0 for j in range(3)]
        for i in range(21):
            for j in range(3):
                c[1 + 3 * i + j] = repr(g[j] + k * (p[i][j] - g[j]))
        out.append(",".join(c))
    with open(dst, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
