/* The data files' grammar at the level of tokens (docs/FORMATS.md 1.1), shared by the readers and the command line. */
#ifndef JM_GRAMMAR_H
#define JM_GRAMMAR_H

#include <stddef.h>
#include <stdio.h>

/* What separates numbers on a line: space and tab, nothing else (no \r, \v, \f). */
int jm_is_blank(int c);
int jm_is_digit(int c);

/*
 * Whether p[0..len) is a number of the grammar, shared by the data files and the command
 * line: [+-]?(digits[.[digits]] | .digits)[(e|E)[+-]digits].
 */
int jm_plain_decimal(const char *p, size_t len);

/* NaN or infinity in any case, signs anywhere: "not a finite number" rather than "not a number". */
int jm_names_non_finite(const char *p, size_t len);

enum { JM_NUM_OK, JM_NUM_SYNTAX, JM_NUM_NON_FINITE, JM_NUM_OVERFLOW, JM_NUM_NOMEM, JM_NUM_OUT_OF_RANGE };

/*
 * The largest magnitude of a data value (docs/FORMATS.md 1.1): 1e9 s of time is 1e18 ns, well
 * inside a 64-bit release time with room for the clock's origin and the deadlines; 1e9 m or rad
 * is far beyond any robot's and keeps the filter's sums and squares finite. The Java reader's
 * DataGrammar.VALUE_MAX.
 */
#define JM_VALUE_MAX 1e9
#define JM_VALUE_MAX_TEXT "1e9"

/*
 * Parses p[0..len) as a double of magnitude at most JM_VALUE_MAX, correctly rounded (as Java's
 * Double.parseDouble): a JM_NUM_ code.
 */
int jm_parse_number(const char *p, size_t len, double *out);

/* The words of a number's problem (a JM_NUM_ code other than JM_NUM_OK); what follows the quoted token. */
const char *jm_number_problem(int r);

/* What a message writes after the quoted token of a number's problem ("" for most). */
const char *jm_number_detail(int r);

/* At most this many bytes of a token are quoted in a message, then "...". */
#define JM_QUOTE_MAX 40

/*
 * A token or value as a message quotes it, into out: printable ASCII as is, every other byte
 * (and the backslash) as \xHH, so that a message stays one printable line whatever the file holds.
 */
const char *jm_quote(char *out, size_t outlen, const char *p, size_t len);

/*
 * Reads one line of f into *line (getline's buffer): returns its length without the line
 * end (LF, and a CR right before it or before the end of the file), or -1 at the end.
 */
long jm_read_line(FILE *f, char **line, size_t *cap);

#endif
