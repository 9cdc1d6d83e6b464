# sample3D -tile -slurm on a real (private, single-node) Slurm cluster
# (tests/lib/slurm.sh): the 2 x 2 tiles of a small contact array are
# written as a job array (tiles.sbatch) and a stitching job after it
# (submit.sh), nothing run by sample3D itself; after the jobs end
# (squeue polled, at most 120 s) the stitched curves.plot and image.cont
# must be byte-identical to those of the local make -j2 run.  Without
# Slurm or root the test skips.
. "$TOP/tests/lib/common.sh"
. "$TOP/tests/lib/slurm.sh"
built sample3D stitch
cat >mask.in <<'M'
wavelength 0.365
na 0.6
sigma 0.5
background dark
window -2 2 -2 2
rect -1.25 -1.25 -0.75 -0.75
rect 0.75 -1.25 1.25 -0.75
rect -0.25 -0.25 0.25 0.25
rect 0.75 0.75 1.25 1.25
grid 41 41
contour image.cont
M
sed 's/nz 300/nz 30/' "$TOP/examples/array40/resist.in" >resist.in
set -- -q -if "$PWD/mask.in" -bf "$PWD/resist.in" -et 60 -last -tile 2 -halo 1
mkdir local cluster
# the local run goes on while the cluster comes up
(cd local && sample3D "$@" -j 2) 2>local.err &
local=$!
(cd cluster && sample3D "$@" -slurm) 2>err.txt || fail "sample3D -slurm: $(cat err.txt)"
[ -f cluster/tiles/tiles.sbatch ] && [ -x cluster/tiles/submit.sh ] ||
	fail "sample3D -slurm wrote no job array"
[ ! -e cluster/tiles/curves.plot ] || fail "sample3D -slurm ran the tiles itself"
slurm_start
wait $local || fail "local tiled run: $(cat local.err)"
cluster/tiles/submit.sh >submit.out 2>&1 || fail "submit.sh failed: $(cat submit.out)"
i=0
while [ -n "$(squeue -h 2>/dev/null)" ]; do
	i=$((i + 1))
	[ $i -lt 1200 ] || fail "the jobs did not end in 120 s: $(squeue 2>&1)"
	sleep 0.1
done
same cluster/tiles/curves.plot local/tiles/curves.plot
same cluster/tiles/image.cont local/tiles/image.cont
exit 0
