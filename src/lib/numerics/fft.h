/*
 * fft.h - complex discrete Fourier transforms of any length, ours (house
 * rules: no FFT library).
 *
 *   X[k] = sum_{j=0}^{n-1} x[j] exp(sign 2 pi i j k / n),  sign = -1 or +1,
 *
 * unnormalised both ways (a forward and a backward transform multiply by
 * n).  Lengths whose prime factors are all at most FFT_MAX_RADIX run as a
 * mixed-radix Cooley-Tukey decimation in time (special butterflies for
 * 2, 3, 4 and 5, a general one for 7, 11, 13); any other length (97, say)
 * runs as Bluestein's chirp-z convolution on a power-of-two length.  Cost
 * about n log n either way; rounding about 1e-16 log n relative to the
 * largest |X|.
 *
 * A plan is read-only once made: several threads may run the same plan
 * at once, each with its own work array of fft_work_size() values.
 */
#ifndef S3D_FFT_H
#define S3D_FFT_H

#include <complex.h>
#include <stddef.h>

enum { FFT_MAX_RADIX = 13 };

struct fft_plan;

/* A plan for length n >= 1 and direction sign (-1 forward, +1 backward). */
struct fft_plan *fft_plan_new(size_t n, int sign);
void fft_plan_free(struct fft_plan *p);
size_t fft_length(const struct fft_plan *p);
/* Complex values of work array fft_exec needs. */
size_t fft_work_size(const struct fft_plan *p);
/* x[0 .. n-1] replaced by its transform; work holds fft_work_size values. */
void fft_exec(const struct fft_plan *p, double complex *x, double complex *work);

/* The 2D transform of a[j nx + i], 0 <= i < nx, 0 <= j < ny, in place:
 * px of length nx for the rows, py of length ny for the columns, the same
 * sign; work holds fft_work2_size(px, py) values. */
size_t fft_work2_size(const struct fft_plan *px, const struct fft_plan *py);
void fft_exec2(const struct fft_plan *px, const struct fft_plan *py, double complex *a,
	       double complex *work);

#endif
