/*
 * fmt_rate.h - the etch-rate array written by bleach and read by etch:
 * rval.3D (ASCII) and rval.3D.binary.  See man/man5/rval.5.
 *
 * A regular grid over the resist: nx*ny*nz points including both ends,
 * x varying fastest, then y, then z; z runs from zmin (the substrate,
 * -thickness) to zmax (the resist top, 0).  Lengths in micrometres, rates
 * in micrometres per second.  ny = 1 is a 2D x-z array (etch2d's input;
 * its row sits at ymin, any y bounds accepted).  Besides the rate the file may carry more
 * arrays of the same shape, each with a name; bleach stores the PAC
 * concentration as "M".
 *
 * The binary form is little-endian whatever the machine, starts with a
 * magic string and a version, and ends with a CRC-32 of everything before
 * it, so a truncated, corrupt or foreign file is refused.  ASCII numbers
 * are printed to round-trip exactly, so ASCII -> binary -> ASCII is the
 * identity.  fmt_rate_read tells the two apart by content.
 */
#ifndef S3D_FMT_RATE_H
#define S3D_FMT_RATE_H

#include <stddef.h>

enum {
	RATE_MAX_ARRAYS = 8,
	RATE_NAME_LEN = 8,          /* bytes of an array name, NUL-padded */
	RATE_MAX_N = 1 << 20        /* per dimension */
};

#define RATE_MAGIC_BIN "\x89RVAL3D\n"   /* 8 bytes */
#define RATE_MAGIC_ASCII "RVAL3D"
#define RATE_VERSION 1

struct rate_array {
	char name[RATE_NAME_LEN + 1];
	double *v;                  /* nx*ny*nz values */
};

struct ratefile {
	int nx, ny, nz;
	double xmin, xmax, ymin, ymax, zmin, zmax;
	int narrays;                /* >= 1; array 0 is the rate */
	struct rate_array arrays[RATE_MAX_ARRAYS];
};

/* A zeroed grid with one array named "rate". */
struct ratefile *fmt_rate_new(int nx, int ny, int nz, const double bounds[6]);
/* Adds a zeroed array; returns its values. */
double *fmt_rate_add_array(struct ratefile *r, const char *name);
/* The values of the named array, or NULL. */
double *fmt_rate_array(const struct ratefile *r, const char *name);
static inline double *fmt_rate_values(const struct ratefile *r) { return r->arrays[0].v; }
static inline size_t fmt_rate_index(const struct ratefile *r, int i, int j, int k)
{
	return ((size_t)k * (size_t)r->ny + (size_t)j) * (size_t)r->nx + (size_t)i;
}
double fmt_rate_x(const struct ratefile *r, int i);
double fmt_rate_y(const struct ratefile *r, int j);
double fmt_rate_z(const struct ratefile *r, int k);

struct ratefile *fmt_rate_read(const char *path);
/* The same, keeping only the rate (array 0) and the arrays named in want
 * (NULL-terminated; NULL keeps all), in file order.  A binary file on disk
 * is streamed, so memory is the arrays kept, never a copy of the file;
 * the others are still read for the CRC, but their values are not
 * checked.  Otherwise the same errors as fmt_rate_read. */
struct ratefile *fmt_rate_read_arrays(const char *path, const char *const *want);
void fmt_rate_write(const char *path, const struct ratefile *r, int ascii);
/* The same, for a grid too large to hold every array: an array whose
 * values are NULL is made plane by plane (k = 0 .. nz-1, nx*ny values,
 * x fastest) by gen(ctx, array, k, plane) as it is written, so memory is
 * the arrays held plus one plane.  The file is byte-identical to
 * fmt_rate_write's of the same values. */
typedef void (*rate_plane_fn)(void *ctx, int array, int k, double *plane);
void fmt_rate_write_planes(const char *path, const struct ratefile *r, int ascii,
			   rate_plane_fn gen, void *ctx);
void fmt_rate_free(struct ratefile *r);

/* The rate (array 0) of r as the interpolated field of rfield.h (r must
 * outlive f); name is r's file, for rfield_init's messages. */
struct rfield;
void fmt_rate_field(struct rfield *f, const struct ratefile *r, const char *name);

/* CRC-32 (IEEE 802.3, as in zlib), exposed for tests. */
unsigned long fmt_crc32(unsigned long crc, const void *data, size_t len);

#endif
