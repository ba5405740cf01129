/*
 * libFuzzer target of the command-line parser (docs/FORMATS.md 2): the input is the
 * arguments separated by NUL bytes. Built with AddressSanitizer and UBSan (make fuzz); a
 * crash, or an accepted command line that breaks the parser's promises, is a finding.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "options.h"

#define MAX_ARGS 64

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *copy = malloc(size + 1), *argv[MAX_ARGS + 2], err[512];
	int argc = 1;
	size_t i, start = 0;
	jm_options o;

	if (!copy)
		return 0;
	memcpy(copy, data, size);
	copy[size] = '\0';
	argv[0] = "jmclbench-native";
	for (i = 0; i <= size && argc <= MAX_ARGS; i++) {
		if (i == size || copy[i] == '\0') {
			argv[argc++] = copy + start;
			start = i + 1;
		}
	}
	argv[argc] = NULL;
	err[0] = '\0';
	if (jm_options_parse(&o, argc, argv, err, sizeof(err)) == 0) {
		if (!o.help && !o.version &&
		    (o.particles < 1 || o.number < 0 || !(o.time_scale > 0.0) || !(o.warmup_s >= 0.0) ||
		     o.spin_us < 0 || (o.dataset && o.odometry) || (!o.odometry != !o.laser) ||
		     (!o.odometry != !o.real)))
			abort();
	} else if (strlen(err) == 0 || strchr(err, '\n') || strchr(err, '\r')) {
		abort(); /* a message is one non-empty line */
	}
	free(copy);
	return 0;
}
