# fem on a real Slurm cluster: a single-node cluster on this machine (munged
# with a key generated here, slurmctld and slurmd with a slurm.conf written
# into this test's directory, addresses 127.0.0.1, ports picked free, run
# as root, stopped by a trap) runs the 2 focus x 2 dose sweep of
# 003-sweep.sh through DIR/submit.sh (the per-focus images as one job
# array, the points as another with a dependency on it, two points per
# task), then fem -collect; fem.dat must be byte-identical to the local
# make -j2 run's.  Bounded: the cluster must come up in 30 s and the jobs
# finish in 120 s (squeue polled).  Without Slurm (no sbatch, slurmctld,
# slurmd or munged) or without root, the test skips.
. "$TOP/tests/lib/common.sh"
built measure
for t in sbatch squeue scontrol slurmctld slurmd munged; do
	command -v $t >/dev/null 2>&1 || [ -x /usr/sbin/$t ] || skip "Slurm is not installed (no $t; apt-get install slurm-wlm munge)"
done
[ "$(id -u)" -eq 0 ] || skip "a private Slurm cluster needs root (slurmd runs jobs as their user)"
PATH=$PATH:/usr/sbin
E=$TOP/examples/contact
D=$PWD

cat >mask.in <<'M'
wavelength 0.436
na 0.28
sigma 0.5
window -1.5 1.5 -1.5 1.5
grid 21 21
background dark
rect -0.6 -0.6 0.6 0.6
M
sed 's/^grid .*/grid nz 60/' "$E/resist.in" >resist.in
set -- -if "$D/mask.in" -bf "$D/resist.in" -et 60 -dose 80,100 -focus -0.5,0.5 \
	-measure "-rel 10 -hole 0 0" -q
fem "$@" -j 2 -d local || fail "local sweep failed"

# ports: from the test's pid, moved on while ss shows them taken
port() {
	p=$(( 20000 + ($$ * 7 + $1 * 131) % 20000 ))
	while ss -ltn 2>/dev/null | grep -q ":$p "; do
		p=$((p + 1))
	done
	echo $p
}
ctlport=$(port 1)
dport=$(port 2)
[ "$dport" != "$ctlport" ] || dport=$((ctlport + 1))

mkdir -p munge state spool log
# the cluster's own munge key and socket: never the machine's
dd if=/dev/urandom of=munge/munge.key bs=1024 count=1 2>/dev/null
chmod 700 munge
chmod 400 munge/munge.key
pids=""
stop() {
	for p in $pids; do kill "$p" 2>/dev/null; done
	sleep 0.5
	for p in $pids; do kill -9 "$p" 2>/dev/null; done
	return 0
}
trap stop EXIT INT TERM
munged --foreground --force --key-file="$D/munge/munge.key" --socket="$D/munge/socket" \
	--pid-file="$D/munge/pid" --log-file="$D/munge/log" --seed-file="$D/munge/seed" \
	>munge/out 2>&1 &
pids="$pids $!"

host=$(hostname -s)
cat >slurm.conf <<C
ClusterName=femtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctlport
SlurmdPort=$dport
AuthType=auth/munge
AuthInfo=socket=$D/munge/socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$D/state
SlurmdSpoolDir=$D/spool
SlurmctldPidFile=$D/slurmctld.pid
SlurmdPidFile=$D/slurmd.pid
SlurmctldLogFile=$D/log/slurmctld.log
SlurmdLogFile=$D/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
MinJobAge=300
NodeName=$host NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
C
SLURM_CONF=$D/slurm.conf
export SLURM_CONF
i=0
while [ ! -S munge/socket ]; do
	i=$((i + 1)); [ $i -lt 100 ] || fail "munged did not start: $(cat munge/log 2>/dev/null)"
	sleep 0.1
done
slurmctld -D -i -f "$D/slurm.conf" >log/slurmctld.out 2>&1 &
pids="$pids $!"
slurmd -D -f "$D/slurm.conf" -N "$host" >log/slurmd.out 2>&1 &
pids="$pids $!"
i=0
until sinfo -h -o '%T' 2>/dev/null | grep -q '^idle'; do
	i=$((i + 1))
	[ $i -lt 300 ] || fail "the cluster did not come up in 30 s: $(tail -n 5 log/slurmctld.log log/slurmd.log 2>&1)"
	sleep 0.1
done

fem "$@" -d cluster -slurm -chunk 2 || fail "fem -slurm failed"
[ -x cluster/submit.sh ] && [ -s cluster/fem.sbatch ] || fail "submit.sh or fem.sbatch missing"
grep -q '^#SBATCH --array=0-1$' cluster/fem.sbatch || fail "4 points in chunks of 2: expected --array=0-1"
[ ! -e cluster/fem.dat ] && [ ! -e cluster/f-0.5/image.cont ] || fail "fem -slurm ran something itself"
cluster/submit.sh >submit.out 2>&1 || fail "submit.sh failed: $(cat submit.out)"
i=0
while [ -n "$(squeue -h -o %i 2>/dev/null)" ]; do
	i=$((i + 1))
	[ $i -lt 1200 ] || fail "the jobs did not finish in 120 s: $(squeue 2>&1)"
	sleep 0.1
done
fem -collect -d cluster -q || fail "fem -collect failed: $(cat cluster/slurm/*.out 2>/dev/null | head -5)"
same cluster/fem.dat local/fem.dat
exit 0
