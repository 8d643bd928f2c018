#!/bin/sh
# call_graph.sh — the calls between source files, read from a build's object files with nm:
#  a unit is a file name without its extension (as in layout_check.sh), and an edge runs from
#  unit A to unit B when A.o references a global symbol (a function or data) that B.o defines.
#  Reported, one line each, exit status 1 if any:
#  (a) every elementary cycle between units of one layer (model/, harness/, tool/, bench/),
#      printed as a -> b -> a with the symbols that make each edge (at most 3 per edge);
#  (b) every reference from a lower layer into a higher one: model < harness < tool, and bench
#      may use model and harness only (tool and bench do not call each other).
# What nm cannot see: a static inline function of a header is compiled into each caller and
# leaves no symbol, so calls to it make no edge (that is fine: such a header is data and
# arithmetic, not a concept that calls back), and neither does a static function of a file.
# Include cycles are layout_check.sh's.
#
# usage: call_graph.sh [[LAYER=]DIR|LAYER=ARCHIVE...]
#  each DIR holds objects (*.o) of one layer, named by the DIR's base name unless LAYER= says
#  otherwise; an archive (.a) gives its members (`make check-calls` reads the libraries' archives,
#  which hold no object of a source file since removed, as a folder may); symbols that none of
#  them defines (libc, libccd...) make no edge. Without arguments:
#  $BUILD/obj/{model,harness,tool} and bench=$BUILD/bench/obj (BUILD defaults to build), those
#  that exist. MAX_CYCLES (default 200) stops the listing of cycles after that many.
set -eu
BUILD=${BUILD:-build}
MAX_CYCLES=${MAX_CYCLES:-200}
NM=${NM:-nm}
if [ "$#" -eq 0 ]; then
	for d in "$BUILD/obj/model" "$BUILD/obj/harness" "$BUILD/obj/tool" "bench=$BUILD/bench/obj"; do
		[ -d "${d#*=}" ] && set -- "$@" "$d"
	done
	[ "$#" -gt 0 ] || { echo "call_graph: no objects under $BUILD/obj (run make first)" >&2; exit 2; }
fi

# one line per symbol: "layer/unit D|U symbol" (D: defined here, U: used here, defined elsewhere)
layer_symbols() { # LAYER DIR|ARCHIVE
	layer=$1
	if [ -d "$2" ]; then
		set -- "$2"/*.o
		[ -e "$1" ] || return 0
	elif [ -f "$2" ]; then
		set -- "$2"
	else
		echo "call_graph: $2: no such folder or archive" >&2; exit 2
	fi
	# -A names the object on each line: "DIR/unit.o: symbol type [value size]", or
	# "ARCHIVE[unit.o]: ..." for a member of an archive
	"$NM" -A -P -g "$@" | awk -v layer="$layer" '
		{ u = $1; sub(/\]?:$/, "", u); sub(/.*[\/[]/, "", u); sub(/\.o$/, "", u) }
		$3 == "U" || $3 == "w" || $3 == "v" { print layer "/" u, "U", $2; next }
		NF >= 3 { print layer "/" u, "D", $2 }'
}
symbols() {
	for arg in "$@"; do
		case "$arg" in
		*=*) layer=${arg%%=*}; path=${arg#*=} ;;
		*) path=$arg; layer=$(basename "$path") ;;
		esac
		layer_symbols "$layer" "$path"
	done
}

# the edges, sorted: "from to count sym1,sym2,sym3"
edges() {
	awk '
		$2 == "D" { if (!($3 in def)) def[$3] = $1; next }
		{ used[++n] = $1; sym[n] = $3 }
		END {
			for (i = 1; i <= n; i++) {
				if (!(sym[i] in def) || def[sym[i]] == used[i]) continue
				print used[i], def[sym[i]], sym[i]
			}
		}' | sort -u | awk '
		function flush() { if (key != "") print key, count, list }
		{
			k = $1 " " $2
			if (k != key) { flush(); key = k; count = 0; list = "" }
			if (++count <= 3) list = list (list == "" ? "" : ",") $3
		}
		END { flush() }'
}

syms=$(mktemp "${TMPDIR:-/tmp}/call_graph.XXXXXX")
trap 'rm -f "$syms"' EXIT
symbols "$@" > "$syms"
edges < "$syms" | awk -v max="$MAX_CYCLES" '
	function layer(u) { return substr(u, 1, index(u, "/") - 1) }
	function unit(u) { return substr(u, index(u, "/") + 1) }
	function may_call(from, to) {
		if (from == to) return 1
		if (to == "model") return from == "harness" || from == "tool" || from == "bench"
		if (to == "harness") return from == "tool" || from == "bench"
		return !(from == "model" || from == "harness" || (from == "tool" && to == "bench") || (from == "bench" && to == "tool"))
	}
	function named(a, b,   s) {
		s = syms[a, b]; gsub(/,/, ", ", s)
		return unit(a) " -> " unit(b) ": " s (cnt[a, b] > 3 ? ", ..." : "")
	}
	# every elementary cycle through start s whose other units sort after s (each cycle once)
	function walk(s, u, depth,   i, w, j, line, why) {
		for (i = 1; i <= nadj[u]; i++) {
			w = adj[u, i]
			if (w == s) {
				if (++found > max) return
				path[depth + 1] = s; line = unit(s); why = ""
				for (j = 2; j <= depth + 1; j++) {
					line = line " -> " unit(path[j])
					why = why (why == "" ? "" : "; ") named(path[j - 1], path[j])
				}
				printf "%s/: call cycle %s (%s)\n", layer(s), line, why
			} else if (w > s && !on[w]) {
				on[w] = 1; path[depth + 1] = w
				walk(s, w, depth + 1)
				on[w] = 0
			}
			if (found > max) return
		}
	}
	{
		a = $1; b = $2; cnt[a, b] = $3; syms[a, b] = $4
		if (layer(a) == layer(b)) {
			if (!(a in nadj)) { starts[++nstarts] = a; nadj[a] = 0 }
			adj[a, ++nadj[a]] = b
		} else if (!may_call(layer(a), layer(b)))
			bad[++nbad] = sprintf("layers: %s calls the higher layer %s (%s)", a, b, named(a, b))
	}
	END {
		for (k = 1; k <= nstarts && found <= max; k++) {
			s = starts[k]; on[s] = 1; path[1] = s
			walk(s, s, 1)
			on[s] = 0
		}
		if (found > max) printf "call cycles: more than %d, the rest not listed (MAX_CYCLES)\n", max
		for (k = 1; k <= nbad; k++) print bad[k]
		if (found || nbad) exit 1
		print "calls: no cycle within a layer, layers call one way"
	}'
