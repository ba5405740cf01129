/* xoshiro256** (Blackman and Vigna, 2018) and the Irwin-Hall Gaussian, bit-identical to mcl/Rng.java. */
#include "rng.h"

static uint64_t splitmix64(uint64_t *state)
{
	uint64_t z;

	*state += 0x9E3779B97F4A7C15ULL;
	z = *state;
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
	return z ^ (z >> 31);
}

static inline uint64_t rotl(uint64_t x, int k)
{
	return (x << k) | (x >> (64 - k));
}

void jm_rng_seed(jm_rng *r, uint64_t seed)
{
	uint64_t sm = seed;
	int i;

	for (i = 0; i < 4; i++)
		r->s[i] = splitmix64(&sm);
}

uint64_t jm_rng_next(jm_rng *r)
{
	uint64_t *s = r->s;
	uint64_t result = rotl(s[1] * 5, 7) * 9;
	uint64_t t = s[1] << 17;

	s[2] ^= s[0];
	s[3] ^= s[1];
	s[1] ^= s[2];
	s[0] ^= s[3];
	s[2] ^= t;
	s[3] = rotl(s[3], 45);
	return result;
}

double jm_rng_uniform(jm_rng *r)
{
	return (double)(jm_rng_next(r) >> 11) * 0x1.0p-53;
}

double jm_rng_gaussian(jm_rng *r)
{
	double s = 0.0;
	int i;

	for (i = 0; i < 12; i++)
		s = s + jm_rng_uniform(r);
	return s - 6.0;
}
