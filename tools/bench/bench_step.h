/* One timed load step of the benchmark programs, added to their totals. */
#ifndef GB_BENCH_STEP_H
#define GB_BENCH_STEP_H

#include "bench_clock.h"
#include "gembem/gembem.h"

typedef struct {
    long iterations;
    double seconds;
    double contact_iterations; /* each step's iterations times its contacts at the end */
    int contacts;              /* at the end of the last step */
} bench_totals;

/* Relaxes sim under wc (at most cap iterations) and adds the step to t. */
static inline gb_status bench_load_step(gb_sim *sim, const gb_wall_control *wc, long cap, bench_totals *t,
                                        double *max_force, double *wall_residual, gb_error *err)
{
    gb_solve_result res;
    double t0 = bench_now();
    gb_status st = gb_solver_relax(sim, wc, cap, &res, err);
    long n = res.iterations;
    *max_force = res.max_force, *wall_residual = res.wall_residual;
    t->seconds += bench_now() - t0;
    t->iterations += n;
    t->contacts = gb_sim_contacts(sim, NULL, 0);
    t->contact_iterations += (double)n * t->contacts;
    return st;
}

#endif
