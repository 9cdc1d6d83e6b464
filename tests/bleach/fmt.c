/*
 * fmt.c - the bleach input format (src/lib/fmt_bleach.c): every resist
 * file shipped in examples/resists/ parses, and write -> read -> write is
 * byte-identical with the values read back exactly (the writer prints
 * numbers to round-trip).  Also the defaults: ambient 1, standing waves
 * on, no bake, nz = 40 points a standing-wave period (at least 50); the
 * stochastic statement's bake word: linear by default and not written
 * (the files of before it stay byte for byte), full written and read back.
 */
#include "fmt_bleach.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

static char *slurp(const char *path)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return NULL;
	static char buf[1 << 16];
	size_t n = fread(buf, 1, sizeof buf - 1, f);
	buf[n] = '\0';
	fclose(f);
	return buf;
}

static void roundtrip(const char *path)
{
	struct bleach_input a, b;
	fmt_bleach_read(path, &a);
	fmt_bleach_write("a.in", &a);
	fmt_bleach_read("a.in", &b);
	fmt_bleach_write("b.in", &b);
	char *ta = strdup(slurp("a.in")), *tb = slurp("b.in");
	if (strcmp(ta, tb) != 0 || a.dose != b.dose || a.C != b.C || a.nz != b.nz ||
	    a.npar != b.npar || a.par[0] != b.par[0] || a.nlayers != b.nlayers ||
	    a.bake != b.bake || a.diffusion != b.diffusion || a.k0 != b.k0 ||
	    a.have_car != b.have_car || a.kamp != b.kamp || a.kq != b.kq || a.q0 != b.q0 ||
	    a.dacid != b.dacid || a.dquench != b.dquench || a.peb_time != b.peb_time ||
	    a.model != b.model || a.par[4] != b.par[4] || a.pag != b.pag ||
	    a.stochastic != b.stochastic || a.seed != b.seed ||
	    a.noise_photons != b.noise_photons || a.noise_acid != b.noise_acid ||
	    a.bake_full != b.bake_full) {
		printf("FAIL round trip of %s\n", path);
		failures++;
	} else {
		printf("ok %s\n", path);
	}
	free(ta);
	remove("a.in");
	remove("b.in");
}

int main(void)
{
	const char *top = getenv("TOP");
	if (!top)
		top = ".";
	static const char *files[] = {"kodak820-fig22", "shipley1470", "olinhunt6512",
				      "kodak820", "ca-negative"};
	for (int i = 0; i < 5; i++) {
		char p[4096];
		snprintf(p, sizeof p, "%s/examples/resists/%s.in", top, files[i]);
		roundtrip(p);
	}
	/* the CA positive resists (car, peb; ARRHENIUS written back as its
	 * value; pag and stochastic in the EUV ones) and the notch model */
	static const char *more[] = {"car-krf-lines", "car-arf-contact", "notch-iline",
				     "euv-lines", "euv-contacts"};
	for (int i = 0; i < 5; i++) {
		char p[4096];
		snprintf(p, sizeof p, "%s/examples/%s/resist.in", top, more[i]);
		roundtrip(p);
	}
	struct bleach_input in;
	fmt_bleach_parse("mem", "wavelength 0.436\n"
			 "RESIST dill 0.64 0.04 0.01 index 1.68 thickness 0.7\n"
			 "substrate 4.73 0.14\ndose 240\ndevelop kim 0.062 0.0001 8.5\n", &in);
	/* 40 a period of 0.436 / 3.36 um over 0.7 um: ceil(215.8) + 1 */
	if (in.ambient != 1 || !in.standing || in.bake != BAKE_NONE || in.nz != 217 ||
	    in.thick != 0.7 || in.model != BLEACH_KIM || in.npar != 3) {
		printf("FAIL defaults: ambient %g standing %d bake %d nz %d\n", in.ambient,
		       in.standing, (int)in.bake, in.nz);
		failures++;
	}
	/* stochastic bake: linear (0) unless full; full round-trips */
	static const char *car = "wavelength 0.0135\n"
		"resist thickness 0.040 index 0.97 dill 0.0 4.5 0.03\nsubstrate 0.999 0.0018\n"
		"dose 30\ncar quencher 0.3 amplification 0.4 order 1 loss 0.002 quenching 5 "
		"pag 0.3\npeb time 60 dacid 3e-7 dquencher 1e-7\ndevelop mack 0.1 0.0002 0.5 12\n";
	static const char *word[] = {"", " bake linear", " bake FULL"};
	for (int i = 0; i < 3; i++) {
		char text[1024];
		snprintf(text, sizeof text, "%sstochastic seed 5%s\n", car, word[i]);
		fmt_bleach_parse("mem", text, &in);
		fmt_bleach_write("c.in", &in);
		struct bleach_input back;
		fmt_bleach_read("c.in", &back);
		int written = strstr(slurp("c.in"), " bake full\n") != NULL;
		if (in.bake_full != (i == 2) || back.bake_full != in.bake_full || written != (i == 2)) {
			printf("FAIL stochastic%s: bake_full %d, read back %d, written %d\n", word[i],
			       in.bake_full, back.bake_full, written);
			failures++;
		}
		remove("c.in");
	}
	return failures != 0;
}
