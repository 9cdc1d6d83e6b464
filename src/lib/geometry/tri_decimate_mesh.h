/*
 * tri_decimate_mesh.h - the decimator's mesh (tri_decimate.c), shared
 * with its input checks (tri_decimate_input.c); not a library interface.
 */
#ifndef S3D_TRI_DECIMATE_MESH_H
#define S3D_TRI_DECIMATE_MESH_H

#include <stddef.h>

struct cand;

struct star_tri {
	int tv[3];
	double n[3];            /* twice the area vector */
	double q;               /* quality */
};

struct dmesh {
	size_t nv, nt;
	double *p;              /* 3 per vertex */
	double *q;              /* quadric, 10 per vertex: aa ab ac ad bb bc bd cc cd dd */
	unsigned char *face;    /* box faces a vertex lies on, bit f for bounds[f] */
	unsigned char *flag;    /* F_* */
	int *tv;                /* 3 vertex per triangle, -1: dead triangle */
	int *head, *next;       /* corner lists: head per vertex, next per corner (int: a
				 * tile has fewer than 2^31 corners, tri_decimate checks) */
	double tol, tol2;
	int *thead;             /* per triangle: the first input vertex it answers for */
	int *pnext;             /* per vertex: the next one of the same triangle */
	int *otv;               /* the input triangles (welded) */
	size_t *ostart;         /* per vertex: its input triangles (CSR) */
	int *otri;
	float *osph;            /* per input triangle: a bounding sphere, centre
				 * and radius (rounded outwards) */
	/* scratch */
	long *star;
	int *pts;
	size_t cstar, cpts, nstar, npts;
	int *nbr;
	size_t cnbr;
	size_t *phint, cphint;
	struct cand *cands;
	size_t ccands;
	unsigned *mark;
	unsigned stamp;
	int *cnt;               /* per vertex: triangles shared with consider's u */
	unsigned char *exact;   /* per vertex: its heap entry (or none) is what
				 * consider(u, 0) would give now */
	unsigned *ver;          /* per vertex: bumped when its star changes */
	unsigned char *checked; /* per vertex: its entry passed valid when its
				 * and its target's versions were vu, vv */
	unsigned *vu, *vv;
	int *ring, *ring2;
	size_t cring, cring2;
	struct star_tri *stri;  /* star_prep's: the star of su */
	size_t nstri, cstri, snu;
	int su, sring;          /* sring: snu and umark are su's */
	unsigned *umark;        /* per vertex: ustamp if a neighbour of su */
	unsigned ustamp;
	unsigned *tmark;        /* per input triangle: tstamp if in tset */
	unsigned tstamp;
	size_t *tset, ctset;    /* input_set's triangles */
};

enum { F_LOCKED = 1, F_BOUNDARY = 2, F_DEAD = 4 };

/* whether, once u is on v, every input vertex u's star answers for stays
 * within tol of the star, and the star's points on the barycentric grid
 * of step 1/TRI_DECIMATE_SAMPLES within tol of the input triangles
 * around them */
int dm_points_ok(struct dmesh *m, int u, int v);

/* collapses u onto v: u's triangles go to v (those holding both die),
 * the input vertices u's star answered for go to the nearest triangle
 * of the new star, and v takes u's quadric */
void dm_collapse(struct dmesh *m, int u, int v);

#endif
