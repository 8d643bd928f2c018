#!/bin/sh
# sweep_table.sh — the robustness sweep as one markdown table: a row per scenario, a column per
# frame time, each cell "seeds passing of seeds run", and the nominal run's result.
#   sweep_table.sh TOOL [FILE|DIR]...   run `TOOL sweep` on each scenario file (a DIR: its *.yaml;
#                                       default scenarios/hand) and tabulate the outputs
#   sweep_table.sh -                    tabulate `handspring sweep` outputs read from stdin
# A scenario whose sweep could not run (no robust block, bad input) gets a row saying so.
# The table goes to stdout; the exit status is 0 (it reports, check-sweep judges).
set -eu
if [ $# -lt 1 ]; then
	echo "usage: sweep_table.sh TOOL [FILE|DIR]... | sweep_table.sh -" >&2
	exit 2
fi

tabulate() {
	awk '
	function flush() {
		if (name == "") return
		rows[++n] = name
		nominal[name] = nom
		name = ""
	}
	/^sweep [^ ]+: / {                       # "sweep NAME: D dt x S seeds, ..."
		flush()
		name = $2; sub(/:$/, "", name)
		nom = "?"; in_rows = 0
		next
	}
	/^cannot sweep / { flush(); name = $3; nom = "no sweep"; flush(); next }
	name != "" && /^dt / { in_rows = 1; next }
	name != "" && /^nominal / { in_rows = 0; nom = $NF; next }
	name != "" && /^sweep: / { next }
	name != "" && in_rows && NF > 1 {
		dt = $1
		if (!(dt in seen)) { seen[dt] = 1; cols[++m] = dt }
		pass = 0
		for (i = 2; i <= NF; ++i) if ($i == "ok") ++pass
		cell[name, dt] = pass " of " (NF - 1)
	}
	END {
		flush()
		line = "| scenario |"; rule = "| --- |"
		for (j = 1; j <= m; ++j) { line = line " " cols[j] " |"; rule = rule " --- |" }
		print line " nominal |"; print rule " --- |"
		for (i = 1; i <= n; ++i) {
			r = rows[i]; line = "| " r " |"
			for (j = 1; j <= m; ++j) line = line " " ((r, cols[j]) in cell ? cell[r, cols[j]] : "-") " |"
			print line " " nominal[r] " |"
		}
	}'
}

if [ "$1" = "-" ]; then
	tabulate
	exit 0
fi
tool=$1
shift
[ $# -gt 0 ] || set -- scenarios/hand
for arg in "$@"; do
	if [ -d "$arg" ]; then
		for f in "$arg"/*.yaml; do [ -e "$f" ] && echo "$f"; done
	else
		echo "$arg"
	fi
done | while read -r f; do
	"$tool" sweep "$f" 2>/dev/null || [ $? -eq 1 ] || echo "cannot sweep $(basename "$f" .yaml)"
done | tabulate
