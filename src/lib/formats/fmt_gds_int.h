/*
 * fmt_gds_int.h - what the GDSII reader's two files share (fmt_gds.c
 * reads and checks the records, fmt_gds_flat.c counts and flattens): the
 * record types, the tables of cells and elements, the error exit.  Not a
 * library interface: only these two files include it.
 */
#ifndef S3D_FMT_GDS_INT_H
#define S3D_FMT_GDS_INT_H

#include "fmt_gds.h"

#include <setjmp.h>
#include <stddef.h>
#include <stdint.h>

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
	int counted;            /* cnt holds the counts of the layer asked */
	double cnt[3];          /* flattened: shapes on the layer, their vertices, visits */
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

/* "prog: [ctx: ]path: byte off: message", or a longjmp in the _try
 * functions. */
_Noreturn void gds_die(const struct gds_lib *g, size_t off, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
/* The cell named name (len bytes), or -1. */
int gds_find_cell(const struct gds_lib *g, const char *name, size_t len);

static inline unsigned be16(const unsigned char *p) { return (unsigned)p[0] << 8 | p[1]; }
static inline int16_t si16(const unsigned char *p) { return (int16_t)be16(p); }
static inline int32_t si32(const unsigned char *p)
{
	return (int32_t)((uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3]);
}

#endif
