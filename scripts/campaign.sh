#!/bin/sh
# campaign.sh — a Monte-Carlo campaign's trials (docs/campaigns.md) spread over GNU parallel: this
# machine's cores, other machines over ssh, or both; the result is byte for byte the in-process
# run's.
#
#   campaign.sh CAMPAIGN_FILE OUTDIR [--jobs N] [--chunk K] [--sshlogin LOGINS] [--ssh CMD]
#               [--basefile PATH]... [--tool PATH] [--resume]
#
#   --jobs N          jobs at a time on each machine (parallel -j; default: one per core)
#   --chunk K         trials per job (default: T / (4 x the job slots), at least 1, so that there are
#                     at least four jobs per slot and a slow one cannot hold up the end)
#   --sshlogin LOGINS parallel's --sshlogin: comma-separated [N/][user@]host, `:` is this machine
#                     (only when you name it). A remote runs each job in this same directory (the
#                     jobs are run with --workdir "$PWD"): the tool and the campaign file must be
#                     there at the same paths (a shared file system or the same checkout, built),
#                     or be copied there first with --basefile.
#   --ssh CMD         the ssh command parallel runs (e.g. 'ssh -F my_config')
#   --basefile PATH   copied to each remote before its first job (parallel --basefile, needs rsync
#                     on both ends); repeatable: the tool, the campaign file and what it reads
#   --tool PATH       the handspring tool (default: $HS_TOOL, else build/handspring)
#   --resume          continue an interrupted or failed run in OUTDIR: the jobs its joblog records
#                     as done are not run again, the failed and the missing ones are
#                     (parallel --resume-failed). Refused when the campaign file, the tool or the
#                     trial count changed since (OUTDIR/campaign.id). Without --resume a run
#                     starts afresh: the files below from an earlier run in OUTDIR are removed.
#                     A job the joblog records as done whose part is not whole (a full disk) is
#                     recorded as failed there, so --resume runs it again.
#
# Two runs into one OUTDIR are kept apart: each holds OUTDIR/.lock (flock) until it and its jobs
# end; a second is refused with a message naming the lock.
#
# What it does: asks the tool for the trial count T (`campaign FILE --count`), writes the job list
# OUTDIR/jobs (one A:B range of trials per line), runs `TOOL campaign FILE --trials A:B --rows` for
# each with parallel (--joblog OUTDIR/joblog, --halt now,fail=1), each job's rows captured on this
# machine (--results: OUTDIR/parts/SEQ.rows, its stderr beside it as SEQ.rows.err; remote jobs'
# output comes back through ssh), then merges them with scripts/campaign_merge.sh:
# OUTDIR/trials.csv (header + rows sorted by trial) and OUTDIR/summary.csv, whose table it prints.
# Progress: parallel's --bar on stderr when stderr is a terminal; always a last line with the
# trials run, the wall time and the trials per second.
# Exit status: 0; 1 when done but some trials' runs faulted (their rows say `fault`); 2 for bad arguments or input (the tool's `file:line: message` on stderr); a
# failed job's own status (its stderr printed, rerun with --resume once fixed); 130/143 when
# interrupted (rerun with --resume).
set -eu
here=$(dirname "$0")

usage() {
	echo "usage: campaign.sh CAMPAIGN_FILE OUTDIR [--jobs N] [--chunk K] [--sshlogin LOGINS] [--ssh CMD] [--basefile PATH]... [--tool PATH] [--resume]" >&2
	exit 2
}
die() {
	echo "campaign: $*" >&2
	exit 2
}
is_count() { # a positive decimal integer
	case "$1" in '' | *[!0-9]* | 0*) return 1 ;; esac
}
now() { date +%s.%N; }
start=$(now)

[ $# -ge 2 ] || usage
file=$1
out=$2
shift 2
case "$file$out" in -*) usage ;; esac
jobs=""
chunk=""
sshlogin=""
sshcmd=""
basefiles=""
tool=${HS_TOOL:-build/handspring}
resume=no
while [ $# -gt 0 ]; do
	case "$1" in
	--jobs | --chunk | --sshlogin | --ssh | --basefile | --tool)
		[ $# -ge 2 ] || die "$1 needs a value"
		case "$1" in
		--jobs) jobs=$2 ;;
		--chunk) chunk=$2 ;;
		--sshlogin) sshlogin=$2 ;;
		--ssh) sshcmd=$2 ;;
		--basefile) basefiles="$basefiles
$2" ;;
		--tool) tool=$2 ;;
		esac
		shift 2
		;;
	--resume) resume=yes; shift ;;
	*) die "unknown argument '$1'" ;;
	esac
done
[ -z "$jobs" ] || is_count "$jobs" || die "--jobs $jobs: a positive whole number is needed"
[ -z "$chunk" ] || is_count "$chunk" || die "--chunk $chunk: a positive whole number is needed"
[ -r "$file" ] || die "$file: cannot read the campaign file"
case "$tool" in */*) toolfile=$tool ;; *) toolfile=$(command -v "$tool" || true) ;; esac
{ [ -n "$toolfile" ] && [ -x "$toolfile" ]; } || die "$tool: no such tool (build it with make, or give --tool PATH)"
# Debian's moreutils ships another program named parallel
parallel --version 2>/dev/null | grep -q 'GNU parallel' ||
	die "GNU parallel is missing (sh scripts/deps.sh installs the Debian package parallel)"

total=$("$tool" campaign "$file" --count) || exit $?
case "$total" in '' | *[!0-9]*) die "$tool campaign $file --count answered '$total', not a trial count" ;; esac

# What the results depend on: a resumed run must have the same, or the parts would mix two runs.
id=$(printf 'campaign %s\ntool %s\ntrials %s\n' "$(sha256sum < "$file" | cut -c1-64)" \
	"$(sha256sum < "$toolfile" | cut -c1-64)" "$total")
mkdir -p "$out"
# One run at a time in OUTDIR: the lock is held on descriptor 9 by this shell, parallel and every
# job (they inherit it) until the last of them exits, a killed run's too.
command -v flock > /dev/null 2>&1 || die "flock is missing (Debian's util-linux)"
exec 9>> "$out/.lock"
flock -n 9 || die "$out: another campaign run is writing to this folder (it holds $out/.lock); wait for it to end or choose another OUTDIR"
if [ "$resume" = yes ] && [ -f "$out/jobs" ] && [ -f "$out/campaign.id" ]; then
	printf '%s\n' "$id" | cmp -s - "$out/campaign.id" ||
		die "$out: its run was of another campaign file, tool or trial count ($out/campaign.id); run without --resume to start afresh"
	[ -z "$chunk" ] || echo "campaign: --resume keeps the first run's split ($out/jobs), --chunk $chunk is ignored" >&2
else
	[ "$resume" = no ] || echo "campaign: no earlier run in $out to resume, starting afresh" >&2
	rm -rf "$out/parts"
	rm -f "$out/jobs" "$out/joblog" "$out/campaign.id" "$out/trials.csv" "$out/trials.csv.tmp" "$out/summary.csv" \
		"$out"/.trials.csv.??????
	if [ -z "$chunk" ]; then
		# job slots: --jobs per machine; without it the cores here, or the N of an N/login (a
		# remote's own core count, which parallel finds out, is unknown here: taken as ours)
		ncpu=$(nproc 2>/dev/null || echo 1)
		slots=${jobs:-$ncpu}
		if [ -n "$sshlogin" ]; then
			slots=$(printf '%s\n' "$sshlogin" | tr ',' '\n' | awk -v j="$jobs" -v d="$slots" '
				NF { if (j == "" && match($0, /^[0-9]+\//)) s += substr($0, 1, RLENGTH - 1); else s += d }
				END { print (s > 0 ? s : 1) }')
		fi
		chunk=$((total / (4 * slots)))
		[ "$chunk" -ge 1 ] || chunk=1
	fi
	awk -v t="$total" -v k="$chunk" 'BEGIN { for (a = 0; a < t; a += k) print a ":" (a + k < t ? a + k : t) }' > "$out/jobs"
	printf '%s\n' "$id" > "$out/campaign.id"
fi
mkdir -p "$out/parts"
njobs=$(wc -l < "$out/jobs")
before=0
[ -f "$out/joblog" ] && before=$(wc -l < "$out/joblog")

# parallel's arguments; -q quotes the command's words for the shell (also over ssh)
set -- --will-cite -q --joblog "$out/joblog" --results "$out/parts/{#}.rows" --halt now,fail=1 -a "$out/jobs"
[ -z "$jobs" ] || set -- "$@" -j "$jobs"
[ "$resume" = no ] || set -- "$@" --resume-failed
[ -z "$sshlogin" ] || set -- "$@" --sshlogin "$sshlogin" --workdir "$PWD"
[ -z "$sshcmd" ] || set -- "$@" --ssh "$sshcmd"
set -f
old_ifs=$IFS
IFS='
'
for b in $basefiles; do set -- "$@" --basefile "$b"; done
IFS=$old_ifs
set +f
[ ! -t 2 ] || set -- "$@" --bar

echo "campaign: $total trials, $njobs jobs ($out/jobs) on ${sshlogin:-this machine}${jobs:+, $jobs at a time}" >&2
rc=0
status=""
if [ "$njobs" -gt 0 ]; then
	# an interrupt reaches parallel too, which stops its jobs; the shell reports once it has
	trap 'echo "campaign: interrupted; rerun with --resume to run only the jobs not done" >&2; exit 130' INT
	trap 'echo "campaign: terminated; rerun with --resume to run only the jobs not done" >&2; exit 143' TERM
	parallel "$@" "$tool" campaign "$file" --trials {} --rows || rc=$?
	trap - INT TERM
fi
# A job the joblog records as done must have left its whole part: every row of its trials and a
# newline at the end. One that could not (a full disk, an I/O error while its rows were written)
# is recorded as failed in the joblog, so that --resume runs it again once the cause is fixed.
incomplete=$(awk -F'\t' 'NR == FNR { split($0, r, ":"); size[FNR] = r[2] - r[1]; next }
	FNR > 1 && $7 == 0 && $8 == 0 { print $1, size[$1] }' "$out/jobs" "$out/joblog" 2>/dev/null |
	while read -r seq want; do
		p=$out/parts/$seq.rows
		if [ ! -f "$p" ] || [ -n "$(tail -c 1 "$p")" ] || [ "$(wc -l < "$p")" -ne "$want" ]; then echo "$seq"; fi
	done)
if [ -n "$incomplete" ]; then
	awk -F'\t' -v OFS='\t' -v bad=" $(echo $incomplete) " 'FNR > 1 && index(bad, " " $1 " ") && $7 == 0 { $7 = 1 } { print }' \
		"$out/joblog" > "$out/joblog.new" && mv -f "$out/joblog.new" "$out/joblog"
	for seq in $incomplete; do
		echo "campaign: job $seq (trials $(sed -n "${seq}p" "$out/jobs")): its part $out/parts/$seq.rows is incomplete (a full disk or an I/O error?); recorded as failed" >&2
	done
	echo "campaign: rerun with --resume once the cause is fixed: only the failed and missing jobs run again" >&2
	exit 1
fi
if [ "$rc" -ne 0 ]; then
	# the job that failed (a nonzero exit of its own, not one parallel stopped), else any
	awk -F'\t' -v from="$before" 'FNR > 1 && FNR > from && ($7 != 0 || $8 != 0) {
			if ($7 > 0 && $8 == 0) { print $1, $2, $7; found = 1; exit }
			if (!any) any = $1 " " $2 " " $7 "/" $8 }
		END { if (!found && any) print any }' "$out/joblog" > "$out/failed" || true
	if read -r seq host status < "$out/failed"; then
		echo "campaign: job $seq (trials $(sed -n "${seq}p" "$out/jobs")) on $host failed (status $status):" >&2
		sed 's/^/  /' "$out/parts/$seq.rows.err" 2>/dev/null | head -n 20 >&2 || true
	else
		echo "campaign: parallel stopped (status $rc) before every job was done" >&2
	fi
	rm -f "$out/failed"
	done_jobs=$(awk -F'\t' 'NR > 1 && $7 == 0 && $8 == 0 && !($1 in n) { n[$1] = 1; c++ } END { print c + 0 }' "$out/joblog" 2>/dev/null || echo 0)
	echo "campaign: $done_jobs of $njobs jobs done; rerun with --resume to run only the rest" >&2
	case "$status" in [1-9] | [1-9][0-9] | 1[0-9][0-9] | 2[0-4][0-9] | 25[0-5]) exit "$status" ;; esac
	exit 1
fi

# the parts in job order (each seq's output file), merged and summarised
seq=1
set --
while [ "$seq" -le "$njobs" ]; do
	set -- "$@" "$out/parts/$seq.rows"
	seq=$((seq + 1))
done
merged=0
sh "$here/campaign_merge.sh" "$tool" "$file" "$out" "$@" || merged=$?
[ "$merged" -le 1 ] || exit "$merged" # 1: merged, but some trials' runs faulted (said above)

# trials run now: the jobs this run's joblog lines record as done
ran=$(awk -F'\t' -v from="$before" 'NR == FNR { split($0, r, ":"); size[FNR] = r[2] - r[1]; next }
	FNR > from && FNR > 1 && $7 == 0 && $8 == 0 { s += size[$1] } END { print s + 0 }' "$out/jobs" "$out/joblog" 2>/dev/null || echo 0)
[ "$njobs" -gt 0 ] || ran=0
awk -v t="$total" -v r="$ran" -v s="$start" -v e="$(now)" -v o="$out" 'BEGIN {
	w = e - s; if (w <= 0) w = 1e-9
	printf "campaign: %d trials", t
	if (r != t) printf " (%d run now, %d done before)", r, t - r
	printf " in %.2f s, %.1f trials/s -> %s/trials.csv, %s/summary.csv\n", w, r / w, o, o }'
exit "$merged"
