/* Dataset reader: the thesis-format event files and dataset.properties (docs/FORMATS.md 1). */
#ifndef JM_DATASET_H
#define JM_DATASET_H

#include <limits.h>
#include <stddef.h>
#include <stdio.h>

#include "mcl.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* The most columns an event file has (odometry and ground truth: time and three numbers). */
#define JM_MAX_COLUMNS 4

/* The rows of one event file: n rows of cols numbers, row-major, time first. */
typedef struct {
	int n;
	int cols;
	double *v;
} jm_series;

#define JM_ROW(s, i) ((s)->v + (size_t)(i) * (size_t)(s)->cols)

/* A loaded dataset: the three series, the field and the known start pose. */
typedef struct {
	char dir[PATH_MAX];        /* empty for bare thesis-format files */
	char odometry_path[PATH_MAX + 32];
	char laser_path[PATH_MAX + 32];
	char real_path[PATH_MAX + 32];
	char scenario[128];        /* empty when unknown */
	char name[256];            /* the scenario, else the folder's (or odometry file's) name */
	jm_series odometry;        /* time dx dy dtheta */
	jm_series laser;           /* time angle */
	jm_series real;            /* time x y theta */
	jm_playground pg;
	double start_x, start_y, start_theta;
	int start_known;           /* the start pose came from dataset.properties */
} jm_dataset;

/*
 * What the records of one event file must satisfy beyond the grammar (docs/FORMATS.md 1.1): a
 * column that is an angle in [0, 2pi) (the laser's), and the times of another file's records, one
 * record each (the ground truth is at the odometry times, docs/ALGORITHM.md 10). The Java
 * reader's DatasetReader.Rule.
 */
typedef struct {
	int angle_column;             /* -1: none */
	const jm_series *times;       /* NULL: any times */
	const char *times_name;       /* the file times was read from */
} jm_rule;

/* No more than the grammar (the odometry's), and the laser's: column 1 is the beacon's angle. */
extern const jm_rule jm_rule_none, jm_rule_laser;

/*
 * Reads one event file of cols columns into s, each record as rule says. Returns 0, or -1 with
 * err holding "<file>:<line>: <problem>", or "<file>: <problem>" for the whole file (missing, empty).
 */
int jm_series_read(jm_series *s, const char *path, int cols, const jm_rule *rule, char *err, size_t errlen);
/* The same from an open stream, name being what messages call it (the fuzzer reads memory). */
int jm_series_parse(jm_series *s, FILE *f, const char *name, int cols, const jm_rule *rule, char *err,
		    size_t errlen);
void jm_series_free(jm_series *s);

/*
 * Loads a dataset from dir (odometry.txt, laser.txt, real.txt, optional dataset.properties),
 * or, when dir is NULL, from the three thesis-format files. Returns 0, or -1 with err set.
 */
int jm_dataset_load(jm_dataset *ds, const char *dir, const char *odometry, const char *laser,
		    const char *real, char *err, size_t errlen);
void jm_dataset_free(jm_dataset *ds);

/*
 * Refuses a time scale that takes an event past a run's largest time, JM_VALUE_MAX seconds
 * (docs/FORMATS.md 2): each time is within it, but times 1000 of them may not be, and their
 * nanoseconds would overflow the 64-bit release times. Returns 0, or -1 with err set (the Java
 * workload's Dataset.checkTimeScale).
 */
int jm_dataset_check_time_scale(const jm_dataset *ds, double time_scale, char *err, size_t errlen);

/*
 * Refuses a warm-up that reaches the data's last event (docs/FORMATS.md 2): the warm-up replays the
 * first S seconds of data (times before S, unscaled), so one at or past the last event is no first
 * part but the whole dataset, and summary.json's warmupS would claim seconds never replayed. Names
 * the file whose last time is the later (odometry on a tie). Returns 0, or -1 with err set (the
 * Java workload's Dataset.checkWarmup).
 */
int jm_dataset_check_warmup(const jm_dataset *ds, double warmup_s, char *err, size_t errlen);

/*
 * Reads dataset.properties from f into ds (playground, scenario, start pose and start_known),
 * over what ds holds already. Returns 0, or -1 with err holding "<name>:<line>: <problem>", or
 * "<name>: <key>: missing" when the start pose is given in part.
 */
int jm_properties_parse(jm_dataset *ds, FILE *f, const char *name, char *err, size_t errlen);

#endif
