#!/bin/sh
# sample2D - SAMPLE along a cutline (thesis 2.2.1, Figures 2.7 and 9.5):
# splat images the mask and samples the intensity along the cutline,
# bleach exposes and develops-rates that 2D section, etch2d develops it,
# drawplot draws the profiles.
#
#   sample2D -if mask.in -cut x1 y1 x2 y2 -bf resist.in -et 30 [-method M]
#
# Every option is checked before any stage runs; a failing stage stops the
# run with its own message, leaving the earlier stages' files:
# cut.2D (intensity along the cut; splat's image of the window goes to
# cutline.cont), rval.2D.binary (the 2D rate array), profile.plot and its
# picture profile2D.ps (not dataplot.ps, nor image.cont: a sample2D run
# beside a sample3D one keeps sample3D's files).  See man/man1/sample2D.1.
set -eu

prog=sample2D
usage() {
	cat <<'U'
usage: sample2D -if splat-inputfile -cut x1 y1 x2 y2 -bf bleach-inputfile
                -et etchtime [-pt printtime] [-npts n] [-method M]
                [-seg L] [-dt T] [-cells nx nz] [-plot] [-q]
  -if FILE         the mask (splat input file)
  -cut x1 y1 x2 y2 the cutline, um on the mask
  -npts n          points along the cutline (default 201)
  -bf FILE         the resist (bleach input file)
  -et TIME         development time, s
  -pt TIME         print interval, s (default: only the end)
  -method M        etch2d's method: raystring (default), string, ray, cell,
                   huygens or fmm; -seg, -dt, -cells pass to etch2d
  -plot            also preview the profiles on X11 (drawplot)
  -q               quiet: no progress lines
  -h, --help       this text
U
}
die() { echo "$prog: $*" >&2; exit 1; }
bad() { usage_error "$*"; }
say() { [ -n "$quiet" ] || echo "$prog: $*" >&2; }
need_val() { [ $# -ge 2 ] || bad "option $1 needs a value"; }
isnum() { case $1 in ''|*[!0-9.eE+-]*) return 1 ;; *) return 0 ;; esac; }

# the programs beside this script come first (an uninstalled build tree)
here=$(cd "$(dirname "$0")" && pwd)
[ -x "$here/etch2d" ] && PATH="$here:$PATH"
# usage_error (the two-line usage error with "did you mean"), shared with
# the other drivers: beside this script
[ -r "$here/etchopts.sh" ] || { echo "$prog: cannot find etchopts.sh beside $0" >&2; exit 1; }
. "$here/etchopts.sh"

splat_in="" bleach_in="" cut="" npts=201 etchtime="" printtime="" method=raystring
e2opts="" plot="" quiet=""
while [ $# -gt 0 ]; do
	case $1 in
	--help|-h) usage; exit 0 ;;
	-if) need_val "$@"; splat_in=$2; shift 2 ;;
	-bf) need_val "$@"; bleach_in=$2; shift 2 ;;
	-cut) [ $# -ge 5 ] || bad "option -cut needs four numbers: x1 y1 x2 y2"
		for v in "$2" "$3" "$4" "$5"; do isnum "$v" || bad "-cut: \"$v\" is not a number"; done
		cut="$2 $3 $4 $5"; shift 5 ;;
	-npts) need_val "$@"; npts=$2; shift 2
		case $npts in ''|*[!0-9]*) bad "-npts needs a whole number" ;; esac ;;
	-et) need_val "$@"; etchtime=$2; shift 2; isnum "$etchtime" || bad "-et needs a number" ;;
	-pt) need_val "$@"; printtime=$2; shift 2; isnum "$printtime" || bad "-pt needs a number" ;;
	-method) need_val "$@"; method=$2; shift 2
		case $method in raystring|string|ray|cell|huygens|fmm) ;;
		*) bad "unknown -method $method" ;; esac ;;
	-seg|-dt) need_val "$@"; isnum "$2" || bad "$1 needs a number"
		e2opts="$e2opts $1 $2"; shift 2 ;;
	-cells) [ $# -ge 3 ] || bad "option -cells needs two whole numbers"
		e2opts="$e2opts -cells $2 $3"; shift 3 ;;
	-plot) plot=yes; shift ;;
	-q) quiet=-q; shift ;;
	*) bad "unknown option $1" ;;
	esac
done
[ -n "$splat_in" ] || bad "no -if (the mask)"
[ -n "$cut" ] || bad "no -cut x1 y1 x2 y2"
[ -n "$bleach_in" ] || bad "no -bf (the resist)"
[ -n "$etchtime" ] || bad "no -et (the development time)"
[ -r "$splat_in" ] || die "$splat_in: cannot read the splat input file"
[ -r "$bleach_in" ] || die "$bleach_in: cannot read the bleach input file"

# splat reads the mask where it is (a relative gds FILE in it stays
# relative to its folder, and its errors name it) and writes only this
# cutline, in place of the input's own
say "splat $splat_in with the cutline $cut -> cut.2D"
# shellcheck disable=SC2086 # $cut is four numbers on purpose
splat -q -o cutline.cont -cutline $cut "$npts" cut.2D "$splat_in" || die "splat failed; stopping"
say "bleach -cutline cut.2D $bleach_in -> rval.2D.binary"
bleach -cutline $quiet -o rval.2D.binary cut.2D "$bleach_in" || die "bleach failed; stopping"
say "etch2d -method $method for ${etchtime}s${printtime:+, printing every ${printtime}s} -> profile.plot"
# shellcheck disable=SC2086 # e2opts is a list of words on purpose
etch2d -et "$etchtime" ${printtime:+-pt "$printtime"} -method "$method" $e2opts \
	-o profile.plot rval.2D.binary || die "etch2d failed; stopping"
# one page per print time, titled with the cut and its time (the print
# times as etch2d takes them: etch -print-times shares its rule)
times=$(etch -et "$etchtime" ${printtime:+-pt "$printtime"} -print-times) ||
	die "etch -print-times failed"
times=$(printf '%s' "$times" | tr '\n' ',')
# shellcheck disable=SC2086 # $cut is four numbers on purpose
set -- $cut
title="resist profile along ($1, $2) - ($3, $4) um, ${splat_in##*/}"
if [ -n "$plot" ]; then
	drawplot -e -times "$times" -tl "$title" -xl "distance along the cut (um)" -yl "z (um)" \
		-psfile profile2D.ps profile.plot </dev/null || die "drawplot failed"
else
	say "drawplot profile.plot -> profile2D.ps"
	drawplot -noplot -e -times "$times" -tl "$title" -xl "distance along the cut (um)" \
		-yl "z (um)" -psfile profile2D.ps profile.plot </dev/null || die "drawplot failed"
fi
