#!/bin/sh
# campaign_parallel.sh — `make check-campaign` (docs/campaigns.md): scripts/campaign.sh spreads a
# campaign's trials over GNU parallel, and however it splits, interrupts and resumes them,
# trials.csv and summary.csv are byte for byte those of the in-process run
# (`TOOL campaign FILE --out --summary`, the -j1 reference):
#   1. 2 local jobs;
#   2. 2 jobs over ssh to a private sshd on 127.0.0.1 (a free port from 22022 up, its own host key,
#      client key and config in the temporary folder; the system's sshd and ~/.ssh are not
#      touched): every job's joblog line names that login;
#   3. a run killed (SIGTERM to its process group) once half its jobs are in the joblog, then
#      resumed with --resume: no job the joblog records as done runs again, every other job runs
#      exactly once.
# The ssh step needs /usr/sbin/sshd (Debian's openssh-server, scripts/deps.sh installs it) and
# ssh-keygen; when sshd cannot be started the test fails, saying why; it never skips.
# Everything lives in one mktemp folder, removed on exit with sshd stopped, also on failure.
#   campaign_parallel.sh TOOL CAMPAIGN_FILE
set -eu
if [ $# -ne 2 ]; then
	echo "usage: campaign_parallel.sh TOOL CAMPAIGN_FILE" >&2
	exit 2
fi
tool=$1
file=$2
driver=$(dirname "$0")/../scripts/campaign.sh
work=$(mktemp -d)
sshd_pid=""
bg=""
cleanup() {
	# a killed-run test that failed half-way: its process group (never ours: checked below)
	if [ -n "$bg" ]; then kill -s TERM -- -"$bg" 2>/dev/null || true; fi
	if [ -n "$sshd_pid" ]; then
		kill "$sshd_pid" 2>/dev/null || true
		wait "$sshd_pid" 2>/dev/null || true
	fi
	rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
fail() {
	echo "campaign: FAILED: $*"
	exit 1
}
same() { # what, run folder: its trials.csv and summary.csv against the reference's
	for f in trials.csv summary.csv; do
		if ! cmp -s "$work/ref/$f" "$2/$f"; then
			echo "campaign: $1: $f differs from the -j1 run's:"
			diff "$work/ref/$f" "$2/$f" | head -n 6 || true
			fail "$1"
		fi
	done
}
drive() { # name, campaign.sh arguments after FILE OUTDIR: runs it, its output in $work/NAME.txt
	name=$1
	shift
	if ! sh "$driver" "$file" "$work/$name" --tool "$tool" "$@" > "$work/$name.txt" 2>&1; then
		sed 's/^/  /' "$work/$name.txt"
		fail "scripts/campaign.sh $file OUTDIR $* failed"
	fi
}

# the -j1 reference: every trial in process
[ -r "$file" ] || fail "$file: no such campaign file"
mkdir "$work/ref"
"$tool" campaign "$file" --out "$work/ref/trials.csv" --summary "$work/ref/summary.csv" > "$work/ref/table.txt" ||
	fail "the in-process run ($tool campaign $file --out --summary) failed"
total=$("$tool" campaign "$file" --count)
[ "$total" -ge 8 ] || fail "$file has $total trials; the split and the kill half-way need at least 8"

# 1. two local jobs
drive local --jobs 2
same "2 local jobs" "$work/local"

# 2. two jobs over ssh to 127.0.0.1
[ -x /usr/sbin/sshd ] || fail "ssh loopback: /usr/sbin/sshd is missing (sh scripts/deps.sh installs openssh-server)"
command -v ssh-keygen > /dev/null 2>&1 || fail "ssh loopback: ssh-keygen is missing (Debian's openssh-client)"
s=$work/ssh
mkdir "$s"
ssh-keygen -q -t ed25519 -N '' -C handspring-test-host -f "$s/host_key"
ssh-keygen -q -t ed25519 -N '' -C handspring-test-client -f "$s/id"
cp "$s/id.pub" "$s/authorized_keys"
# the privilege separation folder root's sshd wants
if [ "$(id -u)" = 0 ]; then mkdir -p /run/sshd; fi
user=$(id -un)
port=22022
while :; do
	cat > "$s/sshd_config" <<-EOF
	Port $port
	ListenAddress 127.0.0.1
	HostKey $s/host_key
	PidFile $s/sshd.pid
	AuthorizedKeysFile $s/authorized_keys
	StrictModes no
	UsePAM no
	PubkeyAuthentication yes
	PasswordAuthentication no
	KbdInteractiveAuthentication no
	PermitRootLogin prohibit-password
	AllowUsers $user
	EOF
	rm -f "$s/sshd.log"
	/usr/sbin/sshd -f "$s/sshd_config" -D -E "$s/sshd.log" &
	sshd_pid=$!
	# sshd writes its pid file once it listens, and exits when it cannot (the port taken)
	tries=0
	while [ ! -s "$s/sshd.pid" ] && kill -s 0 "$sshd_pid" 2>/dev/null && [ "$tries" -lt 200 ]; do
		sleep 0.05
		tries=$((tries + 1))
	done
	[ ! -s "$s/sshd.pid" ] || break
	kill "$sshd_pid" 2>/dev/null || true
	wait "$sshd_pid" 2>/dev/null || true
	sshd_pid=""
	if ! grep -q 'Address already in use' "$s/sshd.log" 2>/dev/null; then
		sed 's/^/  /' "$s/sshd.log" 2>/dev/null || true
		fail "ssh loopback: cannot start /usr/sbin/sshd -f $s/sshd_config (as $user, log above)"
	fi
	port=$((port + 1))
	[ "$port" -lt 22122 ] || fail "ssh loopback: no free port in 22022..22121 for sshd"
done
printf '[127.0.0.1]:%s %s\n' "$port" "$(cut -d' ' -f1,2 "$s/host_key.pub")" > "$s/known_hosts"
cat > "$s/config" <<EOF
Host 127.0.0.1
	Port $port
	IdentityFile $s/id
	IdentitiesOnly yes
	UserKnownHostsFile $s/known_hosts
	StrictHostKeyChecking yes
	BatchMode yes
	LogLevel ERROR
EOF
if ! ssh -F "$s/config" "$user@127.0.0.1" true > "$s/probe.txt" 2>&1; then
	sed 's/^/  /' "$s/probe.txt" "$s/sshd.log"
	fail "ssh loopback: sshd runs on 127.0.0.1:$port but ssh -F $s/config $user@127.0.0.1 fails"
fi
drive ssh --sshlogin "2/$user@127.0.0.1" --ssh "ssh -F $s/config"
awk -F'\t' -v h="$user@127.0.0.1" 'NR > 1 && $2 != h { print "  job " $1 " ran on " $2; bad = 1 }
	END { exit bad }' "$work/ssh/joblog" || fail "ssh loopback: jobs ran elsewhere than on $user@127.0.0.1"
same "2 jobs over ssh to $user@127.0.0.1:$port" "$work/ssh"

# 3. killed half-way, then resumed
chunk=$((total / 20))
[ "$chunk" -ge 1 ] || chunk=1
njobs=$(((total + chunk - 1) / chunk))
half=$((njobs / 2))
jl=$work/kill/joblog
# its own session, hence its own process group, which the kill below reaches whole
setsid sh "$driver" "$file" "$work/kill" --tool "$tool" --jobs 2 --chunk "$chunk" > "$work/kill.txt" 2>&1 &
bg=$!
while :; do
	# the joblog: a header line, then one line per job finished
	n=0
	[ ! -f "$jl" ] || n=$(($(wc -l < "$jl") - 1))
	[ "$n" -lt "$half" ] || break
	if ! kill -s 0 "$bg" 2>/dev/null; then
		bg=""
		sed 's/^/  /' "$work/kill.txt"
		fail "kill and resume: the run ended with $n of $njobs jobs in its joblog, before the kill"
	fi
	sleep 0.02
done
[ "$(ps -o pgid= -p "$bg" | tr -d ' ')" = "$bg" ] || fail "kill and resume: setsid gave the run no process group of its own"
kill -s TERM -- -"$bg"
wait "$bg" || true
# parallel stops its jobs before it exits: wait for the whole group to be gone
while kill -s 0 -- -"$bg" 2>/dev/null; do sleep 0.02; done
bg=""
awk -F'\t' 'NR > 1 && $7 == 0 && $8 == 0 { print $1 }' "$jl" | sort -n > "$work/done_before"
k=$(wc -l < "$work/done_before")
{ [ "$k" -gt 0 ] && [ "$k" -lt "$njobs" ]; } || fail "kill and resume: $k of $njobs jobs done at the kill"
[ ! -f "$work/kill/trials.csv" ] || fail "kill and resume: the killed run wrote trials.csv"
lines=$(wc -l < "$jl")
cp "$jl" "$work/joblog_at_kill"
# a witness besides the joblog: the done jobs' output files, which a rerun would write again
while read -r seq; do stat -c '%n %y' "$work/kill/parts/$seq.rows"; done < "$work/done_before" > "$work/parts_at_kill"
drive kill --jobs 2 --resume
head -n "$lines" "$jl" | cmp -s - "$work/joblog_at_kill" ||
	fail "kill and resume: the resumed run did not keep the joblog's lines from before the kill"
while read -r seq; do stat -c '%n %y' "$work/kill/parts/$seq.rows"; done < "$work/done_before" |
	cmp -s - "$work/parts_at_kill" || fail "kill and resume: the output of jobs done before the kill was written again"
# every job done before the kill appears once (its old line); every other job ran exactly once now
awk -F'\t' -v from="$lines" -v n="$njobs" 'NR == FNR { before[$1] = 1; next }
	FNR > 1 { lines[$1]++ }
	FNR > from && (($1 in before) || $7 != 0 || $8 != 0) { print "  rerun or failed: " $0; bad = 1 }
	FNR > from && !($1 in before) { now[$1]++ }
	END {
		for (i = 1; i <= n; i++) {
			if ((i in before) && lines[i] != 1) { print "  job " i " done before the kill has " lines[i] " joblog lines"; bad = 1 }
			if (!(i in before) && now[i] != 1) { print "  job " i " ran " now[i] + 0 " times after resuming"; bad = 1 }
		}
		exit bad
	}' "$work/done_before" "$jl" || fail "kill and resume: the joblog shows jobs rerun or not run ($jl)"
same "killed after $k of $njobs jobs, resumed" "$work/kill"

echo "campaign: parallel local, ssh loopback, kill and resume: all equal to -j1 ($total trials)"
