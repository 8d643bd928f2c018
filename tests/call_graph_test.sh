#!/bin/sh
# call_graph_test.sh — scripts/call_graph.sh can fail: tiny objects built in a temporary folder
# that call each other (a cycle, named with its symbols), a chain that does not, a three-unit
# cycle, the same from an archive, a lower layer calling a higher one, and bench calling the tool; each with its exit status.
# usage: tests/call_graph_test.sh [CC]   (under a second)
set -eu
cd "$(dirname "$0")/.."
CC=${1:-${CC:-cc}}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/call_graph_test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fails=0

obj() { # DIR UNIT SOURCE: compiles SOURCE into DIR/UNIT.o
	mkdir -p "$1"
	printf '%s\n' "$3" > "$tmp/$2.c"
	"$CC" -std=c11 -O0 -c "$tmp/$2.c" -o "$1/$2.o"
}
# expect STATUS PATTERN ARGS...: call_graph.sh ARGS exits with STATUS and prints a line matching
# PATTERN (a grep -E pattern; "" for none)
expect() {
	want=$1 pattern=$2; shift 2
	status=0
	sh scripts/call_graph.sh "$@" > "$tmp/out" 2>&1 || status=$?
	if [ "$status" != "$want" ]; then
		echo "FAIL: call_graph.sh $* exited $status, expected $want:"; sed 's/^/  /' "$tmp/out"; fails=$((fails + 1))
	elif [ -n "$pattern" ] && ! grep -Eq "$pattern" "$tmp/out"; then
		echo "FAIL: call_graph.sh $* printed no line matching '$pattern':"; sed 's/^/  /' "$tmp/out"; fails=$((fails + 1))
	fi
}

# a <-> b: the cycle, each edge with its symbols
obj "$tmp/cycle/harness" a 'int b_one(int); int b_two(int); int a_back(int x); int a_back(int x) { return x > 0 ? b_one(x - 1) + b_two(x) : 0; }'
obj "$tmp/cycle/harness" b 'int a_back(int); int b_one(int x); int b_two(int x); int b_one(int x) { return a_back(x); } int b_two(int x) { return x; }'
expect 1 '^harness/: call cycle a -> b -> a \(a -> b: b_one, b_two; b -> a: a_back\)$' "$tmp/cycle/harness"
[ "$(wc -l < "$tmp/out")" -eq 1 ] || { echo "FAIL: one cycle, but:"; cat "$tmp/out"; fails=$((fails + 1)); }
# the same objects in an archive
ar rcs "$tmp/cycle/libh.a" "$tmp/cycle/harness/a.o" "$tmp/cycle/harness/b.o"
expect 1 '^harness/: call cycle a -> b -> a \(a -> b: b_one, b_two; b -> a: a_back\)$' harness="$tmp/cycle/libh.a"

# a -> b -> c, no way back: passes
obj "$tmp/chain/harness" a 'int b_one(int); int a_top(int x); int a_top(int x) { return b_one(x); }'
obj "$tmp/chain/harness" b 'int c_leaf(int); int b_one(int x); int b_one(int x) { return c_leaf(x) + 1; }'
obj "$tmp/chain/harness" c 'int c_leaf(int x); int c_leaf(int x) { return x; }'
expect 0 '^calls: no cycle' "$tmp/chain/harness"

# a -> b -> c -> a: found, and more than three symbols on an edge are cut with "..."
obj "$tmp/three/tool" a 'int b_one(int); int a_top(int x); int a_top(int x) { return b_one(x); }'
obj "$tmp/three/tool" b 'int c_1(int); int c_2(int); int c_3(int); int c_4(int); int b_one(int x); int b_one(int x) { return c_1(x) + c_2(x) + c_3(x) + c_4(x); }'
obj "$tmp/three/tool" c 'int a_top(int); int c_1(int x); int c_2(int x); int c_3(int x); int c_4(int x);
int c_1(int x) { return a_top(x); } int c_2(int x) { return x; } int c_3(int x) { return x; } int c_4(int x) { return x; }'
expect 1 '^tool/: call cycle a -> b -> c -> a \(a -> b: b_one; b -> c: c_1, c_2, c_3, \.\.\.; c -> a: a_top\)$' "$tmp/three/tool"

# the same units in two layers: no cycle, but model may not call the harness
obj "$tmp/layers/model" low 'int high_help(int); int low_step(int x); int low_step(int x) { return high_help(x); }'
obj "$tmp/layers/harness" high 'int high_help(int x); int high_help(int x) { return x; }'
expect 1 '^layers: model/low calls the higher layer harness/high \(low -> high: high_help\)$' "$tmp/layers/model" "$tmp/layers/harness"
# ... while the harness may call the model (LAYER=DIR names a folder's layer)
expect 0 '' harness="$tmp/layers/model" model="$tmp/layers/harness"
# bench may not call the tool
expect 1 '^layers: bench/low calls the higher layer tool/high' bench="$tmp/layers/model" tool="$tmp/layers/harness"
# a folder that is not there is bad input
expect 2 'no such folder or archive' "$tmp/none"

if [ "$fails" -ne 0 ]; then
	echo "call_graph_test: $fails failed"
	exit 1
fi
echo "call_graph_test: the script finds a two- and a three-unit cycle and a call against the layers, and passes a chain"
