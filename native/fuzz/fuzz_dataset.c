/*
 * libFuzzer target of the dataset readers (docs/FORMATS.md 1.1, 1.2): the first byte picks
 * odometry (4 columns), laser (2) or dataset.properties, the rest is the file. Built with
 * AddressSanitizer and UBSan (make fuzz); a crash, a leak or an accepted file that breaks the
 * grammar's promises (values within JM_VALUE_MAX, sorted non-negative times, laser angles in
 * [0, 2pi)) is a finding.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "angles.h"
#include "dataset.h"
#include "grammar.h"

static FILE *open_input(const uint8_t *data, size_t size)
{
	return size ? fmemopen((void *)data, size, "r") : fopen("/dev/null", "r");
}

/* What an accepted file promises its reader; abort() makes a broken promise a finding. */
static void check_series(const jm_series *s)
{
	int i, c;

	for (i = 0; i < s->n; i++) {
		for (c = 0; c < s->cols; c++)
			if (!(fabs(JM_ROW(s, i)[c]) <= JM_VALUE_MAX))
				abort();
		if (JM_ROW(s, i)[0] < 0.0 || (i > 0 && JM_ROW(s, i)[0] < JM_ROW(s, i - 1)[0]))
			abort();
		if (s->cols == 2 && !(JM_ROW(s, i)[1] >= 0.0 && JM_ROW(s, i)[1] < JM_TWO_PI))
			abort(); /* a laser angle in [0, 2pi) */
	}
	if (s->n < 1)
		abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char err[512];
	FILE *f;
	int kind;

	if (size < 1)
		return 0;
	kind = data[0] % 3;
	f = open_input(data + 1, size - 1);
	if (!f)
		return 0;
	if (kind < 2) {
		jm_series s;

		if (jm_series_parse(&s, f, "input", kind == 0 ? 4 : 2, kind == 0 ? &jm_rule_none : &jm_rule_laser, err,
				    sizeof(err)) == 0) {
			check_series(&s);
			jm_series_free(&s);
		} else if (strlen(err) == 0 || strchr(err, '\n')) {
			abort(); /* a message is one non-empty line */
		}
	} else {
		jm_dataset ds;

		memset(&ds, 0, sizeof(ds));
		jm_playground_default(&ds.pg);
		if (jm_properties_parse(&ds, f, "input", err, sizeof(err)) == 0) {
			if (!(ds.pg.width > 0.0) || !(ds.pg.height > 0.0) || ds.pg.nbeacons < 1 ||
			    ds.pg.nbeacons > JM_MAX_BEACONS)
				abort();
		} else if (strlen(err) == 0 || strchr(err, '\n')) {
			abort();
		}
	}
	fclose(f);
	return 0;
}
