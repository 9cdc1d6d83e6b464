#!/bin/sh
# calib - fits numbers of a resist file to measured CDs: Levenberg-Marquardt
# over fem(1) simulations, with the parameters' errors and correlations.
# See man/man1/calib.1.
#
#   calib -if mask.in -bf resist.in -et 60 -data measured.dat \
#         -measure "-rel 5 -hole 0 0" -free "develop 3 0.3:0.7" \
#         -free "resist 5 0.005:0.03" -j 2
#
# The numerics are calibfit(1)'s (no state: every call is told the values,
# the data and the simulations it needs); this script only runs fem on the
# trial resist files.  Each trial is a fem directory DIR/runs/ID named by
# the checksum of its resist file, holding that file and its results, so a
# rerun of the same command replays the fit from the finished runs
# (resumable) and a trial met twice is simulated once.  The images depend on
# the mask and the focus only: every run links them from the first run's
# directory, so splat runs once per focus for the whole fit.
set -eu

prog=calib
usage() {
	cat <<'U'
usage: calib -if mask.in -bf resist.in -et T -data measured.dat -measure "ARGS"
             -free "STATEMENT K LO:HI" [-free ...] [etch options]
             [-validate other.dat] [-accuracy [P|check]] [-d DIR] [-j N]
             [-slurm [-sbatch "OPTS"]] [-q]
  -if FILE      splat input file (the mask and the optics)
  -bf FILE      bleach input file (the resist) holding the starting values
  -et T         development time (s)
  -data FILE    measured CDs: lines "focus dose cd" (um, mJ/cm2, um)
  -measure ARGS measure's arguments giving the cd (at its first height),
                as fem takes them, e.g. "-rel 5 -hole 0 0"
  -free SPEC    "STATEMENT K LO:HI": fit the K-th number on the resist
                file's STATEMENT line within [LO, HI]; repeat per parameter
  -validate F   measured CDs not used in the fit: their rms with the result
  -accuracy [P] choose the image grid, nz and etch's resolution before the
                fit (fem -accuracy P at the middle measured point, the
                starting values) so that the CDs are within P % (default
                1), fit at that grid, and estimate the fitted CDs' error
                (fem -accuracy check on the result)
  -accuracy check  fit at the inputs' grids and estimate the fitted CDs'
                error there
  -d DIR        the fit's directory (default calib)
  -j N          simulations run at once (make -j N; default: the cores)
  -slurm        run each batch of simulations as Slurm job arrays (fem
                -slurm, sbatch --wait), DIR on a shared file system
  -sbatch OPTS  with -slurm: further sbatch options (e.g. "-p short")
  -q            quiet: no progress lines
  etch options passed to fem: -deloop [n] -dt T -seg L -smax R -smin R
              -rl L -linear -clip N -method ray|fmm -refine N -etch "OPTS"
              (default -method fmm)
  --help        this text
U
}
die() { echo "$prog: $*" >&2; exit 1; }
bad() { echo "$prog: $*; see calib --help" >&2; exit 2; }
say() { [ -n "$quiet" ] || echo "$prog: $*" >&2; }
need_val() { [ $# -ge 2 ] || bad "option $1 needs a value"; }

# Levenberg-Marquardt control (calib(1), "The fit"): the first damping,
# the most iterations (Jacobians), the consecutive rejected steps after
# which no downhill step is left, and the relative fall of the sum of
# squares below which an accepted step ends the fit.  A rejected step is
# tried again at half and a quarter of its length along the same
# direction (correlated parameters lie in a long curved valley, along
# which the Gauss-Newton direction points while a larger damping turns
# the step across it), then with the damping raised to at least 1.
LAMBDA0=0.001 MAXITER=30 MAXREJECT=4 SSRTOL=0.001

mask="" resist="" etchtime="" data="" margs="" validate="" dir=calib jobs=""
slurm="" sbopts="" quiet="" etchopts="" method="" etchx="" accuracy=""
nfree=0
frees=""
while [ $# -gt 0 ]; do
	case $1 in
	--help|-h) usage; exit 0 ;;
	-if) need_val "$@"; mask=$2; shift 2 ;;
	-bf) need_val "$@"; resist=$2; shift 2 ;;
	-et) need_val "$@"; etchtime=$2; shift 2 ;;
	-data) need_val "$@"; data=$2; shift 2 ;;
	-measure) need_val "$@"; margs=$2; shift 2 ;;
	-free) need_val "$@"; nfree=$((nfree + 1)); eval "free_$nfree=\$2"; shift 2 ;;
	-validate) need_val "$@"; validate=$2; shift 2 ;;
	-accuracy)
		# a percentage between 0 and 100 or check (etchopts.sh's
		# accuracy_value, as sample3D and fem take it); bare: 1 %
		case ${2:-} in
		[0-9.]*|check)
			{ [ "$2" = check ] || { printf '%s\n' "$2" | grep -Eq '^([0-9]+\.?[0-9]*|\.[0-9]+)$' &&
				awk -v v="$2" 'BEGIN { exit !(v > 0 && v < 100) }'; }; } ||
				bad "-accuracy $2: expected a percentage between 0 and 100, or check"
			accuracy=$2; shift 2 ;;
		*) accuracy=1; shift ;;
		esac ;;
	-d) need_val "$@"; dir=$2; shift 2 ;;
	-j) need_val "$@"; jobs=$2; shift 2 ;;
	-slurm) slurm=yes; shift ;;
	-sbatch) need_val "$@"; sbopts=$2; shift 2 ;;
	-q) quiet=-q; shift ;;
	-linear) etchopts="$etchopts -linear"; shift ;;
	-deloop)
		case ${2:-} in
		[0-9]*) etchopts="$etchopts -deloop $2"; shift 2 ;;
		*) etchopts="$etchopts -deloop"; shift ;;
		esac ;;
	-method) need_val "$@"; method=$2; etchopts="$etchopts $1 $2"; shift 2 ;;
	-dt|-seg|-smax|-smin|-rl|-clip|-refine)
		need_val "$@"; etchopts="$etchopts $1 $2"; shift 2 ;;
	-etch) need_val "$@"; etchx=$2; shift 2 ;;
	*) bad "unknown option $1" ;;
	esac
done
# measure reads surfaces without loops: the fast-marching engine's, unless
# the user chose the engine
case $method$etchx in *fmm*|*ray*) ;; *) etchopts="-method fmm$etchopts" ;; esac

[ -n "$mask" ] || bad "-if (the splat input file) is required"
[ -n "$resist" ] || bad "-bf (the bleach input file) is required"
[ -n "$etchtime" ] || bad "-et (the development time) is required"
[ -n "$data" ] || bad "-data (the measured CDs) is required"
[ -n "$margs" ] || bad "-measure is required (e.g. -measure \"-rel 5 -hole 0 0\")"
[ "$nfree" -gt 0 ] || bad "give at least one -free \"STATEMENT K LO:HI\""
if [ -n "$jobs" ]; then
	case $jobs in ''|*[!0-9]*|0*) bad "-j $jobs: expected a whole number >= 1" ;; esac
else
	jobs=$(nproc 2>/dev/null || echo 1)
fi
[ -n "$slurm" ] || [ -z "$sbopts" ] || bad "-sbatch goes with -slurm"
case $dir$(pwd) in *[!A-Za-z0-9._/+-]*) bad "-d $dir: use letters, digits and ._/+- only, in it and in the path of the current directory (make needs plain names)" ;; esac
[ -r "$mask" ] || die "$mask: cannot read the splat input file"
[ -r "$resist" ] || die "$resist: cannot read the bleach input file"
[ -r "$data" ] || die "$data: cannot read the measured CDs"
[ -z "$validate" ] || [ -r "$validate" ] || die "$validate: cannot read the validation CDs"

here=$(cd "$(dirname "$0")" && pwd)
findprog() {
	if [ -x "$here/$1" ] && [ ! -d "$here/$1" ]; then
		echo "$here/$1"
	else
		command -v "$1" 2>/dev/null || die "cannot find the program $1 (beside $0 or on PATH)"
	fi
}
CALIBFIT=$(findprog calibfit)
FEM=$(findprog fem)
DRAWPLOT=$(findprog drawplot)
[ -z "$slurm" ] || command -v sbatch >/dev/null 2>&1 || die "-slurm: cannot find sbatch"
[ -z "$accuracy" ] || [ "$accuracy" = check ] || [ -z "$slurm" ] ||
	bad "-accuracy $accuracy runs a point to choose the grid: not with -slurm (give -accuracy check)"

# calibfit with the resist file and the -free specs
fit() {
	set -- "$@" -bf "$resist"
	k=1
	while [ $k -le "$nfree" ]; do eval "set -- \"\$@\" -free \"\$free_$k\""; k=$((k + 1)); done
	"$CALIBFIT" "$@"
}
# cf ARGS: fit, calibfit's message (the first line, a usage error's too)
# becoming calib's, its exit status kept
msg=$(mktemp "${TMPDIR:-/tmp}/calib.XXXXXX") || die "cannot make a temporary file"
trap 'rm -f "$msg"' EXIT
cf() {
	st=0
	fit "$@" 2>"$msg" || st=$?
	sed -n 's/^calibfit: warning: /calib: warning: /p' "$msg" >&2
	[ $st -eq 0 ] || { echo "$prog: $(grep -v '^calibfit: warning: ' "$msg" | sed -n '1{s/^calibfit: //;p;}')" >&2; exit $st; }
}
start=$(cf -start)
# the measured points, checked by the library's reader, as fem -points wants them
points=$(cf -points -data "$data")
vpoints=""
[ -z "$validate" ] || vpoints=$(cf -points -data "$validate")

mkdir -p "$dir/runs" || die "$dir: cannot make the directory"
dir=$(cd "$dir" && pwd)
imgsrc=""

# fem's arguments but the resist file, points and directory
femrun() { # femrun RESIST POINTS DIR [fem options]
	r=$1 p=$2 d=$3
	shift 3
	[ -z "$etchx" ] || set -- -etch "$etchx" "$@"
	[ -z "$grid" ] || set -- -grid "$grid" "$@"
	# shellcheck disable=SC2086 # etchopts is a list of words on purpose
	"$FEM" -q -if "$dir/mask.in" -bf "$r" -et "$etchtime" $etchopts \
		-measure "$margs" -points "$p" -d "$d" "$@"
}
cp "$mask" "$dir/mask.in.new"
if cmp -s "$dir/mask.in.new" "$dir/mask.in"; then rm -f "$dir/mask.in.new"; else mv -f "$dir/mask.in.new" "$dir/mask.in"; fi

# -accuracy P: the grid, chosen once before the fit by fem -accuracy P at
# the middle measured point with the starting values (fem(1): refined
# until that point's every cd is within P %, the order of convergence
# observed), so that every trial of the fit runs at the same grid (a grid
# changing between trials would put its error into the Jacobian)
grid=""
if [ -n "$accuracy" ] && [ "$accuracy" != check ]; then
	mid=$(echo "$points" | tr ',' '\n' | awk '{ p[NR] = $0 } END { print p[int((NR + 1) / 2)] }')
	say "accuracy: choosing the grid at focus:dose $mid, within $accuracy %"
	femrun "$resist" "$mid" "$dir/accuracy" -accuracy "$accuracy" -j "$jobs" ||
		die "-accuracy $accuracy: the grid could not be chosen (see $dir/accuracy)"
	# accuracy.opts: "-accuracy P NX NY NZ / ..." (fem(1), FILES)
	grid=$(awk '{ print $3, $4, $5 }' "$dir/accuracy/accuracy.opts")
	say "accuracy: grid $grid (nx ny nz)"
fi
setup="$(cksum <"$mask") $etchtime $etchopts -etch $etchx -measure $margs -points $points${grid:+ -grid $grid}"

# prepare VALUES [POINTS]: writes the trial resist file, makes its fem
# directory (images linked from the first run) and prints it
prepare() {
	cf -write "$1" -o "$dir/trial.in"
	# the run's name covers all it depends on: the resist file, and the
	# setup (mask, time, options, points), so a changed setup gets new runs
	id=$({ cat "$dir/trial.in"; echo "$setup${2:+ $vpoints}"; } | cksum | cut -d' ' -f1)
	run=$dir/runs/$id${2:+-v}
	mkdir -p "$run"
	mv -f "$dir/trial.in" "$run/trial.in"
	if [ -n "$imgsrc" ] && [ "$run" != "$imgsrc" ] && [ ! -e "$run/mask.in" ]; then
		# the images are up to date for make when mask.in is not newer
		cp -p "$imgsrc/mask.in" "$run/mask.in"
		for f in "$imgsrc"/f*/image.cont; do
			[ -e "$f" ] || continue
			g=$(basename "$(dirname "$f")")
			mkdir -p "$run/$g" && ln -f "$f" "$run/$g/image.cont"
		done
	fi
	echo "$run"
}

# simulate RUN...: every run's points, one batch: fem writes each
# directory (fem -n), one make -j N runs them all (or Slurm job arrays),
# fem -collect makes each fem.dat.  A run already collected is skipped.
simulate() {
	[ -n "$imgsrc" ] || imgsrc=$1
	todo=""
	for run in "$@"; do
		[ -e "$run/done" ] || todo="$todo $run"
	done
	[ -n "$todo" ] || return 0
	for run in $todo; do
		p=$points
		case $run in *-v) p=$vpoints ;; esac
		if [ -n "$slurm" ]; then
			femrun "$run/trial.in" "$p" "$run" -slurm -sbatch "--wait $sbopts" >/dev/null
		else
			femrun "$run/trial.in" "$p" "$run" -n
		fi
	done
	if [ -n "$slurm" ]; then
		for run in $todo; do sh "$run/submit.sh" >"$run/submit.log" 2>&1 & done
		wait || :
	else
		{
			printf 'all:'
			for run in $todo; do printf ' %s' "$run"; done
			printf '\n.PHONY: all'
			for run in $todo; do printf ' %s' "$run"; done
			printf '\n'
			for run in $todo; do printf '%s:\n\t@$(MAKE) -k -s --no-print-directory -C %s all\n' "$run" "$run"; done
		} >"$dir/batch.mk"
		# one job per core: each etch on one thread (the output is the same)
		[ -n "${SAMPLE3D_THREADS:-}" ] || [ "$jobs" -lt "$(nproc 2>/dev/null || echo 1)" ] ||
			export SAMPLE3D_THREADS=1
		make -k -s --no-print-directory -j "$jobs" -f "$dir/batch.mk" all >"$dir/batch.log" 2>&1 || :
		# a point that fails (etch, measure) counts as not cleared
		nfail=$(grep -c '^fem: ' "$dir/batch.log" || :)
		[ "$nfail" = 0 ] || say "$nfail simulations failed in this batch, counted as not cleared ($dir/batch.log)"
	fi
	for run in $todo; do
		"$FEM" -q -collect -d "$run" 2>"$run/collect.log" ||
			grep -q 'have no result' "$run/collect.log" || [ ! -s "$run/fem.dat" ] ||
			die "$run: $(tail -n 1 "$run/collect.log")"
		[ -s "$run/fem.dat" ] || die "$run: no simulation finished ($(tail -n 1 "$run/collect.log"))"
		: >"$run/done"
	done
}

ssr_of() { # ssr_of RUN: "ssr n uncleared"
	cf -ssr -data "$data" -sim "$1/fem.dat"
}

# the Jacobian's probes at VALUES: their runs, simulated
probes() {
	prun=""
	pvs=$(cf -probes "$1")
	for pv in $pvs; do prun="$prun $(prepare "$pv")"; done
	# shellcheck disable=SC2086
	simulate $prun
	jac=$(echo $prun | sed 's|\([^ ]*\)|\1/fem.dat|g; s/ /,/g')
}

t0=$(date +%s)
say "start $start; $(echo "$points" | tr ',' '\n' | wc -l) points, make -j $jobs"
v=$start
run=$(prepare "$v")
simulate "$run"
cur=$run
set -- $(ssr_of "$cur")
ssr=$1 npt=$2
lambda=$LAMBDA0 iter=0 why=""
while :; do
	if [ $iter -ge $MAXITER ]; then why="$MAXITER iterations"; break; fi
	iter=$((iter + 1))
	probes "$v"
	rej=0 scale=1
	while :; do
		tv=$(cf -step "$v" -lambda "$lambda" -scale $scale -data "$data" -sim "$cur/fem.dat" -jac "$jac")
		if [ "$tv" = converged ]; then why="negligible step"; break 2; fi
		trun=$(prepare "$tv")
		simulate "$trun"
		set -- $(ssr_of "$trun")
		if awk -v a="$1" -v b="$ssr" 'BEGIN { exit !(a < b) }'; then
			small=$(awk -v a="$1" -v b="$ssr" -v t=$SSRTOL 'BEGIN { print (b - a <= t * b) ? 1 : 0 }')
			say "iteration $iter: $tv rms $(awk -v s="$1" -v n="$npt" 'BEGIN { printf "%.3f", 1000 * sqrt(s / n) }') nm$([ "$3" = 0 ] || echo " ($3 not cleared)")"
			v=$tv cur=$trun ssr=$1
			lambda=$(awk -v l="$lambda" 'BEGIN { l /= 10; print (l < 1e-7) ? 1e-7 : l }')
			if [ "$small" = 1 ]; then why="sum of squares settled"; probes "$v"; break 2; fi
			break
		fi
		rej=$((rej + 1))
		case $rej in
		1) scale=0.5 ;;
		2) scale=0.25 ;;
		*) scale=1 lambda=$(awk -v l="$lambda" 'BEGIN { print (l < 0.1) ? 1 : l * 10 }') ;;
		esac
		if [ $rej -ge $MAXREJECT ]; then why="no downhill step"; break 2; fi
	done
done
say "stopped after $iter iterations ($why): $v"
probes "$v"  # the Jacobian at the result (already there unless the iterations ran out)

# the result: resist.fit.in, simulated as written (it is one of the runs)
cf -write "$v" -o "$dir/resist.fit.in"
final=$(prepare "$v")
simulate "$final"
vargs=""
if [ -n "$validate" ]; then
	vrun=$(prepare "$v" validate)
	simulate "$vrun"
	vargs="-vdata $validate -vsim $vrun/fem.dat"
fi
st=0
# shellcheck disable=SC2086
(cf -report "$v" -data "$data" -sim "$final/fem.dat" -jac "$jac" -iter "$iter" $vargs -d "$dir") || st=$?
if [ -s "$dir/bossung.2D" ]; then
	(cd "$dir" &&
	"$DRAWPLOT" -noplot -t bossung.tpl -tl "measured (markers) and fitted CD" -xl "focus (um)" \
		-yl "cd (um)" -svg bossung.svg bossung.2D && mv -f dataplot.ps bossung.ps &&
	"$DRAWPLOT" -noplot -t residuals.tpl -tl "residuals: fitted - measured CD" -xl "focus (um)" \
		-yl "residual (nm)" -svg residuals.svg residuals.2D && mv -f dataplot.ps residuals.ps) ||
		die "drawplot failed on $dir/bossung.2D or residuals.2D"
fi
[ $st -eq 0 ] || exit $st
# -accuracy: the fitted CDs' discretisation error, fem -accuracy check on
# the result at the grid of the fit (each point also one level coarser)
if [ -n "$accuracy" ]; then
	femrun "$dir/resist.fit.in" "$points" "$dir/accuracy-result" -accuracy check -j "$jobs" ||
		die "-accuracy: the estimate on the result failed (see $dir/accuracy-result)"
	worst=$(cat "$dir"/accuracy-result/f*/d*/measure.dat | awk '!/^#/ && $2 > 0 {
		e = 100 * $NF / $2; if (e > m) m = e } END { printf "%.3g\n", m }')
	lim=$accuracy
	[ "$lim" != check ] || lim=1
	if awk -v w="$worst" -v l="$lim" 'BEGIN { exit !(w > l) }'; then
		echo "$prog: warning: the fitted CDs' estimated discretisation error is up to $worst % (over $lim %; the err column of $dir/accuracy-result/f*/d*/measure.dat)" >&2
	else
		say "accuracy: the fitted CDs' estimated discretisation error is at most $worst %"
	fi
fi
say "$dir/calib.dat, $dir/resist.fit.in: $(grep '^# rms_nm' "$dir/calib.dat" | cut -d' ' -f2-)${validate:+, validation $(grep '^# validate_rms_nm' "$dir/calib.dat" | cut -d' ' -f3) nm}; $(( $(date +%s) - t0 )) s"
exit 0
