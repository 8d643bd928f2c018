#!/usr/bin/env python3
"""cut_leap_json.py — keep the frames of a leapjs-playback recording between two times.

Usage:
    python3 scripts/importers/cut_leap_json.py IN.json OUT.json --from S --to S

IN.json is a decompressed leapjs-playback recording ({"metadata", "frames"}; frames plain or
packed as in formatVersion 2, see leap_json.py). S are seconds from IN's first frame (device
timestamps). The metadata and the kept frames are copied unchanged (same keys, same values);
only the JSON text is re-serialised (compact, keys in their original order), and a
"handspringCut" entry is added to the metadata saying which span was kept.
"""
import argparse
import json


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--from", dest="t_from", type=float, required=True)
    ap.add_argument("--to", dest="t_to", type=float, required=True)
    a = ap.parse_args(argv)
    with open(a.input, encoding="utf-8") as f:
        doc = json.load(f)
    frames = doc["frames"] if isinstance(doc, dict) else doc
    packed = bool(frames) and isinstance(frames[0], list)
    body = frames[1:] if packed else frames
    if packed:
        ts_index = frames[0].index("timestamp")
        ts = [fr[ts_index] for fr in body]
    else:
        ts = [fr["timestamp"] for fr in body]
    t0 = ts[0]
    keep = [fr for fr, t in zip(body, ts) if a.t_from - 1e-9 <= (t - t0) / 1e6 <= a.t_to + 1e-9]
    if not keep:
        raise SystemExit("no frame between %g and %g s" % (a.t_from, a.t_to))
    out_frames = ([frames[0]] if packed else []) + keep
    if isinstance(doc, dict):
        out = dict(doc)
        meta = dict(out.get("metadata") or {})
        meta["handspringCut"] = "frames %g-%g s from the first frame (timestamp %d) of the original, %d of %d frames" % (
            a.t_from, a.t_to, t0, len(keep), len(body))
        out["metadata"] = meta
        out["frames"] = out_frames
    else:
        out = out_frames
    with open(a.output, "w", encoding="utf-8", newline="\n") as f:
        json.dump(out, f, separators=(",", ":"), ensure_ascii=False)
        f.write("\n")


if __name__ == "__main__":
    main()
