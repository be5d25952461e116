/* A load step's clock: its time limit (solver.max_step_seconds) and the progress of a step that
 * runs far longer than the run's others, so that no step runs for minutes without a word. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "core/number.h"
#include "run/run.h"

/* A step reports its progress once it has run LONG_FACTOR times the median of the run's earlier
 * steps and at least LONG_SECONDS, then every REPORT_EVERY seconds. */
static const double LONG_FACTOR = 10, LONG_SECONDS = 10, REPORT_EVERY = 5;

void gb_run_on_progress(gb_run *run, gb_progress_fn fn, void *user)
{
    run->watch.fn = fn;
    run->watch.user = user;
}

void gb_run_watch_step(gb_run *run, double now)
{
    gb_step_watch *w = &run->watch;
    w->t0 = now;
    w->limit = run->sim->scene->solver.max_step_seconds;
    w->max_force = NAN;
    w->median = gb_median(w->seconds, w->n); /* sorted in place: their order is not needed */
    w->report_after = fmax(LONG_SECONDS, LONG_FACTOR * w->median);
    w->report_every = REPORT_EVERY;
    /* a test hook: GB_TEST_PROGRESS_SECONDS=s reports every step after s seconds, then every s */
    const char *test = getenv("GB_TEST_PROGRESS_SECONDS");
    if (test) w->report_after = w->report_every = atof(test);
    w->next_report = now + w->report_after;
}

gb_status gb_run_watch_done(gb_run *run, double seconds)
{
    gb_step_watch *w = &run->watch;
    w->t0 = 0;
    if (w->n == w->cap) {
        int cap = w->cap ? 2 * w->cap : 64;
        double *s = realloc(w->seconds, (size_t)cap * sizeof *s);
        if (!s) return GB_ENOMEM;
        w->seconds = s, w->cap = cap;
    }
    w->seconds[w->n++] = seconds;
    return GB_OK;
}

gb_solve_stop gb_run_poll(void *user, long step_sweeps, double max_force)
{
    gb_run *run = user;
    const gb_sim *sim = run->sim;
    gb_step_watch *w = &run->watch;
    if (!isnan(max_force)) w->max_force = max_force;
    if (!(w->t0 > 0)) return GB_STOP_CONVERGED;
    double now = gb_clock_seconds();
    if (w->limit > 0 && now - w->t0 > w->limit) return GB_STOP_TIME;
    if (w->fn && now >= w->next_report) {
        const gb_run_step *c = &run->p.cur;
        const gb_stage *sg = &sim->scene->stages[c->stage];
        gb_step_progress p = {c->step, c->stage_step, sg->steps, c->attempt, gb_run_step_iterations(c), step_sweeps,
                              w->max_force, sim->accuracy, now - w->t0, w->median};
        w->fn(w->user, &p);
        w->next_report = now + w->report_every;
    }
    return GB_STOP_CONVERGED;
}
