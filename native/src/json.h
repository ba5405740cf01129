/* A small JSON writer with correct string escaping and doubles that read back the same (15 to 17 digits). */
#ifndef JM_JSON_H
#define JM_JSON_H

#include <stdint.h>
#include <stdio.h>

/* Writer state: where to write, nesting depth and whether the current container is empty. */
typedef struct {
	FILE *f;
	int depth;
	int empty[32];
} jm_json;

void jm_json_init(jm_json *j, FILE *f);
/* key is NULL inside arrays and for the top-level value. */
void jm_json_open(jm_json *j, const char *key, char bracket);
void jm_json_close(jm_json *j, char bracket);
void jm_json_str(jm_json *j, const char *key, const char *value); /* NULL writes null */
void jm_json_i64(jm_json *j, const char *key, int64_t value);
void jm_json_double(jm_json *j, const char *key, double value);   /* not finite writes null */
void jm_json_bool(jm_json *j, const char *key, int value);
void jm_json_null(jm_json *j, const char *key);
/* Writes s as a JSON string literal (quotes included). */
void jm_json_escape(FILE *f, const char *s);

#endif
