/* Strict readers: a file that is not exactly what FORMATS.md describes is rejected with its line. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "dataset.h"

/*
 * Whether tok is a plain decimal number, [+-]?(digits[.[digits]] | .digits)[(e|E)[+-]digits]:
 * what %.16e writes and both languages' parsers agree on (no hex, no suffix, no NaN/infinity).
 */
static int plain_decimal(const char *p)
{
	int digits = 0;

	if (*p == '+' || *p == '-')
		p++;
	while (isdigit((unsigned char)*p))
		p++, digits++;
	if (*p == '.') {
		p++;
		while (isdigit((unsigned char)*p))
			p++, digits++;
	}
	if (!digits)
		return 0;
	if (*p == 'e' || *p == 'E') {
		p++;
		if (*p == '+' || *p == '-')
			p++;
		if (!isdigit((unsigned char)*p))
			return 0;
		while (isdigit((unsigned char)*p))
			p++;
	}
	return *p == '\0';
}

/* NaN or infinity in any case and sign: "not a finite number" rather than "not a number". */
static int names_non_finite(const char *tok)
{
	char t[16];
	size_t n = 0;

	for (; *tok && n < sizeof(t) - 1; tok++)
		if (*tok != '+' && *tok != '-')
			t[n++] = (char)tolower((unsigned char)*tok);
	t[n] = '\0';
	return !*tok && (!strcmp(t, "nan") || !strcmp(t, "inf") || !strcmp(t, "infinity"));
}

/* Parses a whole token as a finite double; returns 0, 1 when not a number, 2 when not finite,
 * 3 when it overflows. */
static int parse_number(const char *tok, double *out)
{
	double v;

	if (!plain_decimal(tok))
		return names_non_finite(tok) ? 2 : 1;
	v = strtod(tok, NULL);
	if (!isfinite(v))
		return 3;
	*out = v;
	return 0;
}

static int append_row(jm_series *s, int *cap, const double *row)
{
	if (s->n == *cap) {
		int ncap = *cap ? *cap * 2 : 1024;
		double *nv = realloc(s->v, sizeof(double) * (size_t)ncap * (size_t)s->cols);

		if (!nv)
			return -1;
		s->v = nv;
		*cap = ncap;
	}
	memcpy(JM_ROW(s, s->n), row, sizeof(double) * (size_t)s->cols);
	s->n++;
	return 0;
}

int jm_series_read(jm_series *s, const char *path, int cols, char *err, size_t errlen)
{
	FILE *f;
	char *line = NULL;
	size_t linecap = 0;
	int lineno = 0, cap = 0, ret = -1;
	double prev = 0.0;

	memset(s, 0, sizeof(*s));
	s->cols = cols;
	f = fopen(path, "r");
	if (!f) {
		if (errno == ENOENT)
			snprintf(err, errlen, "%s: no such file", path);
		else
			snprintf(err, errlen, "%s: cannot read: %s", path, strerror(errno));
		return -1;
	}
	while (getline(&line, &linecap, f) != -1) {
		double row[8];
		char first[48] = "";
		char *tok, *save = NULL, *p = line;
		int ncols = 0;

		lineno++;
		while (isspace((unsigned char)*p))
			p++;
		if (*p == '\0' || *p == '#')
			continue;
		for (tok = strtok_r(p, " \t\r\n\v\f", &save); tok; tok = strtok_r(NULL, " \t\r\n\v\f", &save)) {
			double v = 0.0;
			int r;

			ncols++;
			if (ncols > cols)
				continue; /* counted for the message below */
			r = parse_number(tok, &v);
			if (r == 1) {
				snprintf(err, errlen, "%s:%d: not a number: '%.40s'", path, lineno, tok);
				goto out;
			}
			if (r >= 2) {
				snprintf(err, errlen, "%s:%d: not a finite number: '%.40s'%s", path, lineno, tok,
					 r == 3 ? " (overflows)" : "");
				goto out;
			}
			row[ncols - 1] = v;
			if (ncols == 1)
				snprintf(first, sizeof(first), "%s", tok);
		}
		if (ncols != cols) {
			snprintf(err, errlen, "%s:%d: expected %d columns but found %d", path, lineno, cols, ncols);
			goto out;
		}
		if (row[0] < 0.0) {
			snprintf(err, errlen, "%s:%d: negative time %s", path, lineno, first);
			goto out;
		}
		if (s->n > 0 && row[0] < prev) {
			snprintf(err, errlen, "%s:%d: time %s is before the previous line's (not sorted by time)",
				 path, lineno, first);
			goto out;
		}
		prev = row[0];
		if (append_row(s, &cap, row) < 0) {
			snprintf(err, errlen, "%s:%d: out of memory", path, lineno);
			goto out;
		}
	}
	if (ferror(f)) {
		snprintf(err, errlen, "%s: cannot read: %s", path, strerror(errno));
		goto out;
	}
	if (s->n == 0) {
		snprintf(err, errlen, "%s: empty file (no data lines)", path);
		goto out;
	}
	ret = 0;
out:
	free(line);
	fclose(f);
	if (ret < 0)
		jm_series_free(s);
	return ret;
}

void jm_series_free(jm_series *s)
{
	free(s->v);
	s->v = NULL;
	s->n = 0;
}

static char *trim(char *p)
{
	char *e;

	while (isspace((unsigned char)*p))
		p++;
	e = p + strlen(p);
	while (e > p && isspace((unsigned char)e[-1]))
		*--e = '\0';
	return p;
}

/* "x,y;x,y;..." into the playground's beacons; returns 0 or -1. */
static int parse_beacons(char *value, jm_playground *pg)
{
	char *pair, *save = NULL;
	int n = 0;

	for (pair = strtok_r(value, ";", &save); pair; pair = strtok_r(NULL, ";", &save)) {
		char *comma = strchr(pair, ',');

		if (!comma || n == JM_MAX_BEACONS)
			return -1;
		*comma = '\0';
		if (parse_number(trim(pair), &pg->beacon[n][0]) ||
		    parse_number(trim(comma + 1), &pg->beacon[n][1]))
			return -1;
		n++;
	}
	if (n == 0)
		return -1;
	pg->nbeacons = n;
	return 0;
}

enum { HAS_X = 1, HAS_Y = 2, HAS_THETA = 4 };

/* Reads the keys this program uses from dataset.properties; a missing file is fine. */
static int read_properties(jm_dataset *ds, const char *path, int *has_start, char *err, size_t errlen)
{
	FILE *f = fopen(path, "r");
	char *line = NULL;
	size_t linecap = 0;
	int lineno = 0, ret = -1;

	if (!f) {
		if (errno == ENOENT)
			return 0;
		snprintf(err, errlen, "%s: cannot read: %s", path, strerror(errno));
		return -1;
	}
	while (getline(&line, &linecap, f) != -1) {
		char *p = trim(line), *eq, *key, *value;
		double v;

		lineno++;
		if (*p == '\0' || *p == '#' || *p == '!')
			continue;
		eq = strchr(p, '=');
		if (!eq) {
			snprintf(err, errlen, "%s:%d: expected key=value", path, lineno);
			goto out;
		}
		*eq = '\0';
		key = trim(p);
		value = trim(eq + 1);
		if (!strcmp(key, "scenario")) {
			snprintf(ds->scenario, sizeof(ds->scenario), "%s", value);
		} else if (!strcmp(key, "beacons")) {
			if (parse_beacons(value, &ds->pg) < 0) {
				snprintf(err, errlen, "%s:%d: beacons: expected x,y;x,y;... (at most %d)",
					 path, lineno, JM_MAX_BEACONS);
				goto out;
			}
		} else if (!strcmp(key, "playground.width") || !strcmp(key, "playground.height") ||
			   !strcmp(key, "start.x") || !strcmp(key, "start.y") || !strcmp(key, "start.theta")) {
			int r = parse_number(value, &v);

			if (r) {
				snprintf(err, errlen, "%s:%d: %s: %s: '%.40s'", path, lineno, key,
					 r == 1 ? "not a number" : "not a finite number", value);
				goto out;
			}
			if (!strncmp(key, "playground.", 11) && v <= 0.0) {
				snprintf(err, errlen, "%s:%d: %s: must be positive", path, lineno, key);
				goto out;
			}
			if (!strcmp(key, "playground.width"))
				ds->pg.width = v;
			else if (!strcmp(key, "playground.height"))
				ds->pg.height = v;
			else if (!strcmp(key, "start.x"))
				ds->start_x = v, *has_start |= HAS_X;
			else if (!strcmp(key, "start.y"))
				ds->start_y = v, *has_start |= HAS_Y;
			else
				ds->start_theta = v, *has_start |= HAS_THETA;
		}
	}
	ret = 0;
out:
	free(line);
	fclose(f);
	return ret;
}

int jm_dataset_load(jm_dataset *ds, const char *dir, const char *odometry, const char *laser,
		    const char *real, char *err, size_t errlen)
{
	char props[PATH_MAX + 32];
	int has_start = 0;

	memset(ds, 0, sizeof(*ds));
	jm_playground_default(&ds->pg);
	if (dir) {
		struct stat st;

		if (stat(dir, &st) || !S_ISDIR(st.st_mode)) {
			snprintf(err, errlen, "%s: no such dataset folder", dir);
			return -1;
		}
		snprintf(ds->dir, sizeof(ds->dir), "%s", dir);
		snprintf(ds->odometry_path, sizeof(ds->odometry_path), "%s/odometry.txt", dir);
		snprintf(ds->laser_path, sizeof(ds->laser_path), "%s/laser.txt", dir);
		snprintf(ds->real_path, sizeof(ds->real_path), "%s/real.txt", dir);
		snprintf(props, sizeof(props), "%s/dataset.properties", dir);
	} else {
		snprintf(ds->odometry_path, sizeof(ds->odometry_path), "%s", odometry);
		snprintf(ds->laser_path, sizeof(ds->laser_path), "%s", laser);
		snprintf(ds->real_path, sizeof(ds->real_path), "%s", real);
	}
	if (jm_series_read(&ds->odometry, ds->odometry_path, 4, err, errlen) < 0 ||
	    jm_series_read(&ds->laser, ds->laser_path, 2, err, errlen) < 0 ||
	    jm_series_read(&ds->real, ds->real_path, 4, err, errlen) < 0)
		goto fail;
	if (dir && read_properties(ds, props, &has_start, err, errlen) < 0)
		goto fail;
	/* the start pose: all three keys of the metadata, or the first ground-truth line */
	if (has_start && has_start != (HAS_X | HAS_Y | HAS_THETA)) {
		snprintf(err, errlen, "%s: %s: missing", props,
			 !(has_start & HAS_X) ? "start.x" : !(has_start & HAS_Y) ? "start.y" : "start.theta");
		goto fail;
	}
	if (!has_start) {
		ds->start_x = JM_ROW(&ds->real, 0)[1];
		ds->start_y = JM_ROW(&ds->real, 0)[2];
		ds->start_theta = JM_ROW(&ds->real, 0)[3];
	}
	if (!ds->scenario[0]) {
		const char *base = dir ? dir : ds->odometry_path, *slash;
		size_t len = strlen(base);

		while (len > 1 && base[len - 1] == '/')
			len--;
		for (slash = base + len; slash > base && slash[-1] != '/'; slash--)
			;
		snprintf(ds->name, sizeof(ds->name), "%.*s", (int)(base + len - slash), slash);
	} else {
		snprintf(ds->name, sizeof(ds->name), "%s", ds->scenario);
	}
	return 0;
fail:
	jm_dataset_free(ds);
	return -1;
}

void jm_dataset_free(jm_dataset *ds)
{
	jm_series_free(&ds->odometry);
	jm_series_free(&ds->laser);
	jm_series_free(&ds->real);
}
