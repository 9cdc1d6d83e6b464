# tests/lib/slurm.sh - a private single-node Slurm cluster for a test
# (tests/fem/010-slurm.sh, tests/calib/004-slurm.sh): munged with a key
# generated in the test's directory, slurmctld and slurmd with a
# slurm.conf written there, addresses 127.0.0.1, ports picked free, run as
# root, stopped by a trap on exit.  Source it after common.sh and call
# slurm_start: it skips the test without Slurm or root, fails when the
# cluster does not come up in 30 s, and exports SLURM_CONF.  slurm_check
# alone skips the test early, before it does work of its own.
# slurm_fast_wait (after slurm_start) puts first on PATH an sbatch whose
# --wait polls squeue every 0.1 s, for tests whose program under test
# submits with sbatch --wait (calib -slurm).
slurm_port() { # slurm_port N: a free TCP port, from the test's pid
	_p=$(( 20000 + ($$ * 7 + $1 * 131) % 20000 ))
	while ss -ltn 2>/dev/null | grep -q ":$_p "; do _p=$((_p + 1)); done
	echo $_p
}
slurm_stop() {
	for _p in $slurm_pids; do kill "$_p" 2>/dev/null; done
	# up to 0.5 s for the daemons to end (polled), then SIGKILL
	_i=0
	while [ $_i -lt 10 ]; do
		_alive=""
		for _p in $slurm_pids; do kill -0 "$_p" 2>/dev/null && _alive=1; done
		[ -n "$_alive" ] || break
		sleep 0.05
		_i=$((_i + 1))
	done
	for _p in $slurm_pids; do kill -9 "$_p" 2>/dev/null; done
	return 0
}
slurm_check() {
	for _t in sbatch squeue scontrol sinfo slurmctld slurmd munged; do
		command -v $_t >/dev/null 2>&1 || [ -x /usr/sbin/$_t ] ||
			skip "Slurm is not installed (no $_t; apt-get install slurm-wlm munge)"
	done
	[ "$(id -u)" -eq 0 ] || skip "a private Slurm cluster needs root (slurmd runs jobs as their user)"
	PATH=$PATH:/usr/sbin
}
slurm_start() {
	slurm_check
	_D=$PWD
	_ctl=$(slurm_port 1)
	_dp=$(slurm_port 2)
	[ "$_dp" != "$_ctl" ] || _dp=$((_ctl + 1))
	mkdir -p munge state spool log
	dd if=/dev/urandom of=munge/munge.key bs=1024 count=1 2>/dev/null
	chmod 700 munge
	chmod 400 munge/munge.key
	slurm_pids=""
	trap slurm_stop EXIT INT TERM
	munged --foreground --force --key-file="$_D/munge/munge.key" --socket="$_D/munge/socket" \
		--pid-file="$_D/munge/pid" --log-file="$_D/munge/log" --seed-file="$_D/munge/seed" \
		>munge/out 2>&1 &
	slurm_pids="$slurm_pids $!"
	_host=$(hostname -s)
	# MinJobAge: sbatch --wait (calib -slurm) polls every 2 s, and spaces
	# its polls out to 8, then 32 s, only while they stay under half of
	# MinJobAge (so that a finished job is not purged unseen); a job is
	# kept 5 s after it ends, polled every 2 s (300 had the polls wait up
	# to 32 s after a job of a few seconds); batch_sched_delay=0: a job
	# submitted is scheduled at once, not up to 3 s later (with both, the
	# Slurm half of calib/004 went from 71 to 52 s; slurm_fast_wait's
	# sbatch polls every 0.1 s, well under MinJobAge).  CPUs=4 on this
	# 2-core machine (config_overrides: slurmd takes the configured count):
	# an array of 4 short tasks (calib/004's points, tile/004's tiles)
	# starts as one wave rather than two, each wave waiting up to 1 s for
	# slurmctld's scheduling pass
	cat >slurm.conf <<C
ClusterName=testcluster
SlurmctldHost=$_host(127.0.0.1)
SlurmctldPort=$_ctl
SlurmdPort=$_dp
AuthType=auth/munge
AuthInfo=socket=$_D/munge/socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$_D/state
SlurmdSpoolDir=$_D/spool
SlurmctldPidFile=$_D/slurmctld.pid
SlurmdPidFile=$_D/slurmd.pid
SlurmctldLogFile=$_D/log/slurmctld.log
SlurmdLogFile=$_D/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SchedulerParameters=batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
SlurmdParameters=config_overrides
ReturnToService=2
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
MinJobAge=5
NodeName=$_host NodeAddr=127.0.0.1 CPUs=4 State=UNKNOWN
PartitionName=test Nodes=$_host Default=YES MaxTime=INFINITE State=UP
C
	SLURM_CONF=$_D/slurm.conf
	export SLURM_CONF
	_i=0
	while [ ! -S munge/socket ]; do
		_i=$((_i + 1)); [ $_i -lt 100 ] || fail "munged did not start: $(cat munge/log 2>/dev/null)"
		sleep 0.1
	done
	slurmctld -D -i -f "$_D/slurm.conf" >log/slurmctld.out 2>&1 &
	slurm_pids="$slurm_pids $!"
	slurmd -D -f "$_D/slurm.conf" -N "$_host" >log/slurmd.out 2>&1 &
	slurm_pids="$slurm_pids $!"
	_i=0
	until sinfo -h -o '%T' 2>/dev/null | grep -q '^idle'; do
		_i=$((_i + 1))
		[ $_i -lt 300 ] || fail "the cluster did not come up in 30 s: $(tail -n 5 log/slurmctld.log log/slurmd.log 2>&1)"
		sleep 0.1
	done
}

# slurm_fast_wait: an sbatch first on PATH (in bin/ here) that is Slurm's
# own for every option but --wait (-W): it submits without it and waits
# itself, polling squeue every 0.1 s until the job (every task of an
# array) has left the queue, and exits as sbatch --wait does, with the
# highest exit code of the job's tasks (a task killed by a signal: 1).
# Slurm's sbatch --wait sleeps 2 s before each poll, and with short jobs
# those sleeps were most of a test's wall time (calib/004: four batches of
# two sbatch --wait each).  A program that forgets --wait still gets an
# sbatch that returns at once, so the test still sees it.
slurm_fast_wait() {
	_real=$(command -v sbatch) || fail "no sbatch"
	mkdir -p bin
	cat >bin/sbatch <<W
#!/bin/sh
# sbatch --wait with 0.1 s polls (tests/lib/slurm.sh, slurm_fast_wait)
w=""
for a do
	shift
	case \$a in --wait|-W) w=yes ;; *) set -- "\$@" "\$a" ;; esac
done
[ -n "\$w" ] || exec '$_real' "\$@"
out=\$('$_real' "\$@") || exit \$?
[ -z "\$out" ] || echo "\$out"
id=\${out##* }
id=\${id%%;*}
case \$id in ''|*[!0-9]*) echo "sbatch: no job id in \\"\$out\\"" >&2; exit 1 ;; esac
while [ -n "\$(squeue -h -j "\$id" -o %i 2>/dev/null)" ]; do
	sleep 0.1
done
scontrol -o show job "\$id" | awk '{ for (i = 1; i <= NF; i++) if (\$i ~ /^ExitCode=/) {
		split(substr(\$i, 10), e, ":"); c = e[2] + 0 ? 1 : e[1] + 0; if (c > m) m = c } }
	END { exit m }'
W
	chmod +x bin/sbatch
	PATH=$PWD/bin:$PATH
}
