/*
 * Strict readers of docs/FORMATS.md 1: a file that is not exactly in the grammar written
 * there is rejected with its line. The Java reader (workload's DatasetReader) implements the
 * same grammar byte for byte and says the same words; a differential test and a fuzzer hold
 * the two equal, so keep them in step.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "angles.h"
#include "dataset.h"
#include "grammar.h"

const jm_rule jm_rule_none = { -1, NULL, NULL };
const jm_rule jm_rule_laser = { 1, NULL, NULL };

static int append_row(jm_series *s, int *cap, const double *row)
{
	if (s->n == *cap) {
		int ncap = *cap ? *cap * 2 : 1024;
		double *nv;

		if (ncap < 0)
			return -1;
		nv = realloc(s->v, sizeof(double) * (size_t)ncap * (size_t)s->cols);
		if (!nv)
			return -1;
		s->v = nv;
		*cap = ncap;
	}
	memcpy(JM_ROW(s, s->n), row, sizeof(double) * (size_t)s->cols);
	s->n++;
	return 0;
}

/* The tokens of a record line: start offsets and lengths of at most max, and their count. */
static int split(const char *line, long len, size_t *start, size_t *tlen, int max)
{
	long i = 0;
	int n = 0;

	for (;;) {
		long b;

		while (i < len && jm_is_blank(line[i]))
			i++;
		if (i == len)
			return n;
		for (b = i; i < len && !jm_is_blank(line[i]); i++)
			;
		if (n < max) {
			start[n] = (size_t)b;
			tlen[n] = (size_t)(i - b);
		}
		n++;
	}
}

/* One record line into row; returns 0 or -1 with err set. */
static int parse_record(const char *name, int lineno, const char *line, long len, int cols, double *row,
			char *err, size_t errlen)
{
	size_t start[JM_MAX_COLUMNS], tlen[JM_MAX_COLUMNS];
	char q[4 * JM_QUOTE_MAX + 8];
	int c, n = split(line, len, start, tlen, cols);

	if (n != cols) {
		snprintf(err, errlen, "%s:%d: expected %d columns but found %d", name, lineno, cols, n);
		return -1;
	}
	for (c = 0; c < cols; c++) {
		int r = jm_parse_number(line + start[c], tlen[c], &row[c]);

		if (r != JM_NUM_OK) {
			snprintf(err, errlen, "%s:%d: %s: '%s'%s", name, lineno, jm_number_problem(r),
				 jm_quote(q, sizeof(q), line + start[c], tlen[c]), jm_number_detail(r));
			return -1;
		}
	}
	return 0;
}

/* The token of column c of a record line, quoted as messages quote it, into q. */
static const char *column_token(char *q, size_t qlen, const char *line, long len, int c)
{
	size_t start[JM_MAX_COLUMNS], tlen[JM_MAX_COLUMNS];

	split(line, len, start, tlen, JM_MAX_COLUMNS);
	return jm_quote(q, qlen, line + start[c], tlen[c]);
}

/* Refuses record index (at lineno) when it breaks rule; returns 0 or -1 with err set. */
static int check_rule(const jm_rule *rule, int index, const double *row, const char *name, int lineno,
		      const char *line, long len, char *err, size_t errlen)
{
	char q[4 * JM_QUOTE_MAX + 8];
	int a = rule->angle_column;

	if (a >= 0 && !(row[a] >= 0.0 && row[a] < JM_TWO_PI)) {
		snprintf(err, errlen, "%s:%d: angle %s is not in [0, 2pi) (the beacon's angle from the heading)", name,
			 lineno, column_token(q, sizeof(q), line, len, a));
		return -1;
	}
	if (!rule->times)
		return 0;
	if (index >= rule->times->n) {
		snprintf(err, errlen, "%s:%d: time %s after the last of the %d records of %s (the ground truth is at "
			 "the odometry times)", name, lineno, column_token(q, sizeof(q), line, len, 0), rule->times->n,
			 rule->times_name);
		return -1;
	}
	if (row[0] != JM_ROW(rule->times, index)[0]) {
		snprintf(err, errlen, "%s:%d: time %s is not that of record %d of %s (the ground truth is at the "
			 "odometry times)", name, lineno, column_token(q, sizeof(q), line, len, 0), index + 1,
			 rule->times_name);
		return -1;
	}
	return 0;
}

int jm_series_parse(jm_series *s, FILE *f, const char *name, int cols, const jm_rule *rule, char *err,
		    size_t errlen)
{
	char *line = NULL, q[4 * JM_QUOTE_MAX + 8];
	size_t linecap = 0;
	long len;
	int lineno = 0, cap = 0, ret = -1;
	double prev = 0.0;

	memset(s, 0, sizeof(*s));
	s->cols = cols;
	while ((len = jm_read_line(f, &line, &linecap)) >= 0) {
		double row[JM_MAX_COLUMNS];
		long i = 0;

		lineno++;
		while (i < len && jm_is_blank(line[i]))
			i++;
		if (i == len || line[i] == '#')
			continue; /* blank line or comment */
		if (parse_record(name, lineno, line, len, cols, row, err, errlen))
			goto out;
		if (row[0] < 0.0 || (s->n > 0 && row[0] < prev)) {
			size_t tl;

			for (tl = 0; i + (long)tl < len && !jm_is_blank(line[i + (long)tl]); tl++)
				;
			jm_quote(q, sizeof(q), line + i, tl);
			if (row[0] < 0.0)
				snprintf(err, errlen, "%s:%d: negative time %s", name, lineno, q);
			else
				snprintf(err, errlen, "%s:%d: time %s is before the previous line's (not sorted by time)",
					 name, lineno, q);
			goto out;
		}
		if (check_rule(rule, s->n, row, name, lineno, line, len, err, errlen))
			goto out;
		prev = row[0];
		if (append_row(s, &cap, row) < 0) {
			snprintf(err, errlen, "%s:%d: out of memory", name, lineno);
			goto out;
		}
	}
	if (ferror(f)) {
		snprintf(err, errlen, "%s: cannot read", name);
		goto out;
	}
	if (s->n == 0) {
		snprintf(err, errlen, "%s: empty file (no data lines)", name);
		goto out;
	}
	if (rule->times && s->n < rule->times->n) {
		snprintf(err, errlen, "%s: %d records for the %d of %s (the ground truth is at the odometry times)", name,
			 s->n, rule->times->n, rule->times_name);
		goto out;
	}
	ret = 0;
out:
	free(line);
	if (ret < 0)
		jm_series_free(s);
	return ret;
}

/*
 * Opens a file of a dataset, or says why not in the words both readers use: "no such file"
 * (nothing there, whatever stat's reason), "is a directory", "not a regular file" (a FIFO
 * would block the run), "permission denied". Returns NULL with *absent set when nothing is
 * there, so that an optional file can be skipped.
 */
static FILE *open_data(const char *path, int *absent, char *err, size_t errlen)
{
	struct stat st;
	FILE *f;

	*absent = 0;
	if (stat(path, &st)) {
		if (errno == EACCES) {
			snprintf(err, errlen, "%s: permission denied", path);
			return NULL;
		}
		*absent = 1;
		snprintf(err, errlen, "%s: no such file", path);
		return NULL;
	}
	if (S_ISDIR(st.st_mode)) {
		snprintf(err, errlen, "%s: is a directory", path);
		return NULL;
	}
	if (!S_ISREG(st.st_mode)) {
		snprintf(err, errlen, "%s: not a regular file", path);
		return NULL;
	}
	f = fopen(path, "r");
	if (!f)
		snprintf(err, errlen, "%s: %s", path, errno == EACCES ? "permission denied" : "cannot read");
	return f;
}

int jm_series_read(jm_series *s, const char *path, int cols, const jm_rule *rule, char *err, size_t errlen)
{
	int absent, ret;
	FILE *f = open_data(path, &absent, err, errlen);

	memset(s, 0, sizeof(*s));
	if (!f)
		return -1;
	ret = jm_series_parse(s, f, path, cols, rule, err, errlen);
	fclose(f);
	return ret;
}

void jm_series_free(jm_series *s)
{
	free(s->v);
	s->v = NULL;
	s->n = 0;
}

/* p[0..*len) without the blanks at both ends. */
static const char *trim(const char *p, size_t *len)
{
	while (*len && jm_is_blank(*p))
		p++, (*len)--;
	while (*len && jm_is_blank(p[*len - 1]))
		(*len)--;
	return p;
}

/* "x,y;x,y;..." (blanks around numbers allowed) into the playground's beacons; 0 or -1. */
static int parse_beacons(const char *v, size_t len, jm_playground *pg)
{
	const char *end = v + len;
	int n = 0;

	for (;;) {
		const char *pair_end = memchr(v, ';', (size_t)(end - v)), *comma;
		size_t xl, yl;
		const char *x, *y;

		if (!pair_end)
			pair_end = end;
		comma = memchr(v, ',', (size_t)(pair_end - v));
		if (!comma || n == JM_MAX_BEACONS)
			return -1;
		xl = (size_t)(comma - v);
		yl = (size_t)(pair_end - comma - 1);
		x = trim(v, &xl);
		y = trim(comma + 1, &yl);
		if (jm_parse_number(x, xl, &pg->beacon[n][0]) || jm_parse_number(y, yl, &pg->beacon[n][1]))
			return -1;
		n++;
		if (pair_end == end)
			break;
		v = pair_end + 1;
	}
	pg->nbeacons = n;
	return 0;
}

enum { HAS_X = 1, HAS_Y = 2, HAS_THETA = 4 };

/* The key's number, checked; returns 0 or -1 with err set. */
static int property_number(const char *name, int lineno, const char *key, const char *v, size_t vl, double *out,
			   char *err, size_t errlen)
{
	char q[4 * JM_QUOTE_MAX + 8];
	int r = jm_parse_number(v, vl, out);

	if (r != JM_NUM_OK) {
		snprintf(err, errlen, "%s:%d: %s: %s: '%s'%s", name, lineno, key, jm_number_problem(r),
			 jm_quote(q, sizeof(q), v, vl), jm_number_detail(r));
		return -1;
	}
	if (!strncmp(key, "playground.", 11) && !(*out > 0.0)) {
		snprintf(err, errlen, "%s:%d: %s: must be positive", name, lineno, key);
		return -1;
	}
	return 0;
}

/* One key=value line (already trimmed, not a comment) into ds; returns 0 or -1 with err set. */
static int parse_property(jm_dataset *ds, const char *name, int lineno, const char *p, size_t len, int *has,
			  char *err, size_t errlen)
{
	static const char *const numeric[] = { "playground.width", "playground.height", "start.x", "start.y",
					       "start.theta" };
	const char *eq = memchr(p, '=', len), *key, *v;
	size_t kl, vl, i;
	char k[32];
	double d;

	for (i = 0; i < len; i++) {
		unsigned char c = (unsigned char)p[i];

		if ((c < 0x20 && c != '\t') || c >= 0x7f) {
			snprintf(err, errlen, "%s:%d: not printable ASCII: byte 0x%02x", name, lineno, c);
			return -1;
		}
	}
	kl = eq ? (size_t)(eq - p) : 0;
	key = trim(p, &kl);
	if (!eq || kl == 0) {
		snprintf(err, errlen, "%s:%d: expected key=value", name, lineno);
		return -1;
	}
	vl = len - (size_t)(eq + 1 - p);
	v = trim(eq + 1, &vl);
	if (kl >= sizeof(k))
		return 0; /* longer than every key this reader knows */
	memcpy(k, key, kl);
	k[kl] = '\0';
	if (!strcmp(k, "scenario")) {
		if (vl >= sizeof(ds->scenario)) {
			snprintf(err, errlen, "%s:%d: scenario: longer than %d characters", name, lineno,
				 (int)sizeof(ds->scenario) - 1);
			return -1;
		}
		snprintf(ds->scenario, sizeof(ds->scenario), "%.*s", (int)vl, v);
		return 0;
	}
	if (!strcmp(k, "beacons")) {
		if (parse_beacons(v, vl, &ds->pg)) {
			snprintf(err, errlen, "%s:%d: beacons: expected x,y;x,y;... (1 to %d beacons)", name, lineno,
				 JM_MAX_BEACONS);
			return -1;
		}
		return 0;
	}
	for (i = 0; i < sizeof(numeric) / sizeof(numeric[0]); i++) {
		if (strcmp(k, numeric[i]))
			continue;
		if (property_number(name, lineno, k, v, vl, &d, err, errlen))
			return -1;
		switch (i) {
		case 0: ds->pg.width = d; break;
		case 1: ds->pg.height = d; break;
		case 2: ds->start_x = d, *has |= HAS_X; break;
		case 3: ds->start_y = d, *has |= HAS_Y; break;
		default: ds->start_theta = d, *has |= HAS_THETA; break;
		}
	}
	return 0; /* a key this reader does not use */
}

int jm_properties_parse(jm_dataset *ds, FILE *f, const char *name, char *err, size_t errlen)
{
	char *line = NULL;
	size_t linecap = 0;
	long len;
	int lineno = 0, has = 0, ret = -1;

	while ((len = jm_read_line(f, &line, &linecap)) >= 0) {
		size_t n = (size_t)len;
		const char *p = trim(line, &n);

		lineno++;
		if (n == 0 || *p == '#' || *p == '!')
			continue;
		if (parse_property(ds, name, lineno, p, n, &has, err, errlen))
			goto out;
	}
	if (ferror(f)) {
		snprintf(err, errlen, "%s: cannot read", name);
		goto out;
	}
	/* the start pose: all three keys, or none (the first ground-truth line) */
	if (has && has != (HAS_X | HAS_Y | HAS_THETA)) {
		snprintf(err, errlen, "%s: %s: missing", name,
			 !(has & HAS_X) ? "start.x" : !(has & HAS_Y) ? "start.y" : "start.theta");
		goto out;
	}
	ds->start_known = has != 0;
	ret = 0;
out:
	free(line);
	return ret;
}

/* The path as Java's File writes it: no repeated '/', no trailing '/' (but "/" itself). */
static void normalize(char *dst, size_t dstlen, const char *src)
{
	size_t n = 0;

	for (; *src && n + 1 < dstlen; src++)
		if (!(*src == '/' && n > 0 && dst[n - 1] == '/'))
			dst[n++] = *src;
	if (n > 1 && dst[n - 1] == '/')
		n--;
	dst[n] = '\0';
}

int jm_dataset_load(jm_dataset *ds, const char *dir, const char *odometry, const char *laser,
		    const char *real, char *err, size_t errlen)
{
	char props[PATH_MAX + 32];
	const char *base, *slash;

	memset(ds, 0, sizeof(*ds));
	jm_playground_default(&ds->pg);
	if (dir) {
		struct stat st;

		normalize(ds->dir, sizeof(ds->dir), dir);
		if (stat(dir, &st) || !S_ISDIR(st.st_mode)) {
			snprintf(err, errlen, "%s: no such dataset folder", ds->dir);
			return -1;
		}
		snprintf(ds->odometry_path, sizeof(ds->odometry_path), "%s/odometry.txt", ds->dir);
		snprintf(ds->laser_path, sizeof(ds->laser_path), "%s/laser.txt", ds->dir);
		snprintf(ds->real_path, sizeof(ds->real_path), "%s/real.txt", ds->dir);
		snprintf(props, sizeof(props), "%s/dataset.properties", ds->dir);
	} else {
		normalize(ds->odometry_path, sizeof(ds->odometry_path), odometry);
		normalize(ds->laser_path, sizeof(ds->laser_path), laser);
		normalize(ds->real_path, sizeof(ds->real_path), real);
	}
	/* in this order in both languages, so that a dataset with two problems names the same one */
	if (jm_series_read(&ds->odometry, ds->odometry_path, 4, &jm_rule_none, err, errlen) < 0 ||
	    jm_series_read(&ds->laser, ds->laser_path, 2, &jm_rule_laser, err, errlen) < 0)
		goto fail;
	{
		jm_rule real_rule = { -1, &ds->odometry, ds->odometry_path };

		if (jm_series_read(&ds->real, ds->real_path, 4, &real_rule, err, errlen) < 0)
			goto fail;
	}
	if (dir) {
		int absent;
		FILE *f = open_data(props, &absent, err, errlen);

		if (!f && !absent)
			goto fail;
		if (f) {
			int r = jm_properties_parse(ds, f, props, err, errlen);

			fclose(f);
			if (r)
				goto fail;
		}
	}
	if (!ds->start_known) {
		ds->start_x = JM_ROW(&ds->real, 0)[1];
		ds->start_y = JM_ROW(&ds->real, 0)[2];
		ds->start_theta = JM_ROW(&ds->real, 0)[3];
	}
	if (ds->scenario[0]) {
		snprintf(ds->name, sizeof(ds->name), "%s", ds->scenario);
		return 0;
	}
	base = dir ? ds->dir : ds->odometry_path;
	slash = strrchr(base, '/');
	snprintf(ds->name, sizeof(ds->name), "%.255s", slash && slash[1] ? slash + 1 : base);
	return 0;
fail:
	jm_dataset_free(ds);
	return -1;
}

static int check_scaled(const jm_series *s, const char *path, double time_scale, char *err, size_t errlen)
{
	if (JM_ROW(s, s->n - 1)[0] * time_scale > JM_VALUE_MAX) {
		snprintf(err, errlen, "--time-scale: scales the last time of %s past " JM_VALUE_MAX_TEXT
			 " s, the largest time of a run", path);
		return -1;
	}
	return 0;
}

int jm_dataset_check_time_scale(const jm_dataset *ds, double time_scale, char *err, size_t errlen)
{
	return check_scaled(&ds->odometry, ds->odometry_path, time_scale, err, errlen) ||
	       check_scaled(&ds->laser, ds->laser_path, time_scale, err, errlen) ? -1 : 0;
}

int jm_dataset_check_warmup(const jm_dataset *ds, double warmup_s, char *err, size_t errlen)
{
	double odo_last = JM_ROW(&ds->odometry, ds->odometry.n - 1)[0];
	double laser_last = JM_ROW(&ds->laser, ds->laser.n - 1)[0];

	if (warmup_s > 0.0 && warmup_s >= (odo_last >= laser_last ? odo_last : laser_last)) {
		snprintf(err, errlen, "--warmup: reaches the last time of %s: a warm-up replays the data before it"
			 " and must leave an event after it", odo_last >= laser_last ? ds->odometry_path : ds->laser_path);
		return -1;
	}
	return 0;
}

void jm_dataset_free(jm_dataset *ds)
{
	jm_series_free(&ds->odometry);
	jm_series_free(&ds->laser);
	jm_series_free(&ds->real);
}
