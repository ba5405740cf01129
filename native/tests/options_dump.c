/*
 * options-dump --serve: what the C command-line parser makes of argument lists, in a text the
 * Java side writes too (workload's OptionsDifferentialTest), so that the two parsers can be
 * held equal on the options they share. A request is "args <count> <len>\n" and <len> bytes,
 * the <count> arguments separated by NUL; the answer "error <message>", "ok help" or "ok <fields>", then
 * "end".
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "options.h"

#define MAX_ARGS 64

static uint64_t bits(double v)
{
	uint64_t u;

	memcpy(&u, &v, sizeof(u));
	return u;
}

static const char *or_none(const char *s)
{
	return s ? s : "(none)";
}

static void answer(char *buf, size_t len, int count)
{
	char *argv[MAX_ARGS + 2], err[1024];
	int argc = 1;
	size_t i, start = 0;
	jm_options o;

	argv[0] = "options-dump";
	for (i = 0; count > 0 && i <= len && argc <= MAX_ARGS; i++) {
		if (i == len || buf[i] == '\0') {
			argv[argc++] = buf + start;
			start = i + 1;
		}
	}
	argv[argc] = NULL;
	if (jm_options_parse(&o, argc, argv, err, sizeof(err)))
		printf("error %s\n", err);
	else if (o.help)
		printf("ok help\n");
	else
		printf("ok p=%d n=%d j=%s O=%s odo=%s laser=%s real=%s dataset=%s policy=%s ideal=%d cov=%d "
		       "memory=%s estimate=%s resample=%s init=%s seed=%" PRId64 " scale=%016" PRIx64
		       " warmup=%016" PRIx64 " spin=%d gclog=%d cputime=%d force=%d\n",
		       o.particles, o.number, o.runtime_name, o.out, or_none(o.odometry), or_none(o.laser),
		       or_none(o.real), or_none(o.dataset), jm_policy_name(o.policy), o.ideal, o.covariance,
		       jm_memory_name(o.memory), jm_estimate_name(o.estimate), jm_resample_name(o.resample),
		       jm_init_name(o.init), o.seed, bits(o.time_scale), bits(o.warmup_s), o.spin_us, o.gc_log,
		       o.cpu_time, o.force);
	printf("end\n");
	fflush(stdout);
}

int main(int argc, char **argv)
{
	char head[64];
	size_t len;
	int count;

	if (argc != 2 || strcmp(argv[1], "--serve")) {
		fprintf(stderr, "usage: options_dump --serve\n");
		return 2;
	}
	while (fgets(head, sizeof(head), stdin)) {
		char *buf;

		if (sscanf(head, "args %d %zu", &count, &len) != 2)
			return 2;
		buf = malloc(len + 1);
		if (!buf || fread(buf, 1, len, stdin) != len) {
			free(buf);
			return 2;
		}
		buf[len] = '\0';
		answer(buf, len, count);
		free(buf);
	}
	return 0;
}
