/*
 * The command lines of the C timing loops (bench/kernel_bench.c, bench/kernel_jobs.c and
 * bench/record_cost.c): a bad
 * one is one line on stderr naming the option, exit 2, before any timing, as in every jmclbench
 * command. kernel-bench read numbers with atoi and fell back to a default for a bad word, and
 * both printed their usage (or getopt's message and then it) as more lines.
 *
 *   build/test_tools build/kernel-bench build/kernel-jobs DATASET [build/record-cost]
 */
#define _GNU_SOURCE
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "child.h"
#include "harness.h"

static char tmp[64];
static char out_text[1 << 14], err_text[1 << 14];

/* Runs prog with args (NULL-terminated); returns its exit status, -1 when it did not exit. */
static int run(const char *prog, const char *const *args)
{
	const char *argv[32];
	int n = 0;

	argv[n++] = prog;
	while (*args && n < 31)
		argv[n++] = *args++;
	argv[n] = NULL;
	return jt_run_child(argv, tmp, out_text, sizeof(out_text), err_text, sizeof(err_text));
}

/* One line on stderr that starts with want, nothing on stdout, exit status 2. */
static void expect_bad(const char *prog, const char *const *args, const char *want)
{
	int rc = run(prog, args);

	if (rc != 2 || strncmp(err_text, want, strlen(want)) || jt_count_lines(err_text) != 1 || *out_text)
		JT_FAIL("%s %s ...: exit %d, stderr \"%s\", stdout \"%.80s\"; want exit 2 and one line starting \"%s\"",
			prog, args[0] ? args[0] : "", rc, err_text, out_text, want);
	else
		jt_passed++;
}

#define BAD(prog, want, ...)                                             \
	do {                                                             \
		const char *a_[] = { __VA_ARGS__, NULL };                \
		expect_bad(prog, a_, want);                              \
	} while (0)

static void test_kernel_bench(const char *kb, const char *ds)
{
	const char *help[] = { "--help", NULL };
	const char *ok[] = { "--dataset", ds, "--particles", "10", "--repetitions", "1", "--memory", "allocating", NULL };

	BAD(kb, "kernel-bench: --bogus: unknown option", "--bogus");
	BAD(kb, "kernel-bench: stray: unexpected argument", "stray");
	BAD(kb, "kernel-bench: --dataset: needs a value", "--dataset");
	BAD(kb, "kernel-bench: --repetitions: not a count in [1, 1000000]: 'x'", "--repetitions", "x");
	BAD(kb, "kernel-bench: --repetitions: not a count in [1, 1000000]: '0'", "--repetitions", "0");
	BAD(kb, "kernel-bench: --memory: not one of preallocated|allocating: 'allocatin'", "--memory", "allocatin");
	BAD(kb, "kernel-bench: --particles: not a count in [1, 100000000]: '10x'", "--particles", "10x");
	BAD(kb, "kernel-bench: --particles: not a count in [1, 100000000]: ''", "--particles", "10,,20");
	BAD(kb, "kernel-bench: --particles: not a count in [1, 100000000]: '99999999999'", "--particles", "99999999999");
	BAD(kb, "kernel-bench: /no/such/dataset: no such dataset folder", "--dataset", "/no/such/dataset");
	CHECK_INT(run(kb, help), 0);
	CHECK_STR_PREFIX(out_text, "usage: kernel-bench [--dataset DIR]");
	CHECK_INT(run(kb, ok), 0);
	CHECK_CONTAINS(out_text, "memory allocating, 1 repetitions");
}

static void test_kernel_jobs(const char *kj, const char *ds)
{
	const char *help[] = { "-h", NULL };
	const char *ok[] = { "-d", ds, "-p", "10", "-j", "predict", "-m", "preallocated", "-w", "0", "-i", "1",
			     "-r", "0.01", NULL };

	BAD(kj, "kernel-jobs: --bogus: unknown option", "--bogus");
	BAD(kj, "kernel-jobs: -x: unknown option", "-x");
	BAD(kj, "kernel-jobs: stray: unexpected argument", "stray");
	BAD(kj, "kernel-jobs: --particles: needs a value", "--particles");
	BAD(kj, "kernel-jobs: -p: needs a value", "-p");
	BAD(kj, "kernel-jobs: -p: bad value 'x'", "--particles", "x");
	BAD(kj, "kernel-jobs: -r: bad value '1e999'", "--time", "1e999");
	BAD(kj, "kernel-jobs: -w: bad value ''", "--warmup=");
	BAD(kj, "kernel-jobs: /no/such/dataset: no such dataset folder", "-d", "/no/such/dataset");
	CHECK_INT(run(kj, help), 0);
	CHECK_STR_PREFIX(out_text, "usage: kernel-jobs [options]");
	CHECK_INT(run(kj, ok), 0);
	CHECK_CONTAINS(out_text, "predict 10 preallocated ");
}

static void test_record_cost(const char *rc)
{
	const char *help[] = { "-h", NULL };
	const char *ok[] = { "-w", "0", "-i", "1", "-r", "0.001", NULL };

	BAD(rc, "record-cost: --bogus: unknown option", "--bogus");
	BAD(rc, "record-cost: stray: unexpected argument", "stray");
	BAD(rc, "record-cost: --time: needs a value", "--time");
	BAD(rc, "record-cost: -i: bad value '0'", "--iterations", "0");
	BAD(rc, "record-cost: -r: bad value 'nan'", "-r", "nan");
	CHECK_INT(run(rc, help), 0);
	CHECK_STR_PREFIX(out_text, "usage: record-cost [options]");
	CHECK_INT(run(rc, ok), 0);
	CHECK_CONTAINS(out_text, "\nrecord on ");
	CHECK_CONTAINS(out_text, "\nheld off ");
}

int main(int argc, char **argv)
{
	if (argc < 4) {
		fprintf(stderr, "usage: test_tools KERNEL-BENCH KERNEL-JOBS DATASET [RECORD-COST]\n");
		return 2;
	}
	if (jt_tempdir(tmp, sizeof(tmp), "tools"))
		return 1;
	test_kernel_bench(argv[1], argv[3]);
	test_kernel_jobs(argv[2], argv[3]);
	if (argc > 4)
		test_record_cost(argv[4]);
	unlink(strcat(strcpy(out_text, tmp), "/stdout"));
	unlink(strcat(strcpy(out_text, tmp), "/stderr"));
	rmdir(tmp);
	return jt_report();
}
