/* Dataset reader: the thesis-format event files and dataset.properties (docs/FORMATS.md 1). */
#ifndef JM_DATASET_H
#define JM_DATASET_H

#include <limits.h>
#include <stddef.h>

#include "mcl.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

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
	char odometry_path[PATH_MAX];
	char laser_path[PATH_MAX];
	char real_path[PATH_MAX];
	char scenario[128];        /* empty when unknown */
	char name[256];            /* the scenario, else the folder's (or odometry file's) name */
	jm_series odometry;        /* time dx dy dtheta */
	jm_series laser;           /* time angle */
	jm_series real;            /* time x y theta */
	jm_playground pg;
	double start_x, start_y, start_theta;
} jm_dataset;

/*
 * Reads one event file of cols columns into s. Returns 0, or -1 with err holding
 * "<file>:<line>: <problem>", or "<file>: <problem>" for the whole file (missing, empty).
 */
int jm_series_read(jm_series *s, const char *path, int cols, char *err, size_t errlen);
void jm_series_free(jm_series *s);

/*
 * Loads a dataset from dir (odometry.txt, laser.txt, real.txt, optional dataset.properties),
 * or, when dir is NULL, from the three thesis-format files. Returns 0, or -1 with err set.
 */
int jm_dataset_load(jm_dataset *ds, const char *dir, const char *odometry, const char *laser,
		    const char *real, char *err, size_t errlen);
void jm_dataset_free(jm_dataset *ds);

#endif
