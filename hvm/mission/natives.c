/*
 * The natives of the jmclbench mission on the icecap HVM (org.jmclbench.hvm.HvmData) and the
 * java.lang.StrictMath natives the VM lacks (atan2, exp, pow).
 *
 * Calling convention of the VM: arguments arrive in sp[0], sp[1], ...; an int or a reference
 * takes one slot, a long or a double two. A long is stored most significant word first, a
 * double in the machine's order. The result is written from sp[0]; returning -1 means "no
 * exception".
 *
 * Files are 64-bit little-endian words (docs/HVM.md); doubles are their raw IEEE 754 bits.
 * Both are read and written outside the mission's measured window (before the launch, after
 * the mission ends).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ostypes.h"

static uint64_t *input;
static int32 inputWords;
static uint64_t *output;
static size_t outputWords;
static size_t outputCapacity;

static uint64_t getLong(const int32 *sp)
{
	return ((uint64_t) (uint32_t) sp[0] << 32) | (uint32_t) sp[1];
}

static void setLong(int32 *sp, uint64_t v)
{
	sp[0] = (int32) (uint32_t) (v >> 32);
	sp[1] = (int32) (uint32_t) v;
}

static double getDouble(const int32 *sp)
{
	double d;
	memcpy(&d, sp, sizeof d);
	return d;
}

static void setDouble(int32 *sp, double d)
{
	memcpy(sp, &d, sizeof d);
}

/* int open() */
int16 n_org_jmclbench_hvm_HvmData_open(int32 *sp)
{
	const char *name = getenv("JMCLBENCH_HVM_INPUT");
	FILE *f;
	long bytes;

	sp[0] = -1;
	if (name == NULL || (f = fopen(name, "rb")) == NULL)
		return -1;
	if (fseek(f, 0, SEEK_END) == 0 && (bytes = ftell(f)) > 0 && bytes % 8 == 0
			&& bytes / 8 < INT32_MAX && fseek(f, 0, SEEK_SET) == 0) {
		input = malloc((size_t) bytes);
		if (input != NULL && fread(input, 1, (size_t) bytes, f) == (size_t) bytes) {
			inputWords = (int32) (bytes / 8);
			sp[0] = inputWords;
		}
	}
	fclose(f);
	return -1;
}

/* long word(int i): out of range reads 0 (the Java side checks the counts it reads) */
int16 n_org_jmclbench_hvm_HvmData_word(int32 *sp)
{
	int32 i = sp[0];
	setLong(sp, (i >= 0 && i < inputWords) ? input[i] : 0);
	return -1;
}

/* double real(int i) */
int16 n_org_jmclbench_hvm_HvmData_real(int32 *sp)
{
	int32 i = sp[0];
	uint64_t bits = (i >= 0 && i < inputWords) ? input[i] : 0;
	double d;
	memcpy(&d, &bits, sizeof d);
	setDouble(sp, d);
	return -1;
}

static void append(uint64_t w)
{
	if (outputWords == outputCapacity) {
		size_t n = outputCapacity ? 2 * outputCapacity : 4096;
		uint64_t *grown = realloc(output, n * sizeof *output);
		if (grown == NULL) {
			fprintf(stderr, "hvm: out of C memory for the job records\n");
			exit(1);
		}
		output = grown;
		outputCapacity = n;
	}
	output[outputWords++] = w;
}

/* void put(long value) */
int16 n_org_jmclbench_hvm_HvmData_put(int32 *sp)
{
	append(getLong(sp));
	return -1;
}

/* void putReal(double value) */
int16 n_org_jmclbench_hvm_HvmData_putReal(int32 *sp)
{
	double d = getDouble(sp);
	uint64_t bits;
	memcpy(&bits, &d, sizeof bits);
	append(bits);
	return -1;
}

/* int finish() */
int16 n_org_jmclbench_hvm_HvmData_finish(int32 *sp)
{
	const char *name = getenv("JMCLBENCH_HVM_OUTPUT");
	FILE *f;

	sp[0] = -1;
	if (name == NULL || (f = fopen(name, "wb")) == NULL)
		return -1;
	if (fwrite(output, sizeof *output, outputWords, f) == outputWords && fclose(f) == 0)
		sp[0] = 0;
	return -1;
}

/* void fail(int code) */
int16 n_org_jmclbench_hvm_HvmData_fail(int32 *sp)
{
	static const char *const messages[] = {
		"unknown failure",
		"cannot read the run file (JMCLBENCH_HVM_INPUT) or it is not a jmclbench run file",
		"the mission ended without handing over its job records",
		"cannot write the result file (JMCLBENCH_HVM_OUTPUT)",
	};
	int32 code = sp[0];
	if (code < 0 || code >= (int32) (sizeof messages / sizeof messages[0]))
		code = 0;
	fprintf(stderr, "hvm: %s\n", messages[code]);
	return -1;
}

/* StrictMath natives the VM does not have (the C library's, as HotSpot's intrinsics are close to) */
int16 n_java_lang_StrictMath_atan2(int32 *sp)
{
	setDouble(sp, atan2(getDouble(sp), getDouble(sp + 2)));
	return -1;
}

int16 n_java_lang_StrictMath_exp(int32 *sp)
{
	setDouble(sp, exp(getDouble(sp)));
	return -1;
}

int16 n_java_lang_StrictMath_pow(int32 *sp)
{
	setDouble(sp, pow(getDouble(sp), getDouble(sp + 2)));
	return -1;
}
