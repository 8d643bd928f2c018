#!/bin/sh
# campaign_merge.sh — the merge step of a campaign split into parts (docs/campaigns.md), shared by
# scripts/campaign.sh (GNU parallel) and scripts/campaign.sbatch (a Slurm job array):
#   1. OUTDIR/trials.csv = the header (`TOOL campaign FILE --header`) + every part's rows sorted
#      numerically by their first field (the trial index): byte for byte what the in-process run
#      (`TOOL campaign FILE --out TRIALS.csv`) writes, however the trials were split;
#   2. `TOOL campaign FILE --summarize OUTDIR/trials.csv --summary OUTDIR/summary.csv`, which checks
#      that every trial 0..T-1 appears exactly once, writes the summary and prints its table.
#   campaign_merge.sh TOOL CAMPAIGN_FILE OUTDIR PART...
# A part is the rows of some trials (no header), as `--trials A:B --rows` writes them. A part that
# does not end in a newline was cut short (a killed job) and is refused, as is a row count other
# than T. The merged file is written to a temporary made by mktemp in OUTDIR (.trials.csv.XXXXXX:
# never through a link planted there) and renamed to trials.csv only once --summarize accepts it.
# Exit status: 0; 1 when merged and summarised but some trials' runs faulted (clauses `fault`); 2
# with the reason on stderr (the tool's own `file:line: message` included).
set -eu
if [ $# -lt 3 ]; then
	echo "usage: campaign_merge.sh TOOL CAMPAIGN_FILE OUTDIR PART..." >&2
	exit 2
fi
tool=$1
file=$2
out=$3
shift 3
total=$("$tool" campaign "$file" --count)
for p in "$@"; do
	if [ ! -f "$p" ]; then
		echo "campaign_merge: $p: no such part" >&2
		exit 2
	fi
	# $(...) drops a final newline: a non-empty answer means the last byte is not one
	if [ -n "$(tail -c 1 "$p")" ]; then
		echo "campaign_merge: $p: the last row is cut short (no newline at the end)" >&2
		exit 2
	fi
done
tmp=$(mktemp "$out/.trials.csv.XXXXXX")
chmod "$(printf '%o' $((0666 & ~$(umask))))" "$tmp" # mktemp's 0600: the mode a new file gets
"$tool" campaign "$file" --header > "$tmp"
if [ $# -gt 0 ]; then
	cat -- "$@" | LC_ALL=C sort -t, -k1,1n >> "$tmp"
fi
rows=$(($(wc -l < "$tmp") - 1))
if [ "$rows" -ne "$total" ]; then
	echo "campaign_merge: $# parts hold $rows rows, the campaign has $total trials ($tmp kept)" >&2
	exit 2
fi
rc=0
"$tool" campaign "$file" --summarize "$tmp" --summary "$out/summary.csv" || rc=$?
if [ "$rc" -gt 1 ]; then
	echo "campaign_merge: --summarize refused the merged trials (status $rc; $tmp kept)" >&2
	exit 2
fi
mv -f "$tmp" "$out/trials.csv"
# status 1: merged and summarised, but some trials' runs faulted (the tool said how many)
[ "$rc" -eq 0 ] || exit 1
