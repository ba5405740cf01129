/* The machine a run happened on: OS, kernel, CPU, clock source, host, start time. */
#ifndef JM_ENV_H
#define JM_ENV_H

/* Facts about the environment, read once before the run. */
typedef struct {
	char os_name[72];
	char arch[72];
	char kernel[136];
	char cpu_model[256];
	int processors;
	char clocksource[64];
	char hostname[256];
	char started_at[32];  /* UTC, ISO 8601 */
} jm_env;

void jm_env_read(jm_env *env);

#endif
