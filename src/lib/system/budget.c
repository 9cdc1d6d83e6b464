/* budget.c - see budget.h. */
#include "budget.h"
#include "util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

static int big;

void budget_allow_big(void) { big = 1; }

static int big_env(void)
{
	const char *e = getenv("SAMPLE3D_BIG");
	return e && *e && strcmp(e, "0") != 0;
}

static double machine_memory(void)
{
	long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
	if (pages <= 0 || size <= 0)
		return 4e9;   /* unknown: assume a small machine */
	return (double)pages * (double)size;
}

/* SAMPLE3D_MEMORY as a byte count, 0 if unset or not a positive number. */
static double memory_env(void)
{
	const char *e = getenv("SAMPLE3D_MEMORY");
	char *end;
	if (!e || !*e)
		return 0;
	double v = strtod(e, &end);
	return *end == '\0' && v > 0 && v < 1e300 ? v : 0;
}

/* The address space a process may have (ulimit -v), bytes, 0 if none. */
static double address_limit(void)
{
	struct rlimit rl;
	if (getrlimit(RLIMIT_AS, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY)
		return 0;
	return (double)rl.rlim_cur;
}

double budget_memory(void)
{
	double m = machine_memory(), e = memory_env(), a = address_limit();
	if (a > 0 && a < m)
		m = a;
	return e > 0 && e < m ? e : m;
}

const char *budget_bytes(char *buf, double b)
{
	static const char *unit[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
	int u = 0;
	while (b >= 1000 && u < 6)
		b /= 1000, u++;
	snprintf(buf, 16, "%.3g %s", b, unit[u]);
	return buf;
}

static const char *seconds_text(char *buf, double s)
{
	if (s < 120)
		snprintf(buf, 32, "%.2g s", s);
	else if (s < 7200)
		snprintf(buf, 32, "%.2g min", s / 60);
	else if (s < 3 * 86400)
		snprintf(buf, 32, "%.2g h", s / 3600);
	else
		snprintf(buf, 32, "%.2g days", s / 86400);
	return buf;
}

int budget_big(void)
{
	return big || big_env();
}

void budget_check(const char *where, const char *what, double seconds, double bytes)
{
	double mem = budget_memory();
	/* NaN or infinite estimates are beyond any limit */
	if (seconds <= BUDGET_SECONDS && bytes <= mem)
		return;
	char t[32], b[16], m[16];
	seconds_text(t, seconds);
	budget_bytes(b, bytes);
	budget_bytes(m, mem);
	if (big || big_env()) {
		warn("%s: %s: about %s of work and %s of memory (-big: running anyway)",
		     where, what, t, b);
		return;
	}
	die("%s: %s need about %s of work and %s of memory, beyond the limits "
	    "(1 h of work, the %s of memory %s): use -big or "
	    "SAMPLE3D_BIG=1 to run it anyway", where, what, t, b, m,
	    mem >= machine_memory() ? "of this machine" :
	    memory_env() > 0 && mem >= memory_env() ? "SAMPLE3D_MEMORY allows" :
	    "the address-space limit (ulimit -v) allows");
}
