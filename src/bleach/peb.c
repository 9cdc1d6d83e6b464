/*
 * peb.c - the post-exposure bake of a chemically amplified positive
 * resist: acid h, quencher q and protected-site fraction m,
 *
 *     dh/dt = Dh lap(h) - kq h q - kloss h
 *     dq/dt = Dq lap(q) - kq h q
 *     dm/dt = -kamp max(h, 0)^p m,
 *
 * h = h0 = 1 - M of the exposure, q = q0 and m = 1 at the start; x and y
 * periodic over the window (the last grid node repeats the first), no
 * flux through the resist top and bottom.
 *
 * Integration: Strang operator splitting, nested.  The outer level splits
 * the diffusion in x and y (slow: the image varies over 100 nm and more)
 * from the rest, in K outer steps; inside each outer step every column is
 * integrated on its own by n inner Strang steps of z diffusion and
 * reaction.  With K = n (x-y diffusion at every step) the x-y and z
 * diffusions of a step go together between the reactions at its ends
 * instead (run_bake).  The pieces:
 *   - reaction, per point: the acid loss (h e^{-kloss t}) and the
 *     acid-quencher neutralisation are each exact, split loss-quench-loss
 *     (Strang) when kloss > 0.  Quenching alone keeps h - q = d, so
 *     dh/dt = a h - kq h^2 with a = kq d, a Bernoulli equation with the
 *     closed form h(t) = h0 e^{at} / (1 + kq h0 (e^{at} - 1)/a);
 *     m needs only the integral of max(h,0)^p over the step: for p = 1
 *     it is ln(1 + kq h0 (e^{at} - 1)/a) / kq, otherwise Gauss-Legendre
 *     on subintervals graded geometrically from the reaction's time
 *     scale (so that a quenching transient much shorter than the step is
 *     still resolved), on the exact h(t);
 *   - z diffusion: second-order differences (ghost nodes mirror for the
 *     no-flux ends), TR-BDF2 in time (second order, L-stable: the stiff
 *     grid modes that the reaction fronts excite are damped, not kept
 *     ringing as Crank-Nicolson would);
 *   - x, y diffusion: exact in the Fourier basis of the periodic window
 *     (each mode times e^{-D kappa^2 dt}, by fft.h's transform).
 * Consecutive half steps are merged; the final half diffusions are not
 * done at all, since m after the bake depends only on the acid during
 * the reactions.  m = exp(-kamp * integral of h^p dt) at the end.
 *
 * The step count is chosen at run time (peb_steps.c): sample columns (z
 * and reaction only) are integrated with N, 2N, 4N... steps until m
 * changes by less than PEB_TOL between two counts; the second-order
 * error of the finer run is then about a third of that.
 */
#include "bleach.h"
#include "par.h"
#include "util.h"

#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void peb_params_from(struct peb_params *pp, const struct bleach_input *in)
{
	pp->q0 = in->q0;
	pp->kamp = in->kamp;
	pp->p = in->porder;
	pp->kloss = in->kloss;
	pp->kq = in->kq;
	pp->t = in->peb_time;
	pp->dh = in->dacid;
	pp->dq = in->dquench;
	pp->noisy = in->stochastic;
}

/* (e^{x} - 1) / x, 1 at x = 0 */
static double phi1(double x)
{
	return fabs(x) < 1e-300 ? 1.0 : expm1(x) / x;
}

/* h after time s from h0 >= 0, with a = kq d - kloss (h - q = d held). */
static double acid_at(double h0, double a, double kq, double s)
{
	double x = a * s;
	if (x > 1) {
		/* growth (more acid than quencher): the form that cannot overflow */
		double E = exp(-x);
		return h0 * a / (a * E + kq * h0 * -expm1(-x));
	}
	return h0 * exp(x) / (1 + kq * h0 * s * phi1(x));
}

/* x^p, with the usual integer orders by multiplication (pow is most of
 * a bake's time otherwise) */
static double powp(double x, double p)
{
	if (p == 1)
		return x;
	if (p == 2)
		return x * x;
	if (p == 3)
		return x * x * x;
	return pow(x, p);
}

/* Gauss-Legendre, 3 points on [-1, 1]. */
static const double GL_X = 0.7745966692414834, GL_W0 = 8.0 / 9.0, GL_W1 = 5.0 / 9.0;

/* For peb_react_seconds' count of quadrature subintervals (an estimate
 * for the budget, not the integration below): the exponential approach
 * is taken as over past PEB_TAIL time constants 1/|a|, and a subinterval
 * as at most PEB_WMAX of one. */
#define PEB_TAIL 40.0
#define PEB_WMAX 0.5

/* The integral of h over s from h0 > 0 (kq > 0, h - q = d held, a = kq
 * d): ln(1 + kq h0 (e^{as} - 1)/a) / kq; h at s into *h1. */
static double acid_integral(double h0, double a, double kq, double s, double *h1)
{
	double x = a * s;
	if (x > 1) {
		/* e^x factored out: h = h0 a / (a E + kq h0 (1 - E)) and the
		 * integral (x + ln((a E + kq h0 (1 - E)) / a)) / kq, E = e^{-x} */
		double em = -expm1(-x), E = 1 - em;
		double den = a * E + kq * h0 * em;
		*h1 = h0 * a / den;
		return (x + log(den / a)) / kq;
	}
	/* one expm1 gives e^x and (e^x - 1)/a */
	double e1 = fabs(x) < 1e-300 ? 0 : expm1(x);
	double g = kq * h0 * (e1 == 0 ? s : e1 / a);    /* kq h0 (e^x - 1)/a */
	*h1 = h0 * (1 + e1) / (1 + g);
	return log1p(g) / kq;
}

/* The part of the exponent kamp * integral of h^p that may be left to
 * rounding or to the cut-off below: m moves by at most that much (m e^{-x}
 * changes by less than dx), a thousandth of the bake's tolerance PEB_TOL. */
#define PEB_REACT_TOL 1e-6

/* The integral of h^p over tau for p != 1 and kq > 0, h from h0 > 0 with
 * h - q = d held, a = kq d, rate = |a| + kq h0 the fastest time scale of h.
 * Closed forms where there is one, else 3-point Gauss-Legendre on
 * subintervals graded geometrically from 1/rate (so that a quenching
 * transient much shorter than the step is resolved), each at most half
 * the local time scale of h^p, 1/(max(p, 1) (|a| + kq h)) (h'/h = a - kq h;
 * relative error of an exponential below 4e-9 an interval), until h is
 * within PEB_REACT_TOL of its asymptote, where the rest of the step has
 * a closed form again. */
static double power_integral(const struct peb_params *pp, double h0, double a, double kq,
			     double tau)
{
	double p = pp->p, d = a / kq, rate = fabs(a) + kq * h0;
	if (p == 2 && rate * tau > 0.25) {
		/* h^2 = (a h - dh/dt) / kq (the equation of h itself), so the
		 * integral is (a integral of h - (h1 - h0)) / kq; the two terms
		 * cancel when the quencher wins (a < 0) by at most h0, so their
		 * rounding costs kamp h0 2^-52 / kq in the exponent: used when
		 * that is far below PEB_REACT_TOL */
		if (pp->kamp * h0 * 1e-15 / kq < 1e-3 * PEB_REACT_TOL) {
			double h1, in = acid_integral(h0, a, kq, tau, &h1);
			double r = (a * in - (h1 - h0)) / kq;
			return r > 0 ? r : 0;
		}
	}
	if (a == 0 && p != 1) {
		/* no excess either way: h = h0 / (1 + kq h0 t) exactly */
		double u = kq * h0 * tau;
		return pow(h0, p - 1) * expm1((1 - p) * log1p(u)) / (kq * (1 - p));
	}
	double s0 = 0.25 / rate, pm = p > 1 ? p : 1;
	double sum = 0, lo = 0, w = s0, h = h0;
	for (;;) {
		double wmax = 0.5 / (pm * (fabs(a) + kq * h));
		if (w > wmax)
			w = wmax;
		double hi = lo + w;
		if (hi > tau || w <= 0)
			hi = tau;
		double c = 0.5 * (lo + hi), r = 0.5 * (hi - lo);
		double f0 = powp(acid_at(h0, a, kq, c), p);
		double fm = powp(acid_at(h0, a, kq, c - r * GL_X), p);
		double fp = powp(acid_at(h0, a, kq, c + r * GL_X), p);
		sum += r * (GL_W0 * f0 + GL_W1 * (fm + fp));
		if (hi >= tau)
			break;
		lo = hi;
		w = s0 + 0.25 * hi;
		/* the rest of the step once h is near its asymptote */
		h = acid_at(h0, a, kq, lo);
		double rest = tau - lo;
		if (d > 0 && fabs(h - d) <= PEB_REACT_TOL * d) {
			/* h = d + e, |e| < PEB_REACT_TOL d and shrinking: h^p =
			 * d^p + p d^{p-1} e up to p |p-1| / 2 of e^2 */
			double h1, in = acid_integral(h, a, kq, rest, &h1);
			return sum + powp(d, p) * rest + p * pow(d, p - 1) * (in - d * rest);
		}
		if (d < 0 && kq * h <= PEB_REACT_TOL * -a) {
			/* h = C e^{a t} to a relative PEB_REACT_TOL (the Bernoulli
			 * term kq h / |a| is that small): e^{p a t} integrated */
			return sum + powp(h, p) * -expm1(p * a * rest) / (p * -a);
		}
	}
	return sum;
}

/* The acid-quencher reaction alone over tau (kloss = 0): h - q = d held,
 * dh/dt = kq d h - kq h^2; returns the integral of h^p. */
static double quench(const struct peb_params *pp, double tau, double *hp, double *qp)
{
	double h0 = *hp, q0 = *qp;
	double kq = pp->kq, d = h0 - q0, a = kq * d;
	if (h0 == 0)
		return 0;       /* no acid: nothing reacts */
	if (pp->p == 1 && kq > 0) {
		/* h and its integral from one exponential */
		double h1, in = acid_integral(h0, a, kq, tau, &h1);
		*hp = h1;
		*qp = h1 - d > 0 ? h1 - d : 0;
		return in;
	}
	if (kq == 0 || !(q0 > 0))
		return powp(h0, pp->p) * tau;    /* nothing to neutralise: h constant */
	double h1 = acid_at(h0, a, kq, tau);
	*hp = h1;
	*qp = h1 - d;
	if (*qp < 0)
		*qp = 0;        /* rounding: q never goes below zero */
	return power_integral(pp, h0, a, kq, tau);
}

/* seconds a Gauss-Legendre subinterval of quench (three pow, three
 * acid_at), measured on the development machine, 2020 x86-64 */
static const double T_SUB = 1.5e-7;

double peb_react_seconds(const struct peb_params *pp, double h0max, double tau)
{
	if (pp->p == 1 || !(pp->kq > 0))
		return 0;
	double worst = 0;
	/* quench's subintervals, counted as it makes them, for h0 from
	 * h0max / 8 to h0max */
	for (int k = 1; k <= 8; k++) {
		double h0 = h0max * k / 8, d = h0 - pp->q0, a = pp->kq * d;
		double rate = fabs(a) + pp->kq * h0;
		double s0 = rate > 0 ? 0.25 / rate : tau;
		double wmax = fabs(a) > 0 ? PEB_WMAX / fabs(a) : tau;
		double lo = 0, w = s0, n = 0;
		while (lo < tau && n < 1e7) {
			if (fabs(a) * lo > PEB_TAIL)
				break;
			n++;
			lo += w < wmax ? w : wmax;
			w = s0 + 0.25 * lo;
		}
		if (n > worst)
			worst = n;
	}
	return worst * T_SUB;
}

/* peb_react with e = exp(-kloss tau / 2) given (one exp a step, not a
 * point). */
static double react(const struct peb_params *pp, double tau, double e, double *hp, double *qp)
{
	double h = *hp > 0 ? *hp : 0, q = *qp > 0 ? *qp : 0;
	double acc;
	/* loss, quenching, loss (Strang): the loss alone is exact, the
	 * quenching (with the deprotection of m) alone is exact; only their
	 * coupling is split (e = 1 without loss, and nothing is split) */
	h *= e;
	acc = quench(pp, tau, &h, &q);
	h *= e;
	*hp = h;
	*qp = q;
	return acc;
}

double peb_react(const struct peb_params *pp, double tau, double *hp, double *qp)
{
	return react(pp, tau, exp(-pp->kloss * 0.5 * tau), hp, qp);
}

/* ---- z diffusion: TR-BDF2 on the no-flux second-difference Laplacian ---- */

static const double TRB_G = 0.5857864376269050;        /* 2 - sqrt(2) */

/* Thomas factors of (I - c Lap) on n nodes, s = c / dz^2: the sub- and
 * super-diagonal are -s (-2s on the first row's super and the last row's
 * sub, the mirrored ghost node).  inv[j] = 1 / pivot, up[j] = the
 * eliminated super-diagonal over the pivot. */
struct tridiag {
	double s;
	double *inv, *up;
};

/* buf: 2 n values, the factors' storage (the caller's) */
static void tridiag_init(struct tridiag *t, int n, double s, double *buf)
{
	t->s = s;
	t->inv = buf;
	t->up = buf + n;
	double prev_up = 0;
	for (int j = 0; j < n; j++) {
		double sub = j == 0 ? 0 : (j == n - 1 ? -2 * s : -s);
		double sup = j == n - 1 ? 0 : (j == 0 ? -2 * s : -s);
		double piv = 1 + 2 * s - sub * prev_up;
		t->inv[j] = 1 / piv;
		t->up[j] = sup / piv;
		prev_up = t->up[j];
	}
}

/* x[j * ld + i] for the b columns i (rows ld apart): solves (I - c Lap)
 * x = r in place. */
static void tridiag_solve(const struct tridiag *t, int n, size_t b, size_t ld, double *x)
{
	double s = t->s;
	for (int j = 0; j < n; j++) {
		double *xj = x + (size_t)j * ld;
		double sub = j == 0 ? 0 : (j == n - 1 ? -2 * s : -s);
		if (j > 0) {
			const double *xp = xj - ld;
			for (size_t i = 0; i < b; i++)
				xj[i] = (xj[i] - sub * xp[i]) * t->inv[j];
		} else {
			for (size_t i = 0; i < b; i++)
				xj[i] *= t->inv[0];
		}
	}
	for (int j = n - 2; j >= 0; j--) {
		double *xj = x + (size_t)j * ld;
		const double *xn = xj + ld;
		double u = t->up[j];
		for (size_t i = 0; i < b; i++)
			xj[i] -= u * xn[i];
	}
}

/* One TR-BDF2 step of u' = D Lap u for the b columns of u[j * ld + i]
 * (in place in the whole field: rows ld apart), with the factors of the
 * two stages (c1 = g tau / 2, c2 = (1-g)/(2-g) tau); y is scratch of n
 * rows of b. */
struct zstep {
	int on;                 /* 0: D = 0, nothing to do */
	double s1;              /* g tau D / (2 dz^2), the explicit half */
	struct tridiag a, b;
};

/* buf: ZSTEP_BUF(n) values for the factors */
#define ZSTEP_BUF(n) (4 * (size_t)(n))

static void zstep_init(struct zstep *z, int n, double D, double dz, double tau, double *buf)
{
	memset(z, 0, sizeof *z);
	if (!(D > 0) || n < 2 || !(tau > 0))
		return;
	z->on = 1;
	double k = D / (dz * dz);
	z->s1 = 0.5 * TRB_G * tau * k;
	tridiag_init(&z->a, n, z->s1, buf);
	tridiag_init(&z->b, n, (1 - TRB_G) / (2 - TRB_G) * tau * k, buf + 2 * (size_t)n);
}

static void zstep_apply(const struct zstep *z, int n, size_t b, size_t ld, double *u, double *y)
{
	if (!z->on)
		return;
	double s = z->s1;
	/* stage 1, trapezoid over g tau: y = (I + s Lap) u, then solved */
	for (int j = 0; j < n; j++) {
		const double *uj = u + (size_t)j * ld;
		const double *um = j > 0 ? uj - ld : uj + ld;   /* mirrored ghost */
		const double *up = j < n - 1 ? uj + ld : uj - ld;
		double *yj = y + (size_t)j * b;
		for (size_t i = 0; i < b; i++)
			yj[i] = uj[i] + s * (um[i] - 2 * uj[i] + up[i]);
	}
	tridiag_solve(&z->a, n, b, b, y);
	/* stage 2, BDF2 through u, y and the new u */
	double c1 = 1 / (TRB_G * (2 - TRB_G));
	double c0 = (1 - TRB_G) * (1 - TRB_G) * c1;
	for (int j = 0; j < n; j++) {
		double *uj = u + (size_t)j * ld;
		const double *yj = y + (size_t)j * b;
		for (size_t i = 0; i < b; i++)
			uj[i] = c1 * yj[i] - c0 * uj[i];
	}
	tridiag_solve(&z->b, n, b, ld, u);
}

/* ---- the column integration (z diffusion and reaction) ---- */

/* The time nodes of the bake: node i of n at T (i / n)^PEB_GRADE.  The
 * neutralisation's transient at the start is fast (1 / (kq h), a tenth of
 * a second) and the splitting error of a step grows with the reaction's
 * rate, so the steps grow from short ones at the start; measured against
 * 2048 steps, 32 graded steps err by 5.8e-4 in m on examples/car-krf-lines
 * (2.0e-3 uniform) and 8e-4 on examples/car-arf-contact (4.1e-3), the
 * error still falling 4 times per doubling.  Exponents 1.3 to 2 do about
 * as well; 1.5 is between. */
#define PEB_GRADE 1.5

static double peb_node(double T, int n, int i)
{
	return i >= n ? T : T * pow((double)i / n, PEB_GRADE);
}

/* The reaction of order 1 with a quencher over tr, nb values at once:
 * peb_react's arithmetic (loss e, the exact neutralisation with h - q = d
 * held, loss e) in one form for every sign of d.  With u = |kq d tr|, E =
 * e^{-u} and rho = (1 - E) / |kq d| (tr as d -> 0): for d >= 0, h1 = h /
 * (E + kq h rho) and e^{kq integral of h} = (E + kq h rho) e^u; for d < 0,
 * h1 = h E / (1 + kq h rho) and e^{kq integral} = 1 + kq h rho.  So the
 * integral is (ln den + max(kq d tr, 0)) / kq with den = s + kq h rho >= 1
 * (s = E or 1): the second term is added to A at once, den multiplied
 * into P, so that a point costs one expm1 and one division a step and a
 * logarithm a bake instead of expm1, log1p and two divisions (P is a field
 * of the whole bake, folded into A before it could overflow and at the
 * end: with the x-y diffusion at every step a pass is one step, and a
 * logarithm a pass was a fifth of the reaction). */
/* 2^{-j/64} and 1 - 2^{-j/64}, j < 64, for one_minus_exp (set by
 * exp_tables_init before any worker starts; the same values each time). */
static double exp_t[64], exp_c[64];

static void exp_tables_init(void)
{
	for (int j = 0; j < 64; j++) {
		exp_t[j] = exp2(-j / 64.0);
		exp_c[j] = -expm1(-j * M_LN2 / 64);
	}
}

/* 1 - e^{-u} for u >= 0 to its own relative precision (it is over a for
 * small u), inline and without a call, so that the divisions of
 * consecutive points overlap (the call of expm1 and the division waiting
 * on it, one point at a time, were most of the reaction's time): u = (64 k
 * + j) ln 2 / 64 + r, |r| <= ln 2 / 128, e^{-u} = 2^-k t_j e^{-r} with t_j
 * = 2^{-j/64} from the table, e^{-r} - 1 by its Taylor series to r^6 / 6!
 * (the remainder below 6e-18 of it).  1 - e^{-u} = (1 - 2^-k t_j) - 2^-k
 * t_j (e^{-r} - 1), the first term from the table when k = 0, so that it
 * is exact to rounding for small u too; its two terms cancel by at most
 * half.  u beyond 700 is taken as 700 (e^{-700} = 1e-304 is below
 * anything it is added to). */
static inline double one_minus_exp(double u)
{
	/* ln 2 / 64 in two parts, the first with its low 32 bits zero so
	 * that n times it is exact for any n here (n < 2^17) */
	static const double L_HI = 6.93147180369123816490e-01 / 64,
		L_LO = 1.90821492927058770002e-10 / 64, INV_L = 64 / M_LN2;
	u = u < 700 ? u : 700;
	int n = (int)(u * INV_L + 0.5), j = n & 63, k = n >> 6;
	double r = (u - n * L_HI) - n * L_LO;
	double p = r * (-1 + r * (1.0 / 2 + r * (-1.0 / 6 + r * (1.0 / 24 + r * (-1.0 / 120 +
									  r * (1.0 / 720))))));
	union {
		double d;
		unsigned long long i;
	} sc = {.i = (unsigned long long)(1023 - k) << 52};
	double e = sc.d * exp_t[j];
	/* chosen by an index, not a branch: which one varies from point to
	 * point, and the mispredicted branch cost more than the table */
	const double base[2] = {1 - e, exp_c[j]};
	return base[k == 0] - e * p;
}

/* One point of react_order1: h1, q1, den and max(kq d tr, 0) from h >= 0
 * (the loss applied) and q >= 0.  rho = em / |a| is kept as the quotient
 * (w / ad) so that den = (s ad + kq h w) / ad and h1 = h num ad / (s ad +
 * kq h w) take two divisions that do not wait on each other. */
static inline void neutralise1(double kq, double tr, double h, double q, double *h1,
			       double *q1, double *den, double *xp)
{
	double d = h - q, a = kq * d, x = a * tr, u = x > 0 ? x : -x;
	/* 1 - e^{-u} to its own precision, e^{-u} from it to 1e-16
	 * absolute, all that is used of it */
	double em = one_minus_exp(u);
	int tiny = !(u > 1e-12);        /* rho = tr as d -> 0 */
	double ad = tiny ? 1 : fabs(a), w = tiny ? tr : em;
	/* s = E, num = 1 for x >= 0, else s = 1, num = E (E = 1 - em): by
	 * arithmetic rather than a branch on the sign of the excess, which
	 * changes across every image edge (the same values) */
	double pos = x >= 0;
	double s = 1 - em * pos, num = 1 - em * (1 - pos);
	double D = s * ad + kq * h * w, iad = 1 / ad, iD = 1 / D;
	*den = D * iad;
	*h1 = h * num * ad * iD;
	*q1 = *h1 - d > 0 ? *h1 - d : 0;
	*xp = x > 0 ? x : 0;
}

/* P folded into A where it has grown large */
static void fold_products(size_t nb, double *A, double *P, double ikq)
{
	for (size_t k = 0; k < nb; k++)
		if (P[k] > 1e200) {
			A[k] += log(P[k]) * ikq;
			P[k] = 1;
		}
}

static void react_order1(const struct peb_params *pp, double tr, double e, size_t nb,
			 double *H, double *Q, double *A, double *P)
{
	double kq = pp->kq, ikq = 1 / kq;
	for (size_t k = 0; k < nb; k++) {
		double h = H[k] > 0 ? H[k] * e : 0, q = Q[k] > 0 ? Q[k] : 0, h1, q1, den, xp;
		neutralise1(kq, tr, h, q, &h1, &q1, &den, &xp);
		P[k] *= den;
		A[k] += xp * ikq;
		H[k] = h1 * e;
		Q[k] = q1;
	}
	fold_products(nb, A, P, ikq);
}

/* The reaction of order 2 with a quencher over tr, b values at once:
 * where power_integral takes its closed form (the step longer than a
 * quarter of the reaction's time scale, rounding far below
 * PEB_REACT_TOL), the integral of h^2 = (a integral of h - (h1 - h)) /
 * kq with the integral of h and h1 from neutralise1 (kq integral of h =
 * ln den + max(kq d tr, 0)), one inline exponential and one logarithm a
 * point instead of expm1, log1p and the calls through react; elsewhere
 * react itself. */
static void react_order2(const struct peb_params *pp, double tr, double e, size_t b,
			 double *H, double *Q, double *A)
{
	double kq = pp->kq, ikq = 1 / kq, hcut = 1e-3 * PEB_REACT_TOL * kq / (pp->kamp * 1e-15);
	for (size_t k = 0; k < b; k++) {
		double h = H[k] > 0 ? H[k] * e : 0, q = Q[k] > 0 ? Q[k] : 0;
		double a = kq * (h - q);
		if (h > 0 && q > 0 && (fabs(a) + kq * h) * tr > 0.25 && h < hcut) {
			double h1, q1, den, xp;
			neutralise1(kq, tr, h, q, &h1, &q1, &den, &xp);
			double in = (log(den) + xp) * ikq;
			double r = (a * in - (h1 - h)) * ikq;
			A[k] += r > 0 ? r : 0;
			H[k] = h1 * e;
			Q[k] = q1;
		} else {
			A[k] += react(pp, tr, e, &H[k], &Q[k]);
		}
	}
}

/* The linear-noise bake (bleach.1, shot noise): the noise dh, dq of the
 * acid and quencher carried through the bake to first order about the
 * deterministic h, q, its integral of h^p into dA.  The derivative of
 * the exact reaction of a step along (dh, dq) is taken in closed form at
 * order 1 with a quencher (neutralise1_tangent), elsewhere by a
 * difference over a step eps along it, eps (dh, dq) a ten-millionth of
 * h + q: its truncation error is of that relative size and its rounding
 * 1e-16 over it, both far below the noise they describe (the two agree
 * to 1e-7 in m on examples/euv-*). */
#define NOISE_EPS 1e-7

static double noise_eps(double h, double q, double dh, double dq)
{
	double sc = fabs(dh) > fabs(dq) ? fabs(dh) : fabs(dq);
	return sc > 0 ? NOISE_EPS * (h + q + 1e-12) / sc : 0;
}

/* neutralise1 and its derivative along (dh, dq), from the closed form
 * itself (the derivative of 1 - e^{-u} is e^{-u}, the rest quotients
 * and products): h1, q1 and ln den + xp moved by *dh1, *dq1 and *dl.  0
 * (nothing set) where the closed form has no derivative to take: d
 * within rounding of zero (neutralise1's rho = tr), no acid, a quencher
 * below zero (a diffusion undershoot); a quencher of exactly zero moves
 * only up (the clamp before the reaction). */
static inline int neutralise1_tangent(double kq, double tr, double h, double q, double dh,
				      double dq, double *h1, double *q1, double *den, double *xp,
				      double *dh1, double *dq1, double *dl)
{
	double d = h - q, a = kq * d, x = a * tr, u = fabs(x);
	if (!(u > 1e-12) || !(h > 0) || q < 0)
		return 0;
	if (q == 0 && dq < 0)
		dq = 0;
	double em = one_minus_exp(u), E = 1 - em, ad = fabs(a);
	double pos = x >= 0;
	double s = 1 - em * pos, num = 1 - em * (1 - pos);
	double D = s * ad + kq * h * em, iad = 1 / ad, iD = 1 / D;
	*den = D * iad;
	*h1 = h * num * ad * iD;
	*q1 = *h1 - d > 0 ? *h1 - d : 0;
	*xp = x > 0 ? x : 0;
	/* the step along (dh, dq): u, |a| and em first, then s, num, D */
	double dd = dh - dq, sg = x >= 0 ? 1 : -1;
	double dad = sg * kq * dd, du = dad * tr, dem = E * du;
	double ds = -dem * pos, dnum = -dem * (1 - pos);
	double dD = ds * ad + s * dad + kq * (dh * em + h * dem);
	*dh1 = (dh * num * ad + h * dnum * ad + h * num * dad) * iD - *h1 * dD * iD;
	*dq1 = *h1 - d > 0 ? *dh1 - dd : 0;
	*dl = dD * iD - dad * iad + (x > 0 ? kq * dd * tr : 0);
	return 1;
}

static void react_order1_noise(const struct peb_params *pp, double tr, double e, size_t nb,
			       double *H, double *Q, double *A, double *P, double *dH,
			       double *dQ, double *dA)
{
	double kq = pp->kq, ikq = 1 / kq;
	for (size_t k = 0; k < nb; k++) {
		double h = H[k] > 0 ? H[k] * e : 0, q = Q[k] > 0 ? Q[k] : 0, h1, q1, den, xp;
		double dh = dH[k] * e, dq = dQ[k], dh1, dq1, dl;
		if (neutralise1_tangent(kq, tr, H[k] * e, Q[k], dh, dq, &h1, &q1, &den, &xp, &dh1,
					&dq1, &dl)) {
			dH[k] = dh1 * e;
			dQ[k] = dq1;
			dA[k] += dl * ikq;
		} else {
			neutralise1(kq, tr, h, q, &h1, &q1, &den, &xp);
			double eps = noise_eps(h, q, dh, dq);
			if (eps > 0) {
				/* by a difference, perturbed before the clamps
				 * (a value below zero, a diffusion undershoot,
				 * has no derivative) */
				double hp = H[k] * e + eps * dh, qp = Q[k] + eps * dq, h1p, q1p, denp, xpp;
				neutralise1(kq, tr, hp > 0 ? hp : 0, qp > 0 ? qp : 0, &h1p, &q1p, &denp,
					    &xpp);
				dH[k] = (h1p - h1) / eps * e;
				dQ[k] = (q1p - q1) / eps;
				dA[k] += ((denp - den) / den + (xpp - xp)) / eps * ikq;
			}
		}
		P[k] *= den;
		A[k] += xp * ikq;
		H[k] = h1 * e;
		Q[k] = q1;
	}
	fold_products(nb, A, P, ikq);
}

/* The same for any order, through peb_react's react. */
static void react_noise(const struct peb_params *pp, double tr, double e, size_t nb,
			double *H, double *Q, double *A, double *dH, double *dQ, double *dA)
{
	for (size_t k = 0; k < nb; k++) {
		double h = H[k], q = Q[k], eps = noise_eps(h > 0 ? h : 0, q > 0 ? q : 0, dH[k], dQ[k]);
		double r = react(pp, tr, e, &H[k], &Q[k]);
		if (eps > 0) {
			double hp = h + eps * dH[k], qp = q + eps * dQ[k];
			double rp = react(pp, tr, e, &hp, &qp);
			dH[k] = (hp - H[k]) / eps;
			dQ[k] = (qp - Q[k]) / eps;
			dA[k] += (rp - r) / eps;
		}
		A[k] += r;
	}
}

/* Per worker: the z operators of the current step, acid and quencher,
 * with their factors' storage. */
struct zops {
	int fixed;              /* set once for the pass (its one step) */
	struct zstep h, q;
	double *buf;            /* 2 ZSTEP_BUF(nz) */
};

static void zops_set(struct zops *o, const struct peb_params *pp, int nz, double dz, double dt)
{
	zstep_init(&o->h, nz, pp->dh, dz, dt, o->buf);
	zstep_init(&o->q, nz, pp->dq, dz, dt, o->buf + ZSTEP_BUF(nz));
}

/* A block's arrays, in place in the whole field ([j * ld + i] for its b
 * columns, ld the field's columns): acid, quencher, the integral of h^p,
 * and their noise (NULL without), the product P of react_order1 (NULL at
 * other orders); y scratch of nz rows of b. */
struct block {
	double *H, *Q, *A, *dH, *dQ, *dA, *y, *P;
	size_t ld;
};

/* The inner steps i0 .. i1 - 1 (of n over T, peb_node) on the b columns
 * of k: reaction over the first half step (with the half of the step
 * lead before it, which the caller has not reacted yet: 0 when it has),
 * then z diffusion over each step with the reaction over the halves on
 * either side of a node between them, and, if tail, the reaction over the
 * last half step (the m integral sees the acid right up to the end of the
 * bake). */
static void columns_steps(const struct peb_params *pp, struct zops *o, int nz, size_t b,
			  const struct block *k, double T, int n, int i0, int i1, double lead,
			  int tail, double dz)
{
	size_t ld = k->ld;
	int fast = pp->p == 1 && pp->kq > 0;
	double prev = lead;     /* the step before node i not yet reacted over */
	for (int i = i0; i <= i1 && (i < i1 || tail); i++) {
		double next = i < i1 ? peb_node(T, n, i + 1) - peb_node(T, n, i) : 0;
		double tr = 0.5 * (prev + next);
		double e = exp(-pp->kloss * 0.5 * tr);
		for (int z = 0; z < nz; z++) {
			size_t r = (size_t)z * ld;
			double *H = k->H + r, *Q = k->Q + r, *A = k->A + r, *P = fast ? k->P + r : NULL;
			if (fast && k->dH)
				react_order1_noise(pp, tr, e, b, H, Q, A, P, k->dH + r, k->dQ + r, k->dA + r);
			else if (fast)
				react_order1(pp, tr, e, b, H, Q, A, P);
			else if (k->dH)
				react_noise(pp, tr, e, b, H, Q, A, k->dH + r, k->dQ + r, k->dA + r);
			else if (pp->p == 2 && pp->kq > 0)
				react_order2(pp, tr, e, b, H, Q, A);
			else
				for (size_t j = 0; j < b; j++)
					A[j] += react(pp, tr, e, &H[j], &Q[j]);
		}
		if (i < i1) {
			if (!o->fixed)
				zops_set(o, pp, nz, dz, next);
			zstep_apply(&o->h, nz, b, ld, k->H, k->y);
			zstep_apply(&o->q, nz, b, ld, k->Q, k->y);
			if (k->dH) {
				zstep_apply(&o->h, nz, b, ld, k->dH, k->y);
				zstep_apply(&o->q, nz, b, ld, k->dQ, k->y);
			}
		}
		prev = next;
	}
}

/* Columns per block: the block's rows of H, Q, A (PEB_BLOCK values
 * each, contiguous in the field) and its scratch stay in cache. */
#define PEB_BLOCK 32

struct peb_pass {
	const struct peb_params *pp;
	double *f[6];           /* H, Q, A, dH, dQ, dA: [k * ncol + q]; no noise: 3 */
	double *P;              /* react_order1's products, or NULL */
	int nf;
	size_t ncol;
	int nz, n, i0, i1;      /* steps i0 .. i1 - 1 of n */
	double lead;            /* columns_steps' lead and tail */
	int tail;
	double dz;
	double *scratch;        /* per worker: PASS_SCRATCH(nz) */
	const struct zops *z1;  /* a one-step pass's z operators, made once
				 * for all the blocks (NULL: per block) */
};

#define PASS_SCRATCH(nz) ((size_t)(nz) * (PEB_BLOCK + 2 * ZSTEP_BUF(1)))

/* The blocks lo .. hi - 1 in place: a block's columns are PEB_BLOCK
 * consecutive values of every plane, so they are worked on where they
 * are (a copy to and from a packed block cost as much as the z steps). */
static void pass_blocks(void *ctx, size_t lo, size_t hi, int worker)
{
	struct peb_pass *p = ctx;
	int nz = p->nz;
	size_t per = (size_t)nz * PEB_BLOCK;
	double *w = p->scratch + (size_t)worker * PASS_SCRATCH(nz);
	struct zops o = {.buf = w + per};
	if (p->z1)
		o = *p->z1;
	for (size_t blk = lo; blk < hi; blk++) {
		size_t q0 = blk * PEB_BLOCK;
		size_t b = p->ncol - q0 < PEB_BLOCK ? p->ncol - q0 : PEB_BLOCK;
		double *v[6];
		for (int a = 0; a < 6; a++)
			v[a] = a < p->nf ? p->f[a] + q0 : NULL;
		struct block k = {v[0], v[1], v[2], v[3], v[4], v[5], w, p->P ? p->P + q0 : NULL, p->ncol};
		columns_steps(p->pp, &o, nz, b, &k, p->pp->t, p->n, p->i0, p->i1, p->lead, p->tail,
			      p->dz);
	}
}

void peb_run(const struct peb_params *pp, double *f, int nx, int ny, int nz,
	     double dx, double dy, double dz, int nouter, int ninner, double *hout)
{
	peb_run_noise(pp, f, NULL, NULL, nx, ny, nz, dx, dy, dz, nouter, ninner, hout);
}

/* The bake of peb_run_noise and peb_run_field: the quencher at the start
 * q0 (NULL: pp->q0 everywhere), the first-order noise dh, dq (NULL:
 * none). */
static void run_bake(const struct peb_params *pp, double *f, const double *q0, double *dh,
		     double *dq, int nx, int ny, int nz, double dx, double dy, double dz,
		     int nouter, int ninner, double *hout)
{
	size_t ncol = (size_t)nx * (size_t)ny, np = ncol * (size_t)nz;
	double *H = f;          /* h0 in, m out */
	double *Q = xreallocarray(NULL, np, sizeof *Q);
	double *A = xcalloc(np, sizeof *A);
	double *dA = dh ? xcalloc(np, sizeof *dA) : NULL;
	double *P = pp->p == 1 && pp->kq > 0 ? xreallocarray(NULL, np, sizeof *P) : NULL;
	for (size_t k = 0; k < np; k++) {
		Q[k] = q0 ? q0[k] : pp->q0;
		if (P)
			P[k] = 1;
		if (!(H[k] > 0))
			H[k] = 0;
		/* a noisy acid (the drawn counts over the mean PAG count, the
		 * full bake's input) may exceed one */
		if (H[k] > 1 && !q0)
			H[k] = 1;
	}
	int xy = (nx > 2 || ny > 2) && (pp->dh > 0 || pp->dq > 0);
	if (!xy)
		nouter = 1;
	/* nouter x-y steps, each over ninner of the n graded column steps:
	 * x-y diffusion over half of the outer steps on either side of each
	 * outer node (Strang) */
	int n = nouter * ninner;
	double T = pp->t, prev = 0;
	size_t nblk = (ncol + PEB_BLOCK - 1) / PEB_BLOCK;
	exp_tables_init();
	struct peb_pass pass = {pp, {H, Q, A, dh, dq, dA}, P, dh ? 6 : 3, ncol, nz, n, 0, 0, 0, 1, dz,
				xreallocarray(NULL, (size_t)par_threads(), PASS_SCRATCH(nz) * sizeof(double)), NULL};
	int whole = xy && ninner == 1 && T > 0;
	if (whole) {
		/* x-y diffusion at every step: the x-y and z diffusions of a
		 * step together between the reactions on either side of it
		 * (they commute), R(dt/2) Z(dt) XY(dt) R(dt/2), the two half
		 * reactions at a node merged into one, so one reaction a step
		 * where the nested form below has two (it puts the x-y
		 * diffusion between two half reactions of its own).  Measured
		 * against 512 steps, max |m - m_512| at 32 steps: 7.4e-4
		 * (nested 5.7e-4) on examples/car-krf-lines, 7.3e-4 (8.0e-4)
		 * on examples/car-arf-contact, 8.2e-4 (5.5e-4) on the 0.6 um
		 * line image of tests/bench/car.sh at order 1, and at 64 steps
		 * 4.1e-4 (5.2e-4) on examples/euv-lines without its noise;
		 * second order in the step either way. */
		/* the step's z operators once, not per block */
		struct zops z1 = {.fixed = 1, .buf = xreallocarray(NULL, 2 * ZSTEP_BUF(nz), sizeof(double))};
		for (int s = 0; s <= n; s++) {
			pass.i0 = s;
			pass.i1 = s < n ? s + 1 : n;
			pass.lead = prev;
			pass.tail = s == n;
			if (s < n) {
				zops_set(&z1, pp, nz, dz, peb_node(T, n, s + 1) - peb_node(T, n, s));
				pass.z1 = &z1;
			}
			par_for(nblk, 1, pass_blocks, &pass);
			if (s == n)
				break;
			prev = peb_node(T, n, s + 1) - peb_node(T, n, s);
			peb_diffuse_xy(H, nx, ny, nz, dx, dy, pp->dh, prev);
			peb_diffuse_xy(Q, nx, ny, nz, dx, dy, pp->dq, prev);
			if (dh) {
				peb_diffuse_xy(dh, nx, ny, nz, dx, dy, pp->dh, prev);
				peb_diffuse_xy(dq, nx, ny, nz, dx, dy, pp->dq, prev);
			}
		}
		free(z1.buf);
	} else if (T > 0) {
		for (int s = 0; s < nouter; s++) {
			pass.i0 = s * ninner;
			pass.i1 = pass.i0 + ninner;
			double Ds = peb_node(T, n, pass.i1) - peb_node(T, n, pass.i0);
			if (xy) {
				peb_diffuse_xy(H, nx, ny, nz, dx, dy, pp->dh, 0.5 * (prev + Ds));
				peb_diffuse_xy(Q, nx, ny, nz, dx, dy, pp->dq, 0.5 * (prev + Ds));
				if (dh) {
					peb_diffuse_xy(dh, nx, ny, nz, dx, dy, pp->dh, 0.5 * (prev + Ds));
					peb_diffuse_xy(dq, nx, ny, nz, dx, dy, pp->dq, 0.5 * (prev + Ds));
				}
			}
			prev = Ds;
			par_for(nblk, 1, pass_blocks, &pass);
		}
	}
	if (hout) {
		/* the acid at the end: the last x-y half step, which m does not
		 * need, completes it */
		if (xy && T > 0 && !whole)
			peb_diffuse_xy(H, nx, ny, nz, dx, dy, pp->dh, 0.5 * prev);
		memcpy(hout, H, np * sizeof *H);
	}
	if (P) {
		for (size_t k = 0; k < np; k++)
			A[k] += log(P[k]) / pp->kq;
		free(P);
	}
	for (size_t k = 0; k < np; k++)
		f[k] = exp(-pp->kamp * A[k]);
	/* the integral of h^p is never below zero: where the first-order
	 * noise would take it there (a large negative dA at low G0), m = 1 */
	if (dA)
		for (size_t k = 0; k < np; k++)
			f[k] = exp(-pp->kamp * (A[k] + dA[k] > 0 ? A[k] + dA[k] : 0));
	free(pass.scratch);
	free(Q);
	free(A);
	free(dA);
}

void peb_run_noise(const struct peb_params *pp, double *f, double *dh, double *dq, int nx,
		   int ny, int nz, double dx, double dy, double dz, int nouter, int ninner,
		   double *hout)
{
	run_bake(pp, f, NULL, dh, dq, nx, ny, nz, dx, dy, dz, nouter, ninner, hout);
}

void peb_run_field(const struct peb_params *pp, double *f, const double *q0, int nx, int ny,
		   int nz, double dx, double dy, double dz, int nouter, int ninner, double *hout)
{
	run_bake(pp, f, q0, NULL, NULL, nx, ny, nz, dx, dy, dz, nouter, ninner, hout);
}

void peb_columns(const struct peb_params *pp, double *f, size_t ncol, int nz, double dz, int nsteps)
{
	peb_run(pp, f, (int)ncol, 1, nz, 1, 1, dz, 1, nsteps, NULL);
}
