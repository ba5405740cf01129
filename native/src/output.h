/* The run folder (docs/FORMATS.md 3 and 4), written only after the run has ended. */
#ifndef JM_OUTPUT_H
#define JM_OUTPUT_H

#include <stddef.h>

#include "dataset.h"
#include "engine.h"
#include "env.h"
#include "options.h"

/* Everything a run folder is made from. */
typedef struct {
	const jm_options *opt;
	const jm_dataset *ds;
	const jm_timeline *tl;
	const jm_sched_info *sched;
	const jm_env *env;
	double init_x, init_y, init_theta; /* the estimate before the first job */
	int argc;
	char **argv;
} jm_run;

/* <out>/<runtime>/<cov|nocov>/<particles>/<Test>/<n> into buf, out without repeated or trailing
 * '/' as Java's File writes it; -1 when too long. */
int jm_run_dir(const jm_options *o, char *buf, size_t len);
/* Creates dir and its parents. 0, or -1 with errno. */
int jm_mkdirs(const char *dir);
/* Removes a folder tree. 0, or -1 with errno. */
int jm_remove_tree(const char *dir);
/* Writes every file of the run into dir. 0, or -1 with err holding "<file>: <problem>". */
int jm_output_write(const jm_run *r, const char *dir, char *err, size_t errlen);

#endif
