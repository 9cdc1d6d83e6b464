# etchopts.sh - the etch options the drivers pass through to etch, sourced
# by sample3D and fem (installed beside them) so that both parse the same
# list and print the same usage lines for it; a change of etch's
# pass-through options is made here once.  See etch(1) for what each does.
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
