/*
 * vec3.h - the three-vector arithmetic the geometry files share (a point
 * or vector is 3 doubles, um): difference, cross and dot product.  Static
 * inline, so each caller compiles them as if written in place and its
 * results are bit for bit what the private copies gave.
 */
#ifndef S3D_VEC3_H
#define S3D_VEC3_H

/* r = a - b */
static inline void vec3_sub(const double *a, const double *b, double *r)
{
	r[0] = a[0] - b[0], r[1] = a[1] - b[1], r[2] = a[2] - b[2];
}

/* r = a x b */
static inline void vec3_cross(const double *a, const double *b, double *r)
{
	r[0] = a[1] * b[2] - a[2] * b[1];
	r[1] = a[2] * b[0] - a[0] * b[2];
	r[2] = a[0] * b[1] - a[1] * b[0];
}

static inline double vec3_dot(const double *a, const double *b)
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

#endif
