/*
 * femwin.h - the pieces of femwin(1): collecting a focus-exposure matrix
 * into fem.dat (collect.c), the process window (window.c), and the probe
 * surface fem(1) checks measure's arguments on (probe.c).
 */
#ifndef FEMWIN_H
#define FEMWIN_H

#include "fmt_fem.h"

/* One swept point: where its measure table is. */
struct femwin_input {
	double focus, dose;
	const char *table;
};

/* Reads every table that exists, writes fem.dat (and, when given, the
 * Bossung plot file and its drawplot template); returns how many points
 * had no table.  With stoch_path, the tables of one (focus, dose) given
 * more than once are the seeds of a stochastic point: fem.dat holds
 * their mean, stoch_path (stoch.dat) the mean, 3 sigma and failures;
 * without it a point given twice is an error. */
int femwin_collect(const struct femwin_input *in, int n, const char *fem_path,
		   const char *bossung_path, const char *template_path,
		   const char *stoch_path);

struct femwin_spec {
	double target;  /* um */
	double tol;     /* percent of target */
};

/* The process window of t: writes window.dat (and the EL/DOF plot file
 * when plot_path is set, the in-spec region in (focus, dose) with the 5 %
 * and 10 % EL rectangles and its drawplot template when region_path is)
 * and prints the summary on stdout. */
void femwin_window(const struct fem_table *t, const struct femwin_spec *s,
		   const char *name, const char *window_path, const char *plot_path,
		   const char *region_path, const char *region_template);

/* Writes an undeveloped resist surface (flat top over the mask window,
 * resist from -thickness to 0) as etch would, for checking measure's
 * arguments before a sweep. */
void femwin_probe(const char *splat_in, const char *bleach_in, const char *out);
/* Prints "nx ny nz" on stdout: the image grid of splat_in and the points
 * through the resist of bleach_in (its grid nz, or the default), the
 * resolution the drivers' -accuracy refines (splat -grid, bleach -nz);
 * dies when bleach_in resamples the image on its own grid nx ny, which
 * -accuracy could not refine. */
void femwin_resolution(const char *splat_in, const char *bleach_in);

#endif
