# Acid shot noise alone (stochastic seed S photons off): the line-edge
# roughness scales as G0^(-1/2), the acid and quencher counts being
# binomial and Poisson on G0 dx dy dz molecules a voxel.  EUV lines (16 nm
# at 32 nm pitch, dipole) 100 nm long in a 40 nm CA resist on a 1 x 1 x
# 1.48 nm grid; the edge measured is coordinate-free: for every y row of
# the planes 7 to 20 of the M array, the x where M crosses 0.5 going out
# from the space's centre (linear between nodes), about its edge's and
# plane's mean, both edges; the roughness is the interquartile range of
# those positions over 1.349 (the standard deviation of a normal law,
# robust to the few rows where a noise blob moves the crossing far).  Two
# seeds at G0 = 0.4 and 1.6 per nm^3 (4x): the ratio of the mean
# roughnesses must be within 0.35 to 0.65 (0.5 expected; measured 0.41;
# 200 nm lines, twice the points at twice the CPU, gave 0.40; two seeds of
# 2800 edge points each leave several % of scatter).
. "$TOP/tests/lib/common.sh"
printf '%s\n' 'wavelength 0.0135' 'na 0.33' 'dipole 0.64 0.2 x' 'background dark' \
	'window -0.016 0.016 -0.05 0.05' 'rect -0.008 -0.05 0.008 0.05' 'grid 33 5' \
	'contour image.cont' >mask.in
splat -q mask.in || fail "splat fails"
cat >edges.awk <<'A'
/^[A-Za-z]/ { m = ($1 == "M"); next }
NR == 2 { nx = $1; ny = $2 }
NR == 3 { x0 = $1; x1 = $2 }
NR > 3 && m { for (i = 1; i <= NF; i++) v[n++] = $i }
END {
	dx = (x1 - x0) / (nx - 1); c = int(nx / 2)
	for (k = 7; k <= 20; k++) for (j = 0; j < ny - 1; j++) {
		b = (k * ny + j) * nx
		for (s = -1; s <= 1; s += 2) {
			for (i = c; i + s >= 0 && i + s < nx && v[b + i + s] < 0.5; i += s) ;
			if (i + s < 0 || i + s >= nx) continue
			a = v[b + i]; e = v[b + i + s]
			x = (i + s * (0.5 - a) / (e - a)) * dx * 1000
			key = k "," s; sum[key] += x; cnt[key]++; X[key, cnt[key]] = x
		}
	}
	for (key in cnt) for (t = 1; t <= cnt[key]; t++) print X[key, t] - sum[key] / cnt[key]
}
A
ler() { # ler G0 SEED: the robust edge roughness, nm
	printf '%s\n' 'wavelength 0.0135' 'resist thickness 0.040 index 0.97 dill 0.0 4.5 0.03' \
		'substrate 0.999 0.0018' 'standingwaves off' 'dose 30' \
		"car quencher 0.3 amplification 0.4 order 1 loss 0.002 quenching 5 pag $1" \
		'peb time 60 dacid 3e-7 dquencher 1e-7' 'develop mack 0.1 0.0002 0.5 12' \
		'grid nx 33 ny 101 nz 28' "stochastic seed $2 photons off" >r.in
	bleach -q -ascii -o r.txt image.cont r.in || fail "bleach fails at G0 $1 seed $2"
	awk -f edges.awk r.txt | sort -g >e.txt
	n=$(wc -l <e.txt)
	[ "$n" -ge 2500 ] || fail "G0 $1 seed $2: $n edge points of 2800"
	awk '{ d[NR] = $1 } END { printf "%.6g\n", (d[int(3 * NR / 4) + 1] - d[int(NR / 4) + 1]) / 1.349 }' e.txt
}
a=$(ler 0.4 1) && b=$(ler 0.4 2) && c=$(ler 1.6 1) && d=$(ler 1.6 2) || exit 1
awk -v a="$a" -v b="$b" -v c="$c" -v d="$d" 'BEGIN {
	r = (c + d) / (a + b)
	printf "LER %.3f %.3f nm at G0 0.4, %.3f %.3f nm at G0 1.6: ratio %.3f (0.5 expected)\n", a, b, c, d, r
	exit !(r >= 0.35 && r <= 0.65) }' || fail "the roughness does not scale as G0^(-1/2)"
exit 0
