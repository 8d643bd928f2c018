#!/bin/sh
# bench_cmd.sh — `make check-bench-cmd`: `handspring bench FILE [--frames N] [--repeat K] [--instr]`
# (docs/tool.md), run from the top folder. No timing is asserted, only what the output says:
#   1. the report's lines and their format, the frames and repeats asked for;
#   2. exactly N frames stepped: the final hash is the hash `run --out -` writes at frame N, also
#      past the scenario's end (it is loaded again: frame N mod its frames);
#   3. a missing file: one error line naming it, nothing on stdout, status 1;
#   4. bad --frames and --repeat values refused with status 2 and a line naming the value;
#   5. --instr: without valgrind on PATH it says so (status 0); with it, instructions a frame and
#      the frame's stages, whose top-level shares add up to 100 %.
# Usage: sh tests/bench_cmd.sh [TOOL]   (default build/handspring)
set -u
tool=${1:-build/handspring}
fails=0
fail() { echo "bench_cmd: FAIL: $*"; fails=$((fails + 1)); }
work=$(mktemp -d /tmp/hs-bench-cmd.XXXXXX) || exit 2
trap 'rm -rf "$work"' EXIT INT TERM
scn=scenarios/drop_cube.yaml # 90 frames
# has FILE REGEX: a line of FILE matches the extended regular expression
has() { grep -Eq "$2" "$1" || { fail "no line /$2/ in:"; sed 's/^/    /' "$1"; }; }
hash_at() { "$tool" run "$scn" --out - 2>/dev/null | awk -F, -v f="$1" '$1 == f { print $NF; exit }'; }

# 1. the report
"$tool" bench "$scn" --frames 50 --repeat 3 > "$work/out" 2> "$work/err"
rc=$?
[ $rc -eq 0 ] || fail "bench --frames 50 --repeat 3: status $rc: $(cat "$work/err")"
has "$work/out" '^scenario   : drop_cube \(scenarios/drop_cube\.yaml\)$'
has "$work/out" '^frames     : 50 a repeat, 3 repeats \(the scenario has 90 frames of 0\.0166667 s\)$'
has "$work/out" '^us/frame   : [0-9]+\.[0-9]{3} median, [0-9]+\.[0-9]{3}-[0-9]+\.[0-9]{3} over 3 repeats \(CPU time of the process\)$'
has "$work/out" '^frames/s   : [0-9]+ \(median\)$'
has "$work/out" '^final hash : [0-9a-f]{16}$'
has "$work/out" '^expect     : [0-9]+ of 6 hold after frame 50 of the last load'
[ "$(wc -l < "$work/out")" -eq 6 ] || fail "bench printed $(wc -l < "$work/out") lines, not 6"
grep -q . "$work/err" && fail "bench wrote on stderr: $(cat "$work/err")"

# 2. the frames stepped are the frames asked for
for n in 1 50 90 200; do
	"$tool" bench "$scn" --frames "$n" --repeat 1 > "$work/out" 2>&1 || fail "bench --frames $n failed"
	has "$work/out" "^frames     : $n a repeat, 1 repeat "
	got=$(sed -n 's/^final hash : //p' "$work/out")
	at=$((n > 90 ? n - 90 * ((n - 1) / 90) : n))
	want=$(hash_at "$at")
	[ -n "$want" ] && [ "$got" = "$want" ] || fail "--frames $n: final hash $got, run's at frame $at is '$want'"
done
"$tool" bench "$scn" > "$work/out" 2>&1 || fail "bench with no options failed"
has "$work/out" '^frames     : 90 a repeat, 5 repeats '

# 3. a missing file
"$tool" bench "$work/missing.yaml" > "$work/out" 2> "$work/err"
rc=$?
[ $rc -eq 1 ] || fail "missing file: status $rc, not 1"
[ "$(wc -l < "$work/err")" -eq 1 ] || fail "missing file: $(wc -l < "$work/err") lines on stderr, not 1"
grep -q "missing.yaml.*No such file" "$work/err" || fail "missing file: the error does not name it: $(cat "$work/err")"
[ -s "$work/out" ] && fail "missing file: stdout not empty: $(cat "$work/out")"

# 4. bad values
for bad in 0 -3 abc 1.5 '' 12x 100000001 99999999999999999999; do
	"$tool" bench "$scn" --frames "$bad" > "$work/out" 2> "$work/err"
	rc=$?
	[ $rc -eq 2 ] || fail "--frames '$bad': status $rc, not 2"
	head -n 1 "$work/err" | grep -Fq "handspring bench: --frames takes a whole number from 1 to 100000000, got '$bad'" ||
		fail "--frames '$bad': $(head -n 1 "$work/err")"
	[ -s "$work/out" ] && fail "--frames '$bad' printed a report"
done
"$tool" bench "$scn" --frames > /dev/null 2> "$work/err"
[ $? -eq 2 ] && grep -q "got '(nothing)'" "$work/err" || fail "--frames without a value: $(head -n 1 "$work/err")"
"$tool" bench "$scn" --frames=0 > /dev/null 2> "$work/err"
[ $? -eq 2 ] || fail "--frames=0 accepted"
"$tool" bench "$scn" --repeat 0 > /dev/null 2> "$work/err"
[ $? -eq 2 ] && grep -q "repeat takes a whole number from 1 to 1000, got '0'" "$work/err" ||
	fail "--repeat 0: $(head -n 1 "$work/err")"
"$tool" bench > /dev/null 2> "$work/err"
[ $? -eq 2 ] && grep -q "missing the scenario FILE" "$work/err" || fail "no FILE: $(head -n 1 "$work/err")"

# 5. --instr
PATH=/nonexistent "$tool" bench "$scn" --frames 10 --repeat 1 --instr > "$work/out" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "--instr without valgrind: status $rc"
has "$work/out" '^instr      : not measured: valgrind is not on PATH \(sh scripts/deps\.sh valgrind'
if command -v valgrind > /dev/null 2>&1; then
	"$tool" bench scenarios/hand/seed_scene_hand.yaml --frames 60 --repeat 1 --instr > "$work/out" 2>&1 ||
		fail "--instr: status $?"
	has "$work/out" '^instr      : [0-9]+ instructions a frame \(callgrind, the 60 measured frames only\)$'
	has "$work/out" '^stage      : +[0-9]+\.[0-9] %  world step \(hs_world_step\), of which:$'
	has "$work/out" '^stage      : +[0-9]+\.[0-9] %    hands on objects: contacts, grasps, pushes \(hs_manipulate\)$'
	sum=$(awk -F'%' '/^stage/ && $2 ~ /^  [^ ]/ { split($1, a, ":"); s += a[2] } END { printf "%.1f", s }' "$work/out")
	awk -v s="$sum" 'BEGIN { exit !(s >= 99.5 && s <= 100.5) }' || fail "--instr: top-level stages add up to $sum %"
else
	echo "bench_cmd: valgrind missing: --instr with valgrind not checked (sh scripts/deps.sh valgrind)"
fi

[ $fails -eq 0 ] && echo "bench_cmd: all checks passed" || { echo "bench_cmd: $fails check(s) failed"; exit 1; }
