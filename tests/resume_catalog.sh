#!/bin/sh
# resume_catalog.sh — save and resume for every catalog scenario (noisy ones included): the run is
# saved half-way (`handspring run FILE --save-at N --state-out S`), resumed from that file
# (`handspring run FILE --resume S`), and the resumed trajectory must equal the rest of the full
# run's trajectory byte for byte, expectation report included (the harness saves its captures).
#   resume_catalog.sh TOOL [DIR]     (DIR defaults to scenarios)
set -eu
tool=$1
dir=${2:-scenarios}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0
fail=0
for f in $(find "$dir" -name '*.yaml' | sort); do
	name=$(echo "${f#"$dir"/}" | sed 's/\.yaml$//; s|/|_|g')
	rc=0
	"$tool" run "$f" --out "$work/$name.full.csv" > "$work/$name.full.txt" 2>&1 || rc=$?
	if [ "$rc" -gt 1 ]; then
		echo "resume: $f: the full run failed (status $rc)"; fail=1; continue
	fi
	frames=$(tail -n 1 "$work/$name.full.csv" | cut -d, -f1)
	half=$((frames / 2))
	"$tool" run "$f" --save-at "$half" --state-out "$work/$name.state" --out /dev/null > /dev/null 2>&1 || true
	if [ ! -s "$work/$name.state" ]; then
		echo "resume: $f: no state written at frame $half"; fail=1; continue
	fi
	rc2=0
	"$tool" run "$f" --resume "$work/$name.state" --out "$work/$name.rest.csv" > "$work/$name.rest.txt" 2>&1 || rc2=$?
	head -n 1 "$work/$name.full.csv" > "$work/$name.expect.csv"
	awk -F, -v h="$half" 'NR > 1 && $1 + 0 > h' "$work/$name.full.csv" >> "$work/$name.expect.csv"
	if ! cmp -s "$work/$name.expect.csv" "$work/$name.rest.csv"; then
		echo "resume: $f: the trajectory resumed at frame $half differs from the full run's:"
		diff "$work/$name.expect.csv" "$work/$name.rest.csv" | head -n 4
		fail=1; continue
	fi
	if [ "$rc" -ne "$rc2" ]; then
		echo "resume: $f: status $rc2 after resuming, $rc for the full run"; fail=1; continue
	fi
	grep -E '^(PASS|FAIL) ' "$work/$name.full.txt" > "$work/$name.full.checks" || true
	grep -E '^(PASS|FAIL) ' "$work/$name.rest.txt" > "$work/$name.rest.checks" || true
	if ! cmp -s "$work/$name.full.checks" "$work/$name.rest.checks"; then
		echo "resume: $f: the expectations report differs after resuming:"
		diff "$work/$name.full.checks" "$work/$name.rest.checks" | head -n 4
		fail=1; continue
	fi
	n=$((n + 1))
done
if [ "$fail" -ne 0 ]; then
	echo "resume: FAILED"
	exit 1
fi
echo "resume: $n scenarios resumed half-way give the rest of the full run byte for byte"
