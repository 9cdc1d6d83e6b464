/*
 * rate.h - the etch-rate field R(x, y, z) of the ray advance lives in the
 * library (src/lib/rfield.h), shared with etch2d.
 */
#ifndef ETCH_RATE_H
#define ETCH_RATE_H

#include "fmt_rate.h"
#include "rfield.h"

#endif
