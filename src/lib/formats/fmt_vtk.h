/*
 * fmt_vtk.h - VTK XML PolyData (.vtp) for ParaView and every VTK reader:
 * the triangles (and polylines) of a plot3d file with shared points.  See
 * man/man5/vtp.5.
 *
 * Each set of the plot file becomes one <Piece>; within a piece, points
 * with identical coordinates are stored once, numbered in the order they
 * first appear, so the output is deterministic.  A closed curve of 4
 * points (etch's triangles) is a triangle, a closed curve of n + 1 points
 * a polygon of n points, an open curve a polyline.  Each cell carries the
 * number of its set (from 1) in the cell-data array "set".
 */
#ifndef S3D_FMT_VTK_H
#define S3D_FMT_VTK_H

#include "fmt_plot.h"

/* Writes pf (dim 3) to path (atomic, as every output). */
void fmt_vtk_write(const char *path, const struct plot_file *pf);

#endif
