#!/bin/sh
# docs/make-images.sh [BUILD] - remakes the pictures of
# docs/walkthrough.md (docs/img/*.png) from our own PostScript, rendered by
# ghostscript.  Run after a change that alters the plots.
set -eu
TOP=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-build}
case $BUILD in /*) ;; *) BUILD=$TOP/$BUILD ;; esac
PATH=$BUILD/bin:$PATH
export LC_ALL=C
unset DISPLAY
E=$TOP/examples/contact
work=$(mktemp -d "${TMPDIR:-/tmp}/s3dimg.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
cd "$work"
png() { # png NAME [PAGE] [FILE]: FILE (default dataplot.ps) page PAGE (default: last) -> docs/img/NAME.png
	f=${3:-dataplot.ps}
	n=$(grep -c '^%%Page: ' "$f")
	p=${2:-$n}
	gs -q -dSAFER -dBATCH -dNOPAUSE -sPAPERSIZE=letter -dFIXEDMEDIA -sDEVICE=png16m \
		-dTextAlphaBits=4 -dGraphicsAlphaBits=4 -r60 -dFirstPage="$p" -dLastPage="$p" \
		-sOutputFile="$TOP/docs/img/$1.png" "$f" </dev/null
}
drawmask -noplot -lbl "$E/mask.in"; png mask
sample3D -q -if "$E/mask.in" -bf "$E/resist.in" -et 60 -pt 20 -solid -deloop
contour -noplot -cstep 0.1 -tl "Aerial image, 1.25 um contact" -xl "x (um)" -yl "y (um)" image.cont
png aerial
pdraw -noplot -h -nosort -e -tl "M = 0.8 after exposure and bake" mxyz.solid.3D; png solid
# sample3D's own pictures, as it draws them by default
png profile-20s 1 profile.ps
png profile-60s 3 profile.ps
png cut "" cut.ps
# fem: Bossung curves and process window of a 7 x 7 matrix of the NA 0.6
# contact (docs/walkthrough.md, "Focus-exposure matrices")
H=$TOP/examples/contact-highna
fem -q -if "$H/mask.in" -bf "$H/resist.in" -et 60 -method fmm -dose 60:120:10 -focus -1.2:0.6:0.3 \
	-measure "-rel 5,95 -hole 0 0" -target 0.5 -tol 10 -j 2 >/dev/null
cp fem/bossung.ps dataplot.ps; png bossung
cp fem/window.ps dataplot.ps; png window
cp fem/region.ps dataplot.ps; png region
