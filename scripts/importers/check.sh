#!/bin/sh
# check.sh — re-runs every importer on every raw cut under tests/data/ and compares the result
# byte for byte with the committed joint CSVs (exit 1 on any difference or failure).
#   scripts/importers/check.sh            check (for make check)
#   scripts/importers/check.sh --update   rewrite the CSVs and the events.md analyses instead
# Run from the repository root (or anywhere: it cds there). Needs only python3 (stdlib).
set -eu
cd "$(dirname "$0")/../.."
I=scripts/importers
D=tests/data
PY=${PYTHON:-python3}
update=0
[ "${1:-}" = "--update" ] && update=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
fail=0

# run NAME OUTCSV IMPORTER ARGS... : the importer writes to $tmp, then compare with $D/NAME/OUTCSV
run() {
	name=$1 out=$2 imp=$3
	shift 3
	if ! "$PY" "$I/$imp" "$@" --out "$tmp/$out"; then
		echo "check: $name/$out: importer $imp failed" >&2
		fail=1
		return 0
	fi
	if [ $update = 1 ]; then
		cp "$tmp/$out" "$D/$name/$out"
		echo "check: wrote $D/$name/$out"
	elif ! cmp -s "$tmp/$out" "$D/$name/$out"; then
		echo "check: $D/$name/$out differs from a fresh import" >&2
		cmp "$tmp/$out" "$D/$name/$out" >&2 || true
		fail=1
	fi
}

LEAP='leapmotion/leapjs-playback@4ff4b5b, recorder/recordings'
run leap_grab grab_right.csv leap_json.py "$D/leap_grab/grab.json" --hand right \
	--source "leapjs-playback recording grab.json.lz ($LEAP; Leap Motion Controller, right hand closes into a fist and opens), cut 0-1.75 s"
run leap_pinch pinch_right.csv leap_json.py "$D/leap_pinch/pinch.json" --hand right \
	--source "leapjs-playback recording pinch.json.lz ($LEAP; Leap Motion Controller, right thumb and index pinch and open), whole 2.69 s"
run leap_hand_splay hand_splay_right.csv leap_json.py "$D/leap_hand_splay/HandSplay-110fps.json" --hand right \
	--source "leapjs-playback recording HandSplay-110fps.json.lz ($LEAP; Leap Motion Controller, flat right hand spreads its fingers and brings them together, never closes), cut 0.5-2.65 s"
for h in left right; do
	run leap_two_hands_grab confidence2_$h.csv leap_json.py "$D/leap_two_hands_grab/confidence2.json" --hand $h \
		--source "leapjs-playback recording confidence2.json.lz ($LEAP; Leap Motion Controller, two hands: the left closes into a fist twice while the right stays open), cut 0-2.45 s"
done
run hololens2_fist_open fist_open_right.csv mrtk_joint_csv.py "$D/hololens2_fist_open/20240216_204214403-Tracking.csv" --hand right \
	--source "HoloLens 2 via MRTK 2, Duke-I3T-Lab/Hand-gesture-recognition@81fcf35 ModelTraining/dataset/labeled/20240216_204214403-Tracking.csv (right hand rests in a fist, opens wide and closes again), rows 52-281 = 2.0-12.0 s"

if [ $update = 1 ]; then
	"$PY" $I/analyse.py --title "leap_grab (Leap Motion, right hand grab)" --out $D/leap_grab/events.md $D/leap_grab/grab_right.csv
	"$PY" $I/analyse.py --title "leap_pinch (Leap Motion, right hand pinch)" --out $D/leap_pinch/events.md $D/leap_pinch/pinch_right.csv
	"$PY" $I/analyse.py --title "leap_hand_splay (Leap Motion, open hand, no closing)" --out $D/leap_hand_splay/events.md \
		--note "The hand stays open and flat: its fingers spread and come together. The pinch-aperture 'closes' rows below are the thumb swinging in against the side of the index (about 60 mm between the tips), not a pinch; the grip aperture never falls by 20 mm." \
		$D/leap_hand_splay/hand_splay_right.csv
	"$PY" $I/analyse.py --title "leap_two_hands_grab (Leap Motion, two hands)" --out $D/leap_two_hands_grab/events.md \
		--note "Both files share the time origin (the first frame of the cut). The left hand closes into a fist twice (the second time with the thumb left out, so its pinch aperture only falls to ~87 mm); the right hand stays open throughout (its apertures vary by less than 10 mm)." \
		$D/leap_two_hands_grab/confidence2_left.csv $D/leap_two_hands_grab/confidence2_right.csv
	"$PY" $I/analyse.py --title "hololens2_fist_open (HoloLens 2 / MRTK, right hand)" --out $D/hololens2_fist_open/events.md \
		--note "The hand enters the view at the start (tracked, lost 0.17-0.56 s, re-acquired half open: the first 'opens' rows are that entry), relaxes half open until ~4 s, closes into a fist (~4.0-4.5 s), is opened wide on the observer's label 4 (~5.9-6.0 s) and closed into a fist again (~7.6-7.7 s), then opens partway (~8.7-9.6 s). Positions are 1 mm-quantised by the logger, so single-frame apertures jitter by a few mm; rows are ~42 ms apart." \
		$D/hololens2_fist_open/fist_open_right.csv
	echo "check: wrote the events.md analyses"
fi

if [ $fail != 0 ]; then
	echo "check: FAILED" >&2
	exit 1
fi
[ $update = 1 ] || echo "check: all imported joint CSVs match"
