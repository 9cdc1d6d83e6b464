/*
 * fmt_rate.c - see fmt_rate.h.  Binary layout (all little-endian):
 *
 *   8   magic "\x89RVAL3D\n" (the high byte and newline catch text-mode
 *       transfers, as PNG's signature does)
 *   4   version (1)
 *   4   narrays
 *   12  nx ny nz (uint32)
 *   48  xmin xmax ymin ymax zmin zmax (IEEE-754 binary64)
 *   8*narrays  array names, NUL-padded
 *   8*nx*ny*nz*narrays  the arrays, one after another
 *   4   CRC-32 of every byte before it
 *
 * The ASCII form:
 *   RVAL3D 1
 *   nx ny nz narrays
 *   xmin xmax ymin ymax zmin zmax
 *   then per array: its name on a line, then its values, nx per line.
 */
#include "fmt_rate.h"
#include "rfield.h"
#include "checked.h"
#include "lex.h"
#include "num.h"
#include "util.h"

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

_Static_assert(sizeof(double) == 8, "binary64 doubles required");

static const char *bound_names[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};

/* CRC-32 by slicing (Intel's slicing-by-8): table[0] is the bytewise
 * table, table[k][n] the CRC of byte n followed by k zero bytes, so eight
 * bytes are folded in per step with eight independent lookups instead of
 * eight dependent ones.  The same value as the bytewise loop, which the
 * tail still uses; tests/formats/crc32.c compares the two. */
static uint32_t crc_table[8][256];
static pthread_once_t crc_once = PTHREAD_ONCE_INIT;

static void crc_init(void)
{
	for (uint32_t n = 0; n < 256; n++) {
		uint32_t c = n;
		for (int k = 0; k < 8; k++)
			c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
		crc_table[0][n] = c;
	}
	for (int k = 1; k < 8; k++)
		for (int n = 0; n < 256; n++) {
			uint32_t c = crc_table[k - 1][n];
			crc_table[k][n] = (c >> 8) ^ crc_table[0][c & 0xFF];
		}
}

unsigned long fmt_crc32(unsigned long crc, const void *data, size_t len)
{
	pthread_once(&crc_once, crc_init);
	const uint32_t (*t)[256] = crc_table;
	const unsigned char *p = data;
	uint32_t c = (uint32_t)crc ^ 0xFFFFFFFFu;
	for (; len >= 8; len -= 8, p += 8) {
		uint32_t a = c ^ ((uint32_t)p[0] | (uint32_t)p[1] << 8 |
				  (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24);
		uint32_t b = (uint32_t)p[4] | (uint32_t)p[5] << 8 |
			     (uint32_t)p[6] << 16 | (uint32_t)p[7] << 24;
		c = t[7][a & 0xFF] ^ t[6][a >> 8 & 0xFF] ^ t[5][a >> 16 & 0xFF] ^ t[4][a >> 24] ^
		    t[3][b & 0xFF] ^ t[2][b >> 8 & 0xFF] ^ t[1][b >> 16 & 0xFF] ^ t[0][b >> 24];
	}
	for (; len; len--, p++)
		c = t[0][(c ^ *p) & 0xFF] ^ (c >> 8);
	return c ^ 0xFFFFFFFFu;
}

static size_t npoints(const struct ratefile *r)
{
	return (size_t)r->nx * (size_t)r->ny * (size_t)r->nz;
}

struct ratefile *fmt_rate_new(int nx, int ny, int nz, const double b[6])
{
	struct ratefile *r = xcalloc(1, sizeof *r);
	r->nx = nx, r->ny = ny, r->nz = nz;
	r->xmin = b[0], r->xmax = b[1], r->ymin = b[2];
	r->ymax = b[3], r->zmin = b[4], r->zmax = b[5];
	fmt_rate_add_array(r, "rate");
	return r;
}

double *fmt_rate_add_array(struct ratefile *r, const char *name)
{
	if (r->narrays >= RATE_MAX_ARRAYS)
		die("internal error: more than %d arrays in a rate file", RATE_MAX_ARRAYS);
	if (strlen(name) > RATE_NAME_LEN || !*name)
		die("internal error: bad rate array name \"%s\"", name);
	struct rate_array *a = &r->arrays[r->narrays++];
	memset(a->name, 0, sizeof a->name);
	memcpy(a->name, name, strlen(name));
	a->v = xcalloc(npoints(r), sizeof *a->v);
	return a->v;
}

double *fmt_rate_array(const struct ratefile *r, const char *name)
{
	for (int i = 0; i < r->narrays; i++)
		if (strcmp(r->arrays[i].name, name) == 0)
			return r->arrays[i].v;
	return NULL;
}

double fmt_rate_x(const struct ratefile *r, int i) { return r->xmin + (r->xmax - r->xmin) * i / (r->nx - 1); }
/* ny = 1 (a 2D x-z array): the single row sits at ymin */
double fmt_rate_y(const struct ratefile *r, int j) { return r->ny > 1 ? r->ymin + (r->ymax - r->ymin) * j / (r->ny - 1) : r->ymin; }
double fmt_rate_z(const struct ratefile *r, int k) { return r->zmin + (r->zmax - r->zmin) * k / (r->nz - 1); }

void fmt_rate_free(struct ratefile *r)
{
	if (!r)
		return;
	for (int i = 0; i < r->narrays; i++)
		free(r->arrays[i].v);
	free(r);
}

/* ---- shared validation ---- */

static const char *check_header(const struct ratefile *r)
{
	if (!(r->xmax > r->xmin)) return "xmax must be greater than xmin";
	/* a 2D array (ny = 1) has no y extent: any finite y bounds do */
	if (r->ny != 1 && !(r->ymax > r->ymin)) return "ymax must be greater than ymin";
	if (!(r->zmax > r->zmin)) return "zmax must be greater than zmin";
	return NULL;
}

static int valid_name(const char *s)
{
	size_t n = strlen(s);
	if (n == 0 || n > RATE_NAME_LEN)
		return 0;
	for (size_t i = 0; i < n; i++)
		if (!((s[i] >= 'a' && s[i] <= 'z') || (s[i] >= 'A' && s[i] <= 'Z') ||
		      (s[i] >= '0' && s[i] <= '9') || s[i] == '_'))
			return 0;
	return 1;
}

/* ---- little-endian helpers ---- */

static uint32_t get_u32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static double get_f64(const unsigned char *p)
{
	uint64_t u = 0;
	for (int i = 7; i >= 0; i--)
		u = u << 8 | p[i];
	double d;
	memcpy(&d, &u, 8);
	return d;
}

static void put_u32(unsigned char *p, uint32_t v)
{
	for (int i = 0; i < 4; i++)
		p[i] = (unsigned char)(v >> (8 * i));
}

static void put_f64(unsigned char *p, double d)
{
	if (d == 0)
		d = 0; /* folds -0, as the ASCII form does, so both carry the same values */
	uint64_t u;
	memcpy(&u, &d, 8);
	for (int i = 0; i < 8; i++)
		p[i] = (unsigned char)(u >> (8 * i));
}

enum { HDR_FIXED = 8 + 4 + 4 + 12 + 48 };

/* Whether array name nm is wanted: all are when want is NULL, the rate
 * (array 0) always. */
static int wanted(const char *const *want, uint32_t a, const char *nm)
{
	if (!want || a == 0)
		return 1;
	for (; *want; want++)
		if (strcmp(*want, nm) == 0)
			return 1;
	return 0;
}

static void read_exact(const char *name, FILE *f, void *p, size_t n)
{
	if (fread(p, 1, n, f) != n)
		die("%s:1: cannot read the binary rate file%s", name, ferror(f) ? ":" : " (shortened while reading)");
}

/* The binary form from f, positioned anywhere, len bytes long.  Streams
 * the arrays through a small buffer, so memory is the wanted arrays and
 * no copy of the file; unwanted arrays are read (the CRC covers them) but
 * not kept. */
static struct ratefile *read_binary(const char *name, FILE *f, size_t len,
				    const char *const *want)
{
	/* binary files have no lines; report offset 1 as ":0" would confuse */
	if (len < HDR_FIXED + 4)
		die("%s:1: truncated binary rate file (%zu bytes)", name, len);
	unsigned char buf[HDR_FIXED + 8 * RATE_MAX_ARRAYS];
	if (fseek(f, 0, SEEK_SET) != 0)
		die("%s: cannot seek:", name);
	read_exact(name, f, buf, HDR_FIXED);
	uint32_t version = get_u32(buf + 8);
	if (version != RATE_VERSION)
		die("%s:1: binary rate file version %lu, this program reads version %d",
		    name, (unsigned long)version, RATE_VERSION);
	uint32_t na = get_u32(buf + 12);
	uint32_t n[3] = {get_u32(buf + 16), get_u32(buf + 20), get_u32(buf + 24)};
	if (na < 1 || na > RATE_MAX_ARRAYS)
		die("%s:1: bad array count %lu in binary rate file", name, (unsigned long)na);
	for (int d = 0; d < 3; d++)
		if (n[d] < (d == 1 ? 1 : 2) || n[d] > RATE_MAX_N) /* ny = 1: a 2D array */
			die("%s:1: bad grid size %lu in binary rate file", name, (unsigned long)n[d]);
	/* the exact length the header implies, by checked arithmetic: with
	 * 2^20 points a side and 2 arrays 8 pts na is 2^64, which wraps to 0
	 * and would let a 96-byte file ask for 8 EiB */
	size_t pts, need;
	if (!ck_mul_ok((size_t)n[0] * n[1], n[2], &pts) || !ck_mul_ok(pts, 8 * (size_t)na, &need) ||
	    need > SIZE_MAX - HDR_FIXED - 8 * (size_t)na - 4)
		die("%s:1: binary rate file header claims a %lu x %lu x %lu grid of %lu arrays, "
		    "more bytes than can exist (corrupt)", name, (unsigned long)n[0],
		    (unsigned long)n[1], (unsigned long)n[2], (unsigned long)na);
	need += HDR_FIXED + 8 * (size_t)na + 4;
	if (len != need)
		die("%s:1: binary rate file is %zu bytes, its header says %llu "
		    "(truncated or corrupt)", name, len, (unsigned long long)need);
	read_exact(name, f, buf + HDR_FIXED, 8 * (size_t)na);
	unsigned long crc = fmt_crc32(0, buf, HDR_FIXED + 8 * (size_t)na);

	struct ratefile *r = xcalloc(1, sizeof *r);
	r->nx = (int)n[0], r->ny = (int)n[1], r->nz = (int)n[2];
	double b[6];
	for (int k = 0; k < 6; k++)
		b[k] = get_f64(buf + 28 + 8 * k);
	r->xmin = b[0], r->xmax = b[1], r->ymin = b[2], r->ymax = b[3], r->zmin = b[4], r->zmax = b[5];
	char names[RATE_MAX_ARRAYS][RATE_NAME_LEN + 1];
	for (uint32_t a = 0; a < na; a++) {
		memcpy(names[a], buf + HDR_FIXED + 8 * a, 8);
		names[a][8] = '\0';
	}
	/* the values, a chunk at a time; the first problem found is reported
	 * only once the CRC is known good, so a corrupt file says so */
	size_t np = (size_t)pts;
	unsigned char chunk[64 * 1024];
	size_t bad_at = 0;
	uint32_t bad_array = 0;
	for (uint32_t a = 0; a < na; a++) {
		double *v = NULL;
		if (wanted(want, a, names[a]) && r->narrays < RATE_MAX_ARRAYS) {
			v = xreallocarray(NULL, np, sizeof *v);
			struct rate_array *ra = &r->arrays[r->narrays++];
			memcpy(ra->name, names[a], sizeof ra->name);
			ra->v = v;
		}
		for (size_t i = 0; i < np;) {
			size_t m = np - i < sizeof chunk / 8 ? np - i : sizeof chunk / 8;
			read_exact(name, f, chunk, 8 * m);
			crc = fmt_crc32(crc, chunk, 8 * m);
			if (!v) {       /* not kept: only the CRC needs it */
				i += m;
				continue;
			}
			for (size_t j = 0; j < m; j++, i++) {
				double x = get_f64(chunk + 8 * j);
				if (!isfinite(x) && !bad_at)
					bad_at = i + 1, bad_array = a;
				v[i] = x;
			}
		}
	}
	unsigned char tail[4];
	read_exact(name, f, tail, 4);
	if (crc != get_u32(tail)) {
		fmt_rate_free(r);
		die("%s:1: checksum mismatch: the binary rate file is corrupt", name);
	}
	for (int k = 0; k < 6; k++)
		if (!isfinite(b[k])) {
			fmt_rate_free(r);
			die("%s:1: %s is not a finite number", name, bound_names[k]);
		}
	const char *err = check_header(r);
	if (err) {
		fmt_rate_free(r);
		die("%s:1: %s", name, err);
	}
	for (uint32_t a = 0; a < na; a++)
		if (!valid_name(names[a])) {
			fmt_rate_free(r);
			die("%s:1: bad array name in binary rate file", name);
		}
	if (bad_at) {
		fmt_rate_free(r);
		die("%s:1: value %zu of array %s is not finite", name, bad_at, names[bad_array]);
	}
	return r;
}

static struct ratefile *read_ascii(struct lex *lx)
{
	const char *t = lex_token(lx);
	if (!t || strcmp(t, RATE_MAGIC_ASCII) != 0)
		lex_error(lx, "not a rate file: expected \"%s\" or the binary magic",
			  RATE_MAGIC_ASCII);
	long version = lex_count(lx, "version", 0, 1000000);
	if (version != RATE_VERSION)
		lex_error(lx, "rate file version %ld, this program reads version %d",
			  version, RATE_VERSION);
	long n[3];
	n[0] = lex_count(lx, "nx", 2, RATE_MAX_N);
	n[1] = lex_count(lx, "ny", 1, RATE_MAX_N);   /* ny = 1: a 2D x-z array */
	n[2] = lex_count(lx, "nz", 2, RATE_MAX_N);
	long na = lex_count(lx, "narrays", 1, RATE_MAX_ARRAYS);
	double b[6];
	for (int k = 0; k < 6; k++)
		b[k] = lex_number(lx, bound_names[k]);
	struct ratefile hdr = {0};
	hdr.ny = (int)n[1];
	hdr.xmin = b[0], hdr.xmax = b[1], hdr.ymin = b[2], hdr.ymax = b[3], hdr.zmin = b[4], hdr.zmax = b[5];
	const char *err = check_header(&hdr);
	if (err)
		lex_error(lx, "%s", err);
	/* values are grown as they arrive: a header claiming 2^60 points
	 * allocates only what the file holds */
	uint64_t pts64 = (uint64_t)n[0] * (uint64_t)n[1] * (uint64_t)n[2];
	if (pts64 > SIZE_MAX / 8)
		lex_error(lx, "grid of %llu points is too large", (unsigned long long)pts64);
	size_t pts = (size_t)pts64;
	struct rate_array arr[RATE_MAX_ARRAYS];
	memset(arr, 0, sizeof arr);
	for (long a = 0; a < na; a++) {
		t = lex_token(lx);
		if (!t || !valid_name(t)) {
			for (long q = 0; q < a; q++)
				free(arr[q].v);
			lex_error(lx, "expected the name of array %ld", a + 1);
		}
		for (long q = 0; q < a; q++)
			if (strcmp(arr[q].name, t) == 0) {
				for (long w = 0; w < a; w++)
					free(arr[w].v);
				lex_error(lx, "array \"%s\" given twice", t);
			}
		strcpy(arr[a].name, t);
		size_t cap = 0;
		for (size_t i = 0; i < pts; i++) {
			t = lex_token(lx);
			double v;
			if (!t || !num_parse(t, &v)) {
				for (long q = 0; q <= a; q++)
					free(arr[q].v);
				if (!t)
					lex_error(lx, "truncated: array %s has %zu of %zu values",
						  arr[a].name, i, pts);
				lex_error(lx, "expected value %zu of array %s (a finite number)",
					  i + 1, arr[a].name);
			}
			xgrow(&arr[a].v, &cap, i + 1, sizeof(double));
			arr[a].v[i] = v;
		}
	}
	if (!lex_at_end(lx)) {
		for (long q = 0; q < na; q++)
			free(arr[q].v);
		lex_token(lx);
		lex_error(lx, "unexpected data after the last array");
	}
	struct ratefile *r = xcalloc(1, sizeof *r);
	*r = hdr;
	r->nx = (int)n[0], r->ny = (int)n[1], r->nz = (int)n[2];
	r->narrays = (int)na;
	memcpy(r->arrays, arr, sizeof arr);
	return r;
}

/* The file's bytes while read_binary may die: reachable from here, so the
 * leak checker of make asan does not report them (the program exits). */
static unsigned char *volatile rate_held;

struct ratefile *fmt_rate_read(const char *path)
{
	return fmt_rate_read_arrays(path, NULL);
}

static int is_compressed(const char *path)
{
	size_t n = strlen(path);
	return (n > 3 && strcmp(path + n - 3, ".gz") == 0) ||
	       (n > 2 && strcmp(path + n - 2, ".Z") == 0);
}

/* The stream a binary read has open.  A program's die() exits, which
 * closes it; an in-process caller that returns from die() (the fuzz
 * harness) would leak it, one descriptor a bad file, until fopen fails:
 * so the next read closes what a dead one left. */
static FILE *rate_stream;

struct ratefile *fmt_rate_read_arrays(const char *path, const char *const *want)
{
	const char *name = strcmp(path, "-") == 0 ? "stdin" : path;
	struct ratefile *r;
	if (rate_stream) {
		fclose(rate_stream);
		rate_stream = NULL;
	}
	/* a plain binary file is streamed from disk: no copy of it in memory */
	if (strcmp(path, "-") != 0 && !is_compressed(path)) {
		FILE *f = fopen(path, "rb");
		if (!f)
			die("%s: cannot open:", path);
		rate_stream = f;
		struct stat st;
		unsigned char magic[8];
		if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) &&
		    fread(magic, 1, 8, f) == 8 && memcmp(magic, RATE_MAGIC_BIN, 8) == 0) {
			r = read_binary(name, f, (size_t)st.st_size, want);
			rate_stream = NULL;
			fclose(f);
			return r;
		}
		rate_stream = NULL;
		fclose(f);
	}
	size_t len;
	unsigned char *buf = lex_slurp(path, &len);
	if (len >= 8 && memcmp(buf, RATE_MAGIC_BIN, 8) == 0) {
		FILE *f = fmemopen(buf, len, "rb");
		if (!f)
			die("%s: cannot read:", name);
		rate_held = buf;
		rate_stream = f;
		r = read_binary(name, f, len, want);
		rate_stream = NULL;
		rate_held = NULL;
		fclose(f);
		free(buf);
	} else {
		struct lex *lx = lex_from_memory(name, buf, len);
		lex_expect(lx, "rval(5)");
		free(buf);
		r = read_ascii(lx);
		lex_close(lx);
		/* keep only what was asked for */
		int kept = 0;
		for (int a = 0; a < r->narrays; a++) {
			if (wanted(want, (uint32_t)a, r->arrays[a].name))
				r->arrays[kept++] = r->arrays[a];
			else
				free(r->arrays[a].v);
		}
		r->narrays = kept;
	}
	return r;
}

/* The values of plane k of array a: the array's own, or, for an array
 * without values (fmt_rate_write_planes), made by gen into buf. */
struct planes {
	rate_plane_fn gen;
	void *ctx;
	double *buf;                /* one plane */
};

static const double *plane_of(const struct ratefile *r, const struct planes *p, int a, int k)
{
	size_t n = (size_t)r->nx * (size_t)r->ny;
	if (r->arrays[a].v)
		return r->arrays[a].v + (size_t)k * n;
	p->gen(p->ctx, a, k, p->buf);
	return p->buf;
}

static void write_ascii(FILE *f, const struct ratefile *r, const struct planes *p)
{
	fprintf(f, "%s %d\n%d %d %d %d\n", RATE_MAGIC_ASCII, RATE_VERSION,
		r->nx, r->ny, r->nz, r->narrays);
	double b[6] = {r->xmin, r->xmax, r->ymin, r->ymax, r->zmin, r->zmax};
	num_print_row(f, b, 6);
	for (int a = 0; a < r->narrays; a++) {
		fprintf(f, "%s\n", r->arrays[a].name);
		for (int k = 0; k < r->nz; k++) {
			const double *v = plane_of(r, p, a, k);
			for (int j = 0; j < r->ny; j++)
				num_print_row(f, v + (size_t)j * (size_t)r->nx, r->nx);
		}
	}
}

static void write_binary(FILE *f, const struct ratefile *r, const struct planes *p)
{
	unsigned char hdr[HDR_FIXED + 8 * RATE_MAX_ARRAYS];
	memset(hdr, 0, sizeof hdr);
	memcpy(hdr, RATE_MAGIC_BIN, 8);
	put_u32(hdr + 8, RATE_VERSION);
	put_u32(hdr + 12, (uint32_t)r->narrays);
	put_u32(hdr + 16, (uint32_t)r->nx);
	put_u32(hdr + 20, (uint32_t)r->ny);
	put_u32(hdr + 24, (uint32_t)r->nz);
	double b[6] = {r->xmin, r->xmax, r->ymin, r->ymax, r->zmin, r->zmax};
	for (int k = 0; k < 6; k++)
		put_f64(hdr + 28 + 8 * k, b[k]);
	for (int a = 0; a < r->narrays; a++)
		memcpy(hdr + HDR_FIXED + 8 * a, r->arrays[a].name, strlen(r->arrays[a].name));
	size_t hlen = HDR_FIXED + 8 * (size_t)r->narrays;
	unsigned long crc = fmt_crc32(0, hdr, hlen);
	fwrite(hdr, 1, hlen, f);
	unsigned char chunk[8 * 1024];
	size_t np = (size_t)r->nx * (size_t)r->ny;      /* a plane */
	for (int a = 0; a < r->narrays; a++) {
		for (int k = 0; k < r->nz; k++) {
			const double *v = plane_of(r, p, a, k);
			size_t used = 0;
			for (size_t i = 0; i < np; i++) {
				put_f64(chunk + used, v[i]);
				used += 8;
				if (used == sizeof chunk || i + 1 == np) {
					crc = fmt_crc32(crc, chunk, used);
					fwrite(chunk, 1, used, f);
					used = 0;
				}
			}
		}
	}
	unsigned char tail[4];
	put_u32(tail, (uint32_t)crc);
	fwrite(tail, 1, 4, f);
}

void fmt_rate_write_planes(const char *path, const struct ratefile *r, int ascii,
			   rate_plane_fn gen, void *ctx)
{
	const char *err = check_header(r);
	if (err)
		die("%s: internal error: %s", path, err);
	struct planes p = {gen, ctx, NULL};
	for (int a = 0; a < r->narrays; a++)
		if (!r->arrays[a].v) {
			if (!gen)
				die("%s: internal error: array %s has no values", path,
				    r->arrays[a].name);
			p.buf = xreallocarray(NULL, (size_t)r->nx * (size_t)r->ny, sizeof *p.buf);
			break;
		}
	struct aout *a = aout_open(path);
	if (ascii)
		write_ascii(a->f, r, &p);
	else
		write_binary(a->f, r, &p);
	free(p.buf);
	aout_commit(a);
}

void fmt_rate_write(const char *path, const struct ratefile *r, int ascii)
{
	fmt_rate_write_planes(path, r, ascii, NULL, NULL);
}

void fmt_rate_field(struct rfield *f, const struct ratefile *r, const char *name)
{
	int n[3] = {r->nx, r->ny, r->nz};
	double lo[3] = {r->xmin, r->ymin, r->zmin}, hi[3] = {r->xmax, r->ymax, r->zmax};
	rfield_init(f, n, lo, hi, fmt_rate_values(r), name);
}
