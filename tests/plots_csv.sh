#!/bin/sh
# plots_csv.sh — `make check-plots-csv`: every CSV that `make plots` writes (DIR/*.csv) is what a
# csv reader (Python's csv.DictReader, pandas) takes as it is (docs/plots.md, "The data files"):
#   1. line 1 is the header row: column names (letters, digits, _), comma-separated, no repeats;
#   2. then data rows only, at least one: no '#' line, no blank line, each with the header's
#      number of fields;
#   3. the sidecar DIR/NAME.txt that says what the columns are is there and not empty;
#   4. the files holding several runs of one scenario tell them apart by a column, each run's rows
#      together: the column's values, repeats collapsed, are the runs' in order (fps: 12 17 30 60
#      120, seed: 0 1 2 3 4 5).
# Usage: sh tests/plots_csv.sh [DIR]   (default build/plots; run `make plots` first)
set -u
dir=${1:-build/plots}
fails=0
fail() { echo "plots_csv: FAIL: $*"; fails=$((fails + 1)); }

n=0
for f in "$dir"/*.csv; do
	[ -e "$f" ] || break
	n=$((n + 1))
	# 1 and 2: one awk pass; it prints what is wrong, nothing when the file is right
	problems=$(awk -F, '
		NR == 1 {
			fields = NF
			for (i = 1; i <= NF; i++) {
				if ($i !~ /^[A-Za-z_][A-Za-z0-9_]*$/) { print "line 1 field " i " \"" $i "\" is not a column name"; bad = 1 }
				if ($i in seen) { print "line 1 names column " $i " twice"; bad = 1 }
				seen[$i] = 1
			}
			next
		}
		/^#/ { print "line " NR " is a comment"; bad = 1; exit }
		/^[ \t\r]*$/ { print "line " NR " is blank"; bad = 1; exit }
		NF != fields { print "line " NR " has " NF " fields, the header " fields; bad = 1; exit }
		END { if (NR < 2 && !bad) print "no data row" }' "$f")
	[ -z "$problems" ] || fail "$f: $problems"
	[ -s "${f%.csv}.txt" ] || fail "$f: no sidecar ${f%.csv}.txt"
done
[ "$n" -gt 0 ] || fail "no CSV in $dir (run make plots first)"

# 4: the runs' column, by name, and its values with repeats collapsed
runs() { # FILE COLUMN EXPECTED
	[ -e "$dir/$1" ] || { fail "$dir/$1 missing"; return; }
	got=$(awk -F, -v name="$2" '
		NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; if (!c) exit; next }
		n == 0 || $c != last { printf "%s%s", (n++ ? " " : ""), $c; last = $c }' "$dir/$1")
	[ "$got" = "$3" ] || fail "$dir/$1: column $2 holds runs '$got', not '$3'"
}
runs hand_flick_rates.csv fps "12 17 30 60 120"
runs hand_throw_rates.csv fps "12 17 30 60 120"
runs hand_timeline_noisy.csv seed "0 1 2 3 4 5"

if [ "$fails" -gt 0 ]; then
	echo "plots_csv: $fails failure(s)"
	exit 1
fi
echo "plots_csv: $n CSVs in $dir: header row first, data rows only, a sidecar each; the runs told apart by fps / seed"
