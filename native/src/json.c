/* JSON output: escaping per RFC 8259, numbers that read back to the same double. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "json.h"

void jm_json_init(jm_json *j, FILE *f)
{
	memset(j, 0, sizeof(*j));
	j->f = f;
	j->empty[0] = 1;
}

/* RFC 8259's two-character escapes: ESCAPED[i] is written as a backslash and ESCAPE_LETTER[i]. */
static const char ESCAPED[] = "\"\\\n\r\t\b\f";
static const char ESCAPE_LETTER[] = "\"\\nrtbf";

void jm_json_escape(FILE *f, const char *s)
{
	const unsigned char *p;
	const char *e;

	fputc('"', f);
	for (p = (const unsigned char *)s; *p; p++) {
		e = strchr(ESCAPED, *p); /* *p is never NUL here, so e is never the terminator */
		if (e) {
			fputc('\\', f);
			fputc(ESCAPE_LETTER[e - ESCAPED], f);
		} else if (*p < 0x20 || *p == 0x7f) {
			fprintf(f, "\\u%04x", *p);
		} else {
			fputc(*p, f);
		}
	}
	fputc('"', f);
}

static void prefix(jm_json *j, const char *key)
{
	int i;

	if (j->depth > 0) {
		fputs(j->empty[j->depth] ? "\n" : ",\n", j->f);
		for (i = 0; i < j->depth; i++)
			fputs("  ", j->f);
	}
	j->empty[j->depth] = 0;
	if (key) {
		jm_json_escape(j->f, key);
		fputs(": ", j->f);
	}
}

void jm_json_open(jm_json *j, const char *key, char bracket)
{
	prefix(j, key);
	fputc(bracket, j->f);
	if (j->depth < 31)
		j->depth++;
	j->empty[j->depth] = 1;
}

void jm_json_close(jm_json *j, char bracket)
{
	int i, was_empty = j->empty[j->depth];

	j->depth--;
	if (!was_empty) {
		fputc('\n', j->f);
		for (i = 0; i < j->depth; i++)
			fputs("  ", j->f);
	}
	fputc(bracket, j->f);
	if (j->depth == 0)
		fputc('\n', j->f);
}

void jm_json_str(jm_json *j, const char *key, const char *value)
{
	prefix(j, key);
	if (value)
		jm_json_escape(j->f, value);
	else
		fputs("null", j->f);
}

void jm_json_i64(jm_json *j, const char *key, int64_t value)
{
	prefix(j, key);
	fprintf(j->f, "%lld", (long long)value);
}

void jm_json_double(jm_json *j, const char *key, double value)
{
	char buf[40];
	int prec;

	prefix(j, key);
	if (!isfinite(value)) {
		fputs("null", j->f);
		return;
	}
	for (prec = 15; prec <= 17; prec++) {
		snprintf(buf, sizeof(buf), "%.*g", prec, value);
		if (strtod(buf, NULL) == value)
			break;
	}
	/* keep a double recognisable as one: 1 -> 1.0 */
	if (!strpbrk(buf, ".eEn"))
		strcat(buf, ".0");
	fputs(buf, j->f);
}

void jm_json_bool(jm_json *j, const char *key, int value)
{
	prefix(j, key);
	fputs(value ? "true" : "false", j->f);
}

void jm_json_null(jm_json *j, const char *key)
{
	prefix(j, key);
	fputs("null", j->f);
}
