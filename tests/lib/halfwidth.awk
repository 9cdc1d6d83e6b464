# halfwidth.awk - in the first set of a 2D plot file (plot2d(5)), the
# opening's half-width about x = C: the largest |x - C| where a curve
# crosses z, over the heights z = Z0, Z0 + DZ, ..., Z1 (by default the
# whole set).  Prints the half-width.
#   awk -v C=1 -v Z0=-0.79 -v Z1=-0.71 -v DZ=0.01 -f halfwidth.awk profile.plot
/^#/ { next }
/^[ \t]*$/ { if (seen) exit; next }
{ gsub(",", " ") }
NF == 4 || NF == 1 { have = 0; seen = 1; next }
NF == 2 {
	if (have)
		for (z = Z0; z <= Z1 + 1e-9; z += DZ)
			if ((pz - z) * ($2 - z) <= 0 && pz != $2) {
				d = px + (z - pz) / ($2 - pz) * ($1 - px) - C
				if (d < 0) d = -d
				if (d > w) w = d
			}
	px = $1; pz = $2; have = 1
}
END { printf "%.3f\n", w }
