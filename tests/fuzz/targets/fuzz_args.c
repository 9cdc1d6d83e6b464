/*
 * fuzz_args.c - libFuzzer targets of two command lines, chosen at build
 * time with -DARGS_NAME:
 *
 *   measure_args: the input, split at newlines, is measure's argument
 *     list before a small valid surface file; measure's main (compiled
 *     as measure_main) runs in process, its die() and exit() turned into
 *     a jump back (fuzz_reader.c's allocation tracking frees what a
 *     rejected run left), in a private directory where its outputs go.
 *   fem_args: the words are appended to a valid fem command (stub
 *     programs beside a copy of fem, a stub sbatch), fem runs its sweep,
 *     and submit.sh and fem.sbatch run when -slurm wrote them: a file
 *     named INJECTED anywhere afterwards means a word ran as a command,
 *     and the target aborts (a finding).  Inputs naming another directory
 *     ('/' or "..") are skipped: fem would write there.
 *
 * Built by tests/fuzz/targets/fuzz.sh (measure_args linked with
 * the files of src/measure, main.c compiled with -Dmain=measure_main); seeds in
 * tests/fuzz/corpus/measure_args/ and fem_args/.
 */
#define FUZZ_NO_ENTRY
#define READER_NAME ARGS_NAME
#include "fuzz_reader.c"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>

enum { MAX_WORDS = 48 };

static char dir[128];
static int in_run;

/* the words of the input, one a line (empty lines dropped) */
static int split(const uint8_t *data, size_t size, char *buf, char **w, int max)
{
	int n = 0;
	memcpy(buf, data, size);
	buf[size] = '\0';
	char *p = buf;
	while (n < max && p < buf + size) {
		char *e = memchr(p, '\n', (size_t)(buf + size - p));
		if (e)
			*e = '\0';
		if (*p)
			w[n++] = p;
		if (!e)
			break;
		p = e + 1;
	}
	return n;
}

static void put(const char *name, const char *text, int mode)
{
	FILE *f = fopen(name, "w");
	if (!f || fputs(text, f) < 0 || fclose(f) != 0 || chmod(name, (mode_t)mode) != 0)
		abort();
}

/* Every regular file here but keep, removed (measure's outputs). */
static void clean(const char *keep)
{
	DIR *d = opendir(".");
	if (!d)
		abort();
	struct dirent *e;
	while ((e = readdir(d)))
		if (e->d_name[0] != '.' && strcmp(e->d_name, keep) != 0)
			unlink(e->d_name);
	closedir(d);
}

static int run(char *const argv[], const char *cwd)
{
	pid_t pid = fork();
	if (pid < 0)
		abort();
	if (pid == 0) {
		if (cwd && chdir(cwd) != 0)
			_exit(127);
		int fd = open("/dev/null", O_RDWR);
		if (fd >= 0) {
			dup2(fd, 0);
			dup2(fd, 1);
			dup2(fd, 2);
		}
		execv(argv[0], argv);
		_exit(127);
	}
	int st;
	while (waitpid(pid, &st, 0) < 0)
		;
	return st;
}

static void rm_rf(const char *path)
{
	char *argv[] = {"/bin/rm", "-rf", (char *)path, NULL};
	run(argv, NULL);
}

/* the private directory goes when the fuzzer ends */
static void remove_dir(void)
{
	if (dir[0])
		rm_rf(dir);
}

#if defined(MEASURE_ARGS)
int measure_main(int argc, char **argv);
void __real_exit(int status);
void __wrap_exit(int status);
int __real_fclose(FILE *f);
int __wrap_fclose(FILE *f);

void __wrap_exit(int status)
{
	if (in_run)
		longjmp(back, 1000 + status);
	__real_exit(status);
}

/* measure's fshut(stdout) must not close the harness's stdout */
int __wrap_fclose(FILE *f)
{
	if (f == stdout || f == stderr)
		return fflush(f);
	return __real_fclose(f);
}

static const char surface[] =
	"0 1 0 1 -1 0\n2\n4\n0 0 -1\n1 0 -1\n0 1 -1\n0 0 -1\n4\n1 1 0\n1 0 0\n0 1 0\n1 1 0\n";

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	/* the fuzzer's own directory, where its corpus and findings are
	 * named relative to: measure runs in the private one, and every
	 * input comes back here (libFuzzer writes a new unit after it) */
	static int home = -1;
	if (!dir[0]) {
		util_setprog("measure");
		util_set_die_hook(on_die);
		snprintf(dir, sizeof dir, "/tmp/s3dfuzz-measure-%ld", (long)getpid());
		home = open(".", O_RDONLY | O_DIRECTORY);
		if (home < 0 || mkdir(dir, 0700) != 0 || chdir(dir) != 0)
			abort();
		atexit(remove_dir);
		put("s.plot", surface, 0600);
		int fd = open("/dev/null", O_WRONLY);
		if (fd < 0 || dup2(fd, 1) < 0)
			abort();
		close(fd);
	} else if (chdir(dir) != 0) {
		abort();
	}
	if (size > 4096) {
		if (fchdir(home) != 0)
			abort();
		return 0;
	}
	static char buf[4097];
	char *argv[MAX_WORDS + 3];
	argv[0] = "measure";
	int n = split(data, size, buf, argv + 1, MAX_WORDS);
	argv[n + 1] = "s.plot";
	argv[n + 2] = NULL;
	in_run = 1;
	if (setjmp(back) == 0)
		measure_main(n + 2, argv);
	in_run = 0;
	free_all();
	clean("s.plot");
	if (fchdir(home) != 0)
		abort();
	return 0;
}

#else  /* fem_args */

static const char stub[] =
	"#!/bin/sh\n"
	"# a stand-in for the SAMPLE-3D programs: says it has the options fem\n"
	"# looks for, and succeeds\n"
	"case \"$*\" in *--help*) echo '-defocus -dose' ;; esac\n"
	"exit 0\n";

/* 1 if a file named INJECTED is anywhere under path */
static int injected(const char *path, int depth)
{
	DIR *d = opendir(path);
	if (!d)
		return 0;
	struct dirent *e;
	int found = 0;
	while (!found && (e = readdir(d))) {
		if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
			continue;
		if (!strcmp(e->d_name, "INJECTED"))
			found = 1;
		else if (depth < 6) {
			char sub[1024];
			snprintf(sub, sizeof sub, "%s/%s", path, e->d_name);
			struct stat st;
			if (lstat(sub, &st) == 0 && S_ISDIR(st.st_mode))
				found = injected(sub, depth + 1);
		}
	}
	closedir(d);
	return found;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static char top[256], bin[300], fem[320], work[300];
	if (!dir[0]) {
		snprintf(dir, sizeof dir, "/tmp/s3dfuzz-fem-%ld", (long)getpid());
		snprintf(bin, sizeof bin, "%s/bin", dir);
		snprintf(fem, sizeof fem, "%s/bin/fem", dir);
		snprintf(work, sizeof work, "%s/work", dir);
		const char *t = getenv("S3D_TOP");
		snprintf(top, sizeof top, "%s", t ? t : FEM_TOP);
		if (mkdir(dir, 0700) != 0 || mkdir(bin, 0700) != 0)
			abort();
		atexit(remove_dir);
		char src[400];
		snprintf(src, sizeof src, "%s/scripts/fem.sh", top);
		FILE *in = fopen(src, "r"), *out = fopen(fem, "w");
		if (!in || !out)
			abort();
		int ch;
		while ((ch = getc(in)) != EOF)
			putc(ch, out);
		fclose(in);
		fclose(out);
		chmod(fem, 0700);
		static const char *progs[] = {"splat", "bleach", "etch", "measure", "femwin",
					      "drawplot", "sbatch"};
		for (size_t k = 0; k < sizeof progs / sizeof *progs; k++) {
			char p[400];
			snprintf(p, sizeof p, "%s/%s", bin, progs[k]);
			put(p, stub, 0700);
		}
		char path[1024];
		snprintf(path, sizeof path, "%s:/usr/bin:/bin", bin);
		setenv("PATH", path, 1);
		setenv("TMPDIR", dir, 1);
	}
	if (size > 2048 || memchr(data, '/', size))
		return 0;
	for (size_t i = 0; i + 1 < size; i++)
		if (data[i] == '.' && data[i + 1] == '.')
			return 0;
	rm_rf(work);
	if (mkdir(work, 0700) != 0)
		abort();
	char mask[400], resist[400];
	snprintf(mask, sizeof mask, "%s/mask.in", work);
	snprintf(resist, sizeof resist, "%s/resist.in", work);
	put(mask, "wavelength 0.436\n", 0600);
	put(resist, "wavelength 0.436\n", 0600);
	static char buf[2049];
	char *argv[MAX_WORDS + 24] = {"/bin/sh", fem, "-if", "mask.in", "-bf", "resist.in",
				      "-et", "10", "-dose", "60", "-focus", "0", "-measure",
				      "-rel 50 -hole 0 0", "-d", "sweep", "-q", "-j", "1"};
	int base = 19;
	int n = split(data, size, buf, argv + base, MAX_WORDS);
	argv[base + n] = NULL;
	run(argv, work);
	/* what -slurm wrote, run as a cluster would (the stub sbatch) */
	char script[400];
	snprintf(script, sizeof script, "%s/sweep/submit.sh", work);
	if (access(script, F_OK) == 0) {
		char *sargv[] = {"/bin/sh", script, NULL};
		run(sargv, work);
		snprintf(script, sizeof script, "%s/sweep/fem.sbatch", work);
		setenv("SLURM_ARRAY_TASK_ID", "0", 1);
		char *bargv[] = {"/bin/sh", script, NULL};
		run(bargv, work);
	}
	if (injected(dir, 0)) {
		fprintf(stderr, "fuzz_args: a word of fem's command line ran as a command\n");
		abort();
	}
	return 0;
}
#endif
