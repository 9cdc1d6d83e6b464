/*
 * fmt_kind.c - see fmt_kind.h.  Recognises a kind only on a sure sign:
 * a magic (the binary rate file, GDSII's HEADER record, PostScript, VTK
 * XML), a first word (RVAL3D, stack), the header line of measure's and
 * fem's tables, a keyword only one input format has, or the shape of the
 * first two number lines of the numeric formats (6 bounds: plot3d; 4
 * bounds then one count: plot2d; 4 bounds then two counts: contour).
 */
#include "fmt_kind.h"
#include "fmt_rate.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

static const struct fmt_kind
	K_RATE = {"a rate file", "rval(5)"},
	K_GDS = {"a GDSII layout", "splat(5) gds statement"},
	K_PS = {"a PostScript picture", "PostScript"},
	K_VTK = {"a VTK file", "vtp(5)"},
	K_STACK = {"an image stack", "stack(5)"},
	K_MEASURE = {"measure's table", "measure(5)"},
	K_FEM = {"a focus-exposure table", "fem(5)"},
	K_SPLAT = {"a splat input file", "splat(5)"},
	K_BLEACH = {"a bleach input file", "bleach(5)"},
	K_PLOT3D = {"a 3D plot file", "plot3d(5)"},
	K_PLOT2D = {"a 2D plot file", "plot2d(5)"},
	K_CONTOUR = {"a contour-file", "contour(5)"};

/* Keywords of one input format and not the other (both have resist,
 * wavelength and grid). */
static const char *const splat_words[] = {
	"annular", "astigmatism", "background", "clip", "coma", "contour", "curvature",
	"cutline", "defocus", "dipole", "distortion", "gds", "na", "polygon", "quadrupole",
	"rect", "sigma", "spherical", "window", "zernike", NULL};
static const char *const bleach_words[] = {
	"ambient", "amplification", "bake", "canegative", "car", "crosslink", "dacid",
	"develop", "dill", "dose", "dquencher", "enhanced", "kim", "layer", "loss", "mack",
	"notch", "order", "peb", "quencher", "quenching", "standingwaves", "substrate",
	"temperature", "time", NULL};

/* Lines looked at before giving up. */
enum { KIND_LINES = 64 };

static int in_list(const char *w, size_t len, const char *const *list)
{
	for (; *list; list++)
		if (strlen(*list) == len && strncasecmp(*list, w, len) == 0)
			return 1;
	return 0;
}

static int starts(const char *s, const char *end, const char *with)
{
	size_t n = strlen(with);
	return (size_t)(end - s) >= n && memcmp(s, with, n) == 0;
}

/* How many numbers the line [s, end) holds, or -1 if it holds other words. */
static int numbers_on(const char *s, const char *end)
{
	int n = 0;
	while (s < end) {
		while (s < end && (isspace((unsigned char)*s) || *s == ','))
			s++;
		if (s >= end)
			break;
		const char *w = s;
		while (s < end && !isspace((unsigned char)*s) && *s != ',')
			s++;
		char buf[64], *stop;
		size_t len = (size_t)(s - w);
		if (len >= sizeof buf)
			return -1;
		memcpy(buf, w, len);
		buf[len] = '\0';
		strtod(buf, &stop);
		if (stop == buf || *stop)
			return -1;
		n++;
	}
	return n;
}

/* The kind a text file's line says, or NULL; *nums gets the count of
 * numbers of a number line, -2 for a keyword line that says nothing
 * (resist, grid: both input formats have them), -1 otherwise. */
static const struct fmt_kind *text_line(const char *s, const char *end, int *nums)
{
	*nums = -1;
	if (starts(s, end, "# z cd "))
		return &K_MEASURE;
	if (starts(s, end, "# focus dose "))
		return &K_FEM;
	if (*s == '#')
		return NULL;
	if (starts(s, end, "<?xml") || starts(s, end, "<VTKFile"))
		return &K_VTK;
	const char *w = s;
	while (w < end && isalpha((unsigned char)*w))
		w++;
	size_t len = (size_t)(w - s);
	if (len && (w == end || isspace((unsigned char)*w))) {
		if (len == 6 && memcmp(s, "RVAL3D", 6) == 0)
			return &K_RATE;
		if (len == 5 && strncasecmp(s, "stack", 5) == 0)
			return &K_STACK;
		if (in_list(s, len, splat_words))
			return &K_SPLAT;
		if (in_list(s, len, bleach_words))
			return &K_BLEACH;
		*nums = -2;     /* a word of both or of neither: read on */
		return NULL;
	}
	*nums = numbers_on(s, end);
	return NULL;
}

const struct fmt_kind *fmt_kind_of(const void *data, size_t n)
{
	const char *b = data, *end = b + n;
	if (n >= 8 && memcmp(b, RATE_MAGIC_BIN, 8) == 0)
		return &K_RATE;
	if (n >= 4 && memcmp(b, "\0\6\0\2", 4) == 0)
		return &K_GDS;
	if (n >= 4 && memcmp(b, "%!PS", 4) == 0)
		return &K_PS;
	int first = -1;
	const char *s = b;
	for (int k = 0; k < KIND_LINES && s < end; k++) {
		const char *e = memchr(s, '\n', (size_t)(end - s));
		if (!e)
			e = end;
		while (s < e && isspace((unsigned char)*s))
			s++;
		if (s < e) {
			int nums;
			const struct fmt_kind *kd = text_line(s, e, &nums);
			if (kd)
				return kd;
			if (*s != '#' && nums != -2) {
				if (nums < 0 || (first >= 0 && first != 4))
					return NULL;
				if (first < 0 && nums == 6)
					return &K_PLOT3D;
				if (first < 0 && nums != 4)
					return NULL;
				if (first == 4)
					return nums == 1 ? &K_PLOT2D : nums == 2 ? &K_CONTOUR : NULL;
				first = nums;
			}
		}
		s = e + 1;
	}
	return NULL;
}
