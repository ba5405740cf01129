/* The project's random generator: xoshiro256** seeded with splitmix64 (docs/ALGORITHM.md 1, 2). */
#ifndef JM_RNG_H
#define JM_RNG_H

#include <stdint.h>

/* Generator state: the four 64-bit words of xoshiro256**; copy it by assignment. */
typedef struct {
	uint64_t s[4];
} jm_rng;

/* Seeds the four words from four successive splitmix64 outputs of seed. */
void jm_rng_seed(jm_rng *r, uint64_t seed);
/* The next 64 random bits. */
uint64_t jm_rng_next(jm_rng *r);
/* A double uniform in [0, 1): the top 53 bits of next() times 2^-53. */
double jm_rng_uniform(jm_rng *r);
/* Approximately standard normal: twelve uniforms summed, minus six (Irwin-Hall). */
double jm_rng_gaussian(jm_rng *r);

#endif
