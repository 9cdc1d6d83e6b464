# tile.sh - sourced by sample3D: -tile W, layouts beyond one window.
# The splat input is cut into tiles of W um with a halo (stitch -cut),
# each tile runs splat, bleach and etch on its own window as a make
# target in a work directory (-j N; -slurm writes a Slurm job array
# instead), and stitch joins the tiles' images and developed surfaces,
# each taken in its core, into DIR/image.cont and DIR/curves.plot.
# Tiles whose inputs are the same file (the cells of a periodic array)
# run once.  splat images every tile by Abbe's method, the one it takes
# for large windows: its source points do not depend on the window, so a
# tile's image is the large window's (Hopkins' pair sum differs from it
# by up to 5e-4, splat(1)).  Resumable as fem: the Makefile's targets are
# the tiles' files, and a tile input is rewritten only when it changes.
# See stitch(1) and sample3D(1), TILES.
#
# Every word written into the Makefile and the Slurm scripts goes through
# shq (sh) or mkq (make and sh), etchopts.sh's quoting.

tile_w="" tile_halo="" tile_jobs=1 tile_slurm="" tile_dir=tiles tile_sbopts=""

tile_usage() {
	cat <<'U'
  -tile W     cut the layout (-if) into tiles of W um with a halo, run
              each as a make target in DIR and stitch the images and
              surfaces into DIR/image.cont and DIR/curves.plot (copied
              here); see stitch(1)
  -halo H     with -tile: the halo (um; default 3 lambda/NA)
  -j N        with -tile: N tiles at a time (make -j)
  -tiledir D  with -tile: the work directory (default tiles)
  -slurm      with -tile: write D/tiles.sbatch and D/submit.sh, run nothing
U
}

# tile_opt ARGS: 0 and tile_n (the words taken) if $1 is a -tile option
tile_opt() {
	tile_n=2
	case $1 in
	-tile|-halo|-j|-tiledir) [ $# -ge 2 ] || usage_error "option $1 needs a value" ;;
	esac
	case $1 in
	-tile) tile_w=$2 ;;
	-halo) tile_halo=$2 ;;
	-j) tile_jobs=$2 ;;
	-tiledir) tile_dir=$2 ;;
	-slurm) tile_slurm=yes tile_n=1 ;;
	*) return 1 ;;
	esac
}

# tile_stitch_rule FILE FLAGS: the Makefile rule that stitches every tile's
# FILE (keys.txt: key, shift and core of each tile) into FILE
tile_stitch_rule() {
	printf '%s:' "$1"
	for k in $keys; do printf ' u/%s/%s' "$k" "$1"; done
	printf '\n\t$(STITCH) %s-o %s' "$2" "$1"
	while read -r k dx dy x0 x1 y0 y1; do
		printf ' -t u/%s/%s %s %s %s %s %s %s' "$k" "$1" "$dx" "$dy" "$x0" "$x1" "$y0" "$y1"
	done <"$tile_dir/keys.txt"
	printf '\n'
}
tile_posnum() { awk -v v="$1" 'BEGIN { exit !(v + 0 == v && v > 0) }'; }

# tile_check: the -tile options against the rest, before anything runs
tile_check() {
	if [ -z "$tile_w" ]; then
		[ -z "$tile_halo$tile_slurm" ] && [ "$tile_jobs" = 1 ] && [ "$tile_dir" = tiles ] ||
			usage_error "-halo, -j, -tiledir and -slurm go with -tile"
		return 0
	fi
	tile_posnum "$tile_w" || usage_error "-tile $tile_w: expected a width in um"
	[ -z "$tile_halo" ] || awk -v v="$tile_halo" 'BEGIN { exit !(v + 0 == v && v >= 0) }' ||
		usage_error "-halo $tile_halo: expected a width in um"
	case $tile_jobs in ''|*[!0-9]*|0) usage_error "-j $tile_jobs: expected a whole number of jobs" ;; esac
	[ -n "$splat_in" ] && [ -n "$bleach_in" ] && [ -n "$etchtime" ] ||
		usage_error "-tile cuts the splat input: give -if, -bf and -et"
	[ -z "$accuracy" ] || usage_error "-tile and -accuracy: refine one tile by hand (-accuracy is per window)"
	[ -z "$plot" ] || usage_error "-tile writes no pictures: drop -plot"
	# fast marching unless an etch option chooses: its surfaces are what
	# stitch welds and measure reads (before sample3D checks etch's options)
	etch_engine_default
}

# tile_run: writes the work directory and its Makefile, runs make (or
# writes the Slurm scripts), then measures the stitched surface
tile_run() {
	mkdir -p "$tile_dir/in" "$tile_dir/u" || die "cannot make $tile_dir"
	stitch -cut "$tile_w" ${tile_halo:+-halo "$tile_halo"} -d "$tile_dir/in" "$splat_in" \
		>"$tile_dir/tiles.txt" || die "stitch -cut failed; stopping"
	case $bleach_in in /*) resist=$bleach_in ;; *) resist=$(pwd)/$bleach_in ;; esac
	tile_put() { # tile_put FILE: stdin becomes FILE if different (make's dates)
		cat >"$tile_dir/.new"
		if cmp -s "$tile_dir/.new" "$1"; then rm -f "$tile_dir/.new"; else mv -f "$tile_dir/.new" "$1"; fi
	}
	tile_put "$tile_dir/resist.in" <"$resist"
	# the unique tile inputs, by content; tiles.txt gains each tile's key
	keys=""
	while read -r f dx dy x0 x1 y0 y1; do
		k=$(cksum <"$tile_dir/in/$f" | awk '{ print $1 "-" $2 }')
		if [ ! -d "$tile_dir/u/$k" ]; then
			mkdir "$tile_dir/u/$k" || die "cannot make $tile_dir/u/$k"
		fi
		case " $keys " in *" $k "*) ;; *) keys="$keys $k"
			tile_put "$tile_dir/u/$k/tile.in" <"$tile_dir/in/$f" ;; esac
		echo "$k $dx $dy $x0 $x1 $y0 $y1"
	done <"$tile_dir/tiles.txt" >"$tile_dir/keys.txt"
	nt=$(wc -l <"$tile_dir/keys.txt")
	nk=$(echo $keys | wc -w)
	# shellcheck disable=SC2086 # etchopts is a list of words on purpose
	set -- -q -et "$etchtime" ${printtime:+-pt "$printtime"} $etchopts -no2d
	eq=""
	for w in "$@"; do eq="$eq $(mkq "$w")"; done
	{
		echo "# The tiles of $splat_in, written by sample3D -tile; make -j N runs them."
		printf 'SPLAT = %s\nBLEACH = %s\nETCH = %s\nSTITCH = %s\n' \
			"$(mkq "$(command -v splat)")" "$(mkq "$(command -v bleach)")" \
			"$(mkq "$(command -v etch)")" "$(mkq "$(command -v stitch)")"
		echo "ETCHOPTS =$eq"
		echo "all: curves.plot image.cont"
		for k in $keys; do
			printf 'u/%s/curves.plot: u/%s/tile.in resist.in\n' "$k" "$k"
			printf '\tcd u/%s && $(SPLAT) -q -method abbe tile.in && $(BLEACH) -q -o rval.3D.binary image.cont ../../resist.in && $(ETCH) $(ETCHOPTS) rval.3D.binary && rm -f rval.3D.binary\n' "$k"
			printf 'u/%s/image.cont: u/%s/curves.plot\n' "$k" "$k"
		done
		tile_stitch_rule curves.plot ""
		tile_stitch_rule image.cont "-image "
	} | tile_put "$tile_dir/Makefile"
	if [ -n "$tile_slurm" ]; then
		{
			printf '#!/bin/sh\n# The tiles of %s as a Slurm job array, written by sample3D -tile.\n' "$splat_in"
			echo "#SBATCH --array=0-$((nk - 1))"
			echo "#SBATCH --output=slurm/tile-%a.out"
			echo 'case $SLURM_ARRAY_TASK_ID in'
			i=0
			for k in $keys; do echo "$i) exec make u/$k/curves.plot ;;"; i=$((i + 1)); done
			echo '*) echo "tiles.sbatch: no task $SLURM_ARRAY_TASK_ID" >&2; exit 1 ;;'
			echo 'esac'
		} | tile_put "$tile_dir/tiles.sbatch"
		{
			printf '#!/bin/sh\n# Submits the tiles, then their stitching (written by sample3D -tile).\n'
			printf 'set -eu\ncd %s\nmkdir -p slurm\n' "$(shq "$(cd "$tile_dir" && pwd)")"
			echo 't=$(sbatch --parsable tiles.sbatch)'
			echo 'sbatch --dependency=afterok:${t%%;*} --output=slurm/stitch.out --wrap "make all"'
		} | tile_put "$tile_dir/submit.sh"
		chmod +x "$tile_dir/submit.sh"
		say "$tile_dir: $nt tiles ($nk to simulate) as a Slurm job array; run $tile_dir/submit.sh"
		return 0
	fi
	say "$tile_dir: $nt tiles ($nk to simulate), make -j $tile_jobs"
	make -s -C "$tile_dir" -j "$tile_jobs" all || die "a tile failed; stopping (make -C $tile_dir resumes)"
	for f in curves.plot image.cont; do
		rm -f "$f"
		ln "$tile_dir/$f" "$f" 2>/dev/null || cp "$tile_dir/$f" "$f" || die "cannot write $f"
	done
	if [ -n "$measureopts" ]; then
		say "measure $measureopts curves.plot (stitched)"
		# shellcheck disable=SC2086 # measureopts is a list of words on purpose
		measure $measureopts curves.plot || die "measure failed; stopping"
	fi
}
