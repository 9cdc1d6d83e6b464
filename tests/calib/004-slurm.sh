# calib -slurm on a real (private, single-node) Slurm cluster
# (tests/lib/slurm.sh): a one-parameter fit (Mth of the 0.5 um contact on
# an 11 x 11 grid, 4 points made by fem at Mth 0.5, started from 0.502:
# two iterations, so two rounds of batches, each of images then points)
# whose every batch of simulations runs as fem's Slurm job arrays,
# submitted with sbatch --wait, gives calib.dat and resist.fit.in byte for
# byte as the same fit run locally with make -j 2.  Bounded by the
# runner's timeout.  Without Slurm or root the test skips.  The local fit
# runs while the cluster's jobs run.  sbatch --wait is Slurm's sbatch
# with the waiting done by slurm_fast_wait (tests/lib/slurm.sh), which
# polls squeue every 0.1 s where Slurm's sleeps 2 s a poll: those sleeps
# were most of the test's wall time (on one busy machine 27 s with them,
# 16 s without); a calib that did not pass --wait would still collect
# before the jobs end and fail here.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/slurm.sh"
slurm_check
cat >m.in <<'IN'
wavelength 0.365
na 0.6
sigma 0.5
background dark
window -1.2 1.2 -1.2 1.2
rect -0.25 -0.25 0.25 0.25
grid 11 11
resist thickness 1 index 1.7 planes 5
IN
cat >start.in <<'IN'
wavelength 0.365
resist thickness 1 index 1.7 dill 0.8 0.05 0.014
substrate 6.41 2.62
dose 80
develop mack 0.1 0.0001 0.502 5
grid nz 31
IN
# the data: the same model at Mth 0.5, its CDs as they come
sed 's/mack 0.1 0.0001 0.502 5/mack 0.1 0.0001 0.5 5/' start.in >truth.in
# the data are made while the cluster comes up
fem -q -if m.in -bf truth.in -et 60 -method fmm -focus -0.3,0.3 -dose 80,100 \
	-measure "-rel 5 -hole 0 0" -d truth -j 2 2>truth.err &
truth=$!
slurm_start
slurm_fast_wait
wait $truth || fail "fem on the truth failed: $(cat truth.err)"
cp truth/fem.dat meas.dat
set -- -if m.in -bf start.in -et 60 -data meas.dat -measure "-rel 5 -hole 0 0" \
	-free "develop 3 0.3:0.7" -q
calib "$@" -j 2 -d local 2>local.err &
local=$!
calib "$@" -slurm -d cluster 2>cluster.err || fail "calib -slurm failed: $(cat cluster.err)"
wait $local || fail "local calib failed: $(cat local.err)"
awk '$2 == "points" { n = $9 } END { exit !(n >= 2) }' local/calib.dat || fail "the fit took under two iterations"
ls cluster/runs/*/fem.sbatch >/dev/null 2>&1 || fail "calib -slurm wrote no job arrays"
same cluster/calib.dat local/calib.dat
same cluster/resist.fit.in local/resist.fit.in
exit 0
