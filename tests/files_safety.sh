#!/bin/sh
# files_safety.sh — `make check-files`: the tool's files in and out (tool/output.c, harness readers,
# scripts/campaign.sh). Each case must end with the documented result: one error line and status 2
# (status 1 for a golden that does not match), the input untouched, no temporary left behind.
#   1. an output that is an input (the scenario, a recording it names, the state resumed, the
#      campaign file, the trials summarised; through a link too) or another output: refused;
#   2. /dev/full as an output, as standard output: refused with "No space left on device";
#   3. a link planted at the old fixed temporary name P.tmp is never followed; a link at P itself
#      is followed (the file it names replaced whole, the link kept); a link to nothing refused;
#      a file already at P replaced whole, its mode kept;
#   4. `--out - | head -1` ends the tool quietly (SIGPIPE, nothing on stderr); a FIFO as --out works;
#   5. a full small file system (a 256 KiB tmpfs, when root may mount one; skipped with a message
#      otherwise): refused, the earlier file kept, no temporary left;
#   6. endless inputs: `campaign --summarize /dev/zero`, `check` against a golden that is /dev/zero,
#      `run --resume /dev/zero` each end at once with one line;
#   7. campaigns: a second run into a folder another run holds is refused (its lock named); a part
#      cut short while the joblog says done is recorded as failed, and --resume reruns that job only,
#      the result byte for byte the in-process run's.
#   files_safety.sh TOOL
set -u
if [ $# -ne 1 ]; then
	echo "usage: files_safety.sh TOOL" >&2
	exit 2
fi
tool=$1
case "$tool" in /*) ;; *) tool=$PWD/$tool ;; esac
top=$PWD
work=$(mktemp -d)
mounted=""
cleanup() {
	[ -z "$mounted" ] || umount "$mounted" 2>/dev/null || true
	rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
failed=0
passed=0
fail() {
	echo "files: FAILED: $*"
	failed=$((failed + 1))
}
ok() { passed=$((passed + 1)); }

# expect STATUS PATTERN CMD...: the command's status and its stderr: one line holding PATTERN
expect() {
	want=$1
	pattern=$2
	shift 2
	"$@" > "$work/out.txt" 2> "$work/err.txt"
	got=$?
	lines=$(wc -l < "$work/err.txt")
	if [ "$got" -ne "$want" ] || [ "$lines" -ne 1 ] || ! grep -q -- "$pattern" "$work/err.txt"; then
		fail "$* gave status $got (not $want) and $lines line(s) on stderr, wanted one with '$pattern':"
		sed 's/^/    /' "$work/err.txt" | head -n 5
	else
		ok
	fi
}
# expect_last STATUS PATTERN CMD...: as expect, for a command that reports progress first (view):
# its last line on stderr holds PATTERN
expect_last() {
	want=$1
	pattern=$2
	shift 2
	"$@" > "$work/out.txt" 2> "$work/err.txt"
	got=$?
	if [ "$got" -ne "$want" ] || ! tail -n 1 "$work/err.txt" | grep -q -- "$pattern"; then
		fail "$* gave status $got (not $want), wanted '$pattern' last on stderr:"
		sed 's/^/    /' "$work/err.txt" | tail -n 3
	else
		ok
	fi
}
same() { # what FILE COPY: FILE unchanged
	if cmp -s "$2" "$3"; then ok; else fail "$1: $2 changed"; fi
}
no_temporaries() { # DIR: no .NAME.XXXXXX left
	if ls -A "$1" | grep -q '^\..*\.[A-Za-z0-9]\{6\}$'; then
		fail "a temporary was left in $1: $(ls -A "$1" | tr '\n' ' ')"
	else
		ok
	fi
}

d=$work/in
mkdir "$d"
cp "$top/scenarios/drop_cube.yaml" "$d/drop_cube.yaml"
cp "$top/scenarios/hand/joints_mediapipe.yaml" "$top/scenarios/hand/joints_mediapipe.csv" "$d/"
cp "$d/drop_cube.yaml" "$work/drop_cube.copy"
cp "$d/joints_mediapipe.csv" "$work/joints.copy"
s=$d/drop_cube.yaml

# 1. outputs that are inputs
expect 2 "it is the input" "$tool" run "$s" --out "$s"
same "run --out FILE" "$s" "$work/drop_cube.copy"
expect 2 "it is the input" "$tool" run "$d/joints_mediapipe.yaml" --out "$d/joints_mediapipe.csv"
same "run --out RECORDING" "$d/joints_mediapipe.csv" "$work/joints.copy"
expect 2 "it is the input" "$tool" run "$s" --save-at 3 --state-out "$s"
expect 2 "it is the input" "$tool" all --dir "$d" --out-dir "$d"
same "all --out-dir DIR (joints_mediapipe.csv is a recording)" "$d/joints_mediapipe.csv" "$work/joints.copy"
ln -s drop_cube.yaml "$d/link.csv"
expect 2 "it is the input" "$tool" run "$s" --out "$d/link.csv"
same "run --out LINK-TO-FILE" "$s" "$work/drop_cube.copy"
expect 2 "another output of this command" "$tool" run "$s" --out "$work/o.csv" --hands-out "$work/./o.csv"
"$tool" run "$s" --save-at 10 --state-out "$work/s.state" > /dev/null || fail "run --save-at 10 --state-out"
cp "$work/s.state" "$work/s.copy"
expect 2 "it is the input" "$tool" run "$s" --resume "$work/s.state" --out "$work/s.state"
same "run --resume S --out S" "$work/s.state" "$work/s.copy"
expect 2 "it is the input" "$tool" joints "$d/joints_mediapipe.yaml" --format mediapipe --out "$d/joints_mediapipe.csv"
c=$work/campaign.yaml
printf 'scenario: %s\ntrials: 2\n' "$s" > "$c"
cp "$c" "$work/campaign.copy"
expect 2 "it is the input" "$tool" campaign "$c" --out "$c"
same "campaign --out FILE" "$c" "$work/campaign.copy"
expect 2 "it is the input" "$tool" campaign "$c" --out "$s"
"$tool" campaign "$c" --out "$work/trials.csv" > /dev/null || fail "campaign --out"
expect 2 "it is the input" "$tool" campaign "$c" --summarize "$work/trials.csv" --summary "$work/trials.csv"
if command -v gnuplot > /dev/null 2>&1; then
	expect_last 2 "it is the input" "$tool" view "$s" --strip "$s" --at 0.5
	same "view --strip FILE" "$s" "$work/drop_cube.copy"
fi
expect_last 2 "it is the input" "$tool" view "$s" --html "$s"
same "view --html FILE" "$s" "$work/drop_cube.copy"

# 2. /dev/full
expect 2 "No space left on device" "$tool" run "$s" --out /dev/full
expect 2 "No space left on device" "$tool" run "$s" --hands-out /dev/full
expect 2 "No space left on device" "$tool" run "$s" --save-at 3 --state-out /dev/full
expect 2 "No space left on device" sh -c '"$1" run "$2" > /dev/full' sh "$tool" "$s"
expect 2 "No space left on device" "$tool" campaign "$c" --out /dev/full
expect 2 "No space left on device" "$tool" campaign "$c" --summarize "$work/trials.csv" --summary /dev/full
if command -v gnuplot > /dev/null 2>&1; then
	expect_last 2 "No space left on device" "$tool" view "$s" --strip /dev/full --at 0.5
fi
expect_last 2 "No space left on device" "$tool" view "$s" --html /dev/full

# 3. links and files already there
o=$work/links
mkdir "$o"
echo victim > "$o/victim"
ln -s "$o/victim" "$o/t.csv.tmp"
"$tool" run "$s" --out "$o/t.csv" > /dev/null || fail "run --out with a link planted at t.csv.tmp"
if [ "$(cat "$o/victim")" = victim ] && [ -L "$o/t.csv.tmp" ] && [ -f "$o/t.csv" ] && [ ! -L "$o/t.csv" ]; then ok; else
	fail "a link planted at the old temporary name was followed or replaced"; fi
"$tool" run "$s" --out - > "$work/want.csv" 2> /dev/null
echo old > "$o/real.csv"
ln -s real.csv "$o/link.csv"
"$tool" run "$s" --out "$o/link.csv" > /dev/null || fail "run --out LINK"
if [ -L "$o/link.csv" ] && cmp -s "$o/real.csv" "$work/want.csv"; then ok; else
	fail "a link at the output's path: the file it names was not replaced whole, or the link was"; fi
ln -s missing.csv "$o/dangling.csv"
expect 2 "a symbolic link to a missing file" "$tool" run "$s" --out "$o/dangling.csv"
[ ! -e "$o/missing.csv" ] && ok || fail "a link to nothing was followed"
echo old > "$o/mode.csv"
chmod 640 "$o/mode.csv"
"$tool" run "$s" --out "$o/mode.csv" > /dev/null || fail "run --out over a file"
if cmp -s "$o/mode.csv" "$work/want.csv" && [ "$(stat -c %a "$o/mode.csv")" = 640 ]; then ok; else
	fail "a file at the output's path: not replaced whole, or its mode not kept"; fi
no_temporaries "$o"

# 4. pipes
# a trajectory far larger than a pipe's buffer: the tool is still writing when head has gone
big=$top/scenarios/spring/dense_drop.yaml
status=$( { { "$tool" run "$big" --out - 2> "$work/pipe.err"; echo $? >&3; } | head -n 1 > /dev/null; } 3>&1)
if [ "$status" = 141 ] && [ ! -s "$work/pipe.err" ]; then ok; else
	fail "--out - | head: status $status (not 141: SIGPIPE), the tool said: $(head -n 2 "$work/pipe.err")"; fi
mkfifo "$work/fifo"
cat "$work/fifo" > "$work/from_fifo.csv" &
reader=$!
"$tool" run "$s" --out "$work/fifo" > /dev/null || fail "run --out FIFO"
wait "$reader"
cmp -s "$work/from_fifo.csv" "$work/want.csv" && ok || fail "run --out FIFO: not the trajectory"
[ -p "$work/fifo" ] && ok || fail "run --out FIFO replaced the FIFO"

# 5. a full small file system
if [ "$(id -u)" = 0 ] && mkdir "$work/tiny" && mount -t tmpfs -o size=256k tmpfs "$work/tiny" 2> /dev/null; then
	mounted=$work/tiny
	echo earlier > "$work/tiny/t.csv"
	dd if=/dev/zero of="$work/tiny/filler" bs=4k 2> /dev/null
	expect 2 "No space left on device" "$tool" run "$top/scenarios/hand/joints_openxr.yaml" --out "$work/tiny/t.csv"
	[ "$(cat "$work/tiny/t.csv")" = earlier ] && ok || fail "a full file system: the earlier file was not kept"
	no_temporaries "$work/tiny"
	rm -f "$work/tiny/filler"
	"$tool" run "$s" --out "$work/tiny/t.csv" > /dev/null && cmp -s "$work/tiny/t.csv" "$work/want.csv" && ok ||
		fail "once room is back, run --out writes the file"
	umount "$work/tiny" && mounted=""
else
	echo "files: skipped the full small file system (mounting a tmpfs needs root)"
fi

# 6. endless inputs
expect 2 "a line longer than 65536 bytes" timeout 20 "$tool" campaign "$c" --summarize /dev/zero
mkdir "$work/gold" "$work/cat"
cp "$s" "$work/cat/"
ln -s /dev/zero "$work/gold/drop_cube.csv"
timeout 20 "$tool" check "$work/cat" --golden "$work/gold" > "$work/check.txt" 2>&1
if [ $? -eq 1 ] && grep -q "golden line 1: a line longer than 65536 bytes" "$work/check.txt"; then ok; else
	fail "check against a golden that is /dev/zero:"; sed 's/^/    /' "$work/check.txt"; fi
expect 2 "not a handspring state file" timeout 20 "$tool" run "$s" --resume /dev/zero

# 7. campaigns: the lock, and a part cut short
if command -v parallel > /dev/null 2>&1 && command -v flock > /dev/null 2>&1; then
	camp=$top/tests/campaigns/tiny.yaml
	ref=$work/ref
	mkdir "$ref"
	"$tool" campaign "$camp" --out "$ref/trials.csv" --summary "$ref/summary.csv" > /dev/null
	out=$work/camp
	mkdir "$out"
	exec 8> "$out/.lock" # another run holding the folder: this shell holds its lock (no timing)
	flock -n 8 || fail "could not take $out/.lock"
	expect 2 "another campaign run is writing to this folder" sh "$top/scripts/campaign.sh" "$camp" "$out" --tool "$tool"
	exec 8>&-
	sh "$top/scripts/campaign.sh" "$camp" "$out" --tool "$tool" --jobs 2 --chunk 3 > "$work/c1.txt" 2>&1 ||
		fail "campaign.sh: $(tail -n 3 "$work/c1.txt")"
	head -c -5 "$out/parts/2.rows" > "$work/cut" && cat "$work/cut" > "$out/parts/2.rows" # cut short, as by a full disk
	rm -f "$out/trials.csv"
	sh "$top/scripts/campaign.sh" "$camp" "$out" --tool "$tool" --resume > "$work/c2.txt" 2>&1
	if [ $? -eq 1 ] && grep -q "job 2 (trials 3:6): its part .* is incomplete" "$work/c2.txt" &&
		awk -F'\t' '$1 == 2 && $7 == 1 { f = 1 } END { exit !f }' "$out/joblog"; then ok; else
		fail "a part cut short was not recorded as failed:"; sed 's/^/    /' "$work/c2.txt"; fi
	lines=$(wc -l < "$out/joblog")
	sh "$top/scripts/campaign.sh" "$camp" "$out" --tool "$tool" --resume > "$work/c3.txt" 2>&1 ||
		fail "campaign.sh --resume after the failed part: $(tail -n 3 "$work/c3.txt")"
	if [ "$(tail -n +$((lines + 1)) "$out/joblog" | cut -f1 | tr '\n' ' ')" = "2 " ]; then ok; else
		fail "--resume ran other jobs than job 2: $(tail -n +$((lines + 1)) "$out/joblog" | cut -f1 | tr '\n' ' ')"; fi
	cmp -s "$ref/trials.csv" "$out/trials.csv" && cmp -s "$ref/summary.csv" "$out/summary.csv" && ok ||
		fail "the resumed campaign's files differ from the in-process run's"
else
	fail "the campaign cases need GNU parallel and flock (sh scripts/deps.sh)"
fi

echo "files: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
