#!/bin/sh
# golden_dir.sh — `make check-golden-dir`: where `handspring golden DIR` writes and `check DIR`
# reads (scenarios/README.md, "Your own folder"), run from the top folder:
#   1. a user folder at the top of the repository holding a scenario named like a catalog one
#      (drop_cube): its golden goes to DIR/golden, naming the command that rewrites it; the
#      catalog's golden/ keeps every byte (checksums) and gains no file; `check DIR` passes;
#   2. --golden golden (or below it) for that folder is refused, status 2, golden/ untouched;
#   3. a scenario whose expectations fail: no golden, status 1, a message; --force: written, a
#      warning, status 1;
#   4. a catalog's own layout (a copy: scenarios/ and golden/ in a temporary folder) still writes
#      golden/ beside scenarios/, byte for byte what the repository's golden holds, with the header
#      "Regenerate with `make golden`" (golden/README.md) when run as `make golden` runs it;
#   5. `all --strict` and `golden --strict` refuse a scenario that warns (status 2).
# Usage: sh tests/golden_dir.sh [TOOL]   (default build/handspring)
set -u
tool=${1:-build/handspring}
case "$tool" in /*) ;; *) tool="$PWD/$tool" ;; esac
fails=0
ok() { :; }
fail() { echo "golden_dir: FAIL: $*"; fails=$((fails + 1)); }
sums() { find golden -type f | LC_ALL=C sort | xargs sha256sum; }

user=$(mktemp -d ./hs-golden-user.XXXXXX) || exit 2
work=$(mktemp -d /tmp/hs-golden-dir.XXXXXX) || exit 2
trap 'rm -rf "$user" "$work"' EXIT INT TERM
before=$(sums)

# 1. a user folder at the top, a scenario named like the catalog's drop_cube
cp scenarios/drop_cube.yaml "$user/"
"$tool" golden "$user" > "$work/golden.out" 2>&1
rc=$?
[ $rc -eq 0 ] || { fail "golden $user: status $rc"; cat "$work/golden.out"; }
[ -f "$user/golden/drop_cube.csv" ] || fail "no $user/golden/drop_cube.csv"
head -n 1 "$user/golden/drop_cube.csv" | grep -q '^frame,t,object,' ||
	fail "the user golden does not start with its header row: $(head -n 1 "$user/golden/drop_cube.csv")"
grep -q "Regenerate with \`handspring golden $user\`" "$user/golden/README.md" ||
	fail "the user goldens' README.md does not name 'handspring golden $user': $(cat "$user/golden/README.md")"
[ "$(sums)" = "$before" ] || fail "golden $user changed the catalog's golden/"
"$tool" check "$user" > "$work/check.out" 2>&1
rc=$?
[ $rc -eq 0 ] && grep -q "1 match, 0 differ" "$work/check.out" || { fail "check $user: status $rc"; cat "$work/check.out"; }

# 2. the catalog's goldens folder is refused for a user folder
for g in golden golden/hand "$user/../golden"; do
	"$tool" golden "$user" --golden "$g" > "$work/refused.out" 2>&1
	rc=$?
	[ $rc -eq 2 ] && grep -q "holds the goldens of the catalog" "$work/refused.out" ||
		{ fail "golden $user --golden $g: status $rc"; cat "$work/refused.out"; }
done
"$tool" all --dir "$user" --golden-dir golden > "$work/refused.out" 2>&1
[ $? -eq 2 ] || fail "all --dir $user --golden-dir golden was not refused"
[ "$(sums)" = "$before" ] || fail "a refused command changed the catalog's golden/"

# 3. a failing scenario: no golden without --force
fails_dir="$work/failing"
mkdir -p "$fails_dir"
cp scenarios/drop_cube.yaml "$fails_dir/"
echo "  - { object: cube, at: end, near: [5, 0, 0.05], tolerance: 1e-9 }" >> "$fails_dir/drop_cube.yaml"
"$tool" golden "$fails_dir" > "$work/fail.out" 2> "$work/fail.err"
rc=$?
[ $rc -eq 1 ] || fail "golden of a failing scenario: status $rc, not 1"
[ ! -e "$fails_dir/golden/drop_cube.csv" ] || fail "the golden of a failing scenario was written"
grep -q "drop_cube: 1 expectation(s) failed: its golden is not written (--force writes it)" "$work/fail.err" ||
	{ fail "no message for the golden not written"; cat "$work/fail.err"; }
"$tool" golden "$fails_dir" --force > "$work/fail.out" 2> "$work/fail.err"
rc=$?
[ $rc -eq 1 ] || fail "golden --force of a failing scenario: status $rc, not 1"
[ -f "$fails_dir/golden/drop_cube.csv" ] || fail "--force did not write the golden"
grep -q "warning: drop_cube: 1 expectation(s) failed: its golden is written anyway (--force)" "$work/fail.err" ||
	{ fail "no warning for the forced golden"; cat "$work/fail.err"; }

# 4. the catalog's layout: goldens beside scenarios/, as make golden writes them
mkdir -p "$work/cat/scenarios" "$work/cat/golden"
cp scenarios/drop_cube.yaml "$work/cat/scenarios/"
top=$PWD
(cd "$work/cat" && "$tool" all --dir scenarios --golden-dir golden > all.out 2>&1) || fail "all --golden-dir in a catalog copy"
cmp -s "$work/cat/golden/drop_cube.csv" "$top/golden/drop_cube.csv" ||
	fail "a catalog copy's make-golden run differs from golden/drop_cube.csv"
rm -f "$work/cat/golden/drop_cube.csv"
"$tool" golden "$work/cat/scenarios" > "$work/cat.out" 2>&1 || fail "golden on a catalog copy's scenarios/"
[ -f "$work/cat/golden/drop_cube.csv" ] || fail "golden DIR/scenarios did not write DIR/golden (beside it)"
"$tool" check "$work/cat/scenarios" > "$work/cat.out" 2>&1 || fail "check on a catalog copy's scenarios/"

# 5. --strict refuses a scenario that warns
mkdir -p "$work/warn"
cp tests/bad/warn_under_floor.yaml "$work/warn/"
"$tool" all --dir "$work/warn" > "$work/warn.out" 2>&1
[ $? -eq 0 ] || fail "all on a scenario that only warns did not pass"
"$tool" all --dir "$work/warn" --strict > "$work/warn.out" 2>&1
[ $? -eq 2 ] && grep -q "refused: it has warnings (--strict)" "$work/warn.out" ||
	{ fail "all --strict did not refuse a scenario that warns"; cat "$work/warn.out"; }

"$tool" golden "$work/warn" --strict > "$work/warn.out" 2>&1
[ $? -eq 2 ] && [ ! -e "$work/warn/golden/warn_under_floor.csv" ] || fail "golden --strict wrote a scenario that warns"

[ "$(sums)" = "$before" ] || fail "the catalog's golden/ changed"
if [ $fails -gt 0 ]; then
	echo "golden_dir: $fails failure(s)"
	exit 1
fi
echo "golden_dir: user goldens in DIR/golden, the catalog's golden/ untouched and refused, failing scenarios' goldens held back (--force writes them), the catalog's layout as before"
