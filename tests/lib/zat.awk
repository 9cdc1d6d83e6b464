# zat.awk - in a 2D plot file (plot2d(5)), the height of the profile at
# x = X in every set: the highest z where a curve crosses x = X (the
# resist's top there), or "none".  One line per set: "set z".
#   awk -v X=2.6 -f zat.awk profile.plot
function flush() { if (st > 0) print set, (hit ? zmax : "none"); set++; st = 0; hit = 0 }
BEGIN { set = 0; st = 0 }
/^#/ { next }
/^[ \t]*$/ { flush(); next }
{
	gsub(",", " ")
	if (st == 0) { st = 1; next }               # bounds
	if (st == 1) { st = 2; next }               # ncurves
	if (st == 2) { n = $1 + 0; st = 3; have = 0; next }   # npts
	x = $1 + 0; z = $2 + 0
	if (have && (px - X) * (x - X) <= 0 && px != x) {
		zz = pz + (X - px) / (x - px) * (z - pz)
		if (!hit || zz > zmax) zmax = zz
		hit = 1
	}
	px = x; pz = z; have = 1
	if (--n == 0) st = 2
}
END { flush() }
