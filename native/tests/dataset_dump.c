/*
 * dataset-dump: what the C reader makes of a file, in a text the Java side writes too
 * (workload's DatasetDump), so that a test can hold the two readers equal byte for byte.
 *
 *   dataset-dump --serve          requests on stdin, answers on stdout (the differential
 *                                 test and the Jazzer target keep one process running):
 *                                 "series <cols> <len>\n" or "properties <len>\n" then <len>
 *                                 bytes, read as a file named "input"
 *   dataset-dump DIR              a dataset folder, as the workload loads it
 *   dataset-dump ODO LASER REAL   the thesis's three files
 *
 * An answer is "error <message>" or "ok" and the values as the bits of each double (hex),
 * then "end". Exit 0 (2 on bad usage).
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dataset.h"

static void bits(FILE *out, double v)
{
	uint64_t u;

	memcpy(&u, &v, sizeof(u));
	fprintf(out, " %016" PRIx64, u);
}

static void dump_series(FILE *out, const char *label, const jm_series *s)
{
	int i, c;

	fprintf(out, "%s %d\n", label, s->n);
	for (i = 0; i < s->n; i++) {
		for (c = 0; c < s->cols; c++)
			bits(out, JM_ROW(s, i)[c]);
		fputc('\n', out);
	}
}

/* The field and scenario; with known, whether dataset.properties set the start pose and to what. */
static void dump_metadata(FILE *out, const jm_dataset *ds, int known)
{
	int i;

	fputs("playground", out);
	bits(out, ds->pg.width);
	bits(out, ds->pg.height);
	fprintf(out, "\nbeacons %d", ds->pg.nbeacons);
	for (i = 0; i < ds->pg.nbeacons; i++) {
		bits(out, ds->pg.beacon[i][0]);
		bits(out, ds->pg.beacon[i][1]);
	}
	if (known)
		fprintf(out, "\nstart %s", ds->start_known ? "known" : "unknown");
	if (known && ds->start_known) {
		bits(out, ds->start_x);
		bits(out, ds->start_y);
		bits(out, ds->start_theta);
	}
	fprintf(out, "\nscenario %s\n", ds->scenario);
}

static void dump_dataset(FILE *out, const jm_dataset *ds)
{
	dump_series(out, "odometry", &ds->odometry);
	dump_series(out, "laser", &ds->laser);
	dump_series(out, "real", &ds->real);
	dump_metadata(out, ds, 0);
	fputs("start", out);
	bits(out, ds->start_x);
	bits(out, ds->start_y);
	bits(out, ds->start_theta);
	fprintf(out, "\nname %s\n", ds->name);
}

/* One request of --serve: parses buf as the kind asked and answers. */
static void answer(FILE *out, const char *kind, int cols, char *buf, size_t len)
{
	char err[1024];
	FILE *f = len ? fmemopen(buf, len, "r") : fopen("/dev/null", "r");

	if (!f) {
		fprintf(out, "error harness: cannot open the input\nend\n");
		return;
	}
	if (!strcmp(kind, "series")) {
		jm_series s;

		if (jm_series_parse(&s, f, "input", cols, cols == 2 ? &jm_rule_laser : &jm_rule_none, err, sizeof(err)))
			fprintf(out, "error %s\n", err);
		else
			fputs("ok\n", out), dump_series(out, "series", &s), jm_series_free(&s);
	} else {
		jm_dataset ds;

		memset(&ds, 0, sizeof(ds));
		jm_playground_default(&ds.pg);
		if (jm_properties_parse(&ds, f, "input", err, sizeof(err)))
			fprintf(out, "error %s\n", err);
		else
			fputs("ok\n", out), dump_metadata(out, &ds, 1);
	}
	fclose(f);
	fputs("end\n", out);
}

static int serve(void)
{
	char head[64], kind[16];
	int cols = 0;
	size_t len;

	while (fgets(head, sizeof(head), stdin)) {
		char *buf;

		if (sscanf(head, "series %d %zu", &cols, &len) == 2 && cols >= 1 && cols <= JM_MAX_COLUMNS)
			strcpy(kind, "series");
		else if (sscanf(head, "properties %zu", &len) == 1)
			strcpy(kind, "properties");
		else
			return 2;
		buf = malloc(len ? len : 1);
		if (!buf || fread(buf, 1, len, stdin) != len) {
			free(buf);
			return 2;
		}
		answer(stdout, kind, cols, buf, len);
		free(buf);
		fflush(stdout);
	}
	return 0;
}

int main(int argc, char **argv)
{
	char err[8192];
	jm_dataset ds;
	int r;

	if (argc == 2 && !strcmp(argv[1], "--serve"))
		return serve();
	if (argc != 2 && argc != 4) {
		fprintf(stderr, "usage: dataset-dump --serve | DIR | ODO LASER REAL\n");
		return 2;
	}
	r = argc == 2 ? jm_dataset_load(&ds, argv[1], NULL, NULL, NULL, err, sizeof(err))
		      : jm_dataset_load(&ds, NULL, argv[1], argv[2], argv[3], err, sizeof(err));
	if (r) {
		printf("error %s\nend\n", err);
		return 0;
	}
	fputs("ok\n", stdout);
	dump_dataset(stdout, &ds);
	fputs("end\n", stdout);
	jm_dataset_free(&ds);
	return 0;
}
