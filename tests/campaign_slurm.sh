#!/bin/sh
# campaign_slurm.sh — `make check-slurm` (docs/campaigns.md; not part of make check):
# scripts/campaign.sbatch on a single-node Slurm started for the test from the Debian packages
# (slurmctld, slurmd, slurm-client, munge), all of it private: munged on its own socket and key,
# slurmctld and slurmd in the foreground on free ports, with a slurm.conf for this host (2 CPUs,
# partition debug, proctrack/linuxproc, task/none, select/cons_tres, no cgroups, no accounting),
# state, spool and logs in one mktemp folder; SLURM_CONF points the clients at it. The system's
# /etc/slurm and /etc/munge are not used, and no daemon is left running.
#   1. a 5-task array (`sbatch --array=0-4`) and the merge job after it (`--dependency=afterok`,
#      `sbatch --wait`): trials.csv and summary.csv byte for byte the in-process run's;
#   2. one part removed and the whole array submitted again: only that task runs (the others find
#      their part done), and the merge gives the same files again.
# Needs root (slurmd starts the jobs) and the packages: apt-get install slurmctld slurmd
# slurm-client munge. Run from the top folder (the jobs find scripts/ and the tool from there).
#   campaign_slurm.sh TOOL CAMPAIGN_FILE
set -eu
if [ $# -ne 2 ]; then
	echo "usage: campaign_slurm.sh TOOL CAMPAIGN_FILE" >&2
	exit 2
fi
tool=$1
file=$2
fail() {
	echo "slurm: FAILED: $*"
	exit 1
}
[ "$(id -u)" = 0 ] || fail "needs root (slurmd runs the jobs)"
for c in munged slurmctld slurmd sbatch scontrol scancel sinfo; do
	command -v "$c" > /dev/null 2>&1 || fail "$c is missing: apt-get install slurmctld slurmd slurm-client munge"
done
[ -f scripts/campaign.sbatch ] || fail "run from the top folder (no scripts/campaign.sbatch here)"
work=$(mktemp -d)
chmod 755 "$work"
pids=""
cleanup() {
	for p in $pids; do kill "$p" 2> /dev/null || true; done
	for p in $pids; do wait "$p" 2> /dev/null || true; done
	rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
# poll CONDITION (a shell command) every 0.2 s for at most SECONDS
wait_for() { # seconds, condition
	n=$(($1 * 5))
	while ! eval "$2" > /dev/null 2>&1; do
		n=$((n - 1))
		[ "$n" -gt 0 ] || return 1
		sleep 0.2
	done
}
show() { # the last lines of each log named
	for f in "$@"; do
		[ -f "$f" ] || continue
		echo "  --- $f"
		tail -n 15 "$f" | sed 's/^/  /'
	done
}

# the -j1 reference
mkdir "$work/ref"
"$tool" campaign "$file" --out "$work/ref/trials.csv" --summary "$work/ref/summary.csv" > /dev/null ||
	fail "the in-process run ($tool campaign $file --out --summary) failed"
total=$("$tool" campaign "$file" --count)
tasks=5
[ "$total" -ge "$tasks" ] || tasks=$total

# munged: its own key and socket
m=$work/munge
mkdir -m 700 "$m"
if command -v mungekey > /dev/null 2>&1; then
	mungekey -c -k "$m/munge.key"
else
	dd if=/dev/urandom of="$m/munge.key" bs=1024 count=1 2> /dev/null
fi
chmod 600 "$m/munge.key"
chmod 711 "$m"
munged -F -f --socket="$m/munge.sock" --key-file="$m/munge.key" --pid-file="$m/munged.pid" \
	--seed-file="$m/munged.seed" --log-file="$m/munged.log" > "$m/out.txt" 2>&1 &
pids="$pids $!"
wait_for 10 "munge -S '$m/munge.sock' -n" || { show "$m/out.txt"; fail "munged did not start"; }

# slurm.conf for this host; ports tried from 26817 up until slurmctld can bind them
host=$(hostname)
mkdir "$work/state" "$work/spool" "$work/logs"
export SLURM_CONF="$work/slurm.conf"
port=26817
while :; do
	cat > "$SLURM_CONF" <<-EOF
	ClusterName=hscheck
	SlurmctldHost=$host(127.0.0.1)
	SlurmctldPort=$port
	SlurmdPort=$((port + 1))
	SlurmUser=root
	SlurmdUser=root
	AuthType=auth/munge
	CredType=cred/munge
	AuthInfo=socket=$m/munge.sock
	StateSaveLocation=$work/state
	SlurmdSpoolDir=$work/spool
	SlurmctldPidFile=$work/slurmctld.pid
	SlurmdPidFile=$work/slurmd.pid
	SlurmctldLogFile=$work/slurmctld.log
	SlurmdLogFile=$work/slurmd.log
	MailProg=/bin/true
	ProctrackType=proctrack/linuxproc
	TaskPlugin=task/none
	JobAcctGatherType=jobacct_gather/none
	AccountingStorageType=accounting_storage/none
	JobCompType=jobcomp/none
	SelectType=select/cons_tres
	SelectTypeParameters=CR_CPU
	MpiDefault=none
	SwitchType=switch/none
	ReturnToService=2
	SchedulerType=sched/builtin
	SchedulerParameters=sched_interval=1
	NodeName=$host NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
	PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
	EOF
	rm -f "$work/slurmctld.log"
	slurmctld -D -f "$SLURM_CONF" > "$work/slurmctld.out" 2>&1 &
	ctld=$!
	# up once it answers a ping; gone when it could not bind
	wait_for 20 "scontrol ping | grep -q 'is UP' || ! kill -s 0 $ctld" || true
	if scontrol ping 2> /dev/null | grep -q 'is UP'; then
		pids="$pids $ctld"
		break
	fi
	kill "$ctld" 2> /dev/null || true
	wait "$ctld" 2> /dev/null || true
	if ! grep -qi 'address already in use' "$work/slurmctld.log" "$work/slurmctld.out" 2> /dev/null; then
		show "$work/slurmctld.out" "$work/slurmctld.log"
		fail "slurmctld -D -f $SLURM_CONF did not come up"
	fi
	port=$((port + 2))
	[ "$port" -lt 26917 ] || fail "no free port pair in 26817..26916 for slurmctld and slurmd"
done
slurmd -D -f "$SLURM_CONF" > "$work/slurmd.out" 2>&1 &
pids="$pids $!"
wait_for 30 "sinfo -h -o %t | grep -qx idle" || {
	show "$work/slurmd.out" "$work/slurmd.log" "$work/slurmctld.log"
	fail "slurmd did not register its node idle (sinfo: $(sinfo -h -o '%N %t' 2>&1))"
}

out=$work/out
run_array() { # what: the array, then the merge job after it, waited for
	jid=$(sbatch --parsable -o "$work/logs/%A_%a.out" --array=0-$((tasks - 1)) \
		scripts/campaign.sbatch "$file" "$out" "$tool") || fail "$1: sbatch refused the array"
	mid=$(sbatch --parsable -o "$work/logs/merge_$jid.out" --dependency="afterok:$jid" \
		scripts/campaign.sbatch --merge "$file" "$out" "$tool") || fail "$1: sbatch refused the merge job"
	# the merge job's end, or its dependency failing (a failed task: it would wait for ever);
	# Slurm keeps a finished job's record for MinJobAge (300 s)
	wait_for 120 "scontrol -o show job $mid | grep -qE 'JobState=(COMPLETED|FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY|PREEMPTED|BOOT_FAIL|DEADLINE) |Reason=DependencyNeverSatisfied'" || true
	state=$(scontrol -o show job "$mid" | sed -n 's/.*JobState=\([A-Z_]*\) Reason=\([A-Za-z_]*\).*/\1 (\2)/p')
	case "$state" in
	COMPLETED*) ;;
	*)
		scancel "$mid" 2> /dev/null || true
		show "$work"/logs/"$jid"_*.out "$work/logs/merge_$jid.out"
		fail "$1: the merge job $mid after array job $jid: $state"
		;;
	esac
	for f in trials.csv summary.csv; do
		if ! cmp -s "$work/ref/$f" "$out/$f"; then
			diff "$work/ref/$f" "$out/$f" | head -n 6
			fail "$1: $f differs from the -j1 run's"
		fi
	done
}
run_array "array of $tasks tasks"
first=$jid
# again after losing a part: only its task runs
rm -f "$out/parts/2.csv" "$out/trials.csv" "$out/summary.csv"
run_array "the array submitted again without part 2"
for i in $(seq 0 $((tasks - 1))); do
	if [ "$i" = 2 ]; then want="task 2 of $tasks: trials"; else want="task $i: .* is done already"; fi
	grep -q "$want" "$work/logs/${jid}_$i.out" || {
		show "$work/logs/${jid}_$i.out"
		fail "the array submitted again: task $i did not say '$want'"
	}
done
echo "slurm: array job $first ($tasks tasks) and its merge job, then the array again without one part: equal to -j1 ($total trials)"
