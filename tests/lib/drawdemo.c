/*
 * drawdemo - test tool: draws every kind of primitive of the drawing back
 * end (all 11 line types, all 18 markers, filled and outlined polygons,
 * text with PostScript- and XML-special characters at every alignment and
 * an angle, clipping, two pages) and writes it as PostScript and SVG.
 *
 *   drawdemo OUT.ps OUT.svg [scale [landscape]]
 */
#include "draw.h"
#include "num.h"
#include "util.h"

#include <stdlib.h>

int main(int argc, char **argv)
{
	util_setprog(argv[0]);
	if (argc < 3)
		die("usage: drawdemo OUT.ps OUT.svg [scale [landscape]]");
	struct draw *d = draw_new();
	for (int lt = 0; lt < DRAW_NLINETYPES; lt++) {
		draw_set_line(d, lt, 1.0);
		draw_segment(d, 72, 700 - 20 * lt, 300, 700 - 20 * lt);
	}
	draw_set_line(d, 1, 0.5);
	for (int m = 0; m < DRAW_NMARKERS; m++)
		draw_marker(d, m, 350 + 12 * (m % 9), 700 - 20 * (m / 9), 8);
	double tri[6] = {72, 400, 200, 400, 136, 480};
	draw_polygon(d, 3, tri, 0.5, 1);
	double sq[8] = {220, 400, 300, 400, 300, 480, 220, 480};
	draw_polygon(d, 4, sq, DRAW_NOFILL, 1);
	draw_set_gray(d, 0.3);
	for (int h = -1; h <= 1; h++)
		for (int v = -1; v <= 1; v++)
			draw_text(d, 400 + 60 * h, 450 + 30 * v, 10, 0, h, v, "(a)\\ <b> & \"c\"");
	draw_text(d, 500, 300, 12, 90, DRAW_CENTER, DRAW_BOTTOM, "rotated");
	draw_set_gray(d, 0);
	draw_clip(d, 100, 100, 200, 200);
	draw_segment(d, 50, 50, 250, 250);
	draw_unclip(d);
	draw_page(d);
	draw_segment(d, 72, 72, 540, 72);
	draw_text(d, 306, 396, 24, 0, DRAW_CENTER, DRAW_MIDDLE, "page 2");
	struct draw_ps_opts o = {1.0, 0, "drawdemo"};
	if (argc > 3 && !num_parse(argv[3], &o.scale))
		die("bad scale");
	if (argc > 4)
		o.landscape = 1;
	draw_write_ps(d, argv[1], &o);
	draw_write_svg(d, argv[2]);
	draw_free(d);
	return 0;
}
