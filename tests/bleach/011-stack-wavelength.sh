# The image stack records the wavelength it was computed at (stack(5)),
# and bleach refuses a stack of another wavelength than its input's:
# the standing waves and the dose table are for
# bleach's own wavelength, so another one is another exposure.
#  - splat writes "wavelength L" on the stack's header line;
#  - the same wavelength runs silently; another is one line naming the
#    stack (file:1) and both values, nothing written; a stack in
#    nanometres (365 for 0.365 um) also says "nanometres?";
#  - a stack without the wavelength (written before it was recorded)
#    runs with a one-line warning, and gives the same rate file.
. "$TOP/tests/lib/common.sh"
cat >mask.in <<'IN'
wavelength 0.365
window -1 1 -1 1
rect -0.4 -0.4 0.4 0.4
grid 5 5
resist index 1.7 planes 3 thickness 0.6
IN
splat -q -o st.cont mask.in || fail "splat: $(cat err.txt 2>/dev/null)"
head -1 st.cont | grep -q ' wavelength 0.365$' || fail "stack header: $(head -1 st.cont)"
cat >r.in <<'IN'
wavelength 0.365
resist thickness 0.6 index 1.7 dill 0 0.5 0.02
substrate 1.7 0
dose 50
standingwaves off
develop mack 0.1 0.0001 0.5 5
grid nz 5
IN
bleach -q -o good.bin st.cont r.in 2>err.txt || fail "same wavelength: $(cat err.txt)"
[ -s err.txt ] && fail "same wavelength: stderr not empty: $(cat err.txt)"
# another wavelength
sed 's/^wavelength .*/wavelength 0.436/' r.in >g.in
expect_error bleach -q -o bad.bin st.cont g.in
grep -q '^bleach: st.cont:1: .*0\.365.*0\.436' err.txt || fail "message: $(cat err.txt)"
[ ! -e bad.bin ] || fail "a refused stack left bad.bin"
# the stack in nanometres
sed '1s/ wavelength 0.365$/ wavelength 365/' st.cont >nm.cont
expect_error bleach -q -o bad.bin nm.cont r.in
grep -q '^bleach: nm.cont:1: .*nanometres?' err.txt || fail "no nanometres hint: $(cat err.txt)"
# an old stack: a warning, the same result
sed '1s/ wavelength 0.365$//' st.cont >old.cont
head -1 old.cont | grep -q wavelength && fail "old.cont still has the wavelength"
bleach -q -o old.bin old.cont r.in 2>err.txt || fail "old stack refused: $(cat err.txt)"
[ "$(wc -l <err.txt)" -eq 1 ] && grep -q '^bleach: old.cont:1: .*does not record its wavelength' err.txt ||
	fail "old stack: expected one warning line: $(cat err.txt)"
same good.bin old.bin
:
