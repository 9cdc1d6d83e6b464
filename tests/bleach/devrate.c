/*
 * devrate.c - the development-rate models (src/bleach/devrate.c) against
 * values evaluated by hand (Python, double precision, from the formulas
 * in bleach.5), to a relative 1e-12:
 *   Kim with the Figure 2.3 parameters, with surface retardation, and
 *   Olin Hunt 6512's (Table 9.1) without; Mack; Dill (AZ1350J's E1 E2
 *   E3, nm/s -> um/s); the negative CA resist.
 * Kim's surface factor at d = 0 is R5 (1 - M) + R6 M and at d >> R4 is 1
 * (to 1e-12); the Kim limits M = 0 -> R1 and M = 1 -> R2.
 */
#include "bleach.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define TOL_REL 1e-12

static int failures;

static void near(const char *what, double got, double want)
{
	if (!(fabs(got - want) <= TOL_REL * fabs(want))) {
		printf("FAIL %s: got %.17g want %.17g\n", what, got, want);
		failures++;
	} else {
		printf("ok %s = %.10g\n", what, got);
	}
}

static struct devrate model(enum bleach_model m, int npar, const double *p)
{
	struct bleach_input in;
	memset(&in, 0, sizeof in);
	in.model = m;
	in.npar = npar;
	memcpy(in.par, p, npar * sizeof *p);
	if (m == BLEACH_CANEG) {
		in.k0 = 1e10;
		in.ea = 0.9;
		in.order = 1;
		in.temp = 140;
		in.time = 60;
	}
	struct devrate d;
	devrate_init(&d, &in);
	return d;
}

int main(void)
{
	const double fig23[6] = {0.1143, 0.0001683, 4.667, 0.1, 0.45, 0.3};
	struct devrate k = model(BLEACH_KIM, 6, fig23);
	near("kim M=0.5 d=10", devrate(&k, 0.5, 10), 0.0033741679358518374);
	near("kim M=0.5 d=0", devrate(&k, 0.5, 0), 0.001265312975944439);
	near("kim M=0.2 d=0.05", devrate(&k, 0.2, 0.05), 0.01746421231911506);
	near("kim M=0.9 d=1", devrate(&k, 0.9, 1.0), 0.0002978653576874892);
	near("kim surface d=0", devrate_kim_surface(fig23, 6, 0.4, 0), 0.45 * 0.6 + 0.3 * 0.4);
	near("kim surface d>>R4", devrate_kim_surface(fig23, 6, 0.4, 100 * 0.1), 1.0);

	const double oh[3] = {0.062, 0.0001, 8.5};
	struct devrate o = model(BLEACH_KIM, 3, oh);
	near("kim3 M=0 (R1)", devrate(&o, 0, 0), 0.062);
	near("kim3 M=0.3", devrate(&o, 0.3, 0), 0.04178166214815289);
	near("kim3 M=1 (R2)", devrate(&o, 1, 0), 0.0001);
	near("kim3 no surface factor", devrate_kim_surface(oh, 3, 0.5, 0), 1.0);

	const double mk[4] = {0.1, 0.0001, 0.5, 5};
	struct devrate m = model(BLEACH_MACK, 4, mk);
	near("mack M=0.3", devrate(&m, 0.3, 0), 0.08195735013608131);
	near("mack M=0.8", devrate(&m, 0.8, 0), 0.0008098209556097037);
	near("mack M=1 (Rmin)", devrate(&m, 1, 0), 0.0001);

	const double dl[3] = {5.63, 7.43, -12.6};
	struct devrate d = model(BLEACH_DILL, 3, dl);
	near("dill M=0.5", devrate(&d, 0.5, 0), 0.4902914449980171);

	const double ca[3] = {0.05, 0.0002, 3};
	struct devrate c = model(BLEACH_CANEG, 3, ca);
	near("canegative k(T) t", c.kt, 6.303346101794176);
	near("canegative M=0.9", devrate(&c, 0.9, 0), 0.007746011721571415);
	near("canegative M=0.5", devrate(&c, 0.5, 0), 0.00020391477999209356);
	near("canegative M=1 (no acid: Rmax + Rmin)", devrate(&c, 1, 0), 0.0502);

	/* clamping: M slightly outside [0, 1] is read as the bound */
	near("clamp M>1", devrate(&o, 1 + 1e-9, 0), 0.0001);
	if (failures)
		printf("%d failures\n", failures);
	return failures != 0;
}
