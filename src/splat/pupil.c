/*
 * pupil.c - the projection-lens pupil P(g) = exp(i Phi(g)) for
 * |g| <= NA/lambda (thesis 9.3.3, projection lens aberrations), with
 *   Phi = 2 pi (W + W_defocus),
 *   W_defocus = (d/lambda) (sqrt(1 - lambda^2 |g|^2) - 1)  waves (exact form),
 * and W the sum of the Seidel terms, written with rho the pupil vector
 * normalised to 1 at NA and h the field vector (so that rho^3 h
 * cos(theta - theta_h) = rho^2 (rho . h), and no angle is needed):
 *   spherical    w rho^4
 *   coma         w h rho^3 cos(theta - theta_h)       (tilt included)
 *   astigmatism  w h^2 rho^2 cos^2(theta - theta_h)
 *   curvature    w h^2 rho^2
 *   distortion   w h^3 rho cos(theta - theta_h)
 * and fringe Zernike terms.  The thesis states an aberration as its
 * largest optical path difference at the pupil edge for a field point
 * ("coma 0.4 lambda at (1,0)"), which is w here.
 *
 * Inside the resist (splat(5)'s resist statement) a plane wave
 * of pupil frequency g travels at sin(theta) = lambda |g| / n, so at depth
 * z below the top it has gained, relative to the axial wave,
 *   W_z = (z / lambda) (sqrt(n^2 - lambda^2 |g|^2) - n)   waves,
 * the exact defocus form with the resist's index: for n = 1 depth z is
 * defocus z, and paraxially depth z is defocus z / n.  Its amplitude
 * change at the interface (Fresnel transmission) and the absorption are
 * left to bleach, so every plane stays normalised to a clear field of 1.
 */
#include "splat.h"

#include <math.h>

void pupil_init(struct pupil *p, const struct splat_input *in)
{
	p->lambda = in->wavelength;
	p->na = in->na;
	p->cutoff = in->na / in->wavelength;
	p->defocus = in->defocus;
	p->naberr = in->naberr;
	p->aberr = in->aberr;
	double waves = fabs(in->defocus / in->wavelength) * (1 - sqrt(1 - in->na * in->na));
	int flat = in->defocus == 0;
	for (int i = 0; i < in->naberr; i++) {
		/* every term is at most |w| on the unit pupil for |h| <= 1;
		 * fringe Zernike terms are at most 1 in magnitude */
		waves += fabs(in->aberr[i].w);
		if (in->aberr[i].w != 0)
			flat = 0;
	}
	p->nplanes = 1;
	p->dz = 0;
	p->index = 1;
	if (in->planes >= 2) {
		p->nplanes = in->planes;
		p->dz = in->resist_thick / (in->planes - 1);
		p->index = in->resist_index;
		double n = in->resist_index;
		waves += in->resist_thick / in->wavelength * (n - sqrt(n * n - in->na * in->na));
	}
	p->flat = flat;
	p->waves = waves;
}

double pupil_depth(const struct pupil *p, double gx, double gy)
{
	double q = p->index * p->index - p->lambda * p->lambda * (gx * gx + gy * gy);
	return 2 * M_PI / p->lambda * (sqrt(q > 0 ? q : 0) - p->index);
}

static double factorial(int n)
{
	double f = 1;
	for (int i = 2; i <= n; i++)
		f *= i;
	return f;
}

/* Fringe (University of Arizona) ordering: term 37 is (n, m) = (12, 0);
 * otherwise terms k^2 + 1 .. (k + 1)^2 form group k, holding m = k, k-1,
 * .., 1 (cos then sin) and finally m = 0, with n = 2k - m. */
double pupil_zernike(int num, double rho, double theta)
{
	int n, m, sine = 0;
	if (num == 37) {
		n = 12;
		m = 0;
	} else {
		int k = 0;
		while ((k + 1) * (k + 1) < num)
			k++;
		int idx = num - k * k - 1;
		m = k - idx / 2;
		sine = m > 0 && idx % 2 == 1;
		n = 2 * k - m;
	}
	double r = 0;
	for (int s = 0; s <= (n - m) / 2; s++) {
		double c = factorial(n - s) /
			(factorial(s) * factorial((n + m) / 2 - s) * factorial((n - m) / 2 - s));
		r += (s % 2 ? -c : c) * pow(rho, n - 2 * s);
	}
	if (m == 0)
		return r;
	return r * (sine ? sin(m * theta) : cos(m * theta));
}

double pupil_phase(const struct pupil *p, double gx, double gy)
{
	if (p->flat)
		return 0;
	double g2 = gx * gx + gy * gy;
	double w = 0;
	if (p->defocus != 0) {
		double q = 1 - p->lambda * p->lambda * g2;
		w += p->defocus / p->lambda * (sqrt(q > 0 ? q : 0) - 1);
	}
	double rx = gx / p->cutoff, ry = gy / p->cutoff;
	double r2 = rx * rx + ry * ry;
	for (int i = 0; i < p->naberr; i++) {
		const struct splat_aberr *a = &p->aberr[i];
		double rh = rx * a->hx + ry * a->hy;        /* rho h cos(theta - theta_h) */
		double h2 = a->hx * a->hx + a->hy * a->hy;
		switch (a->kind) {
		case SPLAT_AB_SPHERICAL:   w += a->w * r2 * r2; break;
		case SPLAT_AB_COMA:        w += a->w * r2 * rh; break;
		case SPLAT_AB_ASTIGMATISM: w += a->w * rh * rh; break;
		case SPLAT_AB_CURVATURE:   w += a->w * h2 * r2; break;
		case SPLAT_AB_DISTORTION:  w += a->w * h2 * rh; break;
		case SPLAT_AB_ZERNIKE:
			w += a->w * pupil_zernike(a->zernike, sqrt(r2), atan2(ry, rx));
			break;
		}
	}
	return 2 * M_PI * w;
}
