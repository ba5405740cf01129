/*
 * The data files' grammar at the level of tokens (docs/FORMATS.md 1.1): blanks, numbers,
 * lines, and how a message quotes a token. The Java twin is workload's DataGrammar; a
 * differential test and a fuzzer hold the two equal, so keep them in step.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grammar.h"

int jm_is_blank(int c)
{
	return c == ' ' || c == '\t';
}

int jm_is_digit(int c)
{
	return c >= '0' && c <= '9';
}

/*
 * A token or value as a message quotes it: printable ASCII as is, every other byte (and the
 * backslash) as \xHH, at most JM_QUOTE_MAX bytes of it and then "...", so that a message stays
 * one printable line whatever the file holds.
 */
const char *jm_quote(char *out, size_t outlen, const char *p, size_t len)
{
	size_t i, n = 0;

	for (i = 0; i < len && i < JM_QUOTE_MAX && n + 5 < outlen; i++) {
		unsigned char c = (unsigned char)p[i];

		if (c >= 0x20 && c < 0x7f && c != '\\')
			out[n++] = (char)c;
		else
			n += (size_t)snprintf(out + n, outlen - n, "\\x%02x", c);
	}
	if (i < len && n + 4 < outlen) {
		memcpy(out + n, "...", 3);
		n += 3;
	}
	out[n] = '\0';
	return out;
}

int jm_plain_decimal(const char *p, size_t len)
{
	const char *end = p + len;
	int digits = 0;

	if (p < end && (*p == '+' || *p == '-'))
		p++;
	for (; p < end && jm_is_digit(*p); p++)
		digits++;
	if (p < end && *p == '.')
		for (p++; p < end && jm_is_digit(*p); p++)
			digits++;
	if (!digits)
		return 0;
	if (p < end && (*p == 'e' || *p == 'E')) {
		p++;
		if (p < end && (*p == '+' || *p == '-'))
			p++;
		if (p == end || !jm_is_digit(*p))
			return 0;
		while (p < end && jm_is_digit(*p))
			p++;
	}
	return p == end;
}

/* NaN or infinity in any case, signs anywhere: "not a finite number" rather than "not a number". */
int jm_names_non_finite(const char *p, size_t len)
{
	char t[10];
	size_t i, n = 0;

	for (i = 0; i < len; i++) {
		char c = p[i];

		if (c == '+' || c == '-')
			continue;
		if (n == sizeof(t) - 1)
			return 0;
		t[n++] = (char)(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
	}
	/* by length, not strcmp: a NUL byte inside the token must not end the comparison */
	return (n == 3 && (!memcmp(t, "nan", 3) || !memcmp(t, "inf", 3))) || (n == 8 && !memcmp(t, "infinity", 8));
}

/* Parses p[0..len) as a double within JM_VALUE_MAX, correctly rounded (as Java's Double.parseDouble). */
int jm_parse_number(const char *p, size_t len, double *out)
{
	char small[128], *buf = small;
	double v;

	if (!jm_plain_decimal(p, len))
		return jm_names_non_finite(p, len) ? JM_NUM_NON_FINITE : JM_NUM_SYNTAX;
	if (len >= sizeof(small) && !(buf = malloc(len + 1)))
		return JM_NUM_NOMEM;
	memcpy(buf, p, len);
	buf[len] = '\0';
	v = strtod(buf, NULL);
	if (buf != small)
		free(buf);
	if (!isfinite(v))
		return JM_NUM_OVERFLOW;
	if (fabs(v) > JM_VALUE_MAX)
		return JM_NUM_OUT_OF_RANGE;
	*out = v;
	return JM_NUM_OK;
}

/* The words of a number's problem; what follows the quoted token. */
const char *jm_number_problem(int r)
{
	return r == JM_NUM_SYNTAX ? "not a number" : r == JM_NUM_NOMEM ? "out of memory"
		: r == JM_NUM_OUT_OF_RANGE ? "out of range" : "not a finite number";
}

const char *jm_number_detail(int r)
{
	return r == JM_NUM_OVERFLOW ? " (overflows)"
		: r == JM_NUM_OUT_OF_RANGE ? " (more than " JM_VALUE_MAX_TEXT " in magnitude)" : "";
}

/*
 * Reads one line of f into *line (getline's buffer): returns its length without the line
 * end (LF, and a CR right before it or before the end of the file), or -1 at the end.
 */
long jm_read_line(FILE *f, char **line, size_t *cap)
{
	ssize_t n = getline(line, cap, f);

	if (n < 0)
		return -1;
	if (n > 0 && (*line)[n - 1] == '\n')
		n--;
	if (n > 0 && (*line)[n - 1] == '\r')
		n--;
	return (long)n;
}
