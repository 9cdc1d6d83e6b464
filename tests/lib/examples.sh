# tests/lib/examples.sh - the checks of the example tests (tests/examples/*,
# tests/calib/003-example.sh), shared so that the longest examples can run
# as tests of their own, which the parallel runner spreads over the cores;
# source it after common.sh.
#
# Each example runs once in make check: the test that checks its outputs
# runs the commands of its README as printed (example_readme), and
# tests/docs/004-examples.sh checks that every README command is run by
# one of these tests (examples_readme_run).
#
# The 3D examples are examples/*/run.sh except the 2D ones (sample2D,
# etch2d: 003-2d.sh's, EXAMPLES_2D).  Those in EXAMPLES_OWN have tests of
# their own (examples/004-007); 001-all.sh and 002-deloop.sh take every
# other one, so an example added later is covered without a new test.
EXAMPLES_OWN="defect corner-defect"
# the 2D examples, run and checked by tests/examples/003-2d.sh
EXAMPLES_2D="defect-cutlines elbow-cutline algorithms"
# run and checked by tests/calib/003-example.sh
EXAMPLES_CALIB="calibrate"
# The examples whose run.sh makes surfaces for measure (a contact at the
# cell's centre): example_all measures every curves.plot they leave.
EXAMPLES_MEASURED="car-arf-contact contact-highna"

# examples_rest: the 3D examples not in EXAMPLES_OWN, one name a line.
examples_rest() {
	for _run in "$TOP"/examples/*/run.sh; do
		_name=$(basename "$(dirname "$_run")")
		grep -q 'sample2D\|etch2d' "$_run" && continue
		case " $EXAMPLES_OWN " in *" $_name "*) continue ;; esac
		echo "$_name"
	done
}

# examples_readme_run: the examples whose README commands these tests run
# (every 3D example, EXAMPLES_2D and EXAMPLES_CALIB), one name a line.
examples_readme_run() {
	examples_rest
	for _name in $EXAMPLES_OWN $EXAMPLES_2D $EXAMPLES_CALIB; do echo "$_name"; done
}

# example_readme NAME: every command examples/NAME/README prints in
# backquotes starting with "sh " runs exactly as written, from the
# example's folder after the README's set-up (make at the top of the
# tree), with the build's programs NOT on PATH (the scripts find the
# tree's build), and exits 0 leaving files in the out/ folder (a command
# that remakes a committed input, "sh make-mask.sh 40 >mask.in", the same
# bytes as the committed file); a command with a placeholder ("[SIZE]") is
# not run.  The examples are copied (without any out/) into
# tree/examples beside a link tree/build -> the build under test, so the
# source tree gets no out/ folders: the outputs are in
# tree/examples/NAME/out, the commands' output in NAME.log.
example_readme() {
	_readme=$TOP/examples/$1/README
	[ -f "$_readme" ] || fail "no examples/$1/README"
	if [ ! -d tree/examples ]; then
		mkdir -p tree
		ln -s "$BUILD" tree/build
		# every example folder (they share examples/resists and inputs),
		# in one tar rather than a cp a file (130 processes, seconds on a
		# busy machine)
		tar -C "$TOP" --exclude='examples/*/out' -cf - examples | tar -C tree -xf - ||
			fail "cannot copy the examples into tree/"
	fi
	grep -o '`sh [^`]*`' "$_readme" | tr -d '`' >"$1.cmds"
	[ -s "$1.cmds" ] || fail "examples/$1/README prints no command to run"
	: >"$1.log"
	while IFS= read -r _cmd; do
		case $_cmd in *'['*) continue ;; esac
		(cd "tree/examples/$1" && PATH=/usr/bin:/bin sh -c "$_cmd") >>"$1.log" 2>&1 </dev/null ||
			fail "examples/$1: \"$_cmd\" failed: $(tail -n 3 "$1.log")"
		case $_cmd in
		*'>'*)  # it remakes a committed input: the same bytes
			_made=${_cmd##*>}
			same "tree/examples/$1/$_made" "$TOP/examples/$1/$_made" ;;
		*)
			[ -n "$(find "tree/examples/$1/out" -type f 2>/dev/null | head -n 1)" ] ||
				fail "examples/$1: \"$_cmd\" left nothing in out/" ;;
		esac
	done <"$1.cmds"
}

# example_all NAME: the commands of examples/NAME/README run as printed
# (example_readme; for a 3D example, its run.sh: sample3D runs splat,
# bleach, etch, pdraw) and leave, in every run
# directory, a non-empty curves.plot that reads back as a plot file with
# one set per print time, its curves.plot.2D, and a dataplot.ps with a page
# per set that ghostscript renders (when installed).  For the examples of
# EXAMPLES_MEASURED, measure reads every curves.plot (the hole at 0 0, at
# 10, 50 and 90 % of the resist) and finds the hole open at 90 %.  An
# example whose run.sh itself passes -deloop has its README run checked
# as example_deloop checks a -deloop run (deloop_log), which then does
# not run it a second time.
example_all() {
	example_readme "$1"
	example_figures "$1"
	if example_delooped "$1"; then
		deloop_log "$1" "$1.log"
	fi
	_n=0
	for _plot in $(find "tree/examples/$1/out" -name curves.plot | sort); do
		_d=$(dirname "$_plot")
		[ -s "$_d/curves.plot.2D" ] || fail "$_d: curves.plot.2D missing"
		[ -s "$_d/dataplot.ps" ] || fail "$_d: dataplot.ps missing"
		PATH=$BUILD/tests/lib:$PATH fmtcat plot3 "$_plot" check.plot || fail "$_plot does not read back"
		_sets=$(($(grep -c '^$' "$_plot") + 1))
		_pages=$(grep -c '^%%Page: ' "$_d/dataplot.ps")
		[ "$_sets" -eq "$_pages" ] || fail "$_d: $_sets sets but $_pages pages"
		if command -v gs >/dev/null; then gs_check "$_d/dataplot.ps"; fi
		case " $EXAMPLES_MEASURED " in
		*" $1 "*)
			measure -rel 10,50,90 -hole 0 0 -o "$_d/cd.check" "$_plot" 2>"$_d/measure.err" ||
				fail "$_plot: measure refuses the example's surface: $(head -n 1 "$_d/measure.err")"
			awk '!/^#/ { cd = $2 } END { exit !(cd > 0) }' "$_d/cd.check" ||
				fail "$_plot: no hole at 90 %: $(cat "$_d/cd.check")" ;;
		esac
		_n=$((_n + 1))
	done
	[ $_n -gt 0 ] || fail "example $1 produced no curves.plot"
	echo "$1: $_n runs"
}

# example_delooped NAME: examples/NAME/run.sh passes -deloop itself (on
# a line that is not a comment).
example_delooped() {
	grep -v '^[[:space:]]*#' "$TOP/examples/$1/run.sh" | grep -q -- ' -deloop\( \|$\)'
}

# deloop_log NAME LOG: LOG, the output of examples/NAME's run.sh, has a
# deloop summary of etch and every one reports "0 crossings left".
deloop_log() {
	_runs=$(grep -c 'etch: deloop:' "$2")
	[ "$_runs" -gt 0 ] || fail "example $1: no deloop summary"
	_clean=$(grep 'etch: deloop:' "$2" | grep -c ' 0 crossings left')
	[ "$_clean" -eq "$_runs" ] || fail "example $1: loops left: $(grep 'etch: deloop:' "$2" | grep -v ' 0 crossings left' | head -n 2)"
	echo "$1: $_runs runs, all loop-free"
}

# example_deloop NAME: examples/NAME also runs with -deloop (passed by its
# run.sh through sample3D to etch) and every etch run ends with a
# loop-free mesh: its summary reports "0 crossings left" (etch(1):
# crossings of a segment through a triangle it does not touch, found by
# the deloop pass's own spatial index after the last pass).  The summary
# counts the crossings of the last print time's deloop, so the run also
# passes -last: the sets before it are neither delooped nor drawn, and the
# final set is the same, byte for byte (each print time is delooped on a
# copy of the advancing mesh; examples/corner-defect's Kodak 820 and
# Shipley 1470 at 96 % compared), for about a fifth less CPU on
# examples/defect and corner-defect.  An example developed by fast
# marching (-method fmm in its run.sh) has no mesh and is passed over; one
# whose run.sh already passes -deloop is checked on its README run by
# example_all.
example_deloop() {
	_run=$TOP/examples/$1/run.sh
	[ -f "$_run" ] || fail "no example $1"
	if grep -q -- '-method fmm' "$_run"; then
		echo "$1: fast marching, nothing to deloop"
		return 0
	fi
	if example_delooped "$1"; then
		echo "$1: delooped by its own run.sh, checked with its README run (example_all)"
		return 0
	fi
	OUT=$PWD/$1 sh "$_run" -deloop -last >"$1.log" 2>&1 || fail "example $1 -deloop failed: $(tail -n 3 "$1.log")"
	deloop_log "$1" "$1.log"
}

# readme_figure NAME TEXT WANT GOT TOL: examples/NAME/README still quotes
# TEXT (the words that carry the figure, as printed), and GOT, the run's
# value in the README's unit, is WANT within TOL, half the last digit the
# README prints (22.7 nm: 0.05).  A README changed without its check, or
# a result that moved from the README's figure, fails naming both.
readme_figure() {
	grep -qF -- "$2" "$TOP/examples/$1/README" ||
		fail "examples/$1/README no longer quotes \"$2\" (tests/lib/examples.sh holds it)"
	awk -v a="$4" -v b="$3" -v t="$5" 'BEGIN { d = a - b; if (d < 0) d = -d
		exit !(a != "" && d <= t) }' ||
		fail "examples/$1/README quotes \"$2\" ($3), the run gives ${4:-nothing}"
	echo "$1: \"$2\": $4"
}

# example_figures NAME: every figure examples/NAME/README quotes about a
# result of its README run is that run's output (read from the files the
# run leaves in tree/examples/NAME/out; nothing is run again), at the
# README's precision (readme_figure).  Figures of runs that make check
# does not make (examples/array40's 40 um array, contact-highna's single
# aerial image) and the examples' inputs are not held here.
example_figures() {
	_o=tree/examples/$1/out
	case $1 in
	euv-contacts)
		# run.sh's summary line: N holes of 25, mean diameter D um, LCDU
		# (3 sigma) L um; P smaller pockets
		_s=$(grep '^[0-9]* holes of 25, mean diameter' "$1.log") ||
			fail "examples/$1: no summary line in the run's output"
		set -- $(echo "$_s" | awk '{ print $1, 1000 * $7, 1000 * $12, $14 }')
		readme_figure euv-contacts "25 holes' mean diameter" 25 "$1" 0
		readme_figure euv-contacts "(seed 1: 22.7 nm" 22.7 "$2" 0.05
		readme_figure euv-contacts "22.7 nm, 4.8 nm)" 4.8 "$3" 0.05
		readme_figure euv-contacts "besides them (2)" 2 "$4" 0 ;;
	euv-lines)
		# cd.txt: measure's line width at 10, 50, 90 %; ler.txt: measure -ler
		_w=$(awk '!/^#/ && ++k == 2 { print 1000 * $2 }' "$_o/d30/cd.txt")
		readme_figure euv-lines "prints at about 19 nm" 19 "$_w" 0.5
		_l=$(awk '$2 == "ler" { print 1000 * ($4 + $6) / 2 }' "$_o/d30/ler.txt")
		readme_figure euv-lines "LER about 3.7 nm 3 sigma" 3.7 "$_l" 0.05
		_l=$(awk '$2 == "lwr" { print 1000 * $3 }' "$_o/d30/ler.txt")
		readme_figure euv-lines "LWR 5.5 nm" 5.5 "$_l" 0.05
		_l=$(awk '$2 == "corr_length" { print 1000 * $3 }' "$_o/d30/ler.txt")
		readme_figure euv-lines "correlation length 5.1 nm" 5.1 "$_l" 0.05
		_w=$(awk '!/^#/ && ++k == 2 { print 1000 * $2 }' "$_o/d60/cd.txt")
		readme_figure euv-lines "over-exposed to about 4 nm" 4 "$_w" 0.5
		_l=$(awk '$2 == "ler" { print 1000 * ($4 + $6) / 2 }' "$_o/d60/ler.txt")
		readme_figure euv-lines "LER 1.55 nm" 1.55 "$_l" 0.005 ;;
	arf-immersion-lines)
		# the image stacks' mid-depth contrast, and the beams' angle in the
		# resist from the stack's wavelength and index and the window's one
		# period (tests/lib/contrast.awk)
		set -- $(awk -v D=0.05 -f "$TOP/tests/lib/contrast.awk" "$_o/te/image.stack") \
			$(awk -v D=0.05 -f "$TOP/tests/lib/contrast.awk" "$_o/tm/image.stack")
		[ $# -eq 6 ] || fail "examples/arf-immersion-lines: out/te or out/tm image.stack unreadable"
		readme_figure arf-immersion-lines "cross at about 39 degrees" 39 "$2" 0.5
		readme_figure arf-immersion-lines "|cos 2 theta| ~ 0.2" 0.2 "$3" 0.05
		readme_figure arf-immersion-lines "contrast is about 0.84 in TE" 0.84 "$1" 0.005
		readme_figure arf-immersion-lines "and 0.06 in TM" 0.06 "$4" 0.005
		# cd.txt: the resist line's width at 10, 50, 90 % (measure -line)
		_w=$(awk '!/^#/ && ++k == 2 { print 1000 * $2 }' "$_o/te/cd.txt")
		readme_figure arf-immersion-lines "TE prints a line of about 46 nm" 46 "$_w" 0.5
		# TM does not resolve: at mid-height the resist spans the whole
		# 90 nm period and the film never clears to the substrate
		_w=$(awk '!/^#/ && ++k == 2 { print 1000 * $2 }' "$_o/tm/cd.txt")
		readme_figure arf-immersion-lines "TM does not resolve" 90 "$_w" 0.5
		grep -q '^# cleared no' "$_o/tm/cd.txt" ||
			fail "examples/arf-immersion-lines/README: \"TM does not resolve\", but the TM run clears" ;;
	contact-highna)
		# cd.txt: the hole's CD at 5, 50 and 95 % of the thickness
		for _d in -0.3 0.3; do
			set -- $(awk '!/^#/ { printf " %s", $2 }' "$_o/defocus$_d/cd.txt")
			[ $# -eq 3 ] || fail "examples/contact-highna: out/defocus$_d/cd.txt has not 3 CDs"
			case $_d in
			-0.3) readme_figure contact-highna "(defocus -0.3) its bottom CD is 0.55 um" 0.55 "$1" 0.005
				readme_figure contact-highna "0.547, 0.583, 0.615 um at defocus -0.3" 0.547 "$1" 0.0005
				readme_figure contact-highna "0.547, 0.583, 0.615 um at defocus -0.3" 0.583 "$2" 0.0005
				readme_figure contact-highna "0.547, 0.583, 0.615 um at defocus -0.3" 0.615 "$3" 0.0005 ;;
			0.3) readme_figure contact-highna "(+0.3) only 0.44 um" 0.44 "$1" 0.005
				readme_figure contact-highna "0.441, 0.561, 0.614 um at +0.3" 0.441 "$1" 0.0005
				readme_figure contact-highna "0.441, 0.561, 0.614 um at +0.3" 0.561 "$2" 0.0005
				readme_figure contact-highna "0.441, 0.561, 0.614 um at +0.3" 0.614 "$3" 0.0005 ;;
			esac
		done ;;
	esac
}
