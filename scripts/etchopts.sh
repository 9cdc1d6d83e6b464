# etchopts.sh - the etch options the drivers pass through to etch, sourced
# by sample3D and fem (installed beside them) so that both parse the same
# list and print the same usage lines for it; a change of etch's
# pass-through options is made here once.  See etch(1) for what each does.
# The two drivers' other shared rules are here too: the engine they
# measure with by default, -accuracy (the grid refinement), and shq/mkq,
# the quoting of a word for the Makefiles and Slurm scripts fem and
# sample3D -tile write.
#
#   etchopts=""
#   ... case $1 in
#   *) etchopt "$@" || bad "unknown option $1"; shift "$etchopt_n" ;;
#
# etchopt ARGS...: when $1 is a pass-through option, appends it and its
# value to $etchopts, sets etchopt_n to the number of words it took and
# returns 0; otherwise returns 1.  A missing value is a usage error
# through the driver's need_val.

etchopt() {
	etchopt_n=1
	case $1 in
	-linear|-no2d) etchopts="$etchopts $1" ;;
	-deloop)
		# an optional step count follows
		case ${2:-} in
		[0-9]*) etchopts="$etchopts -deloop $2"; etchopt_n=2 ;;
		*) etchopts="$etchopts -deloop" ;;
		esac ;;
	-dt|-seg|-smax|-smin|-rl|-clip|-method|-refine)
		need_val "$@"; etchopts="$etchopts $1 $2"; etchopt_n=2 ;;
	-etch) need_val "$@"; etchopts="$etchopts $2"; etchopt_n=2 ;;
	*) return 1 ;;
	esac
	return 0
}

# etchopts_usage: the usage lines of the list above
etchopts_usage() {
	cat <<'U'
  etch options passed through: -deloop [n] -dt T -seg L -smax R -smin R
              -rl L -clip N -method ray|fmm|cell|huygens -refine N
              -linear -no2d
              -etch "OPTS" passes any other etch options verbatim
U
}

# ---- the engine the drivers measure with by default ----
#
# etch_engine_default: when $etchopts names no engine (no -method, in
# -etch "OPTS" either) and no option of the ray-string alone (-deloop,
# -dt, -seg, -smax, -smin, -rl, -clip, -linear), appends -method fmm:
# fast marching gives a surface without crossings, which measure reads,
# where the thesis' ray-string leaves loops measure refuses unless
# delooped.  The ray-string stays one option away (-method ray).
etch_engine_default() {
	for w in $etchopts; do
		case $w in
		-method|-deloop|-dt|-seg|-smax|-smin|-rl|-clip|-linear) return 0 ;;
		esac
	done
	etchopts="$etchopts -method fmm"
}

# ---- -accuracy P|check: the grid that holds every CD within P % ----
#
# The resolution is the image grid (splat -grid), the points through the
# resist (bleach -nz) and etch's resolution, which follows the rate grid
# by default (-seg at most its x-y spacing, -dt from -seg, fast marching
# on the rate grid); a -seg or -dt given is scaled with the grid.  Level
# 0 is the inputs' grids (femwin -resolution), level -1 about twice their
# spacing, -2 four times, level k > 0 2^k times finer.  Each level is
# solved once and measured; from the third level on, measure -accuracy
# compares it with the two before (measure(1) ACCURACY: Richardson with
# the order observed from the three, refused when they are not in the
# asymptotic range) and writes the err column.  P: from level 0 on,
# refine by axis group (accuracy_axes, below) until every err is under
# P % of its cd and trusted (at most ACC_MAX_LEVEL in each group); check:
# levels -2 to 0 only, the estimate of the inputs' own grid.  A grid too coarse for level -2, or a level -2 a stage
# refuses, starts at -1 (three levels then need level 1 for P; check gets
# the two-level estimate, order 1 assumed); a level below 0 that measure
# refuses is left out of the estimate (check may then print no err).
ACC_MAX_LEVEL=3

# accuracy_opt ARGS...: when $1 is -accuracy, sets $accuracy to its
# value (P, check, or 1 when no value follows: the default percentage),
# sets etchopt_n to the words it took and returns 0; otherwise returns 1;
# a bad value is a usage error through the driver's bad
accuracy_opt() {
	[ "$1" = -accuracy ] || return 1
	case ${2:-} in
	[0-9.]*|check)
		accuracy_value "$2" ||
			bad "-accuracy $2: expected a percentage between 0 and 100, or check"
		accuracy=$2 etchopt_n=2 ;;
	*) accuracy=1 etchopt_n=1 ;;
	esac
	return 0
}

# accuracy_value WORD: "check", or a percentage between 0 and 100
accuracy_value() {
	[ "$1" = check ] && return 0
	printf '%s\n' "$1" | grep -Eq '^([0-9]+\.?[0-9]*|\.[0-9]+)$' &&
		awk -v v="$1" 'BEGIN { exit !(v > 0 && v < 100) }'
}

# acc_grid NX NY NZ K: the counts of level K, "nx ny nz" (a level below
# 0 halves the intervals of the one above, rounding the count down)
acc_grid() {
	awk -v nx="$1" -v ny="$2" -v nz="$3" -v k="$4" '
	function g(n,   i) {
		if (k >= 0) return (n - 1) * 2 ^ k + 1
		for (i = 0; i > k; i--) n = int(n / 2) + 1
		return n }
	BEGIN { print g(nx), g(ny), g(nz) }'
}

# acc_ratio "NX NY NZ" "NX NY NZ": the coarse grid's spacing over the
# fine one's, the smallest of the three (the larger estimate)
acc_ratio() {
	awk -v c="$1" -v f="$2" 'BEGIN {
		split(c, C, " "); split(f, F, " "); r = 0
		for (i = 1; i <= 3; i++) { q = (F[i] - 1) / (C[i] - 1); if (r == 0 || q < r) r = q }
		printf "%.10g\n", r }'
}

# acc_coarsens "NX NY NZ" "NX NY NZ": the first grid is coarser than the
# second by a ratio of 1.5 at least (a smaller one makes the estimate a
# difference of nearly equal solves)
acc_coarsens() {
	awk -v r="$(acc_ratio "$1" "$2")" 'BEGIN { exit !(r >= 1.5) }'
}

# acc_gratio xy|z "NX NY NZ" "NX NY NZ": the coarse grid's spacing over
# the fine one's along one group of axes (xy: the smaller of x and y)
acc_gratio() {
	awk -v g="$1" -v c="$2" -v f="$3" 'BEGIN {
		split(c, C, " "); split(f, F, " ")
		if (g == "z") r = (F[3] - 1) / (C[3] - 1)
		else { r = (F[1] - 1) / (C[1] - 1); q = (F[2] - 1) / (C[2] - 1); if (q < r) r = q }
		printf "%.10g\n", r }'
}

# acc_etchopts "NX NY NZ" "NX NY NZ": $etchopts for the first grid, whose
# inputs' grids are the second: -seg (the ray-string's segments, an x-y
# length) times the x-y spacing ratio, -dt (its time step, which resolves
# the rates' variation in z, thesis 7.4.1) times the z one
acc_etchopts() {
	printf '%s\n' "$etchopts" | awk -v fs="$(acc_gratio xy "$1" "$2")" -v ft="$(acc_gratio z "$1" "$2")" '{
		for (i = 1; i <= NF; i++) {
			if ($i == "-seg" && i < NF) { printf " %s %.10g", $i, $(i + 1) * fs; i++ }
			else if ($i == "-dt" && i < NF) { printf " %s %.10g", $i, $(i + 1) * ft; i++ }
			else printf " %s", $i
		} }'
}

# accuracy_loop MEASURE-PROGRAM P|check NX NY NZ TABLEDIR: solves level
# after level through the driver's own acc_solve "NX NY NZ" ETCHOPTS
# (which leaves the developed surface in $acc_surface), measures each
# with $margs into TABLEDIR/NXxNYxNZ.dat (measure's notes in .log
# beside it), and stops when measure's estimate holds.  Sets acc_table
# (the last table), acc_grid (its counts) and acc_prevg (the level
# before's); returns 0 when the estimate is within P (always for check),
# 3 when ACC_MAX_LEVEL is reached without it, 1 when a stage fails.
accuracy_loop() {
	acc_m=$1 acc_p=$2 acc_base="$3 $4 $5" acc_dir=$6
	acc_k=-2 acc_prev="" acc_prevg="" acc_pprev="" acc_pprevg=""
	# shellcheck disable=SC2086 # acc_base is three words on purpose
	acc_coarsens "$(acc_grid $acc_base -2)" "$(acc_grid $acc_base -1)" || acc_k=-1
	# shellcheck disable=SC2086 # acc_base is three words on purpose
	acc_coarsens "$(acc_grid $acc_base -1)" "$acc_base" ||
		{ echo "${prog}: -accuracy: the grid $acc_base is too coarse to coarsen" >&2; return 1; }
	while :; do
		# shellcheck disable=SC2086 # acc_base is three words on purpose
		acc_grid=$(acc_grid $acc_base "$acc_k")
		# -accuracy P from level 0 on: refinement by axis, from the
		# levels -1 (and -2) measured
		if [ "$acc_k" -eq 0 ] && [ "$acc_p" != check ] && [ -n "$acc_prev" ]; then
			accuracy_axes
			return
		fi
		# shellcheck disable=SC2086 # the grid is three words on purpose
		set -- $acc_grid
		acc_table=$acc_dir/$1x$2x$3.dat acc_log=$acc_dir/$1x$2x$3.log
		if [ "$acc_k" -eq -2 ]; then
			# level -2 may be too coarse for a stage (bleach refuses
			# points further apart than half the standing-wave period):
			# then the levels start at -1
			acc_solve "$acc_grid" "$(acc_etchopts "$acc_grid" "$acc_base")" \
				2>"$acc_log" || {
				[ -n "${quiet:-}" ] || echo "${prog}: accuracy: level -2 ($acc_grid) not solved" \
					"($(tail -n 1 "$acc_log")): the levels start at -1" >&2
				acc_k=-1
				continue
			}
		else
			acc_solve "$acc_grid" "$(acc_etchopts "$acc_grid" "$acc_base")" ||
				return 1
		fi
		# what is measured: P only where the level may stop the loop
		# (from 0 on, with two levels before it), else check
		acc_a=check
		[ "$acc_p" = check ] || [ "$acc_k" -lt 0 ] || [ -z "$acc_pprev" ] || acc_a=$acc_p
		acc_st=0
		# shellcheck disable=SC2086 # margs is a list of words on purpose
		if [ -z "$acc_prev" ]; then
			"$acc_m" $margs -o "$acc_table" "$acc_surface" 2>"$acc_log" || acc_st=$?
		elif [ -z "$acc_pprev" ]; then
			"$acc_m" $margs -accuracy "$acc_a" -coarse "$acc_prev" \
				-ratio "$(acc_ratio "$acc_prevg" "$acc_grid")" \
				-o "$acc_table" "$acc_surface" 2>"$acc_log" || acc_st=$?
		else
			"$acc_m" $margs -accuracy "$acc_a" -coarse "$acc_prev" \
				-ratio "$(acc_ratio "$acc_prevg" "$acc_grid")" -coarser "$acc_pprev" \
				-ratio2 "$(acc_ratio "$acc_pprevg" "$acc_prevg")" \
				-o "$acc_table" "$acc_surface" 2>"$acc_log" || acc_st=$?
		fi
		case $acc_st in
		0|3) ;;
		*)
			[ "$acc_k" -lt 0 ] || { cat "$acc_log" >&2; return 1; }
			# a coarse level measure refuses (a surface through a gap,
			# a feature that does not form yet) gives no estimate: the
			# levels above start without it
			[ -n "${quiet:-}" ] || echo "${prog}: accuracy: level $acc_k ($acc_grid) not measured" \
				"($(tail -n 1 "$acc_log")): no estimate from it" >&2
			acc_prev="" acc_prevg="" acc_pprev="" acc_pprevg=""
			acc_k=$((acc_k + 1))
			continue ;;
		esac
		if [ "$acc_k" -ge 0 ]; then
			if [ "$acc_p" = check ]; then
				cat "$acc_log" >&2; return 0
			elif [ "$acc_a" != check ] && [ "$acc_st" -eq 0 ]; then
				cat "$acc_log" >&2; return 0
			elif [ "$acc_k" -ge "$ACC_MAX_LEVEL" ]; then
				cat "$acc_log" >&2; return 3
			fi
		fi
		acc_pprev=$acc_prev acc_pprevg=$acc_prevg
		acc_prev=$acc_table acc_prevg=$acc_grid
		acc_k=$((acc_k + 1))
	done
}

# ---- -accuracy P from level 0 on: refinement by axis ----
#
# The error of a CD is taken as a sum of one term per group of axes, the
# image grid x-y (splat -grid, and the rate grid's x-y spacing that etch
# follows) and z (bleach -nz, the rate grid's z spacing): E = C h_xy^p +
# D h_z^q.  Refining one group then changes the CD by the same amount at
# any level of the other, so each group keeps its own history of changes
# and its own Richardson estimate (measure -coarser-fine), with its own
# observed order and steadiness test, and a level's err is the sum of the
# two (measure -plus).  Each step refines the group whose err is the
# larger share of the CD (z on a tie, half the cost), up to
# ACC_MAX_LEVEL per group; standing waves are a z error,
# the edges of dense features an x-y one, and neither pays for the other.
# Levels (KXY, KZ): the start, after the levels -2 and -1 of both, solves
# (-2, -1) (a 32nd of level 0's cost; with level -2 it gives each group
# its earlier change: z from (-2, -2), x-y to (-1, -1)) and (-1, 0) (a
# quarter: z from (-1, -1), x-y to (0, 0)), then (0, 0).

# acc_at KXY KZ: the counts of level KXY of x-y and KZ of z
acc_at() {
	# shellcheck disable=SC2086 # the grids are three words on purpose
	set -- "$(acc_grid $acc_base "$1")" "$(acc_grid $acc_base "$2")"
	echo "${1% *} ${2##* }"
}

# acc_tab "NX NY NZ" [SUFFIX]: the path of that grid's table in the
# table directory (SUFFIX .xy or .z: a group's own estimate)
acc_tab() {
	# shellcheck disable=SC2086 # the grid is three words on purpose
	set -- $1 "${2:-}"
	echo "$acc_dir/$1x$2x$3$4.dat"
}

# acc_tgrid TABLE: the grid a table of acc_tab belongs to
acc_tgrid() {
	basename "$1" | sed 's/\..*//; s/x/ /g'
}

# acc_level KXY KZ: solves that level and measures it into its table;
# sets acc_grid and acc_table (each level is solved after the sides it
# is estimated from, so the files left are the last level's)
acc_level() {
	acc_grid=$(acc_at "$1" "$2")
	acc_table=$(acc_tab "$acc_grid")
	acc_solve "$acc_grid" "$(acc_etchopts "$acc_grid" "$acc_base")" || return 1
	# shellcheck disable=SC2086 # margs is a list of words on purpose
	"$acc_m" $margs -o "$acc_table" "$acc_surface" 2>"${acc_table%.dat}.log"
}

# acc_group xy|z COARSE [FINE0 COARSE0]: the group's estimate for the level
# just solved (acc_grid), whose change from the table COARSE refines that
# group alone; the earlier change from COARSE0 to FINE0 gives the order.
# Writes the table of acc_tab GRID .G and sets acc_gst (measure's status)
acc_group() {
	acc_gt=$(acc_tab "$acc_grid" ".$1")
	acc_gst=0
	# shellcheck disable=SC2086 # margs is a list of words on purpose
	if [ -n "${3:-}" ]; then
		"$acc_m" $margs -accuracy "$acc_p" -coarse "$2" \
			-ratio "$(acc_gratio "$1" "$(acc_tgrid "$2")" "$acc_grid")" \
			-coarser "$4" -coarser-fine "$3" \
			-ratio2 "$(acc_gratio "$1" "$(acc_tgrid "$4")" "$(acc_tgrid "$3")")" \
			-o "$acc_gt" "$acc_surface" 2>"${acc_gt%.dat}.log" || acc_gst=$?
	else
		"$acc_m" $margs -accuracy "$acc_p" -coarse "$2" \
			-ratio "$(acc_gratio "$1" "$(acc_tgrid "$2")" "$acc_grid")" \
			-o "$acc_gt" "$acc_surface" 2>"${acc_gt%.dat}.log" || acc_gst=$?
	fi
	case $acc_gst in 0|3) ;; *) cat "${acc_gt%.dat}.log" >&2; return 1 ;; esac
}

# acc_total xy|z COARSE [FINE0 COARSE0]: acc_group, then the level's table:
# the same estimate plus the other group's latest (acc_xe or acc_ze);
# sets acc_st (its status), acc_log
acc_total() {
	acc_group "$@" || return 1
	if [ "$1" = xy ]; then acc_xe=$acc_gt acc_xst=$acc_gst; else acc_ze=$acc_gt acc_zst=$acc_gst; fi
	acc_log=${acc_table%.dat}.log acc_st=0
	if [ "$1" = xy ]; then set -- "$acc_ze" "$@"; else set -- "$acc_xe" "$@"; fi
	# shellcheck disable=SC2086 # margs is a list of words on purpose
	"$acc_m" $margs -accuracy "$acc_p" -coarse "$3" \
		-ratio "$(acc_gratio "$2" "$(acc_tgrid "$3")" "$acc_grid")" \
		${4:+-coarser "$5" -coarser-fine "$4" -ratio2 "$(acc_gratio "$2" "$(acc_tgrid "$5")" "$(acc_tgrid "$4")")"} \
		-plus "$1" -o "$acc_table" "$acc_surface" 2>"$acc_log" || acc_st=$?
	case $acc_st in 0|3) ;; *) cat "$acc_log" >&2; return 1 ;; esac
}

# acc_share TABLE: the largest err over its cd (where the changes were
# not in the asymptotic range, measure's err is the estimate at order
# 0.5, 2.4 times the last change)
acc_share() {
	awk '!/^#/ && $2 > 0 { e = $NF / $2; if (e > m) m = e } END { printf "%.6g\n", m }' "$1"
}

# accuracy_axes: the loop from level 0 on (accuracy_loop's results and
# return status); acc_prev and acc_pprev are the levels -1 and -2 (or
# empty).  Sets acc_prevg to one level below acc_grid in both groups, the
# coarse solve of fem's points.
accuracy_axes() {
	acc_d1=$acc_prev acc_d2=$acc_pprev
	acc_xf0="" acc_xc0="" acc_zf0="" acc_zc0=""
	if [ -n "$acc_d2" ] && acc_level -2 -1 2>/dev/null; then
		acc_zf0=$acc_table acc_zc0=$acc_d2 acc_xc0=$acc_table acc_xf0=$acc_d1
	fi
	# (-1, 0) is not a level to stop at: its z estimate alone
	acc_level -1 0 || return 1
	acc_group z "$acc_d1" "$acc_zf0" "$acc_zc0" || return 1
	acc_ze=$acc_gt acc_zst=$acc_gst acc_z1=$acc_table
	acc_level 0 0 || return 1
	acc_kx=0 acc_kz=0
	acc_total xy "$acc_z1" "$acc_xf0" "$acc_xc0" || return 1
	acc_xf1=$acc_table acc_xc1=$acc_z1 acc_zf1=$acc_z1 acc_zc1=$acc_d1
	while :; do
		acc_prevg=$(acc_at $((acc_kx - 1)) $((acc_kz - 1)))
		if [ "$acc_st" -eq 0 ] && [ "$acc_xst" -eq 0 ] && [ "$acc_zst" -eq 0 ]; then
			cat "$acc_log" >&2; break
		fi
		acc_g=$(awk -v x="$(acc_share "$acc_xe")" -v z="$(acc_share "$acc_ze")" \
			'BEGIN { print (x > z ? "xy" : "z") }')
		[ "$acc_g" = xy ] && [ "$acc_kx" -ge "$ACC_MAX_LEVEL" ] && acc_g=z
		[ "$acc_g" = z ] && [ "$acc_kz" -ge "$ACC_MAX_LEVEL" ] && acc_g=xy
		if [ "$acc_g" = xy ] && [ "$acc_kx" -ge "$ACC_MAX_LEVEL" ]; then
			cat "$acc_log" >&2; return 3
		fi
		acc_c=$acc_table
		[ -n "${quiet:-}" ] || echo "${prog}: accuracy: refining $acc_g (x-y err $(acc_share "$acc_xe"), z err $(acc_share "$acc_ze") of the cd)" >&2
		if [ "$acc_g" = xy ]; then
			acc_kx=$((acc_kx + 1))
			acc_level "$acc_kx" "$acc_kz" || return 1
			acc_total xy "$acc_c" "$acc_xf1" "$acc_xc1" || return 1
			acc_xf1=$acc_table acc_xc1=$acc_c
		else
			acc_kz=$((acc_kz + 1))
			acc_level "$acc_kx" "$acc_kz" || return 1
			acc_total z "$acc_c" "$acc_zf1" "$acc_zc1" || return 1
			acc_zf1=$acc_table acc_zc1=$acc_c
		fi
	done
	return 0
}

# usage_error MESSAGE: a driver's usage error in two lines at most, then
# exit 2: "prog: MESSAGE" (an unknown option with "; did you mean -X?"
# when one option the driver's usage text names is a slip of the keyboard
# away: the rule of the C programs' args.c, one edit for names up to 5
# characters, two from 6, a single nearest one), then where the usage is.
usage_error() {
	case $1 in
	"unknown option "*)
		set -- "$1$(usage | awk -v w="${1#unknown option }" '
		function dist(a, b,   i, j, la, lb, c, d) {
			la = length(a); lb = length(b)
			for (i = 0; i <= la; i++) d[i, 0] = i
			for (j = 0; j <= lb; j++) d[0, j] = j
			for (i = 1; i <= la; i++)
				for (j = 1; j <= lb; j++) {
					c = d[i-1, j-1] + (substr(a, i, 1) != substr(b, j, 1))
					if (d[i-1, j] + 1 < c) c = d[i-1, j] + 1
					if (d[i, j-1] + 1 < c) c = d[i, j-1] + 1
					if (i > 1 && j > 1 && substr(a, i, 1) == substr(b, j-1, 1) &&
					    substr(a, i-1, 1) == substr(b, j, 1) && d[i-2, j-2] + 1 < c)
						c = d[i-2, j-2] + 1
					d[i, j] = c
				}
			return d[la, lb]
		}
		{ n = split($0, f, /[][ \t|,()]+/)
		  for (k = 1; k <= n; k++) if (f[k] ~ /^-[a-z][a-z0-9]*$/) cand[f[k]] = 1 }
		END {
			best = ""; bd = (length(w) >= 6 ? 2 : 1) + 1; ties = 0
			for (o in cand) {
				if (o == w) continue
				dd = dist(w, o)
				if (dd < bd) { bd = dd; best = o; ties = 0 }
				else if (dd == bd && best != "") ties++
			}
			if (best != "" && !ties) printf "; did you mean %s?", best
		}')" ;;
	esac
	echo "$prog: $1" >&2
	echo "$prog: $prog --help prints the usage" >&2
	exit 2
}

# A word written into a Makefile or a shell script must reach the command
# as the one word the driver checked, whatever it holds.
shq() { # shq WORD: WORD in single quotes for sh (a ' becomes '\'')
	printf "'%s'" "$(printf '%s' "$1" | sed "s/'/'\\\\''/g")"
}
mkq() { # mkq WORD: WORD as a make variable's value that expands to shq WORD:
	# $ becomes $$, and a # with k backslashes before it 2k+1 backslashes
	# and the # (make's comment escape halves a run of backslashes)
	shq "$1" | sed 's/\$/$$/g; s/\(\\*\)#/\1\1\\#/g'
}
