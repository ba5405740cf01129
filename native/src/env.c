/* Environment facts for summary.json; anything that cannot be read is left empty (null). */
#define _GNU_SOURCE
#include <stdio.h>
#include <string.h>
#include <sys/utsname.h>
#include <time.h>
#include <unistd.h>

#include "env.h"

static void chomp(char *s)
{
	size_t n = strlen(s);

	while (n > 0 && (s[n - 1] == '\n' || s[n - 1] == ' ' || s[n - 1] == '\t'))
		s[--n] = '\0';
}

static void read_first_line(const char *path, char *buf, size_t len)
{
	FILE *f = fopen(path, "r");

	buf[0] = '\0';
	if (!f)
		return;
	if (!fgets(buf, (int)len, f))
		buf[0] = '\0';
	fclose(f);
	chomp(buf);
}

static void read_cpu_model(char *buf, size_t len)
{
	FILE *f = fopen("/proc/cpuinfo", "r");
	char line[512];

	buf[0] = '\0';
	if (!f)
		return;
	while (fgets(line, sizeof(line), f)) {
		char *colon = strchr(line, ':');

		if (!colon)
			continue;
		if (!strncmp(line, "model name", 10) || !strncmp(line, "Hardware", 8) ||
		    !strncmp(line, "cpu model", 9)) {
			colon++;
			while (*colon == ' ' || *colon == '\t')
				colon++;
			snprintf(buf, len, "%s", colon);
			chomp(buf);
			break;
		}
	}
	fclose(f);
}

void jm_env_read(jm_env *env)
{
	struct utsname u;
	time_t now = time(NULL);
	struct tm tm;

	memset(env, 0, sizeof(*env));
	if (uname(&u) == 0) {
		snprintf(env->os_name, sizeof(env->os_name), "%s", u.sysname);
		/* the name Java's os.arch uses, so that runtimes group together */
		snprintf(env->arch, sizeof(env->arch), "%s", !strcmp(u.machine, "x86_64") ? "amd64" : u.machine);
		snprintf(env->kernel, sizeof(env->kernel), "%s", u.release);
	}
	read_cpu_model(env->cpu_model, sizeof(env->cpu_model));
	env->processors = (int)sysconf(_SC_NPROCESSORS_ONLN);
	read_first_line("/sys/devices/system/clocksource/clocksource0/current_clocksource",
			env->clocksource, sizeof(env->clocksource));
	if (gethostname(env->hostname, sizeof(env->hostname) - 1))
		env->hostname[0] = '\0';
	if (gmtime_r(&now, &tm))
		strftime(env->started_at, sizeof(env->started_at), "%Y-%m-%dT%H:%M:%SZ", &tm);
}
