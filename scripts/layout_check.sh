#!/bin/sh
# layout_check.sh — the structure rules of the code base, checked on every `make check`:
#  1. no function in model/, harness/ or tool/ longer than MAX_LINES (80) lines, body included;
#  2. no include cycle among the private headers of a layer: a unit is a file name without its
#     extension (contact.c and contact.h are one unit), an edge runs from a unit to each unit whose
#     header it includes, and a cycle means two concepts call each other;
#  3. layers call one way: model/ includes no harness header, no libyaml and no GSL; the harness
#     and the tool include only the public headers of the model (the compiler's include paths
#     enforce the rest).
# Functions are found by the project's formatting: a definition starts at column 0 and ends at the
# first `}` in column 0. Exit status 1 with one line per violation.
set -eu
cd "$(dirname "$0")/.."
MAX_LINES=${MAX_LINES:-80}
status=0

long=$(awk -v max="$MAX_LINES" '
	FNR == 1 { inside = 0 }
	!inside && /^[A-Za-z_][A-Za-z0-9_ \*]*[A-Za-z0-9_\*]+\(/ && !/;[ \t]*$/ { start = FNR; name = $0; inside = 1 }
	inside && /^}/ {
		n = FNR - start + 1
		if (n > max) { sub(/\(.*/, "", name); printf "%s:%d: function %s is %d lines (limit %d)\n", FILENAME, start, name, n, max }
		inside = 0
	}
' model/*/*.c harness/*.c tool/*.c)
if [ -n "$long" ]; then
	echo "$long"
	status=1
fi

for layer in model harness; do
	# the model's files are in its folders (docs/architecture.md), the harness's at its top
	cycles=$(for f in "$layer"/*.c "$layer"/*.h "$layer"/*/*.c "$layer"/*/*.h; do
		[ -e "$f" ] || continue
		u=$(basename "$f"); u=${u%.*}
		sed -n 's/^#include "\([^"]*\)\.h".*/\1/p' "$f" | while read -r h; do
			if [ "$h" != "$u" ] && ls "$layer/$h.h" "$layer"/*/"$h.h" 2>/dev/null | grep -q .; then echo "$u $h"; fi
		done
	done | sort -u | awk -v layer="$layer" '
		{ adj[$1] = adj[$1] " " $2; nodes[$1] = 1; nodes[$2] = 1 }
		function visit(u,   i, n, next_u, parts) {
			color[u] = 1; stack[++depth] = u
			n = split(adj[u], parts, " ")
			for (i = 1; i <= n; i++) {
				next_u = parts[i]
				if (color[next_u] == 1) {
					path = next_u; for (k = depth; k >= 1 && stack[k] != next_u; k--) path = stack[k] " -> " path
					printf "%s/: include cycle %s -> %s\n", layer, next_u, path
				} else if (!color[next_u]) visit(next_u)
			}
			color[u] = 2; depth--
		}
		END { for (u in nodes) if (!color[u]) visit(u) }
	')
	if [ -n "$cycles" ]; then
		echo "$cycles"
		status=1
	fi
done

bad=$(grep -lE '#include [<"](yaml\.h|gsl/|hs_harness\.h|harness_)' model/*/*.c model/*/*.h 2>/dev/null || true)
for f in $bad; do
	echo "$f: the physics must not include the harness, libyaml or GSL"
	status=1
done
for f in harness/*.c harness/*.h tool/*.c; do
	[ -e "$f" ] || continue
	sed -n 's/^#include "\([^"]*\)".*/\1/p' "$f" | while read -r h; do
		if ls model/*/"$h" 2>/dev/null | grep -v '^model/include/' | grep -q .; then echo "$f: includes the model's private header $h"; fi
	done
done | grep . && status=1

if [ "$status" -eq 0 ]; then
	echo "layout: functions <= $MAX_LINES lines, no include cycle, layers call one way"
fi
exit "$status"
