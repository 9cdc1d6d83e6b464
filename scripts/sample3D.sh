#!/bin/sh
# sample3D - the SAMPLE-3D driver: runs splat, bleach and etch in turn and
# plots the developed resist (thesis Appendix B, SAMPLE3D(L)).
#
#   sample3D -if mask.in -bf resist.in -et 30          splat, bleach, etch
#   sample3D -cf image.cont -bf resist.in [-et 30]     bleach (and etch)
#   sample3D -rb rval.3D.binary -et 30 -pt 10          etch only
#   sample3D -ra rval.3D -et 30                        etch only
#
# A stage runs only when its inputs are known; a failing stage stops the run
# with that stage's own message and a non-zero exit, leaving the outputs of
# the earlier stages in place.  See man/man1/sample3D.1.
set -eu

prog=sample3D
# the programs beside this script come first (a build's bin/, or where
# make install put them), then PATH: never another installed splat; a
# script run by a bare name (sh sample3D.sh) is in the current directory
here=.
case $0 in
*/*) here=$(cd "${0%/*}" && pwd) && PATH=$here:$PATH ;;
esac
# the etch pass-through options, shared with fem: beside this script too
[ -r "$here/etchopts.sh" ] || { echo "$prog: cannot find etchopts.sh beside $0" >&2; exit 1; }
. "$here/etchopts.sh"
# -tile: layouts beyond one window (stitch(1)), beside this script too
[ -r "$here/tile.sh" ] || { echo "$prog: cannot find tile.sh beside $0" >&2; exit 1; }
. "$here/tile.sh"
usage() {
	cat <<'U'
usage: sample3D [-if splat-inputfile] [-cf contour-file] [-bf bleach-inputfile]
                [-solid] [-ascii] [-rb binary-etchrate-file] [-ra ascii-etchrate-file]
                [-et etchtime] [-pt printtime] [-plot] [-hidden] [-e | -noe]
                [-cut x|y VALUE|mid] [-last] [-pwindow X0 X1 Y0 Y1|all]
                [-measure "ARGS" [-accuracy [P|check|off]]]
                [-tile W [-halo H] [-j N] [-tiledir D] [-slurm]]
                [etch options] [-q]
  -if FILE    run splat on FILE; its contour-file goes on to bleach
  -cf FILE    the aerial image (contour-file), bypassing splat
  -bf FILE    run bleach with FILE (needs -if or -cf)
  -solid      bleach also writes mxyz.solid.3D
  -ascii      bleach writes rval.3D instead of rval.3D.binary
  -rb FILE    binary etch-rate file, bypassing splat and bleach
  -ra FILE    ASCII etch-rate file, bypassing splat and bleach
  -et TIME    development time (s); etch runs only when it is given
  -pt TIME    print interval (s)
  -plot       interactive pdraw of the result (X11)
  -hidden     the profile as the thesis' hidden-line mesh (default: shaded)
  -e          the profile with every axis scaled to the same length
  -noe        the profile at true scale (default: z stretched when thin)
  -cut x|y V  the cross-section picture's plane (default: y through the
              image's row of features, contour -cutrow; y mid without
              an image); also written by etch to curves.cut
  -last       etch writes only the final set, and the pictures show it
  -pwindow X0 X1 Y0 Y1|all  the part of the window profile.ps shows (um;
              default: the central 6 x 6 um of a window wider than 12 um)
  -q          quiet: no progress lines
  -measure "ARGS"  after etch, measure ARGS on the final set of curves.plot
              and print the table, e.g. -measure "-rel 10,50,90 -hole 0 0";
              etch is fast marching (-method fmm) unless an etch option
              chooses the engine
  -accuracy [P]  with -measure, -if and -bf: refine the image grid, nz
              and etch's resolution until every CD's estimated error is
              under P % (default 1); the table gains the column err (um)
  -accuracy check  the estimate at the inputs' own grids, no refinement
              (the default with -measure, -if and -bf; a warning when
              an err is over 1 %)
  -accuracy off  no estimate: the CDs of the inputs' grids alone
  -h, --help  this text
U
	tile_usage
	etchopts_usage
}
die() { echo "$prog: $*" >&2; exit 1; }
bad() { usage_error "$*"; }
say() { [ -n "$quiet" ] || echo "$prog: $*" >&2; }
need_val() { [ $# -ge 2 ] || bad "option $1 needs a value"; }

splat_in="" contour="" bleach_in="" solid="" ascii="" rate="" etchtime=""
printtime="" plot="" hidden="" quiet="" etchopts="" stretch="-zs auto"
cutaxis="" cutval="" measureopts="" last="" accuracy="" pwindow="-window auto"
while [ $# -gt 0 ]; do
	case $1 in
	-h|--help) usage; exit 0 ;;
	-if) need_val "$@"; splat_in=$2; shift 2 ;;
	-cf) need_val "$@"; contour=$2; shift 2 ;;
	-bf) need_val "$@"; bleach_in=$2; shift 2 ;;
	-solid) solid=-solid; shift ;;
	-ascii) ascii=-ascii; shift ;;
	-rb|-ra) need_val "$@"; rate=$2; shift 2 ;;
	-et) need_val "$@"; etchtime=$2; shift 2 ;;
	-pt) need_val "$@"; printtime=$2; shift 2 ;;
	-plot) plot=yes; shift ;;
	-hidden) hidden=yes; shift ;;
	-e) stretch=-e; shift ;;
	-noe) stretch="-zs 1"; shift ;;
	-q) quiet=-q; shift ;;
	-last) etchopts="$etchopts -last"; last=yes; shift ;;
	-cut) [ $# -ge 3 ] || bad "option -cut needs an axis and a value"
		cutaxis=$2 cutval=$3; shift 3 ;;
	-measure) need_val "$@"; measureopts=$2; shift 2 ;;
	-pwindow) if [ "${2:-}" = all ]; then pwindow="" && shift 2
		else [ $# -ge 5 ] || bad "option -pwindow needs x0 x1 y0 y1 or all"
			for v in "$2" "$3" "$4" "$5"; do
				case $v in ''|*[!0-9.eE+-]*) bad "-pwindow: \"$v\" is not a number" ;; esac
			done
			pwindow="-window $2 $3 $4 $5"; shift 5
		fi ;;
	-accuracy) if [ "${2:-}" = off ]; then accuracy=off; shift 2
		else accuracy_opt "$@"; shift "$etchopt_n"; fi ;;
	-tile|-halo|-j|-tiledir|-slurm) tile_opt "$@"; shift "$tile_n" ;;
	*) etchopt "$@" || bad "unknown option $1"; shift "$etchopt_n" ;;
	esac
done

# the cross-section through the middle of the cell unless -cut says (or
# the image's row of features, chosen once the image is made)
cutauto=""
[ -n "$cutaxis" ] || cutaxis=y cutval=mid cutauto=yes
etchopts="$etchopts -cut $cutaxis $cutval"

[ -n "$splat_in$contour$bleach_in$rate" ] || bad "nothing to do: give -if, -cf with -bf, -rb or -ra"
[ -z "$rate" ] || [ -z "$splat_in$contour$bleach_in" ] ||
	bad "-rb/-ra bypass splat and bleach: do not combine them with -if, -cf or -bf"
[ -z "$splat_in" ] || [ -z "$contour" ] || bad "give either -if or -cf, not both"
[ -z "$measureopts" ] || [ -n "$etchtime" ] || bad "-measure needs -et (it measures etch's result)"
if [ -n "$accuracy" ] && [ "$accuracy" != off ]; then
	[ -n "$measureopts" ] || bad "-accuracy needs -measure (it bounds the error of the CDs)"
	[ -n "$splat_in" ] && [ -n "$bleach_in" ] ||
		bad "-accuracy refines splat's and bleach's grids: give -if and -bf"
fi
# the CDs' discretisation error is estimated unless asked not to: at the
# inputs' grids (check) whenever the grids can be coarsened, -if and -bf
# (levels -2 and -1 cost about a seventh of the run); a tiled run is
# estimated a tile at a time by hand (tile.sh)
if [ -z "$accuracy" ] && [ -z "$tile_w" ] && [ -n "$measureopts" ] && [ -n "$splat_in" ] && [ -n "$bleach_in" ]; then
	accuracy=check
fi
[ "$accuracy" != off ] || accuracy=""
# the engine measure reads: fast marching unless an etch option says
[ -z "$measureopts" ] || etch_engine_default
if [ -n "$measureopts" ]; then
	# measure's options are checked before any stage runs: on an empty
	# input it stops with 1 if they are good, 2 (and its usage) if not
	# shellcheck disable=SC2086
	measure $measureopts /dev/null >/dev/null 2>&1 || [ $? -ne 2 ] ||
		{ measure $measureopts /dev/null >/dev/null; exit 2; }
fi

tile_check

# Check everything before running anything: a bad etch option must not
# cost a splat and a bleach run and their overwritten outputs.
[ -z "$splat_in" ] || [ -r "$splat_in" ] || die "$splat_in: cannot read the splat input file"
[ -z "$contour" ] || [ -n "$splat_in" ] || [ -r "$contour" ] ||
	die "$contour: cannot read the contour-file"
[ -z "$bleach_in" ] || [ -r "$bleach_in" ] || die "$bleach_in: cannot read the bleach input file"
[ -z "$bleach_in" ] || [ -n "$contour$splat_in" ] || bad "-bf needs the aerial image: give -if or -cf"
[ -z "$rate" ] || [ -r "$rate" ] || die "$rate: cannot read the etch-rate file"
if [ -n "$etchtime" ]; then
	[ -n "$rate$bleach_in" ] || bad "-et needs an etch-rate file: give -rb, -ra, or -bf"
	# shellcheck disable=SC2086 # etchopts is a list of words on purpose
	if ! err=$(etch -n -et "$etchtime" ${printtime:+-pt "$printtime"} $etchopts \
		"${rate:-rval.3D.binary}" 2>&1 >/dev/null); then
		printf '%s\n' "$err" | head -n 1 >&2
		exit 2
	fi
fi

# the resist file is read up front (bleach -check): a mistake in it, such
# as "develop kimm", is reported before splat runs
[ -z "$bleach_in" ] || bleach -check "$bleach_in" || exit 1
[ -z "$tile_w" ] || { tile_run; exit 0; }   # -tile: tile.sh runs and stitches

# -accuracy: splat, bleach, etch and measure level after level (etchopts.sh
# accuracy_loop), in this directory, so that the files left are those of
# the table printed; each level's table is kept in accuracy/
acc_solve() { # acc_solve "NX NY NZ" ETCHOPTS
	# shellcheck disable=SC2086 # the grid is three words on purpose
	set -- $1 "$2"
	say "accuracy: splat -grid $1 $2, bleach -nz $3, etch$4"
	splat $quiet -grid "$1" "$2" -bf "$bleach_in" "$splat_in" ||
		{ echo "$prog: splat failed" >&2; return 1; }
	bleach $quiet $ascii $solid -nz "$3" -o "$rate" "$contour" "$bleach_in" ||
		{ echo "$prog: bleach failed" >&2; return 1; }
	# shellcheck disable=SC2086 # etch's options are a list of words on purpose
	etch $quiet -et "$etchtime" ${printtime:+-pt "$printtime"} $4 "$rate" ||
		{ echo "$prog: etch failed" >&2; return 1; }
	acc_surface=curves.plot
}
if [ -n "$accuracy" ]; then
	grid=$(femwin -resolution "$splat_in" "$bleach_in") || exit 1
	contour=$(splat -name "$splat_in") || exit 1
	if [ -n "$ascii" ]; then rate=rval.3D; else rate=rval.3D.binary; fi
	mkdir -p accuracy || die "cannot make the directory accuracy"
	margs=$measureopts st=0
	# shellcheck disable=SC2086 # the grid is three words on purpose
	accuracy_loop measure "$accuracy" $grid accuracy || st=$?
	[ $st -ne 1 ] || die "-accuracy: a stage failed; stopping"
	cat "$acc_table"
	if [ $st -eq 3 ]; then
		die "-accuracy $accuracy: not reached at grid $acc_grid (the err column above); stopping"
	fi
	# check: say when the inputs' grids hold the CDs to less than the
	# default 1 %, or the levels are not in the asymptotic range
	if [ "$accuracy" = check ] && ! head -n 1 "$acc_table" | grep -q ' err$'; then
		echo "$prog: warning: no estimate of the CDs' discretisation error: the coarser levels could not be measured (accuracy/*.log)" >&2
	elif [ "$accuracy" = check ]; then
		if ! awk '!/^#/ && $NF > 0.01 * $2 { exit 1 }' "$acc_table" ||
			grep -q 'asymptotic' "$acc_log"; then
			echo "$prog: warning: at the inputs' grids a CD's estimated discretisation error is over 1 % (the err column): -accuracy 1 refines the grid" >&2
		fi
	fi
	say "accuracy: grid $acc_grid (nx ny nz), the tables of every level in accuracy/"
fi

# splat: the contour-file is the one the input names (its "contour" line),
# else splat's default splat.cont
if [ -n "$splat_in" ] && [ -z "$accuracy" ]; then
	[ -r "$splat_in" ] || die "$splat_in: cannot read the splat input file"
	contour=$(splat -name "$splat_in") || exit 1
	say "splat $splat_in -> $contour"
	# -bf: an imaging vector input images through the resist file's film
	splat $quiet ${bleach_in:+-bf "$bleach_in"} "$splat_in" || die "splat failed; stopping"
fi

if [ -n "$accuracy" ]; then
	:       # bleach, etch and measure ran above
elif [ -n "$bleach_in" ]; then
	[ -n "$contour" ] || bad "-bf needs the aerial image: give -if or -cf"
	if [ -n "$ascii" ]; then rate=rval.3D; else rate=rval.3D.binary; fi
	say "bleach $contour $bleach_in -> $rate${solid:+ and mxyz.solid.3D}"
	bleach $quiet $ascii $solid -o "$rate" "$contour" "$bleach_in" || die "bleach failed; stopping"
elif [ -n "$contour" ] && [ -z "$splat_in" ]; then
	bad "-cf needs -bf (the bleach input file)"
fi

if [ -z "$etchtime" ]; then
	[ -z "$printtime" ] || say "no -et: etch does not run, -pt ignored"
	exit 0
fi
[ -n "$rate" ] || bad "-et needs an etch-rate file: give -rb, -ra, or -bf"
# no -cut: the row of the image whose intensity varies most (contour
# -cutrow), so that the cross-section of an array runs through a row of
# its features, not between two rows
if [ -n "$cutauto" ] && [ -n "$contour" ] && [ -z "$accuracy" ]; then
	cutval=$(contour -cutrow "$contour") || die "contour -cutrow failed"
	etchopts="${etchopts% -cut y mid} -cut y $cutval"
fi
if [ -z "$accuracy" ]; then
	say "etch $rate for ${etchtime}s${printtime:+, printing every ${printtime}s} -> curves.plot"
	# shellcheck disable=SC2086 # etchopts is a list of words on purpose
	etch $quiet -et "$etchtime" ${printtime:+-pt "$printtime"} $etchopts "$rate" ||
		die "etch failed; stopping"
fi

if [ -n "$measureopts" ] && [ -z "$accuracy" ]; then
	say "measure $measureopts curves.plot (the last set)"
	# shellcheck disable=SC2086 # measureopts is a list of words on purpose
	measure $measureopts curves.plot || die "measure failed; stopping"
fi

# The pictures (sample3D(1), PICTURES): profile.ps, the developed resist
# as a solid block, one page per print time; cut.ps, the cross-section;
# image.ps, the aerial image when splat ran.  dataplot.ps is the profile
# (the thesis' name for sample3D's picture).
[ -z "$last" ] || printtime=""      # -last: the final set only
# the print times as etch takes them (etch -print-times: every pt, and
# the end), comma-separated for -times
times=$(etch -et "$etchtime" ${printtime:+-pt "$printtime"} -print-times) ||
	die "etch -print-times failed"
times=$(printf '%s' "$times" | tr '\n' ',')
look="-walls -shade"
[ -z "$hidden" ] || look="-walls"
# the feature: the mask (or image) file, with its folder when it has one
feature=${splat_in:-${contour:-$rate}}
case $feature in */*/*) fdir=${feature%/*}; feature=${fdir##*/}/${feature##*/} ;; esac
# pdraw draws a mesh finer than its pixels shaded in a picture of a
# bounded size (pdraw -raster), so a large window's profile stays small
# shellcheck disable=SC2086 # stretch, look and pwindow are lists of words
if [ -n "$plot" ]; then
	say "pdraw curves.plot (interactive) -> profile.ps"
	pdraw -h $look $stretch $pwindow -times "$times" -tl "developed resist, $feature" \
		-xl "x (um)" -yl "y (um)" -zl "z (um)" -psfile profile.ps curves.plot ||
		die "pdraw failed"
else
	say "pdraw curves.plot -> profile.ps"
	pdraw -noplot -h $look $stretch $pwindow -times "$times" -tl "developed resist, $feature" \
		-xl "x (um)" -yl "y (um)" -zl "z (um)" -psfile profile.ps curves.plot ||
		die "pdraw failed"
fi
# the same file under the thesis' name (a link: no second copy on disk)
rm -f dataplot.ps
ln profile.ps dataplot.ps 2>/dev/null || cp profile.ps dataplot.ps || die "cannot write dataplot.ps"
if [ "$cutaxis" = y ]; then across=x; else across=y; fi
if [ "$cutval" = mid ]; then where="through the middle of the cell"; else where="at $cutaxis = $cutval um"; fi
[ -z "$cutauto" ] || [ "$cutval" = mid ] || where="$where (the row of features)"
say "drawplot curves.cut -> cut.ps"
drawplot -noplot -section -times "$times" -tl "cross-section $where, $feature" \
	-xl "$across (um)" -yl "z (um)" -psfile cut.ps curves.cut || die "drawplot failed"
if [ -n "$splat_in" ]; then
	# an array's many contours are drawn as a grey map (contour -map)
	say "contour $contour -> image.ps"
	contour -noplot -tl "aerial image, $feature" -xl "x (um)" -yl "y (um)" -psfile image.ps \
		"$contour" || die "contour failed"
fi
