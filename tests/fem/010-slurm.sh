# fem on a real Slurm cluster: a private single-node cluster on this
# machine (tests/lib/slurm.sh: munged with a key generated here, slurmctld
# and slurmd with a slurm.conf written into this test's directory,
# addresses 127.0.0.1, ports picked free, run as root, stopped by a trap)
# runs the 2 focus x 2 dose sweep of
# 003-sweep.sh through DIR/submit.sh (the per-focus images as one job
# array, the points as another with a dependency on it, two points per
# task), then fem -collect; fem.dat must be byte-identical to the local
# make -j2 run's.  Bounded: the cluster must come up in 30 s and the jobs
# finish in 120 s (squeue polled).  Without Slurm (no sbatch, slurmctld,
# slurmd or munged) or without root, the test skips.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/slurm.sh"
built measure
slurm_check
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
# the local sweep runs while the cluster comes up
fem "$@" -j 2 -d local 2>local.err &
local=$!
slurm_start
wait $local || fail "local sweep failed: $(cat local.err)"
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
