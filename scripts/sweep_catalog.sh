#!/bin/sh
# sweep_catalog.sh — `make check-sweep`: every hand scenario of the catalog (DIR/*.yaml, default
# scenarios/hand) runs its robustness sweep (`handspring sweep`, in-process: seconds in all) and
# must pass in every cell and in the nominal run.
# A guard first, so that no hand scenario can skip it: its robust block must exist, name at least
# the eight frame times 1/12, 1/17, 1/30, 1/60, 1/72, 1/90, 1/120 and 1/144 s, shift the scripts'
# clock by a fraction of a frame per seed (`phases: true`; not asked of a scene that runs the
# paper's letter grasp, `grasp_rule: any`, whose grasps hang on the frames by design: docs/model.md
# §3), at least 10 seeds and at least the
# realistic noise (glove +-4 units, wrist +-0.762 mm and +-0.15 deg: the tracker of the workbench
# paper's §5.1), read from the sweep's own header and row labels, so any YAML style is checked;
# and at least one of its clauses must be `robust: true`.
# Prints each failing sweep in full, then the table of scripts/sweep_table.sh.
#   sweep_catalog.sh TOOL [DIR]
set -eu
tool=$1
dir=${2:-scenarios/hand}
here=$(dirname "$0")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
n=0
for f in "$dir"/*.yaml; do
	[ -e "$f" ] || continue
	n=$((n + 1))
	name=$(basename "$f" .yaml)
	out="$work/$name.txt"
	rc=0
	"$tool" sweep "$f" > "$out" 2>&1 || rc=$?
	if [ "$rc" -gt 1 ]; then
		echo "check-sweep: $f: cannot sweep (status $rc): $(head -n 1 "$out")"
		echo "cannot sweep $name" > "$out"
		fail=1
		continue
	fi
	# the guard: the matrix and the noise levels the sweep ran with
	joints=0
	grep -q 'drive: *joints' "$f" && joints=1
	letter=0
	grep -q 'grasp_rule: *any' "$f" && letter=1
	why=$(awk -v joints="$joints" -v letter="$letter" '
	BEGIN { want["1/12"] = 1 / 12; want["1/17"] = 1 / 17; want["1/30"] = 1 / 30; want["1/60"] = 1 / 60; want["1/72"] = 1 / 72
	        want["1/90"] = 1 / 90; want["1/120"] = 1 / 120; want["1/144"] = 1 / 144 }
	function value(s,   p) {                  # a frame time as the file wrote it: a fraction or a number
		p = index(s, "/")
		return p ? substr(s, 1, p - 1) / substr(s, p + 1) : s + 0
	}
	NR == 1 {
		if (!match($0, / [0-9]+ seeds/)) { print "no seed count in the sweep header"; exit }
		seeds = substr($0, RSTART + 1, RLENGTH - 7) + 0
		if (seeds < 10) print "robust.seeds is " seeds ", at least 10 needed"
		if (!letter && $0 !~ /of a frame late/) print "robust.phases is not true: each seed must shift the scripts by a fraction of a frame"
		if (!match($0, /glove \+-[0-9.]+ units, wrist \+-[0-9.e+-]+ mm, \+-[0-9.e+-]+ deg/)) {
			print "robust block without its noise levels (glove_units, wrist_mm, wrist_deg)"; exit
		}
		split(substr($0, RSTART, RLENGTH), w, /[ ,]+/)   # glove +-G units wrist +-W mm +-A deg
		g = substr(w[2], 3) + 0; mm = substr(w[5], 3) + 0; deg = substr(w[7], 3) + 0
		if (g < 4) print "robust.glove_units is " g ", at least 4 needed"
		if (mm < 0.762) print "robust.wrist_mm is " mm ", at least 0.762 needed"
		if (deg < 0.15) print "robust.wrist_deg is " deg ", at least 0.15 needed"
		j = match($0, /joints \+-[0-9.e+-]+ mm/) ? substr($0, RSTART + 9, RLENGTH - 12) + 0 : 0
		if (joints && j < 1) print "robust.joint_mm is " j ", at least 1 needed for a hand driven by its joints"
		next
	}
	/^dt / { rows = 1; next }
	/^nominal / { rows = 0; next }
	rows && NF > 1 { v = value($1); for (k in want) if (v > 0 && (v - want[k]) ^ 2 <= 1e-12 * want[k] ^ 2) got[k] = 1 }
	END { for (k in want) if (!(k in got)) print "robust.dt lacks " k " s" }' "$out")
	# a robust block without a robust clause would sweep nothing but faults
	grep -q 'robust: *true' "$f" || why="${why:+$why
}no clause is 'robust: true': the cells would check nothing"
	if [ -n "$why" ]; then
		echo "$why" | sed "s|^|check-sweep: $f: |"
		fail=1
	fi
	if [ "$rc" -ne 0 ]; then
		cat "$out"
		fail=1
	fi
done
if [ "$n" -eq 0 ]; then
	echo "check-sweep: no scenarios in $dir"
	exit 1
fi
cat "$work"/*.txt | sh "$here/sweep_table.sh" -
if [ "$fail" -ne 0 ]; then
	echo "check-sweep: FAILED (a sweep cell, a nominal run or the guard above)"
	exit 1
fi
echo "check-sweep: all $n hand scenarios pass every cell"

