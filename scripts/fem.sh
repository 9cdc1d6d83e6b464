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
set -eu

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
           [-target CD -tol PCT] [-d DIR] [-j N] [-keep] [-n]
           [-slurm [-chunk K] [-sbatch "OPTS"]] [etch options] [-q]
       fem -collect [-d DIR] [-target CD -tol PCT] [-q]
  -if FILE      splat input file (the mask and the optics)
  -bf FILE      bleach input file (the resist)
  -et T         development time (s)
  -dose LIST    doses (mJ/cm2): first:last:step or a list a,b,c
  -focus LIST   foci (um, splat -defocus): first:last:step or a list
  -measure ARGS measure's arguments for every point, without -o and file,
                e.g. "-rel 10,90 -hole 0 0"; cd is at the first height
  -target CD    with -tol: the process window for this CD (um)
  -tol PCT      in spec when |cd - CD| <= PCT % of CD
  -d DIR        the sweep's directory (default fem)
  -j N          points run at once (make -j N; default: the cores)
  -keep         keep every point's rate file and curves.plot
  -n            write DIR and its Makefile, run nothing
  -slurm        write DIR/fem.sbatch and DIR/submit.sh, submit nothing
  -chunk K      with -slurm: K points per array task (default 1)
  -sbatch OPTS  with -slurm: options submit.sh gives sbatch (e.g. "-p short")
  -collect      collect DIR into fem.dat, bossung.ps and the window
  -q            quiet: no progress lines
  -h, --help    this text
U
	etchopts_usage
}
die() { echo "$prog: $*" >&2; exit 1; }
# a usage error: one line (and where the usage is), exit 2
bad() { usage_error "$*"; }
# a wrong value: one line, exit 2
badv() { echo "$prog: $*" >&2; exit 2; }
say() { [ -n "$quiet" ] || echo "$prog: $*" >&2; }
need_val() { [ $# -ge 2 ] || bad "option $1 needs a value"; }

mask="" resist="" etchtime="" doses="" foci="" margs="" target="" tol=""
dir=fem jobs="" keep="" dryrun="" slurm="" chunk=1 sbopts="" collect="" quiet=""
etchopts=""
while [ $# -gt 0 ]; do
	case $1 in
	--help|-h) usage; exit 0 ;;
	-if) need_val "$@"; mask=$2; shift 2 ;;
	-bf) need_val "$@"; resist=$2; shift 2 ;;
	-et) need_val "$@"; etchtime=$2; shift 2 ;;
	-dose) need_val "$@"; doses=$2; shift 2 ;;
	-focus) need_val "$@"; foci=$2; shift 2 ;;
	-measure) need_val "$@"; margs=$2; shift 2 ;;
	-target) need_val "$@"; target=$2; shift 2 ;;
	-tol) need_val "$@"; tol=$2; shift 2 ;;
	-d) need_val "$@"; dir=$2; shift 2 ;;
	-j) need_val "$@"; jobs=$2; shift 2 ;;
	-keep) keep=yes; shift ;;
	-n) dryrun=yes; shift ;;
	-slurm) slurm=yes; shift ;;
	-chunk) need_val "$@"; chunk=$2; shift 2 ;;
	-sbatch) need_val "$@"; sbopts=$2; shift 2 ;;
	-collect) collect=yes; shift ;;
	-q) quiet=-q; shift ;;
	*) etchopt "$@" || bad "unknown option $1"; shift "$etchopt_n" ;;
	esac
done

isnum() { # isnum WORD: a decimal number
	printf '%s\n' "$1" | grep -Eq '^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$'
}
posnum() { isnum "$1" && awk -v v="$1" 'BEGIN { exit !(v > 0) }'; }

# the programs: beside this script first ($here), then PATH
findprog() {
	if [ -x "$here/$1" ] && [ ! -d "$here/$1" ]; then
		echo "$here/$1"
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
	[ -z "$mask$resist$etchtime$doses$foci$margs$slurm$dryrun$keep$etchopts" ] ||
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
[ -n "$doses" ] || bad "-dose is required"
[ -n "$foci" ] || bad "-focus is required"
[ -n "$margs" ] || bad "-measure is required (e.g. -measure \"-rel 10 -hole 0 0\")"
posnum "$etchtime" || badv "-et $etchtime: expected a positive time (s)"
case $chunk in ''|*[!0-9]*|0*) badv "-chunk $chunk: expected a whole number >= 1" ;; esac
if [ -n "$jobs" ]; then
	case $jobs in ''|*[!0-9]*|0*) badv "-j $jobs: expected a whole number >= 1" ;; esac
else
	jobs=$(nproc 2>/dev/null || echo 1)
fi
[ -z "$slurm" ] || [ -z "$dryrun" ] || bad "-slurm already runs nothing: drop -n"
[ -n "$slurm" ] || { [ "$chunk" = 1 ] && [ -z "$sbopts" ]; } || bad "-chunk and -sbatch go with -slurm"
for w in $margs; do
	case $w in
	-o|-plot) badv "-measure: fem gives measure its output file; drop $w" ;;
	esac
done
case $dir$(pwd)$here in *[!A-Za-z0-9._/+-]*) badv "-d $dir: use letters, digits and ._/+- only, in it and in the paths of the current directory and of fem (make needs plain names)" ;; esac

# expand LIST: first:last:step or a,b,c -> one value per line, ascending
expand() { # expand WHAT LIST
	case $2 in
	*:*:*)
		IFS=: read -r a b s <<E
$2
E
		isnum "$a" && isnum "$b" && isnum "$s" || badv "-$1 $2: expected first:last:step"
		awk -v a="$a" -v b="$b" -v s="$s" 'BEGIN {
			if (!(s > 0)) exit 3
			for (k = 0; a + k * s <= b + 1e-9 * s; k++) {
				v = a + k * s
				if (v < 1e-12 * s && v > -1e-12 * s) v = 0
				printf "%.10g\n", v
			}
		}' || badv "-$1 $2: the step must be positive" ;;
	*)
		for v in $(echo "$2" | tr ',' ' '); do
			isnum "$v" || badv "-$1 $2: $v is not a number"
			awk -v v="$v" 'BEGIN { printf "%.10g\n", v + 0 }'
		done ;;
	esac
}
fvals=$(expand focus "$foci") || exit 2
dvals=$(expand dose "$doses") || exit 2
[ -n "$fvals" ] || badv "-focus $foci: no focus in that range"
[ -n "$dvals" ] || badv "-dose $doses: no dose in that range"
for v in $dvals; do posnum "$v" || badv "-dose $doses: doses must be positive ($v)"; done
printf '%s\n' "$fvals" | sort -c -u -g 2>/dev/null || badv "-focus $foci: give the foci in ascending order, each once"
printf '%s\n' "$dvals" | sort -c -u -g 2>/dev/null || badv "-dose $doses: give the doses in ascending order, each once"
nf=$(printf '%s\n' "$fvals" | wc -l)
nd=$(printf '%s\n' "$dvals" | wc -l)
npts=$((nf * nd))

[ -r "$mask" ] || die "$mask: cannot read the splat input file"
[ -r "$resist" ] || die "$resist: cannot read the bleach input file"
SPLAT=$(findprog splat)
BLEACH=$(findprog bleach)
ETCH=$(findprog etch)
MEASURE=$(findprog measure)
command -v make >/dev/null 2>&1 || die "cannot find make (GNU make runs the sweep)"
"$SPLAT" --help 2>&1 | grep -q -- -defocus || die "$SPLAT has no -defocus: this splat cannot sweep focus"
"$BLEACH" --help 2>&1 | grep -q -- -dose || die "$BLEACH has no -dose: this bleach cannot sweep dose"

# check every stage's arguments before anything runs: the inputs through
# femwin -probe (the library's readers), etch's options on a missing file
# (a usage error exits 2 before any file is opened), and measure's on the
# probe surface (the undeveloped resist over the mask window)
chk=$(mktemp -d "${TMPDIR:-/tmp}/fem.XXXXXX") || die "cannot make a temporary directory"
trap 'rm -rf "$chk"' EXIT
"$FEMWIN" -probe "$mask" "$resist" -o "$chk/probe.plot" 2>"$chk/err" ||
	die "$(sed -n '1{s/^femwin: //;p;}' "$chk/err")"
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

# DIR: the inputs (copied, so that the sweep does not change under a later
# edit), the options each stage depends on, and the Makefile; a file is
# replaced only when its content changes, so make redoes exactly the work
# whose inputs changed and nothing else
mkdir -p "$dir" || die "$dir: cannot make the directory"
dir=$(cd "$dir" && pwd)
put() { # put FILE: stdin becomes FILE if different
	cat >"$dir/.new"
	if cmp -s "$dir/.new" "$dir/$1"; then rm -f "$dir/.new"; else mv -f "$dir/.new" "$dir/$1"; fi
}
put mask.in <"$mask"
put resist.in <"$resist"
echo "-et $etchtime$etchopts" | put etch.opts
echo "$margs" | put measure.opts

fname() { echo "f$1"; }
dname() { echo "d$1"; }
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
	echo "# The focus-exposure matrix $dir, written by fem(1): $nf foci x $nd doses."
	echo "# make -j N all runs the sweep (resumable); make collect writes fem.dat,"
	echo "# bossung.2D/.ps/.svg and, with TARGET and TOL, window.dat/.ps."
	echo "SPLAT = $SPLAT"
	echo "BLEACH = $BLEACH"
	echo "ETCH = $ETCH"
	echo "MEASURE = $MEASURE"
	echo "FEMWIN = $FEMWIN"
	echo "DRAWPLOT = $DRAWPLOT"
	echo "ETCHOPTS = -et $etchtime$etchopts"
	echo "MEASUREARGS = $margs"
	echo "TARGET = $target"
	echo "TOL = $tol"
	echo "RUN = sh stage.sh"
	if [ -n "$keep" ]; then echo "CLEAN = :"; else echo "CLEAN = rm -f"; fi
	echo
	echo ".DELETE_ON_ERROR:"
	echo ".PHONY: all images collect"
	printf 'all:'
	for f in $fvals; do for d in $dvals; do printf ' %s/%s/measure.dat' "$(fname "$f")" "$(dname "$d")"; done; done
	echo
	printf 'images:'
	for f in $fvals; do printf ' %s/image.cont' "$(fname "$f")"; done
	echo
	# intermediates: not rebuilt when a point's measure.dat is up to date
	printf '.SECONDARY:'
	for f in $fvals; do for d in $dvals; do
		printf ' %s/%s/rate %s/%s/curves.plot' "$(fname "$f")" "$(dname "$d")" "$(fname "$f")" "$(dname "$d")"
	done; done
	echo
	for f in $fvals; do
		F=$(fname "$f")
		echo
		echo "$F/image.cont: mask.in"
		printf '\t@mkdir -p %s\n' "$F"
		printf '\t@$(RUN) %s/splat.log "focus %s: splat" $@ $(SPLAT) -q -defocus %s -o $@ mask.in\n' "$F" "$f" "$f"
		for d in $dvals; do
			P=$F/$(dname "$d")
			echo "$P/rate: $F/image.cont resist.in"
			printf '\t@mkdir -p %s\n' "$P"
			printf '\t@$(RUN) %s/bleach.log "focus %s dose %s: bleach" $@ $(BLEACH) -q -dose %s -o $@ %s/image.cont resist.in\n' "$P" "$f" "$d" "$d" "$F"
			echo "$P/curves.plot: $P/rate etch.opts"
			printf '\t@$(RUN) %s/etch.log "focus %s dose %s: etch" $@ $(ETCH) -q $(ETCHOPTS) -o $@ %s/rate\n' "$P" "$f" "$d" "$P"
			echo "$P/measure.dat: $P/curves.plot measure.opts"
			printf '\t@$(RUN) %s/measure.log "focus %s dose %s: measure" $@ $(MEASURE) $(MEASUREARGS) -o $@ %s/curves.plot\n' "$P" "$f" "$d" "$P"
			printf '\t@$(CLEAN) %s/rate %s/curves.plot %s/curves.plot.2D\n' "$P" "$P" "$P"
		done
	done
	echo
	echo "# the tables and plots, from whatever points have finished"
	echo "collect:"
	printf '\t@st=0; $(FEMWIN) -collect -o fem.dat -bossung bossung.2D -template bossung.tpl'
	for f in $fvals; do for d in $dvals; do
		printf ' \\\n\t  -p %s %s %s/%s/measure.dat' "$f" "$d" "$(fname "$f")" "$(dname "$d")"
	done; done
	printf ' || st=$$?; \\\n'
	printf '\t[ -s fem.dat ] || exit 1; \\\n'
	printf '\t$(DRAWPLOT) -noplot -t bossung.tpl -tl "Bossung curves: cd against focus" \\\n'
	printf '\t  -xl "focus (um)" -yl "cd (um)" -svg bossung.svg bossung.2D && mv -f dataplot.ps bossung.ps || exit 1; \\\n'
	printf '\tif [ -n "$(TARGET)" ]; then \\\n'
	printf '\t  $(FEMWIN) -target $(TARGET) -tol $(TOL) -o window.dat -plot window.2D \\\n'
	printf '\t    -region region.2D -region-template region.tpl fem.dat || exit 1; \\\n'
	printf '\t  $(DRAWPLOT) -noplot -tl "process window: cd $(TARGET) um +- $(TOL) %%" \\\n'
	printf '\t    -xl "exposure latitude (%%)" -yl "depth of focus (um)" -svg window.svg window.2D && \\\n'
	printf '\t    mv -f dataplot.ps window.ps || exit 1; \\\n'
	printf '\t  $(DRAWPLOT) -noplot -t region.tpl -tl "in spec: cd $(TARGET) um +- $(TOL) %%" \\\n'
	printf '\t    -xl "focus (um)" -yl "dose (mJ/cm2)" -svg region.svg region.2D && \\\n'
	printf '\t    mv -f dataplot.ps region.ps || exit 1; \\\n'
	printf '\telse rm -f window.dat window.2D window.ps window.svg region.2D region.tpl region.ps region.svg; \\\n'
	printf '\tfi; exit $$st\n'
} | put Makefile

if [ -n "$slurm" ]; then
	# one array task per chunk of points; the images first, as their own array
	ntask=$(( (npts + chunk - 1) / chunk ))
	{
		echo "#!/bin/sh"
		echo "# The points of $dir as a Slurm job array, written by fem(1);"
		echo "# DIR/submit.sh submits it after the images.  Each task makes its points."
		echo "#SBATCH --job-name=fem-points"
		echo "#SBATCH --array=0-$((ntask - 1))"
		echo "#SBATCH --chdir=$dir"
		echo "#SBATCH --output=$dir/slurm/points-%a.out"
		echo "set -eu"
		echo "cd $dir"
		echo 'case $SLURM_ARRAY_TASK_ID in'
		k=0 t=0 line=""
		for f in $fvals; do for d in $dvals; do
			line="$line $(fname "$f")/$(dname "$d")/measure.dat"
			k=$((k + 1))
			if [ $k -eq "$chunk" ]; then
				echo "$t) set --$line ;;"
				t=$((t + 1)) k=0 line=""
			fi
		done; done
		[ -z "$line" ] || echo "$t) set --$line ;;"
		echo '*) echo "fem.sbatch: no task $SLURM_ARRAY_TASK_ID" >&2; exit 1 ;;'
		echo "esac"
		echo 'exec make -k -s --no-print-directory "$@"'
	} | put fem.sbatch
	{
		echo "#!/bin/sh"
		echo "# The per-focus images of $dir as a Slurm job array, written by fem(1)."
		echo "#SBATCH --job-name=fem-images"
		echo "#SBATCH --array=0-$((nf - 1))"
		echo "#SBATCH --chdir=$dir"
		echo "#SBATCH --output=$dir/slurm/images-%a.out"
		echo "set -eu"
		echo "cd $dir"
		echo 'case $SLURM_ARRAY_TASK_ID in'
		t=0
		for f in $fvals; do echo "$t) set -- $(fname "$f")/image.cont ;;"; t=$((t + 1)); done
		echo '*) echo "images.sbatch: no task $SLURM_ARRAY_TASK_ID" >&2; exit 1 ;;'
		echo "esac"
		echo 'exec make -s --no-print-directory "$@"'
	} | put images.sbatch
	{
		echo "#!/bin/sh"
		echo "# Submits the sweep $dir to Slurm (written by fem(1)): the images,"
		echo "# then the points with a dependency on them.  Afterwards: fem -collect -d $dir"
		echo "set -eu"
		echo "cd $dir"
		echo "mkdir -p slurm"
		echo "img=\$(sbatch --parsable $sbopts images.sbatch)"
		echo "pts=\$(sbatch --parsable $sbopts --dependency=afterok:\${img%%;*} fem.sbatch)"
		echo "echo \"submitted: images job \${img%%;*}, points job \${pts%%;*} ($npts points in $ntask tasks)\""
		echo "echo \"when they are done: fem -collect -d $dir\""
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
	set -- "$dir"/f*/d*/measure.dat
	if [ -e "$1" ]; then echo $#; else echo 0; fi
}
# progress_loop: "fem: K/N points" on stderr whenever K changes (polled
# each second while make runs in the foreground; killed after it), the
# last K said kept in DIR/.progress.
progress_loop() {
	last=-1
	while :; do
		k=$(points_done)
		[ "$k" = "$last" ] || { echo "$prog: $k/$npts points" >&2; echo "$k" >"$dir/.progress"; }
		last=$k
		sleep 1
	done
}
progress_pid=""
progress_stop() {
	[ -z "$progress_pid" ] || { kill "$progress_pid" 2>/dev/null || :; wait "$progress_pid" 2>/dev/null || :; }
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
[ -n "$quiet" ] || { progress_loop & progress_pid=$!; }
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
