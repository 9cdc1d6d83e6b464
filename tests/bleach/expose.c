/*
 * expose.c - the Dill bleaching integrator and its dose table
 * (src/bleach/expose.c).
 *
 * 1. Exposure integrator alone: standing waves off (Beer-Lambert, no
 *    reflections) and B = 0, where Dill's equations have the closed form
 *    M(z, D) = 1 / (1 + e^{-A z} (e^{C D} - 1)) (Herrick's solution);
 *    direct runs and the dose table must both match it to 1e-6 (the
 *    trapezoidal optical depth on 1001 nodes is good to ~1e-8).
 * 2. Dose table versus direct per-column runs, thin-film standing waves,
 *    Olin Hunt 6512 on Si: max |dM| below 1e-4 at doses that fall
 *    between table rows.
 * 3. Step convergence: halving the dose step changes M by less than 1e-4
 *    (the accuracy asked), Olin Hunt and Kodak 820 on oxide.
 * 4. M stays in (0, 1] and decreases with dose.
 * 5. The bake in z applied to the table's rows (what main.c does) equals
 *    the bake applied to each interpolated column, to 1e-12: smoothing
 *    is linear and the interpolation is a fixed linear combination of
 *    rows.
 */
#include "bleach.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOL_CLOSED 1e-6
#define TOL_TABLE 1e-4
#define TOL_HALVING 1e-4

static int failures;

static void resist(struct bleach_input *in, double T, double A, double B,
		   double C, int standing)
{
	memset(in, 0, sizeof *in);
	in->wavelength = 0.436;
	in->ambient = 1;
	in->thick = T;
	in->index = 1.68;
	in->A = A;
	in->B = B;
	in->C = C;
	in->sub_n = 4.73;
	in->sub_k = 0.14;
	in->standing = standing;
}

static double maxdiff(const double *a, const double *b, int n)
{
	double w = 0;
	for (int j = 0; j < n; j++)
		if (fabs(a[j] - b[j]) > w)
			w = fabs(a[j] - b[j]);
	return w;
}

static void beer_lambert(void)
{
	struct bleach_input in;
	double A = 0.64, C = 0.010;
	resist(&in, 1.0, A, 0, C, 0);
	int nz = 1001;
	struct exposure e;
	exposure_init(&e, &in, nz, 300, 1.0);
	struct dose_table *t = dose_table_build(&e, 300);
	double M[1001], Mt[1001], want[1001];
	const double doses[] = {10, 80, 240, 299.5};
	for (int q = 0; q < 4; q++) {
		double D = doses[q];
		for (int j = 0; j < nz; j++) {
			double z = j * e.tf.dz;
			want[j] = 1 / (1 + exp(-A * z) * (exp(C * D) - 1));
		}
		exposure_column(&e, D, M);
		dose_table_eval(t, D, Mt);
		double d1 = maxdiff(M, want, nz), d2 = maxdiff(Mt, want, nz);
		printf("Beer-Lambert D=%g: direct %.3g, table %.3g\n", D, d1, d2);
		if (!(d1 <= TOL_CLOSED && d2 <= TOL_CLOSED)) {
			printf("FAIL closed form at D=%g\n", D);
			failures++;
		}
	}
	dose_table_free(t);
	exposure_free(&e);
}

static void table_vs_direct(const char *name, struct bleach_input *in, int nz, double dmax)
{
	struct exposure e;
	exposure_init(&e, in, nz, dmax, 1.0);
	struct dose_table *t = dose_table_build(&e, dmax);
	double *M = malloc(nz * sizeof *M), *Mt = malloc(nz * sizeof *Mt);
	double worst = 0, prev_top = 2;
	for (int q = 1; q <= 23; q++) {
		double D = dmax * (q - 0.37) / 23;   /* between table rows */
		exposure_column(&e, D, M);
		dose_table_eval(t, D, Mt);
		double d = maxdiff(M, Mt, nz);
		if (d > worst)
			worst = d;
		for (int j = 0; j < nz; j++)
			if (!(Mt[j] > 0 && Mt[j] <= 1)) {
				printf("FAIL %s: M[%d] = %g out of (0, 1]\n", name, j, Mt[j]);
				failures++;
				break;
			}
		if (!(Mt[0] < prev_top)) {
			printf("FAIL %s: M at the top does not fall with dose\n", name);
			failures++;
		}
		prev_top = Mt[0];
	}
	printf("%s: table vs direct max |dM| = %.3g (%d rows)\n", name, worst, t->nd + 1);
	if (!(worst <= TOL_TABLE)) {
		printf("FAIL %s: table vs direct\n", name);
		failures++;
	}
	/* halving the step */
	struct exposure e2;
	exposure_init(&e2, in, nz, dmax, 0.5);
	double *M2 = malloc(nz * sizeof *M2);
	double hw = 0;
	for (int q = 1; q <= 4; q++) {
		double D = dmax * q / 4;
		exposure_column(&e, D, M);
		exposure_column(&e2, D, M2);
		double d = maxdiff(M, M2, nz);
		if (d > hw)
			hw = d;
	}
	printf("%s: halving the dose step changes M by %.3g\n", name, hw);
	if (!(hw <= TOL_HALVING)) {
		printf("FAIL %s: step halving\n", name);
		failures++;
	}
	exposure_free(&e2);
	free(M2);
	free(M);
	free(Mt);
	dose_table_free(t);
	exposure_free(&e);
}

static void bake_commutes(void)
{
	struct bleach_input in;
	resist(&in, 0.70, 0.64, 0.040, 0.010, 1);
	int nz = 120;
	double dz = in.thick / (nz - 1), sigma = 0.08;
	struct exposure e;
	exposure_init(&e, &in, nz, 240, 1.0);
	struct dose_table *t = dose_table_build(&e, 240);
	double a[120], b[120];
	const double doses[] = {3.3, 61.7, 180.2};
	double before[3][120];
	for (int q = 0; q < 3; q++)
		dose_table_eval(t, doses[q], before[q]);
	bake_rows2(t->M, t->dM, t->nd + 1, nz, dz, sigma);
	double worst = 0;
	for (int q = 0; q < 3; q++) {
		dose_table_eval(t, doses[q], a);
		memcpy(b, before[q], sizeof b);
		bake_rows(b, 1, nz, dz, sigma);
		double d = maxdiff(a, b, nz);
		if (d > worst)
			worst = d;
	}
	printf("bake of the table vs bake of the columns: %.3g\n", worst);
	if (!(worst <= 1e-12)) {
		printf("FAIL bake does not commute with the table\n");
		failures++;
	}
	dose_table_free(t);
	exposure_free(&e);
}

int main(void)
{
	bake_commutes();
	beer_lambert();
	struct bleach_input in;
	resist(&in, 0.70, 0.64, 0.040, 0.010, 1);      /* Olin Hunt 6512 */
	table_vs_direct("Olin Hunt 6512 on Si", &in, 300, 288);
	resist(&in, 1.0, 0.551, 0.058, 0.010, 1);      /* Kodak 820, Figure 2.2 */
	in.nlayers = 1;
	in.layers[0] = (struct bleach_layer){0.0741, 1.47, 0};
	table_vs_direct("Kodak 820 on oxide", &in, 301, 300);
	resist(&in, 0.70, 0.58, 0.030, 0.014, 0);      /* Shipley, no reflections */
	table_vs_direct("Shipley 1470 Beer-Lambert", &in, 200, 96);
	if (failures)
		printf("%d failures\n", failures);
	return failures != 0;
}
