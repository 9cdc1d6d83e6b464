#!/bin/sh
# fem - focus-exposure matrices: sweeps focus and dose through splat, bleach,
# etch and measure, and collects the CDs into fem.dat, Bossung curves and the
# process window.  See man/man1/fem.1.
#
#   fem -if mask.in -bf resist.in -et 60 -dose 60:100:10 -focus -0.6:0.2:0.2 \
#       -measure "-rel 10 -hole 0 0" -target 1.0 -tol 10 -j 2
#
# The driver only writes the work down: DIR/Makefile (splat once per focus,
# bleach, etch and measure per point) run by GNU make (-j, resumable, -k), or
# a Slurm job array (-slurm: DIR/fem.sbatch and DIR/submit.sh).  The tables
# and the window are computed by femwin(1), the plots drawn by drawplot(1).
set -euf	# -f: the words of -measure, -etch and -sbatch are never globbed

prog=fem
# the programs and the etch pass-through options (etchopts.sh, shared with
# sample3D): beside this script first (a build or an install), then PATH
here=$(cd "$(dirname "$0")" && pwd)
[ -r "$here/etchopts.sh" ] || { echo "$prog: cannot find etchopts.sh beside $0" >&2; exit 1; }
. "$here/etchopts.sh"
usage() {
	cat <<'U'
usage: fem -if mask.in -bf resist.in -et T -dose D1:D2:STEP|D1,D2,...
           -focus F1:F2:STEP|F1,F2,... -measure "MEASURE-ARGS"
           (or -points F:D,F:D,... instead of -dose and -focus)
           [-target CD -tol PCT] [-seeds K] [-accuracy [P|check]] [-grid "NX NY NZ"]
           [-d DIR] [-j N] [-keep] [-n] [-big]
           [-slurm [-chunk K] [-sbatch "OPTS"]] [etch options] [-q]
       fem -collect [-d DIR] [-target CD -tol PCT] [-q]
  -if FILE      splat input file (the mask and the optics)
  -bf FILE      bleach input file (the resist)
  -et T         development time (s)
  -dose LIST    doses (mJ/cm2): first:last:step or a list a,b,c
  -focus LIST   foci (um, splat -defocus): first:last:step or a list
  -points LIST  only these (focus, dose) points, focus:dose,focus:dose,...
  -measure ARGS measure's arguments for every point, without -o and file,
                e.g. "-rel 10,90 -hole 0 0"; cd is at the first height
  -target CD    with -tol: the process window for this CD (um)
  -tol PCT      in spec when |cd - CD| <= PCT % of CD
  -seeds K      K stochastic runs a point (bleach -seed 1..K; the resist
                needs a stochastic statement): fem.dat holds the mean cd,
                stoch.dat the mean, its 3 sigma and the failures
  -accuracy [P] choose the image grid, nz and etch's resolution at the
                nominal point (the middle focus and dose) so that every
                CD's estimated error is under P % (default 1), run every
                point there and one level coarser, and give each table the
                column err (um); a point over P fails
  -accuracy check  every point at the inputs' grids and one level coarser:
                the err column, no refinement
  -grid "NX NY NZ"  every point at this image grid and nz (etch's
                resolution scaled with it) instead of the inputs' (not
                with -accuracy P, which chooses it)
  -d DIR        the sweep's directory (default fem)
  -j N          points run at once (make -j N; default: the cores)
  -keep         keep every point's rate file and curves.plot
  -n            write DIR and its Makefile, run nothing
  -big          allow more than 10000 points (also SAMPLE3D_BIG=1)
  -slurm        write DIR/fem.sbatch and DIR/submit.sh, submit nothing
  -chunk K      with -slurm: K points per array task (default 1)
  -sbatch OPTS  with -slurm: options submit.sh gives sbatch (e.g. "-p short")
  -collect      collect DIR into fem.dat, bossung.ps and the window
  -q            quiet: no progress lines
  -h, --help    this text
U
	etchopts_usage
}
die() { printf '%s: %s\n' "$prog" "$*" >&2; exit 1; }
# a usage error: one line (and where the usage is), exit 2
bad() { usage_error "$*"; }
# a wrong value: one line, exit 2
badv() { printf '%s: %s\n' "$prog" "$*" >&2; exit 2; }
say() { [ -n "$quiet" ] || printf '%s: %s\n' "$prog" "$*" >&2; }
need_val() { [ $# -ge 2 ] || bad "option $1 needs a value"; }

mask="" resist="" etchtime="" doses="" foci="" margs="" target="" tol=""
dir=fem jobs="" keep="" dryrun="" slurm="" chunk=1 sbopts="" collect="" quiet="" big=""
etchopts="" points="" seeds="" accuracy="" fixgrid=""
while [ $# -gt 0 ]; do
	case $1 in
	--help|-h) usage; exit 0 ;;
	-if) need_val "$@"; mask=$2; shift 2 ;;
	-bf) need_val "$@"; resist=$2; shift 2 ;;
	-et) need_val "$@"; etchtime=$2; shift 2 ;;
	-dose) need_val "$@"; doses=$2; shift 2 ;;
	-focus) need_val "$@"; foci=$2; shift 2 ;;
	-points) need_val "$@"; points=$2; shift 2 ;;
	-measure) need_val "$@"; margs=$2; shift 2 ;;
	-target) need_val "$@"; target=$2; shift 2 ;;
	-tol) need_val "$@"; tol=$2; shift 2 ;;
	-seeds) need_val "$@"; seeds=$2; shift 2 ;;
	-d) need_val "$@"; dir=$2; shift 2 ;;
	-j) need_val "$@"; jobs=$2; shift 2 ;;
	-keep) keep=yes; shift ;;
	-n) dryrun=yes; shift ;;
	-big) big=yes; shift ;;
	-slurm) slurm=yes; shift ;;
	-chunk) need_val "$@"; chunk=$2; shift 2 ;;
	-sbatch) need_val "$@"; sbopts=$2; shift 2 ;;
	-collect) collect=yes; shift ;;
	-q) quiet=-q; shift ;;
	-accuracy) accuracy_opt "$@"; shift "$etchopt_n" ;;
	-tile|-halo) bad "$1: fem does not tile (every point would be a tiled run); tile one point with sample3D -tile" ;;
	-grid) need_val "$@"; fixgrid=$2; shift 2 ;;
	*) etchopt "$@" || bad "unknown option $1"; shift "$etchopt_n" ;;
	esac
done

nl='
'
isnum() { # isnum WORD: a decimal number (one line: grep would take any line)
	case $1 in *"$nl"*) return 1 ;; esac
	printf '%s\n' "$1" | grep -Eq '^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$'
}
# Every word fem writes into DIR/Makefile and the Slurm scripts is quoted, so
# that make and sh pass it on as the one word the checks below saw, whatever
# it holds ($, `, quotes, ;, &, |, <, >, #, %, \): a word with a newline or
# a carriage return cannot be written on one line and is refused.
plainword() { # plainword WHAT WORD: refuse a word that cannot be quoted
	case $2 in *"$nl"*|*"$(printf '\r')"*) badv "$1: a word with a newline or a carriage return" ;; esac
}
mkwords() { # mkwords WHAT WORDS: the words (split at blanks) through mkq
	for w in $2; do plainword "$1" "$w"; printf ' %s' "$(mkq "$w")"; done
}
cd_height() { # cd_height MEASURE-WORDS: the height of measure's first CD, in words
	while [ $# -gt 0 ]; do
		case $1 in
		-rel) [ $# -lt 2 ] || { echo "${2%%,*} % of the resist's height"; return; } ;;
		-at) [ $# -lt 2 ] || { echo "z = ${2%%,*} um"; return; } ;;
		esac
		shift
	done
	echo "measure's first height"
}
posnum() { isnum "$1" && awk -v v="$1" 'BEGIN { exit !(v > 0) }'; }

# the programs: beside this script first ($here), then PATH
findprog() {
	if [ -x "$here/$1" ] && [ ! -d "$here/$1" ]; then
		printf '%s\n' "$here/$1"
	else
		command -v "$1" 2>/dev/null || die "cannot find the program $1 (beside $0 or on PATH)"
	fi
}
FEMWIN=$(findprog femwin)
DRAWPLOT=$(findprog drawplot)

[ -z "$target$tol" ] || { [ -n "$target" ] && [ -n "$tol" ]; } ||
	bad "-target and -tol go together"
[ -z "$target" ] || posnum "$target" || badv "-target $target: expected a positive CD (um)"
[ -z "$tol" ] || { posnum "$tol" && awk -v v="$tol" 'BEGIN { exit !(v < 100) }'; } ||
	badv "-tol $tol: expected a percentage between 0 and 100"

# -collect: everything else is in DIR/Makefile
if [ -n "$collect" ]; then
	[ -z "$mask$resist$etchtime$doses$foci$points$margs$slurm$dryrun$keep$etchopts$seeds$accuracy$fixgrid" ] ||
		bad "-collect takes only -d, -target, -tol and -q: the sweep is in DIR/Makefile"
	[ -f "$dir/Makefile" ] || die "$dir/Makefile: no sweep there (run fem without -collect first)"
	st=0
	make -s -C "$dir" --no-print-directory collect ${target:+TARGET=$target TOL=$tol} || st=$?
	[ $st -ne 0 ] || say "collected $dir: fem.dat, bossung.ps$([ ! -e "$dir/window.dat" ] || echo ", window.dat, window.ps")"
	exit $st
fi

[ -n "$mask" ] || bad "-if (the splat input file) is required"
[ -n "$resist" ] || bad "-bf (the bleach input file) is required"
[ -n "$etchtime" ] || bad "-et (the development time) is required"
[ -n "$doses$points" ] || bad "-dose is required"
[ -n "$foci$points" ] || bad "-focus is required"
[ -n "$margs" ] || bad "-measure is required (e.g. -measure \"-rel 10 -hole 0 0\")"
posnum "$etchtime" || badv "-et $etchtime: expected a positive time (s)"
case $chunk in ''|*[!0-9]*|0*) badv "-chunk $chunk: expected a whole number >= 1" ;; esac
if [ -n "$seeds" ]; then
	case $seeds in ''|*[!0-9]*|0*) badv "-seeds $seeds: expected a whole number from 1 to 1000" ;; esac
	[ "$seeds" -le 1000 ] || badv "-seeds $seeds: expected a whole number from 1 to 1000"
	[ -z "$accuracy" ] || badv "-seeds with -accuracy: the error estimate of a stochastic run is not a discretisation error; choose the grid with -accuracy first, then run -seeds at it"
fi
if [ -n "$jobs" ]; then
	case $jobs in ''|*[!0-9]*|0*) badv "-j $jobs: expected a whole number >= 1" ;; esac
else
	jobs=$(nproc 2>/dev/null || echo 1)
fi
[ -z "$slurm" ] || [ -z "$dryrun" ] || bad "-slurm already runs nothing: drop -n"
[ -n "$slurm" ] || { [ "$chunk" = 1 ] && [ -z "$sbopts" ]; } || bad "-chunk and -sbatch go with -slurm"
# measure's -s names a set of etch -pt: a whole number (the probe, with one
# set, cannot try it); fem gives measure and etch their output files
skipnext=""
for w in $margs; do
	plainword "-measure" "$w"
	if [ -n "$skipnext" ]; then
		case $w in ''|*[!0-9]*) badv "-measure: -s $w: expected a set number (a whole number)" ;; esac
		skipnext=""
	fi
	case $w in
	-o|-plot) badv "-measure: fem gives measure its output file; drop $w" ;;
	-s) skipnext=yes ;;
	esac
done
[ -z "$skipnext" ] || badv "-measure: -s needs a set number"
for w in $etchopts; do
	plainword "-etch" "$w"
	case $w in -o) badv "-etch: fem gives etch its output file; drop -o" ;; esac
done
for w in $sbopts; do plainword "-sbatch" "$w"; done
plainword "-d" "$dir"
plainword "the current directory" "$(pwd)"
plainword "fem's directory" "$here"

# The most points without -big: a Makefile of 10000 points is written in a
# few seconds and is already days of work on a workstation; a mistyped step
# (1e-7 for 1e-1) is refused before it writes millions of rules.
cap=10000
[ -z "$big" ] && [ "${SAMPLE3D_BIG:-}" != 1 ] || cap=0
# expand WHAT LIST: first:last:step or a,b,c -> one value per line (%.10g),
# in one awk: a range whose step is below the values' resolution (it would
# never advance, or two of its points would print alike) or that holds more
# than cap points is refused in one line with its count, before any loop
expand() {
	case $2 in *"$nl"*) badv "-$1: a list on one line expected" ;; esac
	printf '%s\n' "$2" | awk -v what="-$1 $2" -v cap="$cap" '
	function isnum(w) { return w ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
	function bad(m) { printf "fem: %s: %s\n", what, m >"/dev/stderr"; failed = 1; exit 2 }
	function toomany(n) {
		f = n < 1e15 ? "%.0f" : "%.3g"
		bad(sprintf(f " points, more than %d: use -big or SAMPLE3D_BIG=1", n, cap))
	}
	{ line = $0 }
	END {
		if (failed) exit 2
		if (line ~ /:.*:/) {
			if (split(line, p, ":") != 3 || !isnum(p[1]) || !isnum(p[2]) || !isnum(p[3]))
				bad("expected first:last:step")
			a = p[1] + 0; b = p[2] + 0; s = p[3] + 0
			if (!(s > 0)) bad("the step must be positive")
			if (b < a) exit 0
			n = int((b - a) / s + 1e-9) + 1
			if (cap > 0 && !(n <= cap)) toomany(n)
			if (a + s == a || b - s == b || !(n < 1e15))
				bad(sprintf("the step %s is below the resolution of the values", p[3]))
			last = ""
			for (k = 0; a + k * s <= b + 1e-9 * s; k++) {
				v = a + k * s
				if (v < 1e-12 * s && v > -1e-12 * s) v = 0
				t = sprintf("%.10g", v)
				if (t == last)
					bad(sprintf("the step %s is below the resolution of the values (%s twice)", p[3], t))
				print t
				last = t
			}
			exit 0
		}
		m = split(line, w, ",")
		if (cap > 0 && m > cap) toomany(m)
		for (k = 1; k <= m; k++) {
			if (w[k] == "") continue
			if (!isnum(w[k])) bad(w[k] " is not a number")
			printf "%.10g\n", w[k] + 0
		}
	}'
}
# -points f:d,...: the foci and doses it names, and inpts F D to keep only its points
if [ -n "$points" ]; then
	[ -z "$doses$foci" ] || bad "-points replaces -dose and -focus"
	pts=$(for p in $(echo "$points" | tr ',' ' '); do
		[ "${p%%:*}" != "$p" ] && isnum "${p%%:*}" && isnum "${p#*:}" || badv "-points: $p is not focus:dose"
		awk -v f="${p%%:*}" -v d="${p#*:}" 'BEGIN { printf "%.10g %.10g\n", f + 0, d + 0 }'
	done) || exit 2
	foci=$(printf '%s\n' "$pts" | cut -d' ' -f1 | sort -u -g | paste -sd, -)
	doses=$(printf '%s\n' "$pts" | cut -d' ' -f2 | sort -u -g | paste -sd, -)
fi
inpts() { [ -z "$points" ] || printf '%s\n' "$pts" | grep -qxF -e "$1 $2"; }
fvals=$(expand focus "$foci") || exit 2
dvals=$(expand dose "$doses") || exit 2
[ -n "$fvals" ] || badv "-focus $foci: no focus in that range"
[ -n "$dvals" ] || badv "-dose $doses: no dose in that range"
v=$(printf '%s\n' "$dvals" | awk '!($1 > 0) { print; exit }')
[ -z "$v" ] || badv "-dose $doses: doses must be positive ($v)"
printf '%s\n' "$fvals" | sort -c -u -g 2>/dev/null || badv "-focus $foci: give the foci in ascending order, each once"
printf '%s\n' "$dvals" | sort -c -u -g 2>/dev/null || badv "-dose $doses: give the doses in ascending order, each once"
nf=$(printf '%s\n' "$fvals" | wc -l)
nd=$(printf '%s\n' "$dvals" | wc -l)
npts=$((nf * nd))
[ -z "$points" ] || npts=$(printf '%s\n' "$pts" | sort -u | wc -l)
[ "$cap" -eq 0 ] || [ "$npts" -le "$cap" ] ||
	badv "$npts points ($nf foci x $nd doses), more than $cap: use -big or SAMPLE3D_BIG=1"

[ -r "$mask" ] || die "$mask: cannot read the splat input file"
[ -r "$resist" ] || die "$resist: cannot read the bleach input file"
SPLAT=$(findprog splat)
BLEACH=$(findprog bleach)
ETCH=$(findprog etch)
MEASURE=$(findprog measure)
command -v make >/dev/null 2>&1 || die "cannot find make (GNU make runs the sweep)"
"$SPLAT" --help 2>&1 | grep -q -- -defocus || die "$SPLAT has no -defocus: this splat cannot sweep focus"
"$BLEACH" --help 2>&1 | grep -q -- -dose || die "$BLEACH has no -dose: this bleach cannot sweep dose"
[ -z "$seeds" ] || "$BLEACH" --help 2>&1 | grep -q -- -seed ||
	die "$BLEACH has no -seed: this bleach cannot run -seeds"

# check every stage's arguments before anything runs: the inputs through
# femwin -probe (the library's readers), etch's options on a missing file
# (a usage error exits 2 before any file is opened), and measure's on the
# probe surface (the undeveloped resist over the mask window)
chk=$(mktemp -d "${TMPDIR:-/tmp}/fem.XXXXXX") || die "cannot make a temporary directory"
trap 'rm -rf "$chk"' EXIT
"$FEMWIN" -probe "$mask" "$resist" -o "$chk/probe.plot" 2>"$chk/err" ||
	die "$(sed -n '1{s/^femwin: //;p;}' "$chk/err")"
# -seeds: the runs differ only by bleach -seed, which needs the resist's
# stochastic statement (bleach(5)); looked for before any run (bleach
# itself would refuse every point)
[ -z "$seeds" ] || grep -qi '^[[:space:]]*stochastic[[:space:]]' "$resist" ||
	badv "-seeds $seeds: $resist has no stochastic statement (bleach(5)): every seed would give the same run"
st=0
# shellcheck disable=SC2086 # etchopts is a list of words on purpose
"$ETCH" -q -et "$etchtime" $etchopts "$chk/no-such-rate-file" >/dev/null 2>"$chk/err" || st=$?
[ $st -ne 2 ] || die "etch refuses the options \"-et $etchtime$etchopts\": $(sed -n '1{s/^etch: //;p;}' "$chk/err")"
# the probe has one set: measure's -s (a set of etch -pt) is left out there
pargs="" skipnext=""
for w in $margs; do
	if [ -n "$skipnext" ]; then skipnext=""; continue; fi
	case $w in -s) skipnext=yes ;; *) pargs="$pargs $w" ;; esac
done
# shellcheck disable=SC2086 # pargs is a list of words on purpose
"$MEASURE" $pargs -o "$chk/measure.dat" "$chk/probe.plot" >/dev/null 2>"$chk/err" ||
	die "measure refuses -measure \"$margs\": $(sed -n '1{s/^measure: //;p;}' "$chk/err")"

# the engine measure reads (etchopts.sh): fast marching unless an etch
# option chooses the engine
etch_engine_default

# -accuracy: the grids of the inputs (the library's readers, through
# femwin); P is chosen below at the nominal point, check keeps them
grid="" cgrid="" ratio="" rgrid="" order=1
if [ -n "$fixgrid" ]; then
	printf '%s\n' "$fixgrid" | grep -Eq '^ *[1-9][0-9]* +[1-9][0-9]* +[1-9][0-9]* *$' &&
		awk -v g="$fixgrid" 'BEGIN { split(g, n, " "); exit !(n[1] >= 2 && n[2] >= 2 && n[3] >= 2 && n[1] * n[2] * n[3] <= 1e10) }' ||
		badv "-grid \"$fixgrid\": expected three whole numbers NX NY NZ, each at least 2"
	[ -z "$accuracy" ] || [ "$accuracy" = check ] ||
		bad "-grid with -accuracy $accuracy: -accuracy P chooses the grid (-accuracy check estimates at -grid's)"
fi
if [ -n "$accuracy$fixgrid" ]; then
	[ -z "$accuracy" ] || [ "$accuracy" = check ] || [ -z "$dryrun$slurm" ] ||
		bad "-accuracy $accuracy runs the nominal point to choose the grid: not with -n or -slurm (give -accuracy check)"
	grid=$("$FEMWIN" -resolution "$mask" "$resist" 2>"$chk/err") ||
		die "$(sed -n '1{s/^femwin: //;p;}' "$chk/err")"
	rgrid=$grid
	# shellcheck disable=SC2086 # three words on purpose
	[ -z "$fixgrid" ] || grid=$(echo $fixgrid)
fi

# fem_accuracy_choose: sets grid (the points' counts "nx ny nz"), cgrid
# (the coarse solve's) and ratio (their spacing ratio).  -accuracy P:
# etchopts.sh's accuracy_loop at the nominal point, the middle focus and
# dose, in DIR/accuracy (its tables kept there); check: the inputs' grid
# and level -1
acc_solve() { # acc_solve "NX NY NZ" ETCHOPTS, at focus $nomf, dose $nomd
	# shellcheck disable=SC2086 # the grid is three words on purpose
	set -- $1 "$2"
	say "accuracy: focus $nomf dose $nomd: splat -grid $1 $2, bleach -nz $3"
	"$SPLAT" -q -defocus "$nomf" -grid "$1" "$2" -bf "$dir/resist.in" \
		-o "$dir/accuracy/image.cont" "$dir/mask.in" || return 1
	"$BLEACH" -q -dose "$nomd" -nz "$3" -o "$dir/accuracy/rate" "$dir/accuracy/image.cont" \
		"$dir/resist.in" || return 1
	# shellcheck disable=SC2086 # etch's options are a list of words on purpose
	"$ETCH" -q -et "$etchtime" $4 -no2d -o "$dir/accuracy/curves.plot" "$dir/accuracy/rate" ||
		return 1
	acc_surface=$dir/accuracy/curves.plot
}
fem_accuracy_choose() {
	if [ -z "$accuracy" ]; then
		# -grid alone: etch's options scaled with the grid
		[ -z "$fixgrid" ] || etchopts=$(acc_etchopts "$grid" "$rgrid")
		return 0
	fi
	# shellcheck disable=SC2086 # the grid is three words on purpose
	if [ "$accuracy" = check ]; then
		cgrid=$(acc_grid $grid -1)
	else
		nomf=$(printf '%s\n' "$fvals" | sed -n "$(( (nf + 1) / 2 ))p")
		nomd=$(printf '%s\n' "$dvals" | sed -n "$(( (nd + 1) / 2 ))p")
		mkdir -p "$dir/accuracy" || die "$dir/accuracy: cannot make the directory"
		st=0
		accuracy_loop "$MEASURE" "$accuracy" $grid "$dir/accuracy" || st=$?
		case $st in
		0) ;;
		3) die "-accuracy $accuracy: not reached at the nominal point (focus $nomf dose $nomd) at grid $acc_grid: see $acc_table" ;;
		*) die "-accuracy: the nominal point failed (focus $nomf dose $nomd)" ;;
		esac
		grid=$acc_grid cgrid=$acc_prevg
		# the order the nominal point converged at, read back from its
		# last table's err as if err = |change| / (r^p - 1) (measure's
		# safety factor and fallbacks only lower it): the lowest over
		# its cds, which the points' two-solve estimates assume
		# (by axis, acc_prevg is one level below in both groups, a grid
		# the nominal point may not have solved: then order 1, the
		# lowest in the chain)
		order=1
		# shellcheck disable=SC2086 # the grid is three words on purpose
		[ ! -s "$dir/accuracy/$(echo $cgrid | tr ' ' x).dat" ] ||
		order=$(awk -v r="$(acc_ratio "$cgrid" "$grid")" 'NR == FNR { if (!/^#/) c[FNR] = $2; next }
			!/^#/ && $NF > 0 { d = $2 - c[FNR]; if (d < 0) d = -d; if (d == 0) next
				p = log(1 + d / $NF) / log(r); if (m == "" || p < m) m = p }
			END { if (m == "") m = 1; if (m < 0.5) m = 0.5; if (m > 2) m = 2; printf "%.3g\n", m }' \
			"$dir/accuracy/$(echo $cgrid | tr ' ' x).dat" "$acc_table")
		rm -f "$dir/accuracy/rate" "$dir/accuracy/curves.plot" "$dir/accuracy/image.cont"
		say "accuracy: grid $grid (nx ny nz) at the nominal point, within $accuracy %"
	fi
	ratio=$(acc_ratio "$cgrid" "$grid")
	# etch's options at the two grids (-seg and -dt scaled with them)
	etchopts=$(acc_etchopts "$grid" "$rgrid")
	cetchopts=$(acc_etchopts "$cgrid" "$rgrid")
}
# fem_accuracy_rules F P: the rules of point P (focus directory F) for the
# coarse solve, whose table measure compares the point's with
fem_accuracy_rules() {
	[ -n "$accuracy" ] || return 0
	echo "$2/rate-coarse: $1/image-coarse.cont resist.in accuracy.opts"
	printf '\t@mkdir -p %s\n' "$2"
	printf '\t@$(RUN) %s/bleach-coarse.log "focus %s dose %s: bleach (coarse)" $@ $(BLEACH) -q $(CBLEACHNZ) -dose %s -o $@ %s/image-coarse.cont resist.in\n' "$2" "$f" "$d" "$d" "$1"
	echo "$2/coarse.plot: $2/rate-coarse etch.opts"
	printf '\t@$(RUN) %s/etch-coarse.log "focus %s dose %s: etch (coarse)" $@ $(ETCH) -q $(CETCHOPTS) -no2d -o $@ %s/rate-coarse\n' "$2" "$f" "$d" "$2"
	echo "$2/coarse.dat: $2/coarse.plot measure.opts"
	printf '\t@$(RUN) %s/measure-coarse.log "focus %s dose %s: measure (coarse)" $@ $(MEASURE) $(MEASUREARGS) -o $@ %s/coarse.plot\n' "$2" "$f" "$d" "$2"
	printf '\t@$(CLEAN) %s/rate-coarse %s/coarse.plot\n' "$2" "$2"
}

# DIR: the inputs (copied, so that the sweep does not change under a later
# edit), the options each stage depends on, and the Makefile; a file is
# replaced only when its content changes, so make redoes exactly the work
# whose inputs changed and nothing else
mkdir -p -- "$dir" || die "$dir: cannot make the directory"
dir=$(cd -- "$dir" && pwd)
put() { # put FILE: stdin becomes FILE if different
	cat >"$dir/.new"
	if cmp -s "$dir/.new" "$dir/$1"; then rm -f "$dir/.new"; else mv -f "$dir/.new" "$dir/$1"; fi
}
put mask.in <"$mask"
put resist.in <"$resist"
# the options as make passes them (mkq): each word as the checks above saw it
measureq=$(mkwords -measure "$margs")
printf '%s\n' "$measureq" | put measure.opts
fem_accuracy_choose
etchq="$(mkq -et) $(mkq "$etchtime")$(mkwords -etch "$etchopts")"
cetchq=""
[ -z "$accuracy" ] || cetchq="$(mkq -et) $(mkq "$etchtime")$(mkwords -etch "$cetchopts")"
echo "${accuracy:+-accuracy $accuracy $grid / $cgrid $ratio $order}${fixgrid:+ -grid $grid}" | put accuracy.opts
printf '%s\n' "$etchq${accuracy:+ / $cetchq}" | put etch.opts
# the runs of a point are its directory fF/dD, or with -seeds one
# directory fF/dD/sK per seed: seedsfx lists the suffixes (no fork per
# point: a loop "for s in ${seedsfx:-""}" runs once, with s empty, without)
seedsfx=""
if [ -n "$seeds" ]; then
	_s=1
	while [ $_s -le "$seeds" ]; do seedsfx="$seedsfx /s$_s"; _s=$((_s + 1)); done
fi
{
cat <<'S'
#!/bin/sh
# stage.sh LOG LABEL TARGET PROGRAM ARGS... - one stage of one point, written
# by fem(1): runs the program with its messages in LOG; on failure prints
# "fem: LABEL: " and the program's own message, and fails (make -k goes on
# with the other points).  Leftover temporaries of an interrupted run of the
# same stage are removed first.
log=$1 label=$2 target=$3
shift 3
rm -f "$target".tmp*
if "$@" 2>"$log"; then
	[ -s "$log" ] || rm -f "$log"
	exit 0
fi
echo "fem: $label: $(tail -n 1 "$log")" >&2
exit 1
S
} | put stage.sh

# the Makefile
{
	printf '# The focus-exposure matrix %s, written by fem(1): %s foci x %s doses.\n' "$dir" "$nf" "$nd"
	echo "# make -j N all runs the sweep (resumable); make collect writes fem.dat,"
	echo "# bossung.2D/.ps/.svg and, with TARGET and TOL, window.dat/.ps."
	printf 'SPLAT = %s\n' "$(mkq "$SPLAT")"
	printf 'BLEACH = %s\n' "$(mkq "$BLEACH")"
	printf 'ETCH = %s\n' "$(mkq "$ETCH")"
	printf 'MEASURE = %s\n' "$(mkq "$MEASURE")"
	printf 'FEMWIN = %s\n' "$(mkq "$FEMWIN")"
	printf 'DRAWPLOT = %s\n' "$(mkq "$DRAWPLOT")"
	printf 'ETCHOPTS = %s\n' "$etchq"
	printf 'MEASUREARGS =%s\n' "$measureq"
	# the Bossung curves' title names the height their CD is read at
	# shellcheck disable=SC2086 # the measure options are words on purpose
	printf 'BOSSUNGTITLE = %s\n' "$(mkq "Bossung curves: CD at $(cd_height $margs) against focus")"
	# -accuracy: the grids of the points and of their coarse solves
	if [ -n "$accuracy" ]; then
		# shellcheck disable=SC2086 # two grids of three words on purpose
		set -- $grid $cgrid
		echo "SPLATGRID = -grid $1 $2"
		echo "BLEACHNZ = -nz $3"
		echo "CSPLATGRID = -grid $4 $5"
		echo "CBLEACHNZ = -nz $6"
		printf 'CETCHOPTS = %s\n' "$cetchq"
		echo "ACCURACY = -accuracy $accuracy -ratio $ratio -order $order"
	elif [ -n "$fixgrid" ]; then
		# shellcheck disable=SC2086 # three words on purpose
		set -- $grid
		echo "SPLATGRID = -grid $1 $2"
		echo "BLEACHNZ = -nz $3"
	fi
	echo "TARGET = $target"
	echo "TOL = $tol"
	echo "RUN = sh stage.sh"
	if [ -n "$keep" ]; then echo "CLEAN = :"; else echo "CLEAN = rm -f"; fi
	echo
	echo ".DELETE_ON_ERROR:"
	echo ".PHONY: all images collect"
	printf 'all:'
	for f in $fvals; do for d in $dvals; do inpts "$f" "$d" || continue;
		for s in ${seedsfx:-""}; do R=f$f/d$d$s; printf ' %s/measure.dat' "$R"; done
	done; done
	echo
	printf 'images:'
	for f in $fvals; do printf ' %s/image.cont' "f$f"; done
	# -accuracy: the coarse images too, made once per focus before the points
	[ -z "$accuracy" ] || for f in $fvals; do printf ' %s/image-coarse.cont' "f$f"; done
	echo
	# intermediates: not rebuilt when a point's measure.dat is up to date
	printf '.SECONDARY:'
	for f in $fvals; do for d in $dvals; do inpts "$f" "$d" || continue;
		for s in ${seedsfx:-""}; do R=f$f/d$d$s; printf ' %s/rate %s/curves.plot' "$R" "$R"; done
		[ -z "$accuracy" ] ||
			printf ' %s/%s/rate-coarse %s/%s/coarse.plot' "f$f" "d$d" "f$f" "d$d"
	done; done
	echo
	for f in $fvals; do
		F=f$f
		echo
		echo "$F/image.cont: mask.in resist.in accuracy.opts"
		printf '\t@mkdir -p %s\n' "$F"
		# in the focus's folder: the files the mask writes itself (its
		# cutlines) are the focus's own, not one file all foci write at once
		printf '\t@cd %s && sh ../stage.sh splat.log "focus %s: splat" image.cont $(SPLAT) -q $(SPLATGRID) -defocus %s -bf ../resist.in -o image.cont ../mask.in\n' "$F" "$f" "$f"
		if [ -n "$accuracy" ]; then
			echo "$F/image-coarse.cont: mask.in resist.in accuracy.opts"
			printf '\t@mkdir -p %s\n' "$F"
			printf '\t@cd %s && sh ../stage.sh splat-coarse.log "focus %s: splat (coarse)" image-coarse.cont $(SPLAT) -q $(CSPLATGRID) -defocus %s -bf ../resist.in -o image-coarse.cont ../mask.in\n' "$F" "$f" "$f"
		fi
		for d in $dvals; do inpts "$f" "$d" || continue; for s in ${seedsfx:-""}; do P=$F/d$d$s;
			seed="" what="focus $f dose $d"
			[ -z "$seeds" ] || { seed=" -seed ${P##*/s}" what="$what seed ${P##*/s}"; }
			echo "$P/rate: $F/image.cont resist.in accuracy.opts"
			printf '\t@mkdir -p %s\n' "$P"
			printf '\t@$(RUN) %s/bleach.log "%s: bleach" $@ $(BLEACH) -q $(BLEACHNZ) -dose %s%s -o $@ %s/image.cont resist.in\n' "$P" "$what" "$d" "$seed" "$F"
			echo "$P/curves.plot: $P/rate etch.opts"
			printf '\t@$(RUN) %s/etch.log "%s: etch" $@ $(ETCH) -q $(ETCHOPTS) -o $@ %s/rate\n' "$P" "$what" "$P"
			if [ -n "$accuracy" ]; then
				echo "$P/measure.dat: $P/curves.plot $P/coarse.dat measure.opts accuracy.opts"
				printf '\t@$(RUN) %s/measure.log "%s: measure" $@ $(MEASURE) $(MEASUREARGS) $(ACCURACY) -coarse %s/coarse.dat -o $@ %s/curves.plot\n' "$P" "$what" "$P" "$P"
			else
				echo "$P/measure.dat: $P/curves.plot measure.opts"
				printf '\t@$(RUN) %s/measure.log "%s: measure" $@ $(MEASURE) $(MEASUREARGS) -o $@ %s/curves.plot\n' "$P" "$what" "$P"
			fi
			printf '\t@$(CLEAN) %s/rate %s/curves.plot %s/curves.plot.2D\n' "$P" "$P" "$P"
			fem_accuracy_rules "$F" "$P"
		done; done
	done
	echo
	echo "# the tables and plots, from whatever points have finished"
	echo "collect:"
	printf '\t@st=0; $(FEMWIN) -collect -o fem.dat -bossung bossung.2D -template bossung.tpl'
	[ -z "$seeds" ] || printf ' -stochastic stoch.dat'
	for f in $fvals; do for d in $dvals; do inpts "$f" "$d" || continue;
		for s in ${seedsfx:-""}; do R=f$f/d$d$s;
			printf ' \\\n\t  -p %s %s %s/measure.dat' "$f" "$d" "$R"
		done
	done; done
	printf ' || st=$$?; \\\n'
	printf '\t[ -s fem.dat ] || exit 1; \\\n'
	printf '\t$(DRAWPLOT) -noplot -t bossung.tpl -tl $(BOSSUNGTITLE) \\\n'
	printf '\t  -xl "focus (um)" -yl "CD (um)" -svg bossung.svg bossung.2D && mv -f dataplot.ps bossung.ps || exit 1; \\\n'
	printf '\tif [ -n "$(TARGET)" ]; then \\\n'
	printf '\t  $(FEMWIN) -target $(TARGET) -tol $(TOL) -o window.dat -plot window.2D \\\n'
	printf '\t    -region region.2D -region-template region.tpl fem.dat || exit 1; \\\n'
	printf '\t  $(DRAWPLOT) -noplot -tl "process window: cd $(TARGET) um +- $(TOL) %%" \\\n'
	printf '\t    -xl "exposure latitude (%%)" -yl "depth of focus (um)" -svg window.svg window.2D && \\\n'
	printf '\t    mv -f dataplot.ps window.ps || exit 1; \\\n'
	printf '\t  $(DRAWPLOT) -noplot -fill -t region.tpl -tl "in spec: CD $(TARGET) um +- $(TOL) %%" \\\n'
	printf '\t    -xl "focus (um)" -yl "dose (mJ/cm2)" -svg region.svg region.2D && \\\n'
	printf '\t    mv -f dataplot.ps region.ps || exit 1; \\\n'
	printf '\telse rm -f window.dat window.2D window.ps window.svg region.2D region.tpl region.ps region.svg; \\\n'
	printf '\tfi; exit $$st\n'
} | put Makefile

if [ -n "$slurm" ]; then
	# one array task per chunk of points; the images first, as their own
	# array.  submit.sh runs sbatch in DIR, the jobs' working directory, so
	# the #SBATCH lines name no path (sbatch does not parse sh quoting)
	nruns=$((npts * ${seeds:-1}))
	ntask=$(( (nruns + chunk - 1) / chunk ))
	dirq=$(shq "$dir")
	sbq=""
	for w in $sbopts; do sbq="$sbq $(shq "$w")"; done
	{
		echo "#!/bin/sh"
		printf '# The points of %s as a Slurm job array, written by fem(1);\n' "$dir"
		echo "# DIR/submit.sh submits it after the images.  Each task makes its points."
		echo "#SBATCH --job-name=fem-points"
		echo "#SBATCH --array=0-$((ntask - 1))"
		echo "#SBATCH --output=slurm/points-%a.out"
		echo "set -eu"
		printf 'cd %s\n' "$dirq"
		echo 'case $SLURM_ARRAY_TASK_ID in'
		k=0 t=0 line=""
		for f in $fvals; do for d in $dvals; do inpts "$f" "$d" || continue; for s in ${seedsfx:-""}; do R=f$f/d$d$s;
			line="$line $R/measure.dat"
			k=$((k + 1))
			if [ $k -eq "$chunk" ]; then
				echo "$t) set --$line ;;"
				t=$((t + 1)) k=0 line=""
			fi
		done; done; done
		[ -z "$line" ] || echo "$t) set --$line ;;"
		echo '*) echo "fem.sbatch: no task $SLURM_ARRAY_TASK_ID" >&2; exit 1 ;;'
		echo "esac"
		echo 'exec make -k -s --no-print-directory "$@"'
	} | put fem.sbatch
	{
		echo "#!/bin/sh"
		printf '# The per-focus images of %s as a Slurm job array, written by fem(1).\n' "$dir"
		echo "#SBATCH --job-name=fem-images"
		echo "#SBATCH --array=0-$((nf - 1))"
		echo "#SBATCH --output=slurm/images-%a.out"
		echo "set -eu"
		printf 'cd %s\n' "$dirq"
		echo 'case $SLURM_ARRAY_TASK_ID in'
		t=0
		for f in $fvals; do
			echo "$t) set -- f$f/image.cont${accuracy:+ f$f/image-coarse.cont} ;;"
			t=$((t + 1))
		done
		echo '*) echo "images.sbatch: no task $SLURM_ARRAY_TASK_ID" >&2; exit 1 ;;'
		echo "esac"
		echo 'exec make -s --no-print-directory "$@"'
	} | put images.sbatch
	{
		echo "#!/bin/sh"
		printf '# Submits the sweep %s to Slurm (written by fem(1)): the images,\n' "$dir"
		printf '# then the points with a dependency on them.  Afterwards: fem -collect -d %s\n' "$dir"
		echo "set -eu"
		printf 'cd %s\n' "$dirq"
		echo "mkdir -p slurm"
		printf 'img=$(sbatch --parsable%s images.sbatch)\n' "$sbq"
		printf 'pts=$(sbatch --parsable%s --dependency=afterok:${img%%%%;*} fem.sbatch)\n' "$sbq"
		echo "echo \"submitted: images job \${img%%;*}, points job \${pts%%;*} ($npts points in $ntask tasks)\""
		printf "echo 'when they are done: fem -collect -d '%s\\n" "$dirq"
	} | put submit.sh
	chmod +x "$dir/submit.sh"
	say "$dir: $npts points ($nf foci x $nd doses) as a Slurm array of $ntask tasks; run $dir/submit.sh, then fem -collect -d $dir"
	exit 0
fi

if [ -n "$dryrun" ]; then
	say "$dir: $npts points ($nf foci x $nd doses); run make -C $dir -j $jobs all, then fem -collect -d $dir"
	exit 0
fi

# The points finished so far: those with their measure.dat.
points_done() {
	set +f  # this glob is ours (set -f keeps the options' words from globbing)
	set -- "$dir"/f*/d*/measure.dat "$dir"/f*/d*/s*/measure.dat
	set -f
	_n=0
	for _m in "$@"; do [ ! -e "$_m" ] || _n=$((_n + 1)); done
	echo $_n
}
# progress_loop: "fem: K/N points" on stderr whenever K changes (polled
# each second while make runs in the foreground), the last K said kept in
# DIR/.progress.  It runs while DIR/.progress-on exists (made before the
# loop starts, never by it).  progress_stop removes that file, and kills
# the loop only once the loop has made DIR/.progress-ready: a TERM that
# reaches the new shell before it has dropped the traps it inherited from
# this one is lost there (dash), and the loop then ran forever while fem
# waited for it.  Unkilled, the loop sees the flag gone within a second.
progress_loop() {
	trap - INT TERM HUP
	: >"$dir/.progress-ready"
	last=-1
	while [ -e "$dir/.progress-on" ]; do
		k=$(points_done)
		[ "$k" = "$last" ] || { echo "$prog: $k/$npts points" >&2; echo "$k" >"$dir/.progress"; }
		last=$k
		sleep 1
	done
}
progress_pid=""
progress_stop() {
	rm -f "$dir/.progress-on"
	if [ -n "$progress_pid" ]; then
		[ ! -e "$dir/.progress-ready" ] || kill "$progress_pid" 2>/dev/null || :
		wait "$progress_pid" 2>/dev/null || :
	fi
	rm -f "$dir/.progress-ready"
	progress_pid=""
}
# Interrupted (^C, kill): the finished points stay (make wrote each
# atomically); the same command resumes from them.
interrupted() {
	progress_stop
	rm -f "$dir/.progress"
	echo "$prog: interrupted after $(points_done)/$npts points; run the same command again to resume" >&2
	exit 130
}
trap interrupted INT TERM HUP

say "$dir: $npts points ($nf foci x $nd doses), make -j $jobs"
# the CDs' discretisation error is not estimated unless asked: say so
[ -n "$accuracy" ] ||
	say "the CDs' discretisation error is not estimated: -accuracy check estimates it (one coarser solve a point), -accuracy 1 bounds it"
[ -n "$quiet" ] || { : >"$dir/.progress-on"; progress_loop & progress_pid=$!; }
st=0
make -k -s -C "$dir" --no-print-directory -j "$jobs" all || st=$?
progress_stop
# the last count, unless the loop said it already
[ -n "$quiet" ] || [ "$(points_done)" = "$(cat "$dir/.progress" 2>/dev/null)" ] ||
	echo "$prog: $(points_done)/$npts points" >&2
rm -f "$dir/.progress"
[ $st -eq 0 ] || echo "$prog: some points failed (their messages above); collecting the others" >&2
make -s -C "$dir" --no-print-directory collect || st=1
[ $st -ne 0 ] || say "$dir/fem.dat, $dir/bossung.ps${target:+, $dir/window.dat, $dir/window.ps, $dir/region.ps}"
exit $st
