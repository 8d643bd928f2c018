#!/bin/sh
# layout_check_test.sh — scripts/layout_check.sh can fail: it is run on tiny trees in a temporary
# folder (its own copy in TREE/scripts, so it reads TREE): a clean tree passes; two headers of the
# model that include each other, three harness files in an include cycle, a function of 81 lines
# and the model including the harness's header each fail with their line; files whose last include
# is not their layer's come first. (under a second)
set -eu
cd "$(dirname "$0")/.."
tmp=$(mktemp -d "${TMPDIR:-/tmp}/layout_check_test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fails=0

tree() { # a fresh clean tree: model/a/{x,y}, harness/{p,q}, tool/t.c
	rm -rf "$tmp/t" && mkdir -p "$tmp/t/scripts" "$tmp/t/model/a" "$tmp/t/model/include" "$tmp/t/harness" "$tmp/t/tool"
	cp scripts/layout_check.sh "$tmp/t/scripts/"
	printf '#include "y.h"\nint x(void) { return y(); }\n' > "$tmp/t/model/a/x.c"
	printf 'int x(void);\n' > "$tmp/t/model/a/x.h"
	printf 'int y(void) { return 1; }\n' > "$tmp/t/model/a/y.c"
	printf 'int y(void);\n' > "$tmp/t/model/a/y.h"
	printf '#include "q.h"\nint p(void) { return q(); }\n' > "$tmp/t/harness/p.c"
	printf 'int q(void) { return 2; }\n' > "$tmp/t/harness/q.c"
	printf 'int q(void);\n' > "$tmp/t/harness/q.h"
	printf 'int main(void) { return 0; }\n' > "$tmp/t/tool/t.c"
	# files whose last include is not one of their layer's headers come first (the check once
	# stopped at such a file and saw no cycle after it)
	printf '#include "x.h"\n#include "outside.h"\nint a(void);\n' > "$tmp/t/model/a/a.c"
	printf '#include "q.h"\n#include "outside.h"\nint b(void);\n' > "$tmp/t/harness/b.c"
}
# expect STATUS PATTERN: layout_check.sh on the tree exits with STATUS and prints PATTERN (grep -E)
expect() {
	status=0
	out=$(sh "$tmp/t/scripts/layout_check.sh" 2>&1) || status=$?
	if [ "$status" -ne "$1" ] || ! printf '%s\n' "$out" | grep -Eq "$2"; then
		echo "layout_check_test: $3: exit $status (wanted $1), got:"
		printf '%s\n' "$out" | sed 's/^/  /'
		fails=$((fails + 1))
	fi
}

tree
expect 0 'no include cycle' "a clean tree"
tree
printf '#include "x.h"\nint y(void);\n' > "$tmp/t/model/a/y.h"
expect 1 'model/: include cycle (x -> y -> x|y -> x -> y)' "two model units including each other"
tree
printf '#include "p.h"\nint q(void);\n' > "$tmp/t/harness/q.h"
printf '#include "r.h"\nint p(void);\n' > "$tmp/t/harness/p.h"
printf 'int r(void);\n' > "$tmp/t/harness/r.h"
printf '#include "q.h"\nint r(void) { return q(); }\n' > "$tmp/t/harness/r.c"
expect 1 'harness/: include cycle' "three harness units in a cycle"
tree
{ printf 'int long_one(void) {\n'; i=0; while [ $i -lt 79 ]; do printf '\t(void)0;\n'; i=$((i + 1)); done; printf '}\n'; } > "$tmp/t/model/a/y.c"
expect 1 'function int long_one is 81 lines' "a function of 81 lines"
tree
printf '#include "hs_harness.h"\nint y(void) { return 1; }\n' > "$tmp/t/model/a/y.c"
expect 1 'must not include the harness' "the model including the harness"

if [ "$fails" -ne 0 ]; then
	echo "layout_check_test: $fails case(s) failed"
	exit 1
fi
echo "layout_check_test: the layout check passes a clean tree and fails an include cycle in either layer, a long function and the model reaching the harness"
