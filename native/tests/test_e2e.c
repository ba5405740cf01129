/*
 * End-to-end tests of the jmclbench-native program (path in argv[1]): bad input and bad
 * options (exit 2, one line naming file:line or the option), an ideal run and short
 * real-time runs under each policy producing the whole run folder with the right columns.
 * A small dataset is simulated here; the shipped data/match-short (argv[2]) is used too
 * when present.
 */
#define _GNU_SOURCE
#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "angles.h"
#include "child.h"
#include "harness.h"
#include "output.h"
#include "rng.h"

static const char *prog;
/* when set, the program is started through this command (argv), e.g. setpriv */
static const char *const *wrapper;
static char tmp[64];
static char out_text[1 << 16], err_text[1 << 16];

/* Runs prog (through the wrapper, if any) with args (NULL-terminated); returns its exit status, -1 when it did not exit. */
static int run(const char *const *args)
{
	const char *argv[64];
	int n = 0;

	while (wrapper && wrapper[n] && n < 32) {
		argv[n] = wrapper[n];
		n++;
	}
	argv[n++] = prog;
	while (*args && n < 63)
		argv[n++] = *args++;
	argv[n] = NULL;
	return jt_run_child(argv, tmp, out_text, sizeof(out_text), err_text, sizeof(err_text));
}

static void write_text(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");

	if (f) {
		fputs(text, f);
		fclose(f);
	}
}

/*
 * Simulates a robot driving an arc for duration seconds: odometry and ground truth every 50 ms,
 * a laser hit whenever the turret (3 rev/s) crosses a beacon, with a little noise.
 */
static void make_dataset(const char *dir, double duration, int properties)
{
	static const double beacon[3][2] = { { 0, 1 }, { 3, 0 }, { 3, 2 } };
	char path[256];
	FILE *odo, *las, *real;
	double x = 1.0, y = 0.8, th = 0.3, turret = 0.0;
	int i, s, b, n = (int)(duration / 0.05);
	jm_rng r;

	mkdir(dir, 0777);
	snprintf(path, sizeof(path), "%s/odometry.txt", dir);
	odo = fopen(path, "w");
	snprintf(path, sizeof(path), "%s/laser.txt", dir);
	las = fopen(path, "w");
	snprintf(path, sizeof(path), "%s/real.txt", dir);
	real = fopen(path, "w");
	if (!odo || !las || !real)
		abort();
	jm_rng_seed(&r, 5);
	fprintf(odo, "%.16e  %.16e  %.16e  %.16e\n", 0.0, 0.0, 0.0, 0.0);
	fprintf(real, "%.16e  %.16e  %.16e  %.16e\n", 0.0, x, y, th);
	for (i = 1; i <= n; i++) {
		double t = i * 0.05;

		for (s = 0; s < 7; s++) {
			double ts = t - 0.05 + (s + 0.5) * 0.05 / 7, a0, a1;

			x += 0.25 * cos(th) * 0.05 / 7;
			y += 0.25 * sin(th) * 0.05 / 7;
			th = jm_wrap2pi(th + 0.3 * 0.05 / 7);
			a0 = jm_wrap2pi(turret);
			turret += 3 * JM_TWO_PI * 0.05 / 7;
			a1 = jm_wrap2pi(turret);
			for (b = 0; b < 3; b++) {
				double be = jm_bearing(x, y, th, beacon[b][0], beacon[b][1]);
				int hit = a0 < a1 ? (be >= a0 && be < a1) : (be >= a0 || be < a1);

				if (hit && jm_rng_uniform(&r) > 0.05)
					fprintf(las, "%.16e  %.16e\n", ts + b * 1e-4,
						jm_wrap2pi(be + 0.005 * jm_rng_gaussian(&r)));
			}
		}
		fprintf(odo, "%.16e  %.16e  %.16e  %.16e\n", t, 0.25 * 0.05, 0.0, 0.3 * 0.05);
		fprintf(real, "%.16e  %.16e  %.16e  %.16e\n", t, x, y, th);
	}
	fclose(odo);
	fclose(las);
	fclose(real);
	if (properties) {
		snprintf(path, sizeof(path), "%s/dataset.properties", dir);
		write_text(path, "format=jmclbench-dataset/1\nscenario=e2e\nstart.x=1.0\nstart.y=0.8\nstart.theta=0.3\n"
				 "beacons=0.0,1.0;3.0,0.0;3.0,2.0\n");
	}
}

/* One line on stderr that starts with want_prefix; exit status 2. */
static void expect_bad(const char *const *args, const char *want_prefix)
{
	int rc = run(args);

	if (rc != 2 || strncmp(err_text, want_prefix, strlen(want_prefix)) || jt_count_lines(err_text) != 1)
		JT_FAIL("%s ...: exit %d, stderr \"%s\", want exit 2 and one line starting \"%s\"",
			args[0], rc, err_text, want_prefix);
	else
		jt_passed++;
}

static void test_bad_data(void)
{
	static const struct {
		const char *content;
		const char *line_problem;
	} cases[] = {
		{ "0 0 0 0\n0.05 0.01 0\n", ":2: expected 4 columns but found 3" },
		{ "0 0 0 0\n0.05 zero 0 0\n", ":2: not a number: 'zero'" },
		{ "0 0 0 0\n0.05 nan 0 0\n", ":2: not a finite number" },
		{ "0 0 0 0\n0.05 0 -inf 0\n", ":2: not a finite number" },
		{ "-0.05 0 0 0\n", ":1: negative time" },
		{ "0 0 0 0\n0.1 0 0 0\n# late line\n0.05 0 0 0\n", ":4: time 0.05 is before the previous line's" },
		{ "", ": empty file (no data lines)" },
		{ "# nothing but a comment\n", ": empty file (no data lines)" },
	};
	char dir[128], odo[160], las[160], real[160], want[400], missing[160];
	size_t i;

	snprintf(dir, sizeof(dir), "%s/bad", tmp);
	make_dataset(dir, 1.0, 0);
	snprintf(odo, sizeof(odo), "%s/odometry.txt", dir);
	snprintf(las, sizeof(las), "%s/laser.txt", dir);
	snprintf(real, sizeof(real), "%s/real.txt", dir);
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		char bad[160];
		const char *args[] = { "-odo", bad, "-laser", las, "-real", real, "-O", tmp, "--ideal", NULL };

		snprintf(bad, sizeof(bad), "%s/bad%zu.txt", tmp, i);
		write_text(bad, cases[i].content);
		snprintf(want, sizeof(want), "jmclbench: %s%s", bad, cases[i].line_problem);
		expect_bad(args, want);
	}
	{
		const char *args[] = { "-odo", odo, "-laser", las, "-real", real, "-O", tmp, "--ideal", NULL };
		char badlaser[160];

		/* a wrong laser file is named as such */
		snprintf(badlaser, sizeof(badlaser), "%s/badlaser.txt", tmp);
		write_text(badlaser, "0.1 1.0 2.0\n");
		args[3] = badlaser;
		snprintf(want, sizeof(want), "jmclbench: %s:1: expected 2 columns but found 3", badlaser);
		expect_bad(args, want);
	}
	{
		const char *args[] = { "--dataset", missing, "-O", tmp, "--ideal", NULL };

		snprintf(missing, sizeof(missing), "%s/no-such-dataset", tmp);
		snprintf(want, sizeof(want), "jmclbench: %s: no such dataset folder", missing);
		expect_bad(args, want);
	}
	{
		char nofile[160];
		const char *args[] = { "-odo", odo, "-laser", las, "-real", nofile, "-O", tmp, "--ideal", NULL };

		snprintf(nofile, sizeof(nofile), "%s/no-real.txt", tmp);
		snprintf(want, sizeof(want), "jmclbench: %s: no such file", nofile);
		expect_bad(args, want);
	}
	{
		/* a place that cannot be written fails before the run */
		char file[160], want2[400];
		const char *args[] = { "--dataset", dir, "-O", file, "--ideal", NULL };

		snprintf(file, sizeof(file), "%s/a-file", tmp);
		write_text(file, "not a folder\n");
		snprintf(want2, sizeof(want2), "jmclbench: -O: cannot create %s/native/nocov/400/IdealTest/1.partial: ", file);
		expect_bad(args, want2);
	}
	{
		/* a -j too long for a folder name is -j's problem, not the output root's */
		char name[5001];
		const char *args[] = { "--dataset", dir, "-O", tmp, "--ideal", "-j", name, NULL };

		memset(name, 'j', 300);
		name[300] = '\0';
		expect_bad(args, "jmclbench: -j: 300 characters, longer than a folder name may be (255)");
		memset(name, 'j', 5000);
		name[5000] = '\0';
		expect_bad(args, "jmclbench: -j: 5000 characters");
	}
	/* nothing was recorded as a result */
	{
		char results[160];
		struct stat st;

		snprintf(results, sizeof(results), "%s/native", tmp);
		CHECK(stat(results, &st) != 0);
	}
}

static void test_bad_options(void)
{
	const char *a1[] = { "run", "--bogus", NULL };
	const char *a2[] = { "-p", NULL };
	const char *a3[] = { "-p", "many", NULL };
	const char *a4[] = { "--policy", "never", NULL };
	const char *a5[] = { "-odo", "x", NULL };
	const char *a6[] = { "--time-scale", "-1", NULL };
	const char *help[] = { "-h", NULL };

	expect_bad(a1, "jmclbench: --bogus: unknown option");
	expect_bad(a2, "jmclbench: -p: needs a value");
	expect_bad(a3, "jmclbench: -p: not an integer");
	expect_bad(a4, "jmclbench: --policy: 'never' is not one of skip|terminate|queue");
	expect_bad(a5, "jmclbench: -laser: missing");
	expect_bad(a6, "jmclbench: --time-scale: '-1' must be a finite number > 0");
	{
		const char *version[] = { "--version", NULL };

		CHECK_INT(run(version), 0);
		CHECK_STR_PREFIX(out_text, "jmclbench-native ");
		CHECK_CONTAINS(out_text, "-ffp-contract=off");
		CHECK_INT(jt_count_lines(out_text), 1);
	}
	CHECK_INT(run(help), 0);
	CHECK_CONTAINS(out_text, "-p, --particles N");
	CHECK_CONTAINS(out_text, "(default 400)");
	CHECK_CONTAINS(out_text, "-odo FILE");
	/* every policy of policy.h, not a list of its own */
	CHECK_CONTAINS(out_text, JM_POLICY_LABELS ": an event released");
}

/* Every non-comment line of path has ncols whitespace-separated fields; returns the line count. */
static int check_columns(const char *dir, const char *name, int ncols, const char *header)
{
	char path[512], *text = malloc(1 << 22), *line, *save = NULL;
	int n = 0, bad = 0;

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	jt_slurp(path, text, 1 << 22);
	if (header && strncmp(text, header, strlen(header)))
		JT_FAIL("%s does not start with \"%s\"", path, header);
	for (line = strtok_r(text, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
		char *tok, *s2 = NULL;
		int c = 0;

		if (line[0] == '#')
			continue;
		for (tok = strtok_r(line, " ", &s2); tok; tok = strtok_r(NULL, " ", &s2))
			c++;
		if (c != ncols && !bad++)
			JT_FAIL("%s: a line with %d fields, want %d", path, c, ncols);
		n++;
	}
	if (!bad)
		jt_passed++;
	free(text);
	return n;
}

/* Outcome counts of a job file, and whether every line is consistent with its outcome. */
static void check_jobs(const char *dir, const char *name, int ideal, int *counts)
{
	char path[512], line[256];
	FILE *f;
	int bad = 0;

	memset(counts, 0, 4 * sizeof(int));
	snprintf(path, sizeof(path), "%s/%s", dir, name);
	f = fopen(path, "r");
	if (!f) {
		JT_FAIL("%s missing", path);
		return;
	}
	while (fgets(line, sizeof(line), f)) {
		long long idx, rel, st, en, dl, cpu, ab, seen;
		char outcome[32];

		if (line[0] == '#')
			continue;
		if (sscanf(line, "%lld %lld %lld %lld %lld %31s %lld %lld %lld", &idx, &rel, &st, &en, &dl, outcome, &cpu,
			   &ab, &seen) != 9) {
			bad++;
			continue;
		}
		/* abort_ns: -1, or when the abort took hold, within the job; only terminate asks for aborts */
		bad += ab != -1 && (ideal || ab < st || ab >= en);
		/* seen_ns: -1, or when the job's poll saw that abort, between it and the job's end */
		bad += seen != -1 && (ab == -1 || seen < ab || seen > en);
		/* a job aborted while running was asked to */
		bad += !strcmp(outcome, "terminated") && st != -1 && ab == -1;
		if (!strcmp(outcome, "done")) {
			counts[0]++;
			bad += st < rel || en < st || (!ideal && en > dl) || (ideal && dl != -1) || cpu < 0;
		} else if (!strcmp(outcome, "late")) {
			counts[1]++;
			bad += ideal || st < rel || en <= dl;
		} else if (!strcmp(outcome, "skipped")) {
			counts[2]++;
			bad += ideal || st != -1 || en != -1 || cpu != -1;
		} else if (!strcmp(outcome, "terminated")) {
			counts[3]++;
			/* aborted while running, or superseded before it could start */
			bad += ideal || (st == -1 ? en != -1 || cpu != -1 : st < rel || en < st);
		} else {
			bad++;
		}
	}
	fclose(f);
	if (bad)
		JT_FAIL("%s: %d inconsistent job lines", path, bad);
	else
		jt_passed++;
}

static const char *const data_keys[] = { "deviationXY ", "deviationX ", "deviationY ", "deviationAngle ",
					 "missCount ", "averageReleaseJitter ", "averageTaskTime " };

/* The whole run folder; returns deviationXY from data.txt. */
static double check_run_dir(const char *dir, int ideal, int cov, int nodo, int nlaser, int *miss)
{
	char path[512], text[4096];
	const char *p;
	struct stat st;
	int c[4], i;
	double dev = -1;

	snprintf(path, sizeof(path), "%s.partial", dir);
	CHECK(stat(path, &st) != 0);
	CHECK(stat(dir, &st) == 0 && S_ISDIR(st.st_mode));
	CHECK_INT(check_columns(dir, "odoData.txt", 9, "# index release_ns start_ns end_ns deadline_ns outcome cpu_ns abort_ns seen_ns\n"), nodo);
	CHECK_INT(check_columns(dir, "laserData.txt", 9, "# index release_ns start_ns end_ns deadline_ns outcome cpu_ns abort_ns seen_ns\n"), nlaser);
	CHECK_INT(check_columns(dir, "position.txt", 4, NULL), nodo);
	CHECK_INT(check_columns(dir, "positionDeviation.txt", 5, NULL), nodo);
	snprintf(path, sizeof(path), "%s/covariance.txt", dir);
	if (cov)
		CHECK(check_columns(dir, "covariance.txt", 7, NULL) > 0);
	else
		CHECK(stat(path, &st) != 0);
	check_jobs(dir, "odoData.txt", ideal, c);
	check_jobs(dir, "laserData.txt", ideal, c);
	snprintf(path, sizeof(path), "%s/data.txt", dir);
	jt_slurp(path, text, sizeof(text));
	for (i = 0; i < 7; i++) {
		p = strstr(text, data_keys[i]);
		if (!p || (p != text && p[-1] != '\n')) {
			JT_FAIL("%s: no key %s", path, data_keys[i]);
			continue;
		}
		jt_passed++;
		if (i == 0)
			dev = strtod(p + strlen(data_keys[i]), NULL);
		if (i == 4)
			*miss = atoi(p + strlen(data_keys[i]));
	}
	CHECK_INT(jt_count_lines(text), 7);
	snprintf(path, sizeof(path), "%s/summary.json", dir);
	jt_slurp(path, out_text, sizeof(out_text));
	CHECK_CONTAINS(out_text, "\"schema\": \"jmclbench-run/1\"");
	CHECK_CONTAINS(out_text, "\"status\": \"complete\"");
	CHECK_CONTAINS(out_text, "\"language\": \"c\"");
	CHECK_CONTAINS(out_text, "\"dispatcherLatenessNs\"");
	CHECK_CONTAINS(out_text, "\"scheduling\"");
	CHECK_CONTAINS(out_text, "\"fifoRequested\"");
	CHECK_CONTAINS(out_text, "\"p999\"");
	CHECK_CONTAINS(out_text, "\"deviation\"");
	return dev;
}

static int count_data_lines(const char *path)
{
	char *text = malloc(1 << 22);
	int n = 0;
	char *p;

	jt_slurp(path, text, 1 << 22);
	for (p = text; *p;) {
		if (*p != '#' && *p != '\n')
			n++;
		p = strchr(p, '\n');
		if (!p)
			break;
		p++;
	}
	free(text);
	return n;
}

static void test_runs(const char *dataset, const char *label, int particles, const char *scale)
{
	char out[160], dir[400], odo[300], las[300], pstr[16];
	int nodo, nlaser, miss = -1;
	double dev, ideal_dev;

	snprintf(out, sizeof(out), "%s/out-%s", tmp, label);
	snprintf(odo, sizeof(odo), "%s/odometry.txt", dataset);
	snprintf(las, sizeof(las), "%s/laser.txt", dataset);
	snprintf(pstr, sizeof(pstr), "%d", particles);
	nodo = count_data_lines(odo);
	nlaser = count_data_lines(las);

	{
		const char *args[] = { "run", "--dataset", dataset, "-O", out, "-p", pstr, "--ideal", NULL };

		CHECK_INT(run(args), 0);
		CHECK_INT(strlen(err_text), 0);
		snprintf(dir, sizeof(dir), "%s/native/nocov/%d/IdealTest/1", out, particles);
		/* the one line on stdout: the complete run folder */
		{
			char want[420];

			snprintf(want, sizeof(want), "%s\n", dir);
			CHECK(!strcmp(out_text, want));
		}
		dev = check_run_dir(dir, 1, 0, nodo, nlaser, &miss);
		printf("%s: ideal run, %d particles: deviationXY %.4f m\n", label, particles, dev);
		ideal_dev = dev;
		CHECK(dev >= 0 && dev < 0.10);
		CHECK_INT(miss, 0);
		/* the engine's kind in every run, no release engine facts in an ideal run */
		CHECK_CONTAINS(out_text, "\"engine\": {\n    \"kind\": \"native\"\n  }");
		CHECK(!strstr(out_text, "\"dispatcherPriority\""));
		CHECK_CONTAINS(out_text, "\"engine\": \"native\"");
		CHECK_CONTAINS(out_text, "\"areas\": []");
		/* a complete folder is not overwritten without --force */
		CHECK_INT(run(args), 2);
		CHECK_CONTAINS(err_text, "a complete run folder exists (use --force to overwrite)");
	}
	{
		const char *args[] = { "--dataset", dataset, "-O", out, "-p", pstr, "--ideal", "--force",
				       "--memory", "allocating", NULL };
		static char before[1 << 20], after[1 << 20];
		char first[512];
		double dev2;

		snprintf(first, sizeof(first), "%s/positionDeviation.txt", dir);
		jt_slurp(first, before, sizeof(before));
		CHECK_INT(run(args), 0);
		/* the other memory style computes the same bits */
		jt_slurp(first, after, sizeof(after));
		CHECK(before[0] != '\0' && strcmp(before, after) == 0);
		dev2 = check_run_dir(dir, 1, 0, nodo, nlaser, &miss);
		CHECK_BITS(dev2, dev);
	}
	{
		/* thesis flags: -T -c -n 2 -j, real time, fast */
		const char *args[] = { "-odo", odo, "-laser", las, "-real", NULL, "-O", out, "-p", pstr,
				       "-T", "-c", "-n", "2", "-j", "c-test", "--time-scale", scale, "--no-fifo", NULL };
		char real[300];

		snprintf(real, sizeof(real), "%s/real.txt", dataset);
		args[5] = real;
		CHECK_INT(run(args), 0);
		snprintf(dir, sizeof(dir), "%s/c-test/cov/%d/TermTest/2", out, particles);
		dev = check_run_dir(dir, 0, 1, nodo, nlaser, &miss);
		printf("%s: terminate, %d particles, time scale %s: missCount %d, deviationXY %.4f m\n",
		       label, particles, scale, miss, dev);
		/* how far the robot gets lost depends on the machine's load: only a sane number */
		CHECK(isfinite(dev) && dev >= 0);
	}
	{
		const char *policies[] = { "skip", "queue" };
		const char *tests[] = { "SkipTest", "QueueTest" };
		int i;

		for (i = 0; i < 2; i++) {
			const char *args[] = { "--dataset", dataset, "-O", out, "-p", pstr, "--policy", policies[i],
					       "--time-scale", scale, "--spin-us", "100", "--warmup", "1", "--gc-log", NULL };

			CHECK_INT(run(args), 0);
			snprintf(dir, sizeof(dir), "%s/native/nocov/%d/%s/1", out, particles, tests[i]);
			dev = check_run_dir(dir, 0, 0, nodo, nlaser, &miss);
			{
				char gc[512];
				struct stat st;

				snprintf(gc, sizeof(gc), "%s/gc.log", dir);
				CHECK(stat(gc, &st) == 0);
			}
			CHECK_CONTAINS(out_text, "\"engine\": {");
			CHECK_CONTAINS(out_text, "\"warmupEvents\": ");
			CHECK(!strstr(out_text, "\"warmupEvents\": 0,"));
			printf("%s: %s, %d particles, time scale %s: missCount %d, deviationXY %.4f m\n",
			       label, policies[i], particles, scale, miss, dev);
			CHECK(isfinite(dev) && dev >= 0);
			/* queue completes every job in release order: the ideal run's estimates exactly */
			if (i == 1)
				CHECK_BITS(dev, ideal_dev);
		}
	}
}

/* The number of job lines of a job file whose cpu_ns is not -1; -1 when the file cannot be read. */
static int count_cpu_times(const char *dir, const char *name)
{
	char path[512], line[256];
	FILE *f;
	int n = 0;

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	f = fopen(path, "r");
	if (!f)
		return -1;
	while (fgets(line, sizeof(line), f)) {
		long long idx, rel, st, en, dl, cpu;
		char outcome[32];

		if (line[0] != '#' && sscanf(line, "%lld %lld %lld %lld %lld %31s %lld", &idx, &rel, &st, &en, &dl,
					     outcome, &cpu) == 7 && cpu != -1)
			n++;
	}
	fclose(f);
	return n;
}

/* Run 1 of test <test> under <out>: no job with a CPU time, summary.json's cpuTime false; out_text holds it. */
static void check_no_cpu_times(const char *out, const char *test)
{
	char dir[400], path[500];

	snprintf(dir, sizeof(dir), "%s/native/nocov/50/%s/1", out, test);
	CHECK_INT(count_cpu_times(dir, "odoData.txt"), 0);
	CHECK_INT(count_cpu_times(dir, "laserData.txt"), 0);
	snprintf(path, sizeof(path), "%s/summary.json", dir);
	jt_slurp(path, out_text, sizeof(out_text));
	CHECK_CONTAINS(out_text, "\"cpuTime\": false");
}

/* --no-cpu-time: no job has a CPU time, in the ideal and the real-time engine, and summary.json says so. */
static void test_no_cpu_time(const char *dataset)
{
	char out[160], dir[400], path[500];
	const char *ideal[] = { "--dataset", dataset, "-O", out, "-p", "50", "--ideal", "--no-cpu-time", NULL };
	const char *skip[] = { "--dataset", dataset, "-O", out, "-p", "50", "--time-scale", "0.2", "--no-fifo",
			       "--no-cpu-time", NULL };
	const char *measured[] = { "--dataset", dataset, "-O", out, "-p", "50", "-n", "2", "--time-scale", "0.2",
				   "--no-fifo", NULL };

	snprintf(out, sizeof(out), "%s/out-nocpu", tmp);
	CHECK_INT(run(ideal), 0);
	check_no_cpu_times(out, "IdealTest");

	CHECK_INT(run(skip), 0);
	check_no_cpu_times(out, "SkipTest");
	CHECK_CONTAINS(out_text, "\"cpuTime\": \"off (--no-cpu-time)\"");

	/* and without it, every job that ran has one */
	CHECK_INT(run(measured), 0);
	snprintf(dir, sizeof(dir), "%s/native/nocov/50/SkipTest/2", out);
	CHECK(count_cpu_times(dir, "odoData.txt") > 0);
	snprintf(path, sizeof(path), "%s/summary.json", dir);
	jt_slurp(path, out_text, sizeof(out_text));
	CHECK_CONTAINS(out_text, "\"cpuTime\": true");
}

/* Without the right to real-time scheduling the run still completes, and says what it got. */
static void test_fifo_fallback(const char *dataset)
{
	static const char *const setpriv[] = { "/usr/bin/setpriv", "--bounding-set", "-sys_nice",
					       "--inh-caps", "-sys_nice", NULL };
	char out[160], path[400];
	const char *args[] = { "--dataset", dataset, "-O", out, "-p", "50", "--time-scale", "0.1", NULL };

	if (geteuid() != 0 || access(setpriv[0], X_OK) != 0) {
		printf("fifo fallback: needs root and setpriv, left out\n");
		return;
	}
	snprintf(out, sizeof(out), "%s/out-nofifo", tmp);
	wrapper = setpriv;
	CHECK_INT(run(args), 0);
	wrapper = NULL;
	snprintf(path, sizeof(path), "%s/native/nocov/50/SkipTest/1/summary.json", out);
	jt_slurp(path, out_text, sizeof(out_text));
	CHECK_CONTAINS(out_text, "\"policy\": \"SCHED_OTHER\"");
	CHECK_CONTAINS(out_text, "\"fifoRequested\": true");
}

int main(int argc, char **argv)
{
	char ds[128];
	struct stat st;

	if (argc < 2) {
		fprintf(stderr, "usage: test_e2e PROGRAM [SHIPPED-DATASET]\n");
		return 2;
	}
	prog = argv[1];
	if (jt_tempdir(tmp, sizeof(tmp), "e2e"))
		return 1;
	test_bad_options();
	test_bad_data();
	snprintf(ds, sizeof(ds), "%s/tiny", tmp);
	make_dataset(ds, 6.0, 1);
	test_runs(ds, "tiny", 300, "0.2");
	test_fifo_fallback(ds);
	test_no_cpu_time(ds);
	if (argc > 2 && stat(argv[2], &st) == 0)
		test_runs(argv[2], "match-short", 1000, "0.05");
	else
		printf("match-short: not present, its runs are left out\n");
	if (jm_remove_tree(tmp))
		fprintf(stderr, "could not remove %s\n", tmp);
	return jt_report();
}
