/*
 * fmt_gds.c - GDSII stream reader (see fmt_gds.h).
 *
 * The file is read whole, its records checked once into a compact table
 * of cells and elements that point back into the buffer (the XY data is
 * decoded only when a shape is flattened), so a layout of a million
 * shapes costs one pass and a few tens of bytes per element.  Flattening
 * walks the reference tree from the chosen cell with the composed
 * transform; a cell's bounding box (all layers, computed once) lets a
 * reference that misses the window be skipped whole.
 *
 * Coordinates are kept in database units through the transforms, and
 * rotations by multiples of 90 degrees use exact cosines, so that a
 * layout on a nanometre grid gives the same doubles as the same numbers
 * typed in micrometres (micrometres = dbu / 1000 is correctly rounded,
 * as strtod is).
 */
#include "fmt_gds.h"
#include "lex.h"
#include "util.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* record types */
enum {
	R_HEADER = 0x00, R_BGNLIB = 0x01, R_LIBNAME = 0x02, R_UNITS = 0x03, R_ENDLIB = 0x04,
	R_BGNSTR = 0x05, R_STRNAME = 0x06, R_ENDSTR = 0x07, R_BOUNDARY = 0x08, R_PATH = 0x09,
	R_SREF = 0x0A, R_AREF = 0x0B, R_TEXT = 0x0C, R_LAYER = 0x0D, R_DATATYPE = 0x0E,
	R_WIDTH = 0x0F, R_XY = 0x10, R_ENDEL = 0x11, R_SNAME = 0x12, R_COLROW = 0x13,
	R_NODE = 0x15, R_TEXTTYPE = 0x16, R_STRING = 0x19, R_STRANS = 0x1A, R_MAG = 0x1B,
	R_ANGLE = 0x1C, R_PATHTYPE = 0x21, R_BOX = 0x2D, R_BOXTYPE = 0x2E,
	R_BGNEXTN = 0x30, R_ENDEXTN = 0x31
};
/* data types */
enum { D_NONE = 0, D_BITS = 1, D_INT2 = 2, D_INT4 = 3, D_REAL4 = 4, D_REAL8 = 5, D_STR = 6 };

/* Largest element counts accepted: far beyond real layouts. */
enum { GDS_MAX_CELLS = 10000000, GDS_MAX_ARRAY = 32767 };
/* Deepest reference nesting (real layouts nest a few tens deep). */
enum { GDS_MAX_DEPTH = 1000 };

struct elem {
	unsigned char kind;     /* R_BOUNDARY, R_BOX, R_PATH, R_SREF, R_AREF, R_TEXT, R_NODE */
	unsigned char pathtype;
	unsigned char reflect, absmag, absang;
	int layer, datatype;
	int32_t width, bgnextn, endextn;
	int nxy;
	size_t xy;              /* offset of the XY data in the buffer */
	size_t off;             /* offset of the element's first record */
	int ref;                /* referenced cell (SREF, AREF) */
	size_t sname, snamelen; /* the name in the buffer, until resolved */
	double mag, angle;
	int cols, rows;
};

struct cell {
	char *name;
	size_t off;             /* BGNSTR */
	size_t first, n;        /* elements */
	int state;              /* 0 unseen, 1 on the path, 2 done */
	int referenced;
	int64_t bb[4];          /* bounding box in its own frame, dbu (xmin xmax ymin ymax) */
	int empty;
};

struct gds_lib {
	char *path, *ctx;
	jmp_buf *jmp;           /* where errors go in the _try functions, else die */
	char err[640];
	long max_visit;
	double *tmp;            /* flattening scratch, kept here to be freed on error */
	size_t tcap;
	struct poly_set path_out;
	unsigned char *buf;
	size_t len;
	double um;              /* micrometres per dbu */
	long div;               /* um = dbu / div exactly rounded, 0 if not a whole ratio */
	struct elem *e;
	size_t ne;
	struct cell *c;
	int nc;
};

static _Noreturn void gds_die(const struct gds_lib *g, size_t off, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
static _Noreturn void gds_die(const struct gds_lib *cg, size_t off, const char *fmt, ...)
{
	struct gds_lib *g = (struct gds_lib *)cg;
	char msg[512];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	if (g->ctx)
		snprintf(g->err, sizeof g->err, "%s: %s: byte %zu: %s", g->ctx, g->path, off, msg);
	else
		snprintf(g->err, sizeof g->err, "%s: byte %zu: %s", g->path, off, msg);
	if (g->jmp)
		longjmp(*g->jmp, 1);
	die("%s", g->err);
}

static unsigned be16(const unsigned char *p) { return (unsigned)p[0] << 8 | p[1]; }
static int16_t si16(const unsigned char *p) { return (int16_t)be16(p); }
static int32_t si32(const unsigned char *p)
{
	return (int32_t)((uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3]);
}

/* 8-byte excess-64 base-16 real: sign, 7-bit exponent, 56-bit mantissa. */
static double real8(const unsigned char *p)
{
	uint64_t mant = 0;
	for (int i = 1; i < 8; i++)
		mant = mant << 8 | p[i];
	int ex = (p[0] & 0x7f) - 64;
	double v = ldexp((double)mant, 4 * ex - 56);
	return p[0] & 0x80 ? -v : v;
}

struct rec {
	size_t off;             /* of the header */
	unsigned len;           /* whole record */
	int type, dtype;
	const unsigned char *d; /* data */
	unsigned dlen;
};

/* The record at *pos; dies if it does not fit. */
static void next_rec(const struct gds_lib *g, size_t *pos, struct rec *r)
{
	if (*pos + 4 > g->len)
		gds_die(g, *pos, "truncated file: %s", *pos == g->len ? "no ENDLIB record" :
			"a record header is cut off");
	const unsigned char *p = g->buf + *pos;
	r->off = *pos;
	r->len = be16(p);
	r->type = p[2];
	r->dtype = p[3];
	if (r->len < 4 || r->len % 2)
		gds_die(g, *pos, "bad record length %u", r->len);
	if (*pos + r->len > g->len)
		gds_die(g, *pos, "truncated file: record of %u bytes runs past the end", r->len);
	r->d = p + 4;
	r->dlen = r->len - 4;
	*pos += r->len;
}

static const char *rname(int t)
{
	static const char *n[] = {
		"HEADER", "BGNLIB", "LIBNAME", "UNITS", "ENDLIB", "BGNSTR", "STRNAME", "ENDSTR",
		"BOUNDARY", "PATH", "SREF", "AREF", "TEXT", "LAYER", "DATATYPE", "WIDTH", "XY",
		"ENDEL", "SNAME", "COLROW", "TEXTNODE", "NODE", "TEXTTYPE", "PRESENTATION",
		"SPACING", "STRING", "STRANS", "MAG", "ANGLE", "UINTEGER", "USTRING", "REFLIBS",
		"FONTS", "PATHTYPE", "GENERATIONS", "ATTRTABLE", "STYPTABLE", "STRTYPE",
		"ELFLAGS", "ELKEY", "LINKTYPE", "LINKKEYS", "NODETYPE", "PROPATTR", "PROPVALUE",
		"BOX", "BOXTYPE", "PLEX", "BGNEXTN", "ENDEXTN"};
	return t >= 0 && t < (int)(sizeof n / sizeof *n) ? n[t] : "unknown";
}

/* The record must carry n items (n < 0: a positive multiple of -n) of
 * data type dt. */
static void want(const struct gds_lib *g, const struct rec *r, int dt, int n)
{
	static const int size[] = {0, 2, 2, 4, 4, 8, 1};
	if (r->dtype != dt)
		gds_die(g, r->off, "%s record has data type %d, expected %d", rname(r->type),
			r->dtype, dt);
	unsigned sz = (unsigned)size[dt];
	if (n >= 0 ? r->dlen != (unsigned)n * sz
		   : r->dlen == 0 || r->dlen % ((unsigned)-n * sz) != 0)
		gds_die(g, r->off, "%s record has %u data bytes, expected %s%u", rname(r->type),
			r->dlen, n >= 0 ? "" : "a multiple of ", (unsigned)(n >= 0 ? n : -n) * sz);
}

static char *rec_string(const struct rec *r)
{
	size_t n = r->dlen;
	while (n > 0 && r->d[n - 1] == '\0')
		n--;
	char *s = xmalloc(n + 1);
	memcpy(s, r->d, n);
	s[n] = '\0';
	return s;
}

/* One element, from its opening record to ENDEL. */
static void read_elem(struct gds_lib *g, size_t *pos, const struct rec *open, struct elem *e)
{
	memset(e, 0, sizeof *e);
	e->kind = (unsigned char)open->type;
	e->off = open->off;
	e->ref = -1;
	e->mag = 1;
	e->cols = e->rows = 1;
	want(g, open, D_NONE, 0);
	int have_xy = 0, have_layer = 0, have_name = 0, have_cr = 0;
	for (;;) {
		struct rec r;
		next_rec(g, pos, &r);
		switch (r.type) {
		case R_ENDEL:
			goto done;
		case R_LAYER:
			want(g, &r, D_INT2, 1);
			e->layer = (int)be16(r.d);
			have_layer = 1;
			break;
		case R_DATATYPE: case R_BOXTYPE: case R_TEXTTYPE:
			want(g, &r, D_INT2, 1);
			e->datatype = (int)be16(r.d);
			break;
		case R_WIDTH:
			want(g, &r, D_INT4, 1);
			e->width = si32(r.d);
			break;
		case R_PATHTYPE:
			want(g, &r, D_INT2, 1);
			if (si16(r.d) < 0 || si16(r.d) > 4 || si16(r.d) == 3)
				gds_die(g, r.off, "PATHTYPE %d is not 0, 1, 2 or 4", si16(r.d));
			e->pathtype = (unsigned char)si16(r.d);
			break;
		case R_BGNEXTN: case R_ENDEXTN:
			want(g, &r, D_INT4, 1);
			*(r.type == R_BGNEXTN ? &e->bgnextn : &e->endextn) = si32(r.d);
			break;
		case R_XY: {
			want(g, &r, D_INT4, -2);
			e->nxy = (int)(r.dlen / 8);
			e->xy = (size_t)(r.d - g->buf);
			have_xy = 1;
			break;
		}
		case R_SNAME:
			want(g, &r, D_STR, -1);
			e->sname = (size_t)(r.d - g->buf);
			e->snamelen = r.dlen;
			while (e->snamelen > 0 && r.d[e->snamelen - 1] == '\0')
				e->snamelen--;
			have_name = 1;
			break;
		case R_STRANS:
			want(g, &r, D_BITS, 1);
			e->reflect = (r.d[0] & 0x80) != 0;
			e->absmag = (r.d[1] & 0x04) != 0;
			e->absang = (r.d[1] & 0x02) != 0;
			break;
		case R_MAG:
			want(g, &r, D_REAL8, 1);
			e->mag = real8(r.d);
			if (!(e->mag > 0) || !isfinite(e->mag) || e->mag > 1e6)
				gds_die(g, r.off, "MAG %g is not a positive magnification", e->mag);
			break;
		case R_ANGLE:
			want(g, &r, D_REAL8, 1);
			e->angle = real8(r.d);
			if (!isfinite(e->angle) || fabs(e->angle) > 1e6)
				gds_die(g, r.off, "ANGLE %g is not an angle in degrees", e->angle);
			break;
		case R_COLROW:
			want(g, &r, D_INT2, 2);
			e->cols = si16(r.d);
			e->rows = si16(r.d + 2);
			if (e->cols < 1 || e->rows < 1)
				gds_die(g, r.off, "COLROW %d %d: counts must be 1 to %d", e->cols,
					e->rows, GDS_MAX_ARRAY);
			have_cr = 1;
			break;
		case R_BGNSTR: case R_ENDSTR: case R_ENDLIB: case R_BOUNDARY: case R_PATH:
		case R_SREF: case R_AREF: case R_TEXT: case R_NODE: case R_BOX: case R_HEADER:
		case R_BGNLIB: case R_UNITS:
			gds_die(g, r.off, "%s record inside an element (no ENDEL after the %s at byte %zu)",
				rname(r.type), rname(open->type), open->off);
		default:
			break;  /* properties, presentation, strings, plex: not geometry */
		}
	}
done:
	if (e->kind == R_TEXT || e->kind == R_NODE)
		return;
	if (!have_xy)
		gds_die(g, e->off, "%s without XY", rname(e->kind));
	if ((e->kind == R_BOUNDARY || e->kind == R_BOX || e->kind == R_PATH) && !have_layer)
		gds_die(g, e->off, "%s without LAYER", rname(e->kind));
	int need = e->kind == R_SREF ? 1 : e->kind == R_AREF ? 3 : e->kind == R_BOX ? 5 : 0;
	if (need && e->nxy != need)
		gds_die(g, e->off, "%s has %d XY points, expected %d", rname(e->kind), e->nxy, need);
	if (e->kind == R_BOUNDARY && e->nxy < 3)
		gds_die(g, e->off, "BOUNDARY has %d XY points, expected at least 4", e->nxy);
	if ((e->kind == R_SREF || e->kind == R_AREF) && !have_name)
		gds_die(g, e->off, "%s without SNAME", rname(e->kind));
	if (e->kind == R_AREF && !have_cr)
		gds_die(g, e->off, "AREF without COLROW");
}

static int cmp_cell(const void *a, const void *b)
{
	return strcmp(((const struct cell *)a)->name, ((const struct cell *)b)->name);
}

static int find_cell(const struct gds_lib *g, const char *name, size_t len)
{
	int lo = 0, hi = g->nc - 1;
	while (lo <= hi) {
		int mid = lo + (hi - lo) / 2;
		const char *s = g->c[mid].name;
		int c = strncmp(s, name, len);
		if (c == 0 && s[len] != '\0')
			c = 1;
		if (c == 0)
			return mid;
		if (c < 0)
			lo = mid + 1;
		else
			hi = mid - 1;
	}
	return -1;
}

static struct gds_lib *gds_new(const char *path, const char *ctx)
{
	struct gds_lib *g = xcalloc(1, sizeof *g);
	g->path = xstrdup(path);
	g->ctx = ctx ? xstrdup(ctx) : NULL;
	g->max_visit = FMT_GDS_MAX_VISIT;
	return g;
}

static void parse(struct gds_lib *g);

struct gds_lib *fmt_gds_read(const char *path, const char *ctx)
{
	/* name the statement that asked, not only the file; a device or a
	 * pipe named in an input file must not be read without end */
	const char *pre = ctx ? ctx : "", *sep = ctx ? ": " : "";
	struct stat st;
	if (stat(path, &st) != 0)
		die("%s%s%s: cannot open:", pre, sep, path);
	if (!S_ISREG(st.st_mode))
		die("%s%s%s: not a regular file", pre, sep, path);
	if ((double)st.st_size > FMT_GDS_MAX_BYTES)
		die("%s%s%s: %.3g GB; the reader holds a layout in memory and reads at most "
		    "%.3g GB", pre, sep, path, (double)st.st_size / 1e9, FMT_GDS_MAX_BYTES / 1e9);
	struct gds_lib *g = gds_new(path, ctx);
	g->buf = lex_slurp(path, &g->len);
	parse(g);
	return g;
}

struct gds_lib *fmt_gds_read_mem(const char *name, const void *data, size_t len,
				 char *err, size_t errlen)
{
	struct gds_lib *volatile g = gds_new(name, NULL);
	g->buf = xmalloc(len + 1);
	if (len)
		memcpy(g->buf, data, len);
	g->len = len;
	jmp_buf jb;
	g->jmp = &jb;
	if (setjmp(jb)) {
		snprintf(err, errlen, "%s", g->err);
		fmt_gds_free(g);
		return NULL;
	}
	parse(g);
	g->jmp = NULL;
	return g;
}

void fmt_gds_set_max_visit(struct gds_lib *g, long n)
{
	g->max_visit = n;
}

static void parse(struct gds_lib *g)
{
	size_t pos = 0, ecap = 0, ccap = 0;
	struct rec r;
	next_rec(g, &pos, &r);
	if (r.type != R_HEADER)
		gds_die(g, 0, "not a GDSII stream file (no HEADER record)");
	int have_units = 0, in_cell = 0;
	for (;;) {
		next_rec(g, &pos, &r);
		if (r.type == R_ENDLIB) {
			if (in_cell)
				gds_die(g, r.off, "ENDLIB inside a cell (no ENDSTR)");
			break;
		}
		switch (r.type) {
		case R_UNITS: {
			want(g, &r, D_REAL8, 2);
			double m = real8(r.d + 8);
			if (!(m > 0) || !isfinite(m) || m > 1 || m < 1e-15)
				gds_die(g, r.off, "UNITS: %g metres per database unit is absurd", m);
			g->um = m / 1e-6;
			double k = 1 / g->um;
			long kr = lround(k);
			g->div = kr >= 1 && fabs(k - kr) <= 1e-9 * k ? kr : 0;
			have_units = 1;
			break;
		}
		case R_BGNSTR:
			if (in_cell)
				gds_die(g, r.off, "BGNSTR inside a cell (no ENDSTR)");
			if (!have_units)
				gds_die(g, r.off, "cell before the UNITS record");
			if (g->nc >= GDS_MAX_CELLS)
				gds_die(g, r.off, "more than %d cells", GDS_MAX_CELLS);
			xgrow(&g->c, &ccap, (size_t)g->nc + 1, sizeof *g->c);
			memset(&g->c[g->nc], 0, sizeof *g->c);
			g->c[g->nc].off = r.off;
			g->c[g->nc].first = g->ne;
			next_rec(g, &pos, &r);
			if (r.type != R_STRNAME)
				gds_die(g, r.off, "%s after BGNSTR, expected STRNAME", rname(r.type));
			want(g, &r, D_STR, -1);
			g->c[g->nc].name = rec_string(&r);
			g->nc++;
			in_cell = 1;
			break;
		case R_ENDSTR:
			if (!in_cell)
				gds_die(g, r.off, "ENDSTR outside a cell");
			g->c[g->nc - 1].n = g->ne - g->c[g->nc - 1].first;
			in_cell = 0;
			break;
		case R_BOUNDARY: case R_PATH: case R_SREF: case R_AREF: case R_TEXT:
		case R_NODE: case R_BOX:
			if (!in_cell)
				gds_die(g, r.off, "%s outside a cell", rname(r.type));
			xgrow(&g->e, &ecap, g->ne + 1, sizeof *g->e);
			read_elem(g, &pos, &r, &g->e[g->ne]);
			if (g->e[g->ne].kind == R_TEXT || g->e[g->ne].kind == R_NODE)
				break;
			g->ne++;
			break;
		case R_HEADER:
			gds_die(g, r.off, "second HEADER record");
		case R_ENDEL: case R_XY: case R_LAYER: case R_SNAME:
			gds_die(g, r.off, "%s record outside an element", rname(r.type));
		default:
			break;  /* BGNLIB, LIBNAME, REFLIBS, FONTS, ...: not needed */
		}
	}
	if (!have_units)
		gds_die(g, 0, "no UNITS record");
	/* resolve references by name */
	if (g->nc > 1)
		qsort(g->c, (size_t)g->nc, sizeof *g->c, cmp_cell);
	for (int i = 0; i + 1 < g->nc; i++)
		if (strcmp(g->c[i].name, g->c[i + 1].name) == 0)
			gds_die(g, g->c[i + 1].off > g->c[i].off ? g->c[i + 1].off : g->c[i].off,
				"cell \"%.60s\" is defined twice", g->c[i].name);
	for (size_t i = 0; i < g->ne; i++) {
		struct elem *e = &g->e[i];
		if (e->kind != R_SREF && e->kind != R_AREF)
			continue;
		e->ref = find_cell(g, (const char *)g->buf + e->sname, e->snamelen);
		if (e->ref < 0)
			gds_die(g, e->off, "%s to a missing cell \"%.*s\"", rname(e->kind),
				(int)(e->snamelen > 60 ? 60 : e->snamelen),
				(const char *)g->buf + e->sname);
		g->c[e->ref].referenced = 1;
	}
}

void fmt_gds_free(struct gds_lib *g)
{
	if (!g)
		return;
	for (int i = 0; i < g->nc; i++)
		free(g->c[i].name);
	free(g->c);
	free(g->e);
	free(g->buf);
	free(g->path);
	free(g->ctx);
	free(g->tmp);
	poly_set_free(&g->path_out);
	free(g);
}

double fmt_gds_um_per_dbu(const struct gds_lib *g)
{
	return g->um;
}

/* ---- flattening ---- */

struct xform {
	double a, b, c, d, tx, ty;      /* x' = a x + b y + tx, y' = c x + d y + ty (dbu) */
	double mag, angle;              /* degrees */
	int reflect;
};

static void cos_sin(double deg, double *c, double *s)
{
	double q = deg / 90;
	if (q == floor(q) && fabs(q) < 1e9) {
		static const double cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
		long k = ((long)q % 4 + 4) % 4;
		*c = cs[k][0];
		*s = cs[k][1];
		return;
	}
	*c = cos(deg * (M_PI / 180));
	*s = sin(deg * (M_PI / 180));
}

/* The transform of a reference placed at (x, y) of the parent's frame. */
static struct xform compose(const struct xform *p, const struct elem *e, double x, double y)
{
	struct xform t;
	t.mag = e->absmag ? e->mag : p->mag * e->mag;
	t.angle = e->absang ? e->angle : p->angle + (p->reflect ? -e->angle : e->angle);
	t.reflect = p->reflect ^ e->reflect;
	double c, s;
	cos_sin(t.angle, &c, &s);
	double f = t.reflect ? -1 : 1;
	t.a = t.mag * c;
	t.b = -t.mag * s * f;
	t.c = t.mag * s;
	t.d = t.mag * c * f;
	t.tx = p->a * x + p->b * y + p->tx;
	t.ty = p->c * x + p->d * y + p->ty;
	return t;
}

static void apply(const struct xform *t, double x, double y, double *ox, double *oy)
{
	*ox = t->a * x + t->b * y + t->tx;
	*oy = t->c * x + t->d * y + t->ty;
}

struct flat {
	const struct gds_lib *g;
	int layer, datatype;
	int cull;
	double win[4];          /* dbu of the top frame */
	struct poly_set *out;
	long shapes;
	long visits;
};

static double to_um(const struct gds_lib *g, double v)
{
	return g->div ? v / (double)g->div : v * g->um;
}

static int box_misses(const struct flat *f, double x0, double x1, double y0, double y1)
{
	return f->cull && (x1 < f->win[0] || x0 > f->win[1] || y1 < f->win[2] || y0 > f->win[3]);
}

/* Adds polygon xy (n vertices, top-frame dbu) in micrometres. */
static void out_poly(struct flat *f, double *xy, int n)
{
	double x0 = xy[0], x1 = xy[0], y0 = xy[1], y1 = xy[1];
	for (int i = 1; i < n; i++) {
		x0 = fmin(x0, xy[2 * i]); x1 = fmax(x1, xy[2 * i]);
		y0 = fmin(y0, xy[2 * i + 1]); y1 = fmax(y1, xy[2 * i + 1]);
	}
	if (box_misses(f, x0, x1, y0, y1))
		return;
	for (int i = 0; i < 2 * n; i++)
		xy[i] = to_um(f->g, xy[i]);
	n = poly_dedup(xy, n);
	if (n >= 3)
		poly_set_add(f->out, xy, n);
}

static void shape(struct flat *f, const struct elem *e, const struct xform *t)
{
	struct gds_lib *g = (struct gds_lib *)f->g;
	const unsigned char *p = g->buf + e->xy;
	xgrow(&g->tmp, &g->tcap, 2 * (size_t)e->nxy + 2, sizeof *g->tmp);
	double *tmp = g->tmp;
	for (int i = 0; i < e->nxy; i++)
		apply(t, si32(p + 8 * i), si32(p + 8 * i + 4), &tmp[2 * i], &tmp[2 * i + 1]);
	f->shapes++;
	if (e->kind != R_PATH) {
		out_poly(f, tmp, e->nxy);
		return;
	}
	/* a negative width is absolute: not scaled by the magnification */
	double hw = e->width < 0 ? -(double)e->width / 2 : (double)e->width * t->mag / 2;
	double e0 = 0, e1 = 0, rt = 0;
	if (e->pathtype == 2)
		e0 = e1 = hw;
	else if (e->pathtype == 4) {
		e0 = e->bgnextn * t->mag;
		e1 = e->endextn * t->mag;
	} else if (e->pathtype == 1)
		rt = 1e-3 / f->g->um;   /* 1 nm in dbu */
	struct poly_set *ps = &g->path_out;
	ps->n = 0;
	if (ps->start)
		ps->start[0] = 0;
	poly_path(ps, tmp, e->nxy, hw, e0, e1, rt);
	for (int i = 0; i < ps->n; i++) {
		int nv = poly_set_nv(ps, i);
		double q[2 * 4096];
		if (nv > 4096)
			continue;
		memcpy(q, poly_set_xy(ps, i), 2 * (size_t)nv * sizeof *q);
		out_poly(f, q, nv);
	}
}

/* Bounding box of a cell's contents (every layer), dbu, with loop check. */
static void cell_bbox(struct gds_lib *g, int ci, size_t from, int depth)
{
	struct cell *c = &g->c[ci];
	if (c->state == 2)
		return;
	if (c->state == 1)
		gds_die(g, from, "reference loop: cell \"%.60s\" contains itself", c->name);
	if (depth > GDS_MAX_DEPTH)
		gds_die(g, from, "references nested more than %d deep", GDS_MAX_DEPTH);
	c->state = 1;
	double bb[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
	for (size_t k = c->first; k < c->first + c->n; k++) {
		const struct elem *e = &g->e[k];
		const unsigned char *p = g->buf + e->xy;
		if (e->kind == R_SREF || e->kind == R_AREF) {
			cell_bbox(g, e->ref, e->off, depth + 1);
			const struct cell *s = &g->c[e->ref];
			if (s->empty)
				continue;
			struct xform id = {1, 0, 0, 1, 0, 0, 1, 0, 0};
			double px[3], py[3];
			for (int i = 0; i < e->nxy; i++) {
				px[i] = si32(p + 8 * i);
				py[i] = si32(p + 8 * i + 4);
			}
			struct xform t = compose(&id, e, 0, 0);
			/* the corners of the child's box at the array's four corners */
			for (int a = 0; a < 2; a++)
				for (int b = 0; b < 2; b++) {
					double ox = px[0], oy = py[0];
					if (e->kind == R_AREF) {
						ox += a * (px[1] - px[0]) * (e->cols - 1) / e->cols +
						      b * (px[2] - px[0]) * (e->rows - 1) / e->rows;
						oy += a * (py[1] - py[0]) * (e->cols - 1) / e->cols +
						      b * (py[2] - py[0]) * (e->rows - 1) / e->rows;
					}
					for (int u = 0; u < 2; u++)
						for (int v = 0; v < 2; v++) {
							double x, y;
							apply(&t, (double)s->bb[u], (double)s->bb[2 + v], &x, &y);
							x += ox;
							y += oy;
							bb[0] = fmin(bb[0], x); bb[1] = fmax(bb[1], x);
							bb[2] = fmin(bb[2], y); bb[3] = fmax(bb[3], y);
						}
				}
		} else {
			/* paths reach out by their half-width and extensions */
			double grow = 0;
			if (e->kind == R_PATH) {
				double w = fabs((double)e->width);
				grow = w / 2 + fmax(fabs((double)e->bgnextn), fabs((double)e->endextn)) + w;
			}
			for (int i = 0; i < e->nxy; i++) {
				double x = si32(p + 8 * i), y = si32(p + 8 * i + 4);
				bb[0] = fmin(bb[0], x - grow); bb[1] = fmax(bb[1], x + grow);
				bb[2] = fmin(bb[2], y - grow); bb[3] = fmax(bb[3], y + grow);
			}
		}
	}
	c->empty = !(bb[1] >= bb[0]);
	for (int i = 0; i < 4 && !c->empty; i++)
		c->bb[i] = (int64_t)(i % 2 ? ceil(fmin(bb[i], 9e18)) : floor(fmax(bb[i], -9e18)));
	c->state = 2;
}

static void flatten(struct flat *f, int ci, const struct xform *t)
{
	const struct gds_lib *g = f->g;
	const struct cell *c = &g->c[ci];
	if (c->empty)
		return;
	if (f->cull) {
		double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
		for (int u = 0; u < 2; u++)
			for (int v = 0; v < 2; v++) {
				double x, y;
				apply(t, (double)c->bb[u], (double)c->bb[2 + v], &x, &y);
				x0 = fmin(x0, x); x1 = fmax(x1, x);
				y0 = fmin(y0, y); y1 = fmax(y1, y);
			}
		if (box_misses(f, x0, x1, y0, y1))
			return;
	}
	for (size_t k = c->first; k < c->first + c->n; k++) {
		const struct elem *e = &g->e[k];
		if (++f->visits > g->max_visit)
			gds_die(g, e->off, "flattening visits more than %ld elements (arrays of "
				"arrays?); refusing", g->max_visit);
		if (e->kind == R_SREF || e->kind == R_AREF) {
			const unsigned char *p = g->buf + e->xy;
			double px[3], py[3];
			for (int i = 0; i < e->nxy; i++) {
				px[i] = si32(p + 8 * i);
				py[i] = si32(p + 8 * i + 4);
			}
			/* an array is refused whole before its first copy */
			if ((double)e->cols * e->rows > (double)(g->max_visit - f->visits))
				gds_die(g, e->off, "an AREF of %d x %d copies takes flattening past "
					"%ld elements; refusing", e->cols, e->rows, g->max_visit);
			for (int j = 0; j < e->rows; j++)
				for (int i = 0; i < e->cols; i++) {
					double x = px[0], y = py[0];
					if (e->kind == R_AREF) {
						x += (px[1] - px[0]) * i / e->cols + (px[2] - px[0]) * j / e->rows;
						y += (py[1] - py[0]) * i / e->cols + (py[2] - py[0]) * j / e->rows;
						if ((i || j) && ++f->visits > g->max_visit)
							gds_die(g, e->off, "flattening visits more than %ld "
								"elements (arrays of arrays?); refusing",
								g->max_visit);
					}
					struct xform ct = compose(t, e, x, y);
					flatten(f, e->ref, &ct);
				}
			continue;
		}
		if (e->layer != f->layer || (f->datatype >= 0 && e->datatype != f->datatype))
			continue;
		shape(f, e, t);
	}
}

static long shapes(struct gds_lib *g, const char *cell, int layer, int datatype,
		   const double *win, struct poly_set *out);

long fmt_gds_shapes(const struct gds_lib *cg, const char *cell, int layer, int datatype,
		    const double *win, struct poly_set *out)
{
	char err[640];
	long n = fmt_gds_shapes_try((struct gds_lib *)cg, cell, layer, datatype, win, out,
				    err, sizeof err);
	if (n < 0)
		die("%s", err);
	return n;
}

long fmt_gds_shapes_try(struct gds_lib *g, const char *cell, int layer, int datatype,
			const double *win, struct poly_set *out, char *err, size_t errlen)
{
	jmp_buf jb;
	g->jmp = &jb;
	if (setjmp(jb)) {
		g->jmp = NULL;
		snprintf(err, errlen, "%s", g->err);
		/* a walk cut short leaves cells marked as on the path */
		for (int i = 0; i < g->nc; i++)
			if (g->c[i].state == 1)
				g->c[i].state = 0;
		return -1;
	}
	long n = shapes(g, cell, layer, datatype, win, out);
	g->jmp = NULL;
	return n;
}

/* The names of the library's cells, "A, B, C" (cut short with "..."),
 * for the message of a cell that is not there. */
static void cell_names(const struct gds_lib *g, char *buf, size_t n)
{
	size_t ll = 0;
	buf[0] = '\0';
	for (int i = 0; i < g->nc && ll < n - 80; i++)
		ll += (size_t)snprintf(buf + ll, n - ll, "%s%.60s", i ? ", " : "", g->c[i].name);
	if (ll >= n - 80 && g->nc)
		snprintf(buf + ll, n - ll, ", ...");
}

/* Most distinct layer/datatype pairs listed by fmt_gds_layer_list. */
enum { GDS_LIST_PAIRS = 40 };

static int is_shape(const struct elem *e)
{
	return e->kind == R_BOUNDARY || e->kind == R_BOX || e->kind == R_PATH;
}

int fmt_gds_layer_list(const struct gds_lib *g, int layer, int datatype, char *buf, size_t n)
{
	buf[0] = '\0';
	for (size_t i = 0; i < g->ne; i++)
		if (is_shape(&g->e[i]) && g->e[i].layer == layer &&
		    (datatype < 0 || g->e[i].datatype == datatype))
			return 1;
	/* not there: the distinct pairs, in file order (one pass, against
	 * the few already listed) */
	int pl[GDS_LIST_PAIRS], pd[GDS_LIST_PAIRS], np = 0;
	size_t ll = 0;
	for (size_t i = 0; i < g->ne && np < GDS_LIST_PAIRS; i++) {
		const struct elem *e = &g->e[i];
		int seen = !is_shape(e);
		for (int k = 0; k < np && !seen; k++)
			seen = pl[k] == e->layer && pd[k] == e->datatype;
		if (seen || ll >= n - 40)
			continue;
		pl[np] = e->layer;
		pd[np] = e->datatype;
		ll += (size_t)snprintf(buf + ll, n - ll, "%s%d/%d", np++ ? ", " : "", e->layer,
				       e->datatype);
	}
	return 0;
}

static long shapes(struct gds_lib *g, const char *cell, int layer, int datatype,
		   const double *win, struct poly_set *out)
{
	int top = -1;
	if (cell) {
		top = find_cell(g, cell, strlen(cell));
		if (top < 0)
		{
			char names[400];
			cell_names(g, names, sizeof names);
			gds_die(g, 0, "no cell named \"%.60s\"; its cells: %s", cell, names);
		}
	} else {
		char list[400];
		size_t ll = 0;
		int ntop = 0;
		list[0] = '\0';
		for (int i = 0; i < g->nc; i++)
			if (!g->c[i].referenced) {
				if (ntop++ == 0)
					top = i;
				if (ll < sizeof list - 80)
					ll += (size_t)snprintf(list + ll, sizeof list - ll, "%s\"%.60s\"",
							       ntop > 1 ? ", " : "", g->c[i].name);
			}
		if (ntop == 0)
			gds_die(g, 0, g->nc ? "no top cell (every cell is referenced: a reference loop)"
				: "the library has no cell");
		if (ntop > 1)
			gds_die(g, 0, "%d top cells, give \"cell NAME\": %s", ntop, list);
	}
	cell_bbox(g, top, g->c[top].off, 0);
	struct flat f;
	memset(&f, 0, sizeof f);
	f.g = g;
	f.layer = layer;
	f.datatype = datatype;
	f.out = out;
	if (win) {
		f.cull = 1;
		for (int i = 0; i < 4; i++)
			f.win[i] = win[i] / g->um;
		/* a little slack: culling must never drop a shape that touches */
		double s = 1e-6 * (fabs(f.win[1] - f.win[0]) + fabs(f.win[3] - f.win[2]));
		f.win[0] -= s; f.win[1] += s; f.win[2] -= s; f.win[3] += s;
	}
	struct xform id = {1, 0, 0, 1, 0, 0, 1, 0, 0};
	flatten(&f, top, &id);
	return f.shapes;
}
