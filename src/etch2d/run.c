/*
 * run.c - the dispatch: runs the method -method chose (methods.h) and
 * times it.  It sits on top of the methods; nothing below calls it.
 */
#include "etch2d.h"
#include "methods.h"

#include <time.h>

void e2_run(struct e2 *e)
{
	clock_t c0 = clock();
	switch (e->o.method) {
	case M_CELL: e2_run_cell(e); break;
	case M_HUYGENS: e2_run_huygens(e); break;
	case M_STRING: e2_run_string(e); break;
	case M_RAY: e2_run_ray(e); break;
	case M_FMM: e2_run_fmm(e); break;
	default: e2_run_raystring(e); break;
	}
	e->st.cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
}
