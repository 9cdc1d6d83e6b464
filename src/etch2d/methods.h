/*
 * methods.h - the algorithms of etch2d, one file each (etch2d.h lists
 * them); each runs to e->o.et and emits one set per print time.  They use
 * e2.h and front.h and nothing above; run.c dispatches to them.
 */
#ifndef ETCH2D_METHODS_H
#define ETCH2D_METHODS_H

#include "e2.h"

void e2_run_cell(struct e2 *e);
void e2_run_huygens(struct e2 *e);
void e2_run_string(struct e2 *e);
void e2_run_ray(struct e2 *e);
void e2_run_raystring(struct e2 *e);
void e2_run_fmm(struct e2 *e);

#endif
