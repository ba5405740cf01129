/* Monte-Carlo Localization exactly as docs/ALGORITHM.md sections 4 to 9 define it. */
#ifndef JM_MCL_H
#define JM_MCL_H

#include <stdatomic.h>
#include <stdint.h>

#include "rng.h"

#define JM_MAX_BEACONS 32

/* Motion model (ALGORITHM.md 6) and laser model (7) constants. */
#define JM_ALPHA_XY 0.10
#define JM_FLOOR_XY 0.002
#define JM_ALPHA_THETA 0.10
#define JM_ALPHA_THETA_XY 0.05
#define JM_FLOOR_THETA 0.004
#define JM_SIGMA_LASER 0.05
#define JM_INIT_SPREAD 0.05

/* A job checks its abort request before every block of this many particles. */
#define JM_ABORT_BLOCK 64

/* The field: its size and the beacons in the order the likelihood sums them. */
typedef struct {
	double width;
	double height;
	int nbeacons;
	double beacon[JM_MAX_BEACONS][2];
} jm_playground;

/* The thesis's field: 3 m x 2 m, beacons (0, 1), (3, 0), (3, 2). */
void jm_playground_default(jm_playground *pg);

enum jm_memory { JM_MEMORY_PREALLOCATED, JM_MEMORY_ALLOCATING };
enum jm_estimate { JM_ESTIMATE_MEAN, JM_ESTIMATE_BEST };
enum jm_resample { JM_RESAMPLE_SYSTEMATIC, JM_RESAMPLE_MULTINOMIAL };
enum jm_init { JM_INIT_KNOWN, JM_INIT_UNIFORM };

/* What a filter is built with. */
typedef struct {
	int particles;
	enum jm_memory memory;
	enum jm_estimate estimate;
	enum jm_resample resample;
	enum jm_init init;
	int covariance;
	uint64_t seed;
	double start_x, start_y, start_theta; /* the known start pose */
} jm_mcl_config;

/* One particle set: structure of arrays. */
typedef struct {
	double *x, *y, *th, *w;
} jm_particles;

/*
 * The robot state (particles, estimate, generator) and the scratch a job works in. A job
 * writes into buf[1 - cur], a copy of the generator and local estimate values; only a job
 * that completes commits them, so an aborted job changes nothing (ALGORITHM.md 8).
 */
typedef struct {
	int n;
	enum jm_memory memory;
	enum jm_estimate estimate_kind;
	enum jm_resample resample_kind;
	int covariance;
	jm_playground pg;
	jm_particles buf[2];
	int cur;
	double *lw;   /* likelihood weights of the update in progress */
	double *cum;  /* cumulative weights (multinomial) */
	int *idx;     /* resampling choice */
	jm_rng rng;
	jm_rng work_rng;
	double ex, ey, et;
	double cov[6]; /* cxx cxy cxt cyy cyt ctt of the last completed update */
} jm_mcl;

/*
 * The abort request a job polls (terminate): set by the dispatcher; the first poll that sees it
 * notes when (seen_ns, jm_now_ns), which splits the abort latency into noticing and stopping.
 */
typedef struct {
	atomic_int requested;
	int64_t seen_ns; /* -1 until a poll saw the request; written by the job's thread only */
} jm_abort;

/* Results of jm_mcl_predict / jm_mcl_update. */
enum { JM_JOB_DONE = 0, JM_JOB_ABORTED = 1, JM_JOB_NOMEM = -1 };

/* Allocates and initialises the filter (ALGORITHM.md 5); returns 0, or -1 when out of memory. */
int jm_mcl_init(jm_mcl *m, const jm_mcl_config *cfg, const jm_playground *pg);
/* Frees everything jm_mcl_init allocated; safe on a zeroed or freed filter. */
void jm_mcl_free(jm_mcl *m);
/* An odometry job: JM_JOB_DONE, JM_JOB_ABORTED when abort->requested was seen set, or JM_JOB_NOMEM. */
int jm_mcl_predict(jm_mcl *m, double dx, double dy, double dth, jm_abort *abort);
/* A laser job for the measured angle a; results as jm_mcl_predict. abort may be NULL. */
int jm_mcl_update(jm_mcl *m, double a, jm_abort *abort);
/* The committed estimate. */
void jm_mcl_estimate(const jm_mcl *m, double *x, double *y, double *th);
/* The covariance of the last completed update (zeros before the first; needs covariance). */
void jm_mcl_covariance(const jm_mcl *m, double cov[6]);
/* The committed particles (valid until the next completed job). */
const jm_particles *jm_mcl_particles(const jm_mcl *m);

/* Unnormalised likelihood of a particle for the measured angle: the sum over beacons. */
double jm_likelihood(double x, double y, double th, double angle, const jm_playground *pg);

/*
 * Systematic resampling of n normalised weights: u is the offset in [0, 1/n), i.e.
 * uniform() / n as ALGORITHM.md 7.5 draws it; out_idx[m] is the old particle new m copies.
 */
void jm_resample_systematic(const double *w, int n, double u, int *out_idx);
/* Multinomial resampling: n uniforms from r; out_idx as above. Allocates a scratch array. */
void jm_resample_multinomial(const double *w, int n, jm_rng *r, int *out_idx);

/* The same two with abort checks and caller scratch; return 1 when aborted, else 0. */
int jm_resample_systematic_abortable(const double *w, int n, double u, int *out_idx,
				     jm_abort *abort);
int jm_resample_multinomial_abortable(const double *w, int n, jm_rng *r, double *cum,
				      int *out_idx, jm_abort *abort);

#endif
