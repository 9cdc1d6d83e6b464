/*
 * fmt_vtk.c - the VTK XML PolyData writer (fmt_vtk.h, vtp(5)).
 *
 * ASCII data, so the file diffs like the plot files and every number goes
 * through num_fmt (shortest round trip: a point written and read back is
 * the same double).  Points are shared through an open-addressing hash of
 * their exact bit patterns (-0 and +0 count as one point, since they are
 * the same place).
 */
#include "fmt_vtk.h"
#include "num.h"
#include "util.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

struct piece {
	double *pt;             /* unique points, 3 each */
	size_t npt, ptcap;
	size_t *hash;           /* point index + 1, 0 for empty */
	size_t hcap;
	long *conn[2];          /* connectivity of polys [0] and lines [1] */
	size_t nconn[2], conncap[2];
	long *off[2];           /* end offsets */
	size_t ncell[2], offcap[2];
};

static uint64_t key_of(const double *p)
{
	uint64_t h = 1469598103934665603u;
	for (int d = 0; d < 3; d++) {
		double v = p[d] == 0 ? 0.0 : p[d];
		uint64_t b;
		memcpy(&b, &v, sizeof b);
		h ^= b;
		h *= 1099511628211u;
		h ^= h >> 29;
	}
	return h;
}

static int same(const double *a, const double *b)
{
	return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

static void rehash(struct piece *pc, size_t cap)
{
	free(pc->hash);
	pc->hash = xcalloc(cap, sizeof *pc->hash);
	pc->hcap = cap;
	for (size_t i = 0; i < pc->npt; i++) {
		size_t h = (size_t)key_of(pc->pt + 3 * i) & (cap - 1);
		while (pc->hash[h])
			h = (h + 1) & (cap - 1);
		pc->hash[h] = i + 1;
	}
}

static long point_index(struct piece *pc, const double *p)
{
	if (2 * (pc->npt + 1) > pc->hcap)
		rehash(pc, pc->hcap ? 2 * pc->hcap : 1024);
	size_t h = (size_t)key_of(p) & (pc->hcap - 1);
	while (pc->hash[h]) {
		if (same(pc->pt + 3 * (pc->hash[h] - 1), p))
			return (long)(pc->hash[h] - 1);
		h = (h + 1) & (pc->hcap - 1);
	}
	xgrow(&pc->pt, &pc->ptcap, 3 * (pc->npt + 1), sizeof *pc->pt);
	for (int d = 0; d < 3; d++)
		pc->pt[3 * pc->npt + d] = p[d] == 0 ? 0.0 : p[d];
	pc->hash[h] = ++pc->npt;
	return (long)(pc->npt - 1);
}

static void add_cell(struct piece *pc, int kind, const struct plot_curve *c, int n)
{
	xgrow(&pc->conn[kind], &pc->conncap[kind], pc->nconn[kind] + (size_t)n,
	      sizeof *pc->conn[kind]);
	for (int i = 0; i < n; i++)
		pc->conn[kind][pc->nconn[kind]++] = point_index(pc, c->p + 3 * i);
	xgrow(&pc->off[kind], &pc->offcap[kind], pc->ncell[kind] + 1, sizeof *pc->off[kind]);
	pc->off[kind][pc->ncell[kind]++] = (long)pc->nconn[kind];
}

static void put_longs(FILE *f, const long *v, size_t n)
{
	for (size_t i = 0; i < n; i++)
		fprintf(f, "%s%ld", i % 12 ? " " : i ? "\n          " : "          ", v[i]);
	fputc('\n', f);
}

static void put_set(FILE *f, size_t n, int set)
{
	for (size_t i = 0; i < n; i++)
		fprintf(f, "%s%d", i % 20 ? " " : i ? "\n          " : "          ", set);
	fputc('\n', f);
}

static void write_piece(FILE *f, const struct plot_set *s, int setno)
{
	struct piece pc;
	memset(&pc, 0, sizeof pc);
	for (int k = 0; k < s->ncurves; k++) {
		const struct plot_curve *c = &s->curves[k];
		if (c->npts < 2)
			continue;
		int closed = c->npts >= 4 && same(c->p, c->p + 3 * (c->npts - 1));
		if (closed)
			add_cell(&pc, 0, c, c->npts - 1);
		else
			add_cell(&pc, 1, c, c->npts);
	}
	fprintf(f, "    <Piece NumberOfPoints=\"%zu\" NumberOfVerts=\"0\" NumberOfLines=\"%zu\""
		" NumberOfStrips=\"0\" NumberOfPolys=\"%zu\">\n", pc.npt, pc.ncell[1], pc.ncell[0]);
	fputs("      <Points>\n"
	      "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n",
	      f);
	char buf[NUM_BUFSZ];
	for (size_t i = 0; i < pc.npt; i++) {
		fputs("         ", f);
		for (int d = 0; d < 3; d++) {
			fputc(' ', f);
			fputs(num_fmt(buf, pc.pt[3 * i + d]), f);
		}
		fputc('\n', f);
	}
	fputs("        </DataArray>\n      </Points>\n", f);
	fputs("      <CellData Scalars=\"set\">\n"
	      "        <DataArray type=\"Int32\" Name=\"set\" format=\"ascii\">\n", f);
	/* VTK orders a piece's cells verts, lines, strips, polys */
	put_set(f, pc.ncell[1] + pc.ncell[0], setno);
	fputs("        </DataArray>\n      </CellData>\n", f);
	static const char *const tag[2] = {"Polys", "Lines"};
	for (int kind = 1; kind >= 0; kind--) {
		fprintf(f, "      <%s>\n"
			"        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n",
			tag[kind]);
		put_longs(f, pc.conn[kind], pc.nconn[kind]);
		fputs("        </DataArray>\n"
		      "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n", f);
		put_longs(f, pc.off[kind], pc.ncell[kind]);
		fprintf(f, "        </DataArray>\n      </%s>\n", tag[kind]);
	}
	fputs("    </Piece>\n", f);
	free(pc.pt);
	free(pc.hash);
	for (int kind = 0; kind < 2; kind++) {
		free(pc.conn[kind]);
		free(pc.off[kind]);
	}
}

void fmt_vtk_write(const char *path, const struct plot_file *pf)
{
	if (pf->dim != 3)
		die("%s: VTK output needs a 3D plot file", path);
	struct aout *a = aout_open(path);
	FILE *f = a->f;
	fputs("<?xml version=\"1.0\"?>\n"
	      "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\""
	      " header_type=\"UInt64\">\n"
	      "  <PolyData>\n", f);
	for (int s = 0; s < pf->nsets; s++)
		write_piece(f, &pf->sets[s], s + 1);
	fputs("  </PolyData>\n</VTKFile>\n", f);
	aout_commit(a);
}
