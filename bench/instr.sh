#!/bin/sh
# instr.sh — `make bench-instr` (bench/bench.mk): callgrind's instructions per frame of three
# fixed frames, the measured frames only, and each run's checksum; a table on stdout. Benchmarks
# report: the status is 0 whatever the counts are, and when valgrind is missing it says so.
#   (a) the honest frame: hs_bench --profile-seed-honest (the seed scene, 10 cubes, 2 grasped, new
#       glove noise on all 18 sensors every frame, the wrist moving and turning, the state hashed
#       every frame), the world's glove deadband as by default (3 units);
#   (b) the moving-glove frame: the same with the glove deadband 0 (every noisy reading moves the hand);
#   (c) the joint-driven frame: the seed scene driven by a noisy 21-landmark recording. hs_bench
#       builds its worlds with the library alone and a joint recording is fitted by the harness, so
#       this one is measured through a scenario run, `handspring bench --instr`, whose frame also
#       holds the harness's own work (the recording's fitted keys sampled, the expectations' record).
# Usage: sh bench/instr.sh HS_BENCH TOOL OUT_DIR
set -u
bench=$1 tool=$2 out=$3
frames=600 # five loops of the bench's hand path
if ! command -v valgrind > /dev/null 2>&1; then
	echo "bench-instr: valgrind is not installed: nothing measured."
	echo "bench-instr: install it with 'sh scripts/deps.sh bench' as root (or: sudo apt-get install -y valgrind), then 'make bench-instr' again"
	exit 0
fi
mkdir -p "$out" || exit 0
start=$(date +%s)

# callgrind's total of a profile (the toggled function's frames only)
total() { sed -n 's/^\(totals\|summary\): *\([0-9]*\).*/\2/p' "$1" | tail -n 1; }
# per frame, rounded
per_frame() { awk -v t="$1" -v n="$2" 'BEGIN { if (t == "") print "-"; else printf "%.0f", t / n }'; }

seed_case() { # NAME [hs_bench options...]: the seed scene under callgrind
	name=$1
	shift
	valgrind --tool=callgrind --callgrind-out-file="$out/$name.cg" --toggle-collect=fr_profiled_frames \
		"$bench" "$@" --profile-seed-honest $frames > "$out/$name.txt" 2> "$out/$name.log"
}
seed_case honest
seed_case moving --deadband 0

# (c): the catalog's seed_scene_hand as MediaPipe landmarks, jittered, driving bench/seed_joints_noisy.yaml
"$tool" joints scenarios/hand/seed_scene_hand.yaml --format mediapipe --out "$out/seed_joints.csv" 2> "$out/joints.log" &&
	"$bench" --noisy-joints "$out/seed_joints.csv" "$out/seed_joints_noisy.csv" 2>> "$out/joints.log" &&
	cp bench/seed_joints_noisy.yaml "$out/" &&
	"$tool" bench "$out/seed_joints_noisy.yaml" --repeat 1 --instr > "$out/joints.txt" 2>> "$out/joints.log"

row() { # CASE FRAMES INSTR TARGET CHECKSUM NOTE
	printf '%-58s %6s %12s %10s  %-16s  %s\n' "$1" "$2" "$3" "$4" "$5" "$6"
}
checksum() { sed -n 's/.*checksum \([0-9a-f]*\).*/\1/p' "$1"; }
lost() { sed -n 's/.*grasp lost in \([0-9]*\).*/grasp lost in \1 frames/p' "$1"; }

echo "== make bench-instr: instructions per frame (valgrind $(valgrind --version | sed 's/valgrind-//'), callgrind, measured frames only) =="
echo "machine: $(uname -srm); $(date -u '+%Y-%m-%d %H:%M UTC'); targets from the project's goals, reported, not enforced"
row "case" "frames" "instr/frame" "target" "checksum" "note"
row "(a) honest frame: seed scene, glove deadband 3 (default)" $frames "$(per_frame "$(total "$out/honest.cg")" $frames)" \
	"<= 10,000" "$(checksum "$out/honest.txt")" "$(lost "$out/honest.txt")"
row "(b) moving glove: the same, glove deadband 0" $frames "$(per_frame "$(total "$out/moving.cg")" $frames)" \
	"<= 20,000" "$(checksum "$out/moving.txt")" "$(lost "$out/moving.txt")"
jframes=$(sed -n 's/^frames *: \([0-9]*\) a repeat.*/\1/p' "$out/joints.txt" 2> /dev/null)
row "(c) joint-driven: noisy 21-landmark recording (scenario)" "${jframes:--}" \
	"$(sed -n 's/^instr *: \([0-9]*\) instructions.*/\1/p' "$out/joints.txt" 2> /dev/null)" "-" \
	"$(sed -n 's/^final hash : //p' "$out/joints.txt" 2> /dev/null)" \
	"$(sed -n 's/^expect *: \([0-9]* of [0-9]*\) hold.*/expectations: \1 hold/p' "$out/joints.txt" 2> /dev/null)"
echo "(a), (b): hs_bench --profile-seed-honest $frames [--deadband 0], --toggle-collect=fr_profiled_frames; checksum: the run's"
echo "(c): measured through a scenario run (handspring bench $out/seed_joints_noisy.yaml --instr; checksum: its final"
echo "     state hash): the bench builds worlds without the harness that fits joint recordings, so its frame also"
echo "     holds the harness's input sampling and expectation record; its stages:"
grep '^stage' "$out/joints.txt" 2> /dev/null | sed 's/^stage *: /       /'
for f in honest moving; do
	[ -s "$out/$f.cg" ] || echo "bench-instr: ($f) not measured: see $out/$f.log"
done
[ -s "$out/joints.txt" ] || echo "bench-instr: (c) not measured: see $out/joints.log"
echo "files: $out/*.cg (callgrind_annotate FILE), $out/*.txt; $(($(date +%s) - start)) s in all"
exit 0
