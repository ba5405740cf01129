/*
 * Release engine. The dispatcher sleeps to each event's absolute release time
 * (clock_nanosleep TIMER_ABSTIME, as cyclictest does), records its wake-up and hands the
 * event to the handler thread of its task under the run's policy. The robot is one resource:
 * a handler starts a job only when no job is on it and its event is the oldest released one,
 * so jobs run one at a time in release order. Nothing is allocated or written to a file while
 * the run lasts (except what --memory allocating asks for); the records are preallocated.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <sched.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#include "clock.h"
#include "engine.h"
#include "record.h"

#define JM_DISPATCHER_PRIORITY 80
#define JM_HANDLER_PRIORITY 70
#define JM_THREAD_STACK (256 * 1024)
/* Time between setting the run start and its first release: lets the dispatcher thread get ready. */
#define JM_START_LEAD_NS 20000000LL

#if defined(__SANITIZE_ADDRESS__)
#define JM_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define JM_ASAN 1
#endif
#endif

/*
 * Seconds of the timeline as nanoseconds of the run. The reader and jm_dataset_check_time_scale
 * keep scaled times within JM_VALUE_MAX s (1e18 ns); the clamp (~73 years) is a second guard so
 * that sums cannot overflow.
 */
static int64_t scaled_ns(double seconds, double time_scale)
{
	double ns = seconds * time_scale * 1e9;

	return ns < 2.3e18 ? (int64_t)llround(ns) : (int64_t)2300000000000000000LL;
}

int jm_timeline_build(jm_timeline *tl, const jm_dataset *ds, double time_scale, double until_s,
		      int inclusive)
{
	const jm_series *odo = &ds->odometry, *las = &ds->laser;
	int io = 0, il = 0, k = 0, no = odo->n, nl = las->n, i;

	memset(tl, 0, sizeof(*tl));
	if (until_s >= 0.0) {
		while (no > 0 && (JM_ROW(odo, no - 1)[0] > until_s ||
				  (!inclusive && JM_ROW(odo, no - 1)[0] == until_s)))
			no--;
		while (nl > 0 && (JM_ROW(las, nl - 1)[0] > until_s ||
				  (!inclusive && JM_ROW(las, nl - 1)[0] == until_s)))
			nl--;
	}
	tl->n = no + nl;
	tl->ntask[JM_TASK_PREDICT] = no;
	tl->ntask[JM_TASK_UPDATE] = nl;
	tl->events = calloc((size_t)(tl->n ? tl->n : 1), sizeof(jm_event));
	tl->jobs = calloc((size_t)(tl->n ? tl->n : 1), sizeof(jm_job));
	if (!tl->events || !tl->jobs) {
		jm_timeline_free(tl);
		return -1;
	}
	while (io < no || il < nl) {
		jm_event *e = &tl->events[k++];

		if (il >= nl || (io < no && JM_ROW(odo, io)[0] <= JM_ROW(las, il)[0])) {
			const double *r = JM_ROW(odo, io);

			e->task = JM_TASK_PREDICT;
			e->index = io++;
			e->time = r[0];
			e->arg[0] = r[1];
			e->arg[1] = r[2];
			e->arg[2] = r[3];
			e->release_ns = scaled_ns(r[0], time_scale);
			e->deadline_ns = e->release_ns + scaled_ns(JM_PREDICT_DEADLINE_S, time_scale);
		} else {
			const double *r = JM_ROW(las, il);

			e->task = JM_TASK_UPDATE;
			e->index = il++;
			e->time = r[0];
			e->arg[0] = r[1];
			e->release_ns = scaled_ns(r[0], time_scale);
			/* the update's deadline is the next laser event's release */
			if (il < nl)
				e->deadline_ns = scaled_ns(JM_ROW(las, il)[0], time_scale);
			else
				e->deadline_ns = e->release_ns + scaled_ns(JM_LAST_UPDATE_DEADLINE_S, time_scale);
		}
	}
	for (i = 0; i < tl->n; i++) {
		jm_job *j = &tl->jobs[i];

		j->start_ns = j->end_ns = j->cpu_ns = j->wake_ns = j->abort_ns = j->seen_ns = -1;
		j->release_ns = tl->events[i].release_ns;
		j->deadline_ns = tl->events[i].deadline_ns;
		j->outcome = JM_OUTCOME_PENDING;
	}
	return 0;
}

int64_t jm_abort_from_ns(const jm_job *j)
{
	int64_t from;

	if (j->abort_ns < 0 || j->start_ns < 0 || j->end_ns < 0)
		return -1;
	from = j->abort_ns > j->start_ns ? j->abort_ns : j->start_ns;
	return from < j->end_ns ? from : -1;
}

int64_t jm_abort_seen_from_ns(const jm_job *j)
{
	int64_t from = jm_abort_from_ns(j);

	return from >= 0 && j->seen_ns >= from && j->seen_ns <= j->end_ns ? j->seen_ns : -1;
}

void jm_timeline_free(jm_timeline *tl)
{
	free(tl->events);
	free(tl->jobs);
	tl->events = NULL;
	tl->jobs = NULL;
	tl->n = 0;
}

static int run_job(jm_mcl *m, const jm_event *e, jm_abort *abort)
{
	if (e->task == JM_TASK_PREDICT)
		return jm_mcl_predict(m, e->arg[0], e->arg[1], e->arg[2], abort);
	return jm_mcl_update(m, e->arg[0], abort);
}

static void record_commit(const jm_mcl *m, jm_job *j)
{
	jm_mcl_estimate(m, &j->ex, &j->ey, &j->et);
	jm_mcl_covariance(m, j->cov);
}

static const char *policy_name(int policy)
{
	switch (policy) {
	case SCHED_FIFO:
		return "SCHED_FIFO";
	case SCHED_RR:
		return "SCHED_RR";
	case SCHED_BATCH:
		return "SCHED_BATCH";
	case SCHED_IDLE:
		return "SCHED_IDLE";
	default:
		return "SCHED_OTHER";
	}
}

void jm_lock_memory(jm_sched_info *info)
{
	info->mlocked = 0;
#ifdef JM_ASAN
	/* the sanitizer's shadow memory is terabytes of reserved address space */
	info->mlock_note = "not under AddressSanitizer";
#else
	if (mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
		info->mlocked = 1;
		info->mlock_note = NULL;
	} else {
		info->mlock_note = strerror(errno);
	}
#endif
}

int jm_run_ideal(jm_mcl *m, jm_timeline *tl, int cpu_time, jm_sched_info *info)
{
	struct sched_param sp;
	int64_t t0 = jm_now_ns();
	int k, pol = sched_getscheduler(0);
	jm_recorder rec;

	info->fifo = pol == SCHED_FIFO || pol == SCHED_RR;
	info->policy_name = policy_name(pol);
	info->dispatcher_priority = info->handler_priority =
		sched_getparam(0, &sp) == 0 ? sp.sched_priority : 0;
	jm_recorder_init(&rec, cpu_time, t0);
	rec.end = t0;
	for (k = 0; k < tl->n; k++) {
		jm_job *j = &tl->jobs[k];
		int r;

		jm_recorder_start(&rec);
		r = run_job(m, &tl->events[k], NULL);
		jm_recorder_end(&rec);
		if (r == JM_JOB_NOMEM)
			return -1;
		j->deadline_ns = -1;
		jm_recorder_record(&rec, j, 1); /* no deadline: done */
		j->release_ns = j->start_ns;
		record_commit(m, j);
	}
	info->duration_ns = rec.end - t0;
	return 0;
}

struct engine;

struct handler {
	struct engine *e;
	enum jm_task task;
};

struct engine {
	pthread_mutex_t lock;
	pthread_cond_t cond[2];   /* one a handler */
	jm_mcl *m;
	jm_timeline *tl;
	enum jm_policy policy;
	int64_t t0;
	int64_t spin_ns;
	int cpu_time;             /* the handlers read the thread CPU clock per job */
	struct jm_robot robot;    /* what the policy decides on (policy.h) */
	int dispatch_done;
	int failed;
	int dispatcher_policy, dispatcher_priority;
};

/* Under the lock: whether nothing is waiting and nothing more will be released. */
static int drained(const struct engine *e)
{
	return e->dispatch_done && e->robot.head == e->robot.tail;
}

/* Under the lock: whether the handler of task may start the robot's next event now. */
static int ready_for(const struct engine *e, enum jm_task task)
{
	int k = jm_robot_next(&e->robot);

	return k >= 0 && e->tl->events[k].task == task;
}

/* Under the lock: wakes whoever can make progress. */
static void wake_next(struct engine *e)
{
	int k = jm_robot_next(&e->robot);

	if (drained(e)) {
		pthread_cond_signal(&e->cond[0]);
		pthread_cond_signal(&e->cond[1]);
	} else if (k >= 0) {
		pthread_cond_signal(&e->cond[e->tl->events[k].task]);
	}
}

static void *handler_main(void *arg)
{
	struct handler *h = arg;
	struct engine *e = h->e;
	jm_recorder rec;

	jm_recorder_init(&rec, e->cpu_time, 0);
	pthread_mutex_lock(&e->lock);
	for (;;) {
		jm_job *j;
		int64_t seen;
		int k, r;

		while (!ready_for(e, h->task) && !drained(e))
			pthread_cond_wait(&e->cond[h->task], &e->lock);
		if (!ready_for(e, h->task))
			break;
		k = jm_robot_start(&e->robot);
		rec.t0 = e->t0;
		pthread_mutex_unlock(&e->lock);

		jm_recorder_start(&rec);
		r = run_job(e->m, &e->tl->events[k], &e->robot.abort);
		jm_recorder_end(&rec);

		pthread_mutex_lock(&e->lock);
		j = &e->tl->jobs[k];
		seen = e->robot.abort.seen_ns; /* the next job resets it */
		if (r == JM_JOB_NOMEM)
			e->failed = 1;
		else if (r == JM_JOB_DONE)
			record_commit(e->m, j); /* before the next job moves the particles */
		jm_robot_end(&e->robot);
		wake_next(e);
		pthread_mutex_unlock(&e->lock);

		/* after the hand-over, so that the CPU clock's second read keeps no job waiting; only
		 * this thread writes these fields of job k (the dispatcher may write its abort_ns) */
		jm_recorder_record(&rec, j, r == JM_JOB_DONE);
		j->seen_ns = seen >= 0 ? seen - rec.t0 : -1;
		pthread_mutex_lock(&e->lock);
	}
	pthread_mutex_unlock(&e->lock);
	return NULL;
}

static void sleep_until(int64_t target, int64_t spin_ns)
{
	int64_t park = target - spin_ns;
	struct timespec ts = { .tv_sec = park / 1000000000LL, .tv_nsec = park % 1000000000LL };

	while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR)
		;
	if (spin_ns > 0)
		while (jm_now_ns() < target)
			;
}

static void *dispatcher_main(void *arg)
{
	struct engine *e = arg;
	struct sched_param sp;
	int k;

	if (pthread_getschedparam(pthread_self(), &e->dispatcher_policy, &sp) == 0)
		e->dispatcher_priority = sp.sched_priority;
	for (k = 0; k < e->tl->n;) {
		int64_t wake;
		int end = k + 1;

		sleep_until(e->t0 + e->tl->events[k].release_ns, e->spin_ns);
		wake = jm_now_ns();
		/*
		 * Events of one release instant are decided under one hold of the lock, in timeline
		 * order, so that none of them has started when the next is decided (the Java engines'
		 * rule, docs/RELEASE-ENGINE.md "Events at the same time").
		 */
		while (end < e->tl->n && e->tl->events[end].release_ns == e->tl->events[k].release_ns)
			end++;
		pthread_mutex_lock(&e->lock);
		for (; k < end; k++) {
			e->tl->jobs[k].wake_ns = wake - e->t0;
			jm_policy_release(e->policy, &e->robot, k, wake - e->t0);
		}
		wake_next(e);
		pthread_mutex_unlock(&e->lock);
	}
	pthread_mutex_lock(&e->lock);
	e->dispatch_done = 1;
	wake_next(e);
	pthread_mutex_unlock(&e->lock);
	return NULL;
}

static void *probe_main(void *arg)
{
	return arg;
}

/* Thread attributes: a small stack and, when fifo, SCHED_FIFO at the given priority. */
static int make_attr(pthread_attr_t *attr, int fifo, int priority)
{
	struct sched_param sp = { .sched_priority = priority };

	if (pthread_attr_init(attr))
		return -1;
	pthread_attr_setstacksize(attr, JM_THREAD_STACK);
	if (fifo) {
		if (pthread_attr_setinheritsched(attr, PTHREAD_EXPLICIT_SCHED) ||
		    pthread_attr_setschedpolicy(attr, SCHED_FIFO) ||
		    pthread_attr_setschedparam(attr, &sp)) {
			pthread_attr_destroy(attr);
			return -1;
		}
	}
	return 0;
}

/* Whether this process may create SCHED_FIFO threads: tried once with a thread that exits. */
static int fifo_permitted(void)
{
	pthread_attr_t attr;
	pthread_t t;
	int ok;

	if (make_attr(&attr, 1, JM_HANDLER_PRIORITY))
		return 0;
	ok = pthread_create(&t, &attr, probe_main, NULL) == 0;
	pthread_attr_destroy(&attr);
	if (ok)
		pthread_join(t, NULL);
	return ok;
}

int jm_run_realtime(jm_mcl *m, jm_timeline *tl, enum jm_policy policy, int spin_us, int fifo,
		    int cpu_time, jm_sched_info *info)
{
	struct engine e;
	struct handler h[2];
	pthread_t th[3];
	pthread_attr_t attr;
	int created = 0, ret = -1, i, pmin, pmax, *waiting;

	memset(&e, 0, sizeof(e));
	e.m = m;
	e.tl = tl;
	e.policy = policy;
	e.spin_ns = (int64_t)spin_us * 1000;
	e.cpu_time = cpu_time;
	waiting = malloc(sizeof(int) * (size_t)(tl->n ? tl->n : 1));
	if (!waiting)
		return -1;
	jm_robot_init(&e.robot, waiting, tl->jobs);
	pthread_mutex_init(&e.lock, NULL);
	pthread_cond_init(&e.cond[0], NULL);
	pthread_cond_init(&e.cond[1], NULL);

	info->fifo_requested = fifo;
	info->fifo = fifo && fifo_permitted();
	pmin = sched_get_priority_min(SCHED_FIFO);
	pmax = sched_get_priority_max(SCHED_FIFO);
	info->dispatcher_priority = JM_DISPATCHER_PRIORITY < pmax ? JM_DISPATCHER_PRIORITY : pmax;
	info->handler_priority = JM_HANDLER_PRIORITY > pmin ? JM_HANDLER_PRIORITY : pmin;

	e.t0 = jm_now_ns() + JM_START_LEAD_NS; /* for the failure paths; set again below */
	for (i = 0; i < 2; i++) {
		h[i].e = &e;
		h[i].task = (enum jm_task)i;
		if (make_attr(&attr, info->fifo, info->handler_priority))
			goto out;
		if (pthread_create(&th[i], &attr, handler_main, &h[i])) {
			pthread_attr_destroy(&attr);
			goto out;
		}
		pthread_attr_destroy(&attr);
		created++;
	}
	if (make_attr(&attr, info->fifo, info->dispatcher_priority))
		goto out;
	/*
	 * The run starts once the handlers exist, so that their stacks are allocated before it even
	 * when creating them takes longer than the lead on a busy machine; only the dispatcher's own
	 * creation falls in the lead. The handlers read t0 only under the lock, after a job the
	 * dispatcher (created after this store) released.
	 */
	e.t0 = jm_now_ns() + JM_START_LEAD_NS;
	if (pthread_create(&th[2], &attr, dispatcher_main, &e)) {
		pthread_attr_destroy(&attr);
		goto out;
	}
	pthread_attr_destroy(&attr);
	created++;
	ret = 0;
out:
	if (created < 3) {
		/* no dispatcher: tell the handlers there is nothing to come */
		pthread_mutex_lock(&e.lock);
		e.dispatch_done = 1;
		e.robot.head = e.robot.tail;
		wake_next(&e);
		pthread_mutex_unlock(&e.lock);
	}
	for (i = 0; i < created; i++)
		pthread_join(th[i], NULL);
	info->duration_ns = jm_now_ns() - e.t0;
	info->policy_name = policy_name(e.dispatcher_policy);
	if (!info->fifo)
		info->dispatcher_priority = info->handler_priority = e.dispatcher_priority;
	if (e.failed)
		ret = -1;
	pthread_cond_destroy(&e.cond[0]);
	pthread_cond_destroy(&e.cond[1]);
	pthread_mutex_destroy(&e.lock);
	free(waiting);
	return ret;
}
