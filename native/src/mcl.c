/*
 * The particle filter: the same arithmetic in the same order as the Java workload, so that
 * generator-only results are bit-identical and the rest agrees within the math library's ulps.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "angles.h"
#include "clock.h"
#include "mcl.h"

void jm_playground_default(jm_playground *pg)
{
	memset(pg, 0, sizeof(*pg));
	pg->width = 3.0;
	pg->height = 2.0;
	pg->nbeacons = 3;
	pg->beacon[0][0] = 0.0;
	pg->beacon[0][1] = 1.0;
	pg->beacon[1][0] = 3.0;
	pg->beacon[1][1] = 0.0;
	pg->beacon[2][0] = 3.0;
	pg->beacon[2][1] = 2.0;
}

static inline int abort_requested(jm_abort *abort)
{
	if (!abort || !atomic_load_explicit(&abort->requested, memory_order_relaxed))
		return 0;
	if (abort->seen_ns < 0)
		abort->seen_ns = jm_now_ns();
	return 1;
}

static void particles_free(jm_particles *p)
{
	free(p->x);
	free(p->y);
	free(p->th);
	free(p->w);
	memset(p, 0, sizeof(*p));
}

static int particles_alloc(jm_particles *p, int n)
{
	p->x = malloc(sizeof(double) * (size_t)n);
	p->y = malloc(sizeof(double) * (size_t)n);
	p->th = malloc(sizeof(double) * (size_t)n);
	p->w = malloc(sizeof(double) * (size_t)n);
	if (!p->x || !p->y || !p->th || !p->w) {
		particles_free(p);
		return -1;
	}
	return 0;
}

static void scratch_free(jm_mcl *m)
{
	free(m->lw);
	free(m->cum);
	free(m->idx);
	m->lw = NULL;
	m->cum = NULL;
	m->idx = NULL;
}

static int scratch_alloc(jm_mcl *m)
{
	size_t n = (size_t)m->n;

	m->lw = malloc(sizeof(double) * n);
	m->cum = malloc(sizeof(double) * n);
	m->idx = malloc(sizeof(int) * n);
	if (!m->lw || !m->cum || !m->idx) {
		scratch_free(m);
		return -1;
	}
	return 0;
}

/*
 * Gives a job its work buffer. Preallocated: the second buffer, no allocation. Allocating:
 * new arrays for this job (and new scratch), the garbage a straightforward program makes.
 */
static jm_particles *job_begin(jm_mcl *m)
{
	jm_particles *dst = &m->buf[1 - m->cur];

	if (m->memory == JM_MEMORY_ALLOCATING) {
		if (particles_alloc(dst, m->n) < 0)
			return NULL;
		if (scratch_alloc(m) < 0) {
			particles_free(dst);
			return NULL;
		}
	}
	m->work_rng = m->rng;
	return dst;
}

/*
 * Ends a job: swaps the work buffer in when it completed. Allocating: frees the buffer no longer
 * in use (the old one when the job completed, the job's own when it did not) and the scratch.
 */
static void job_end(jm_mcl *m, int commit)
{
	int work = 1 - m->cur;

	if (commit) {
		m->rng = m->work_rng;
		m->cur = work;
		work = 1 - work;
	}
	if (m->memory == JM_MEMORY_ALLOCATING) {
		particles_free(&m->buf[work]);
		scratch_free(m);
	}
}

int jm_mcl_init(jm_mcl *m, const jm_mcl_config *cfg, const jm_playground *pg)
{
	jm_particles *p;
	int n = cfg->particles, i;

	memset(m, 0, sizeof(*m));
	m->n = n;
	m->memory = cfg->memory;
	m->estimate_kind = cfg->estimate;
	m->resample_kind = cfg->resample;
	m->covariance = cfg->covariance;
	m->pg = *pg;
	if (n <= 0 || particles_alloc(&m->buf[0], n) < 0)
		goto fail;
	if (m->memory == JM_MEMORY_PREALLOCATED &&
	    (particles_alloc(&m->buf[1], n) < 0 || scratch_alloc(m) < 0))
		goto fail;
	jm_rng_seed(&m->rng, cfg->seed);
	p = &m->buf[0];
	if (cfg->init == JM_INIT_KNOWN) {
		for (i = 0; i < n; i++) {
			p->x[i] = cfg->start_x + JM_INIT_SPREAD * jm_rng_gaussian(&m->rng);
			p->y[i] = cfg->start_y + JM_INIT_SPREAD * jm_rng_gaussian(&m->rng);
			p->th[i] = jm_wrap2pi(cfg->start_theta + JM_INIT_SPREAD * jm_rng_gaussian(&m->rng));
		}
		m->ex = cfg->start_x;
		m->ey = cfg->start_y;
		m->et = jm_wrap2pi(cfg->start_theta); /* headings are reported in [0, 2pi) */
	} else {
		for (i = 0; i < n; i++) {
			p->x[i] = pg->width * jm_rng_uniform(&m->rng);
			p->y[i] = pg->height * jm_rng_uniform(&m->rng);
			p->th[i] = JM_TWO_PI * jm_rng_uniform(&m->rng);
		}
		m->ex = pg->width / 2.0;
		m->ey = pg->height / 2.0;
		m->et = 0.0;
	}
	for (i = 0; i < n; i++)
		p->w[i] = 1.0 / n;
	m->work_rng = m->rng;
	return 0;
fail:
	jm_mcl_free(m);
	return -1;
}

void jm_mcl_free(jm_mcl *m)
{
	particles_free(&m->buf[0]);
	particles_free(&m->buf[1]);
	scratch_free(m);
}

int jm_mcl_predict(jm_mcl *m, double dx, double dy, double dth, jm_abort *abort)
{
	const jm_particles *src = &m->buf[m->cur];
	jm_particles *dst;
	double d, sxy, sth, c, s, nx, ny, nt;
	int i, n = m->n;

	dst = job_begin(m);
	if (!dst)
		return JM_JOB_NOMEM;
	d = sqrt(dx * dx + dy * dy);
	sxy = JM_ALPHA_XY * d + JM_FLOOR_XY;
	sth = JM_ALPHA_THETA * fabs(dth) + JM_ALPHA_THETA_XY * d + JM_FLOOR_THETA;

	c = cos(m->et);
	s = sin(m->et);
	nx = m->ex + (dx * c - dy * s);
	ny = m->ey + (dx * s + dy * c);
	nt = jm_wrap2pi(m->et + dth);

	for (i = 0; i < n; i++) {
		double ndx, ndy, ndt;

		if (i % JM_ABORT_BLOCK == 0 && abort_requested(abort)) {
			job_end(m, 0);
			return JM_JOB_ABORTED;
		}
		ndx = dx + sxy * jm_rng_gaussian(&m->work_rng);
		ndy = dy + sxy * jm_rng_gaussian(&m->work_rng);
		ndt = dth + sth * jm_rng_gaussian(&m->work_rng);
		c = cos(src->th[i]);
		s = sin(src->th[i]);
		dst->x[i] = src->x[i] + (ndx * c - ndy * s);
		dst->y[i] = src->y[i] + (ndx * s + ndy * c);
		dst->th[i] = jm_wrap2pi(src->th[i] + ndt);
		dst->w[i] = src->w[i];
	}
	m->ex = nx;
	m->ey = ny;
	m->et = nt;
	job_end(m, 1);
	return JM_JOB_DONE;
}

double jm_likelihood(double x, double y, double th, double angle, const jm_playground *pg)
{
	double sum = 0.0;
	int b;

	for (b = 0; b < pg->nbeacons; b++) {
		double d = jm_wrappi(jm_bearing(x, y, th, pg->beacon[b][0], pg->beacon[b][1]) - angle);

		sum = sum + exp(-(d * d) / (2.0 * JM_SIGMA_LASER * JM_SIGMA_LASER));
	}
	return sum;
}

int jm_resample_systematic_abortable(const double *w, int n, double u, int *out_idx,
				     jm_abort *abort)
{
	double c = w[0];
	int i = 0, k = 0;
	long step;

	/* One loop walks both sequences, as the Java one: each step passes an old particle or places
	 * a new one, so no block of JM_ABORT_BLOCK steps between two polls walks all N. */
	for (step = 0; k < n; step++) {
		double t;

		if (step % JM_ABORT_BLOCK == 0 && abort_requested(abort))
			return 1;
		t = u + (double)k / (double)n;
		if (t > c && i < n - 1) {
			i = i + 1;
			c = c + w[i];
		} else {
			out_idx[k] = i;
			k = k + 1;
		}
	}
	return 0;
}

int jm_resample_multinomial_abortable(const double *w, int n, jm_rng *r, double *cum,
				      int *out_idx, jm_abort *abort)
{
	double acc = 0.0;
	int k;

	for (k = 0; k < n; k++) {
		if (k % JM_ABORT_BLOCK == 0 && abort_requested(abort))
			return 1;
		acc = acc + w[k];
		cum[k] = acc;
	}
	for (k = 0; k < n; k++) {
		double t;
		int lo = 0, hi = n;

		if (k % JM_ABORT_BLOCK == 0 && abort_requested(abort))
			return 1;
		t = jm_rng_uniform(r);
		/* the smallest index with t < cum[index] */
		while (lo < hi) {
			int mid = lo + (hi - lo) / 2;

			if (t < cum[mid])
				hi = mid;
			else
				lo = mid + 1;
		}
		out_idx[k] = lo < n ? lo : n - 1;
	}
	return 0;
}

void jm_resample_systematic(const double *w, int n, double u, int *out_idx)
{
	jm_resample_systematic_abortable(w, n, u, out_idx, NULL);
}

void jm_resample_multinomial(const double *w, int n, jm_rng *r, int *out_idx)
{
	double *cum = malloc(sizeof(double) * (size_t)(n > 0 ? n : 1));

	if (!cum)
		abort();
	jm_resample_multinomial_abortable(w, n, r, cum, out_idx, NULL);
	free(cum);
}

/* Weighted mean (circular for theta) or best particle, from normalised weights. */
static void choose_estimate(const jm_mcl *m, const jm_particles *p, const double *w,
			    double *ex, double *ey, double *et)
{
	int i, n = m->n;

	if (m->estimate_kind == JM_ESTIMATE_BEST) {
		int best = 0;

		for (i = 1; i < n; i++)
			if (w[i] > w[best])
				best = i;
		*ex = p->x[best];
		*ey = p->y[best];
		*et = p->th[best];
	} else {
		double sx = 0.0, sy = 0.0, ss = 0.0, sc = 0.0;

		for (i = 0; i < n; i++) {
			sx = sx + w[i] * p->x[i];
			sy = sy + w[i] * p->y[i];
			ss = ss + w[i] * sin(p->th[i]);
			sc = sc + w[i] * cos(p->th[i]);
		}
		*ex = sx;
		*ey = sy;
		*et = jm_wrap2pi(atan2(ss, sc));
	}
}

static void weighted_covariance(const jm_mcl *m, const jm_particles *p, const double *w,
				double ex, double ey, double et, double cov[6])
{
	double cxx = 0.0, cxy = 0.0, cxt = 0.0, cyy = 0.0, cyt = 0.0, ctt = 0.0;
	int i;

	for (i = 0; i < m->n; i++) {
		double ux = p->x[i] - ex, uy = p->y[i] - ey, ut = jm_wrappi(p->th[i] - et);

		cxx = cxx + w[i] * ux * ux;
		cxy = cxy + w[i] * ux * uy;
		cxt = cxt + w[i] * ux * ut;
		cyy = cyy + w[i] * uy * uy;
		cyt = cyt + w[i] * uy * ut;
		ctt = ctt + w[i] * ut * ut;
	}
	cov[0] = cxx;
	cov[1] = cxy;
	cov[2] = cxt;
	cov[3] = cyy;
	cov[4] = cyt;
	cov[5] = ctt;
}

int jm_mcl_update(jm_mcl *m, double a, jm_abort *abort)
{
	const jm_particles *src = &m->buf[m->cur];
	jm_particles *dst;
	double total = 0.0, ex, ey, et, cov[6] = { 0 };
	int i, n = m->n, aborted;

	dst = job_begin(m);
	if (!dst)
		return JM_JOB_NOMEM;
	for (i = 0; i < n; i++) {
		if (i % JM_ABORT_BLOCK == 0 && abort_requested(abort))
			goto aborted;
		m->lw[i] = jm_likelihood(src->x[i], src->y[i], src->th[i], a, &m->pg);
	}
	for (i = 0; i < n; i++)
		total = total + m->lw[i];
	if (total == 0.0 || !isfinite(total)) {
		for (i = 0; i < n; i++)
			m->lw[i] = 1.0 / n;
	} else {
		for (i = 0; i < n; i++)
			m->lw[i] = m->lw[i] / total;
	}
	choose_estimate(m, src, m->lw, &ex, &ey, &et);
	if (m->covariance)
		weighted_covariance(m, src, m->lw, ex, ey, et, cov);

	if (m->resample_kind == JM_RESAMPLE_MULTINOMIAL)
		aborted = jm_resample_multinomial_abortable(m->lw, n, &m->work_rng, m->cum, m->idx, abort);
	else
		aborted = jm_resample_systematic_abortable(m->lw, n, jm_rng_uniform(&m->work_rng) / n,
							   m->idx, abort);
	if (aborted)
		goto aborted;
	for (i = 0; i < n; i++) {
		int k = m->idx[i];

		if (i % JM_ABORT_BLOCK == 0 && abort_requested(abort))
			goto aborted;
		dst->x[i] = src->x[k];
		dst->y[i] = src->y[k];
		dst->th[i] = src->th[k];
		dst->w[i] = 1.0 / n;
	}
	m->ex = ex;
	m->ey = ey;
	m->et = et;
	if (m->covariance)
		memcpy(m->cov, cov, sizeof(cov));
	job_end(m, 1);
	return JM_JOB_DONE;
aborted:
	job_end(m, 0);
	return JM_JOB_ABORTED;
}

void jm_mcl_estimate(const jm_mcl *m, double *x, double *y, double *th)
{
	*x = m->ex;
	*y = m->ey;
	*th = m->et;
}

void jm_mcl_covariance(const jm_mcl *m, double cov[6])
{
	memcpy(cov, m->cov, sizeof(m->cov));
}

const jm_particles *jm_mcl_particles(const jm_mcl *m)
{
	return &m->buf[m->cur];
}
