/*
 * measure_table.c - fmt_measure (measure(1)'s table, measure(5)) against
 * text written out here by hand: a hole's table and a stretch's table are
 * written and compared byte for byte with the expected text (the column
 * names, the rounding to 1e-6 um, 1e-9 um2 and 1e-3 degree, "# swa -"
 * for an undefined angle), then read back: every value must equal the
 * written value rounded to its resolution (exact: the printed form reads
 * back to the same double), and a rewrite must give the same bytes.
 * A header other than the measure columns keeps its extra values.  The
 * optional last column err (measure -accuracy) is written after the
 * feature's columns, rounded to 1e-6 um, read back to the same value, and
 * does not change the kind of feature; a negative err is refused.
 */
#include "fmt_measure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int nfail;

static void expect(int ok, const char *what)
{
	if (!ok) {
		fprintf(stderr, "measure_table: %s\n", what);
		nfail++;
	}
}

static char *slurp(const char *path)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return NULL;
	static char buf[4096];
	size_t n = fread(buf, 1, sizeof buf - 1, f);
	buf[n] = '\0';
	fclose(f);
	return buf;
}

static void put_text(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");
	if (!f || fputs(text, f) < 0 || fclose(f) != 0) {
		fprintf(stderr, "measure_table: cannot write %s\n", path);
		exit(1);
	}
}

int main(void)
{
	struct measure_row hr[2] = {
		{-0.63, 0.8100004, {0.51530000049, 0.81, 0.7999996}, 0},
		{-0.07, 1.1, {0.950331, 1.1, 1.1}, 0},
	};
	struct measure_table h = {.hole = 1, .nrows = 2, .rows = hr, .have_swa = 1,
				  .swa = 84.50049, .resist_loss = 0.0200001, .cleared = 1};
	fmt_measure_write("hole.tab", &h);
	const char *want_hole = "# z cd area dx dy\n"
				"-0.63 0.81 0.5153 0.81 0.8\n"
				"-0.07 1.1 0.950331 1.1 1.1\n"
				"# swa 84.5\n"
				"# resist_loss 0.02\n"
				"# cleared yes\n";
	const char *got = slurp("hole.tab");
	expect(got && strcmp(got, want_hole) == 0, "the hole's table is not the expected text");

	struct measure_row sr[1] = {{0, 0, {0.25, -0.25, 0}, 0}};
	struct measure_table s = {.hole = 0, .nrows = 1, .rows = sr, .have_swa = 1,
				  .swa = NAN, .resist_loss = 0, .cleared = 0};
	fmt_measure_write("stretch.tab", &s);
	got = slurp("stretch.tab");
	expect(got && strcmp(got, "# z cd lo hi\n0 0 0.25 -0.25\n# swa -\n"
			      "# resist_loss 0\n# cleared no\n") == 0,
	       "the stretch's table is not the expected text");

	struct measure_table r;
	fmt_measure_read("hole.tab", &r);
	expect(r.hole && r.ncols == 5 && r.nrows == 2, "hole: kind, columns or rows");
	expect(r.rows[0].z == -0.63 && r.rows[0].cd == 0.81 && r.rows[0].v[0] == 0.5153 &&
	       r.rows[0].v[2] == 0.8 && r.rows[1].v[0] == 0.950331, "hole: row values");
	expect(r.have_swa && r.swa == 84.5 && r.resist_loss == 0.02 && r.cleared == 1,
	       "hole: figures");
	fmt_measure_write("hole2.tab", &r);
	got = slurp("hole2.tab");
	expect(got && strcmp(got, want_hole) == 0, "hole: the rewrite differs");
	fmt_measure_free(&r);

	fmt_measure_read("stretch.tab", &r);
	expect(!r.hole && r.ncols == 4 && r.nrows == 1 && r.rows[0].v[1] == -0.25,
	       "stretch: kind, columns or values");
	expect(r.have_swa && isnan(r.swa) && r.cleared == 0, "stretch: swa - or cleared no");
	fmt_measure_free(&r);

	/* the err column, after a hole's and after a stretch's columns */
	hr[0].err = 0.0123456789;
	hr[1].err = 0;
	h.have_err = 1;
	fmt_measure_write("err.tab", &h);
	got = slurp("err.tab");
	expect(got && strcmp(got, "# z cd area dx dy err\n"
			      "-0.63 0.81 0.5153 0.81 0.8 0.012346\n"
			      "-0.07 1.1 0.950331 1.1 1.1 0\n"
			      "# swa 84.5\n# resist_loss 0.02\n# cleared yes\n") == 0,
	       "err: the hole's table with err is not the expected text");
	fmt_measure_read("err.tab", &r);
	expect(r.hole && r.have_err && r.ncols == 6 && r.rows[0].err == 0.012346 &&
	       r.rows[0].v[2] == 0.8 && r.rows[1].err == 0, "err: hole read back");
	fmt_measure_free(&r);
	put_text("err2.tab", "# z cd lo hi err\n0.1 0.5 -0.25 0.25 0.002\n# cleared yes\n");
	fmt_measure_read("err2.tab", &r);
	expect(!r.hole && r.have_err && r.ncols == 5 && r.rows[0].err == 0.002 &&
	       r.rows[0].v[1] == 0.25, "err: stretch read back");
	fmt_measure_free(&r);
	fmt_measure_read("hole.tab", &r);
	expect(!r.have_err, "err: a table without err has none");
	fmt_measure_free(&r);

	/* another tool's columns; no swa or resist_loss line; #key form */
	put_text("other.tab", "# z cd width_x width_y\n-0.63 0.8 0.81 0.79\n#cleared yes\n");
	fmt_measure_read("other.tab", &r);
	expect(!r.hole && r.ncols == 4 && r.rows[0].v[0] == 0.81 && r.rows[0].v[1] == 0.79,
	       "other columns: values");
	expect(!r.have_swa && isnan(r.swa) && isnan(r.resist_loss) && r.cleared == 1,
	       "other columns: absent figures");
	fmt_measure_free(&r);
	return nfail ? 1 : 0;
}
