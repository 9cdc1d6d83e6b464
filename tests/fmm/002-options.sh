# etch -method fmm with -refine and -cut: on a uniform rate of 1 um/s the
# cut y = 0 at t = 0.25 and 0.5 s is the flat line z = -t (exact for fast
# marching from a plane: T is linear; tolerance 1e-9), with the same
# bounds line as the ray-string engine's curves.cut; -refine 2 and
# -refine 1 1 3 and auto give the same flat front; -refine without
# -method fmm, or out of range, is a usage error (exit 2); so are -tol
# without -method fmm, -tol with -dense and a negative -tol.
. "$TOP/tests/lib/common.sh"
"$BUILD/tests/lib/mkrate" -o u.bin 5 4 11 -1 1 -1 1 -1 0 1 || fail "mkrate failed"
for r in "" "-refine 2" "-refine 1 1 3" "-refine auto"; do
	etch -q -method fmm $r -et 0.5 -pt 0.25 -cut y 0 u.bin || fail "etch -method fmm $r failed"
	[ "$(sed -n 2p curves.cut)" = "-1 1 -1 0" ] || fail "$r: bounds line $(sed -n 2p curves.cut)"
	[ "$(head -n 1 curves.cut)" = '# labels title "Resist cross-section" x "x (um)" y "z (um)"' ] ||
		fail "$r: labels line $(head -n 1 curves.cut)"
	[ "$(grep -c '^$' curves.cut)" -eq 1 ] || fail "$r: expected two sets"
	awk '/^#/ { next } NF == 0 { s++ } NF == 2 && !/^-1 1/ { t = (s ? 0.5 : 0.25); d = $2 + t; if (d < 0) d = -d; if (d > m) m = d }
	     END { exit !(m < 1e-9) }' m=0 curves.cut || fail "$r: the cut is not at z = -t"
	etch -q -et 0.5 -cut y 0 -o ray.plot u.bin || fail "ray-string run failed"
	[ "$(head -n 2 ray.cut)" = "$(head -n 2 curves.cut)" ] || fail "labels or bounds differ between engines"
done
etch -refine 2 -et 1 u.bin >/dev/null 2>&1; [ $? -eq 2 ] || fail "-refine without fmm: expected exit 2"
etch -method fmm -refine 0 -et 1 u.bin >/dev/null 2>&1; [ $? -eq 2 ] || fail "-refine 0: expected exit 2"
etch -method fmm -refine 65 -et 1 u.bin >/dev/null 2>&1; [ $? -eq 2 ] || fail "-refine 65: expected exit 2"
etch -tol 0.001 -et 1 u.bin >/dev/null 2>&1; [ $? -eq 2 ] || fail "-tol without fmm: expected exit 2"
etch -method fmm -dense -tol 0.001 -et 1 u.bin >/dev/null 2>&1; [ $? -eq 2 ] || fail "-tol with -dense: expected exit 2"
etch -method fmm -tol -1 -et 1 u.bin >/dev/null 2>&1; [ $? -eq 2 ] || fail "-tol -1: expected exit 2"
exit 0
