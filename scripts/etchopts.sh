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
