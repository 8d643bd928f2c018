#!/bin/sh
# exp2_sensitivity.sh — runs campaigns/exp2_sensitivity.yaml (Experiment 2 at 1, 2, 3 and 5 times
# the fitted thrower) and prints docs/campaigns.md's sensitivity table from its summary: per
# thrower and frame rate, the hit rate per throw and per visitor (grouped; the binomial beside it).
#   sh scripts/exp2_sensitivity.sh [TOOL] [OUTDIR]     (defaults: build/handspring, build/campaign/exp2_sensitivity)
set -eu
tool=${1:-${HS_TOOL:-build/handspring}}
out=${2:-build/campaign/exp2_sensitivity}
mkdir -p "$out"
"$tool" campaign campaigns/exp2_sensitivity.yaml --out "$out/trials.csv" --summary "$out/summary.csv" >"$out/table.txt"
# the summary's columns by their header names
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
	{
		s = sprintf("%g", $col["throw_scale"]); r = sprintf("%.0f", 1 / $col["dt"])
		if (!(s in seen)) { seen[s] = 1; scales[++ns] = s }
		if (!(r in rseen)) { rseen[r] = 1; rates[++nr] = r }
		cell[s, r] = sprintf("%.3f / %.3f (%.3f)", $col["rate"], $col["visitor_rate"], $col["visitor_binomial"])
		lost[s] += $col["grasp_lost"]; n = $col["visitor_throws"]
	}
	END {
		printf "| throw_scale (x the fitted 0.33) |"
		for (j = 1; j <= nr; ++j) printf " %s frames/s |", rates[j]
		printf " grasps lost |\n|---|"
		for (j = 1; j <= nr; ++j) printf "---|"
		printf "---|\n"
		for (i = 1; i <= ns; ++i) {
			printf "| %s (x%.0f) |", scales[i], scales[i] / scales[1]
			for (j = 1; j <= nr; ++j) printf " %s |", cell[scales[i], rates[j]]
			printf " %d |\n", lost[scales[i]]
		}
		printf "\nEach cell: hit rate per throw / per visitor of %d throws, grouped (the binomial 1 - (1 - rate)^%d).\n", n, n
	}' "$out/summary.csv"
