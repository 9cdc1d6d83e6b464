/*
 * stitch.h - the pieces of stitch(1): cutting a splat input into tiles
 * (cut.c) and joining the tiles' images and surfaces (image.c, surface.c).
 */
#ifndef S3D_STITCH_H
#define S3D_STITCH_H

/* One tile of a join: its result file, the shift from its coordinates to
 * the output's (um), and its core in output coordinates. */
struct tile {
	const char *file;
	double dx, dy;
	double core[4];     /* xmin xmax ymin ymax */
};

/* Writes DIR/tNNN.in for each tile of width w (um) with a halo of h (um;
 * < 0: the default) of the splat input file, and prints one line per
 * tile on stdout: "tNNN.in dx dy xmin xmax ymin ymax". */
void stitch_cut(const char *input, double w, double h, const char *dir);
/* The tiles' contour-files joined into out (a contour-file). */
void stitch_images(const struct tile *t, int n, const char *out);
/* The tiles' plot3d surfaces cut to their cores and welded into out;
 * returns the seam curves left open (0: watertight at the seams). */
long stitch_surfaces(const struct tile *t, int n, const char *out);

#endif
