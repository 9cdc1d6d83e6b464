/*
 * fmt_gds.c - GDSII stream reader (see fmt_gds.h).
 *
 * The file is read whole, its records checked once into a compact table
 * of cells and elements that point back into the buffer (the XY data is
 * decoded only when a shape is flattened), so a layout of a million
 * shapes costs one pass and a few tens of bytes per element.  Flattening
 * (fmt_gds_flat.c) walks the reference tree from the chosen cell with the composed
 * transform; a cell's bounding box (all layers, computed once) lets a
 * reference that misses the window be skipped whole.
 *
 * Coordinates are kept in database units through the transforms, and
 * rotations by multiples of 90 degrees use exact cosines, so that a
 * layout on a nanometre grid gives the same doubles as the same numbers
 * typed in micrometres (micrometres = dbu / 1000 is correctly rounded,
 * as strtod is).
 */
#include "fmt_gds_int.h"
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

_Noreturn void gds_die(const struct gds_lib *cg, size_t off, const char *fmt, ...)
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

/* A BOUNDARY whose edges cross (properly: one passes through the other;
 * touching, as keyhole polygons do, is allowed) has no one filling: it
 * is refused, as splat's polygon statement refuses it.  Edges sorted by
 * their least x are swept, each tested against the edges still open; a
 * crossing polygon is found at its first crossing, a simple one costs the
 * overlaps of its edges' x ranges (at most 8191 points: an XY record). */
static int64_t orient64(const int64_t *a, const int64_t *b, const int64_t *c)
{
	int64_t v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
	return (v > 0) - (v < 0);
}

static const int64_t *cross_pts;
static int cmp_edge_x(const void *x, const void *y)
{
	int i = *(const int *)x, j = *(const int *)y;
	int64_t a = cross_pts[2 * i] < cross_pts[2 * i + 2] ? cross_pts[2 * i] : cross_pts[2 * i + 2];
	int64_t b = cross_pts[2 * j] < cross_pts[2 * j + 2] ? cross_pts[2 * j] : cross_pts[2 * j + 2];
	return a != b ? (a > b) - (a < b) : (i > j) - (i < j);
}

static void check_crossing(const struct gds_lib *g, const struct elem *e)
{
	int n = e->nxy - 1;     /* edges: the last point closes the ring */
	if (n < 4)
		return;
	int64_t *p = xreallocarray(NULL, 2 * (size_t)n + 2, sizeof *p);
	int *ord = xreallocarray(NULL, (size_t)n, sizeof *ord);
	for (int i = 0; i <= n; i++) {
		p[2 * i] = si32(g->buf + e->xy + 8 * (size_t)i);
		p[2 * i + 1] = si32(g->buf + e->xy + 8 * (size_t)i + 4);
		if (i < n)
			ord[i] = i;
	}
	cross_pts = p;
	qsort(ord, (size_t)n, sizeof *ord, cmp_edge_x);
	int bad_i = -1, bad_j = -1;
	for (int u = 0; u < n && bad_i < 0; u++) {
		int i = ord[u];
		const int64_t *a = p + 2 * i, *b = a + 2;
		for (int v = u - 1; v >= 0; v--) {
			int j = ord[v];
			const int64_t *c = p + 2 * j, *d = c + 2;
			if ((c[0] > d[0] ? c[0] : d[0]) < (a[0] < b[0] ? a[0] : b[0]))
				continue;       /* closed before this edge opens */
			if (orient64(a, b, c) * orient64(a, b, d) < 0 &&
			    orient64(c, d, a) * orient64(c, d, b) < 0) {
				bad_i = i < j ? i : j;
				bad_j = i < j ? j : i;
				break;
			}
		}
	}
	free(ord);
	free(p);
	if (bad_i >= 0)
		gds_die(g, e->off, "BOUNDARY crosses itself: edge %d meets edge %d (of %d)",
			bad_i + 1, bad_j + 1, n);
}

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
	if (e->kind == R_BOUNDARY)
		check_crossing(g, e);
	if ((e->kind == R_SREF || e->kind == R_AREF) && !have_name)
		gds_die(g, e->off, "%s without SNAME", rname(e->kind));
	if (e->kind == R_AREF && !have_cr)
		gds_die(g, e->off, "AREF without COLROW");
}

static int cmp_cell(const void *a, const void *b)
{
	return strcmp(((const struct cell *)a)->name, ((const struct cell *)b)->name);
}

int gds_find_cell(const struct gds_lib *g, const char *name, size_t len)
{
	int lo = 0, hi = g->nc - 1;
	while (lo <= hi) {
		int mid = lo + (hi - lo) / 2;
		const char *s = g->c[mid].name;
		/* s may be shorter than len when name holds a NUL (strncmp
		 * stops there): its length, read no further than its end */
		size_t sl = strnlen(s, len + 1);
		int c = strncmp(s, name, len);
		if (c == 0 && sl != len)
			c = sl > len ? 1 : -1;
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

/* The first records of the file, checked as parse does before the whole
 * file is read: a 2 GB file of zeros (sparse) is refused at byte 0, not
 * after reading it. */
enum { PREFIX = 65536 };
static void prefix_chunk(void *ctx, const char *buf, size_t n)
{
	struct gds_lib *g = ctx;
	size_t k = n < PREFIX - g->len ? n : PREFIX - g->len;
	memcpy(g->buf + g->len, buf, k);
	g->len += k;
}

static void check_prefix(struct gds_lib *g)
{
	g->buf = xmalloc(PREFIX);
	g->len = 0;
	if (lex_compressed(g->path)) {
		lex_gz_scan(g->path, PREFIX, prefix_chunk, g);
	} else {
		FILE *f = fopen(g->path, "rb");
		if (!f)
			die("%s: cannot open:", g->path);
		g->len = fread(g->buf, 1, PREFIX, f);
		fclose(f);
	}
	/* parse's checks of the first two records in its order (the HEADER,
	 * then the next record's length); the rest, and a record running past
	 * the prefix, are left to the whole read */
	size_t pos = 0;
	for (int k = 0; k < 2 && pos + 4 <= g->len; k++) {
		const unsigned char *p = g->buf + pos;
		unsigned len = be16(p);
		if (len < 4 || len % 2)
			gds_die(g, pos, "bad record length %u", len);
		if (pos + len > g->len)
			break;
		if (pos == 0 && p[2] != R_HEADER)
			gds_die(g, 0, "not a GDSII stream file (no HEADER record)");
		pos += len;
	}
	free(g->buf);
	g->buf = NULL;
	g->len = 0;
}

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
	check_prefix(g);
	/* a compressed layout is counted as it inflates (lex.h) */
	g->buf = lex_slurp_max(path, ctx, &g->len, FMT_GDS_MAX_BYTES);
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
		e->ref = gds_find_cell(g, (const char *)g->buf + e->sname, e->snamelen);
		if (e->ref < 0 && memchr(g->buf + e->sname, '\0', e->snamelen))
			gds_die(g, e->off, "%s names a cell with a NUL byte inside its name "
				"(after \"%.60s\"): no cell is named so", rname(e->kind),
				(const char *)g->buf + e->sname);
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

