/* A run: a simulation taken through its scene's loading program (gembem/run.h). The simulation is
 * the problem and its state (src/gem/sim.h); the run is where the program stands, what a failed
 * step goes back to, the work done, the time split and the hooks (private to src/run). */
#ifndef GB_RUN_H
#define GB_RUN_H

#include "gembem/run.h"
#include "io/run_progress.h"

/* A load step's clock (watch.c): its time limit and, where it runs far longer than the run's other
 * steps, its progress. */
typedef struct {
    double t0;              /* when the step started (gb_clock_seconds; 0: no step is watched) */
    double limit;           /* solver.max_step_seconds, 0: none */
    double report_after;    /* seconds after t0 from which progress is reported */
    double next_report;     /* the clock's time of the next report */
    double report_every;    /* seconds between two reports */
    double median;          /* the median of the run's earlier steps, seconds */
    double max_force;       /* the largest fixing force at the last iteration's start */
    double *seconds;        /* the run's completed steps' seconds (this process): n of them */
    int n, cap;
    gb_progress_fn fn;
    void *user;
} gb_step_watch;

struct gb_run {
    gb_sim *sim;
    gb_run_progress p;        /* what a checkpoint holds of the run */
    int begun;                /* the program's start is taken (step 0, or a resume's place): gb_run_advance goes on from p.pos */
    gb_run_profile profile;   /* the loop's phases */
    double *phase;            /* the profile's field the run's time goes to now (NULL: none) */
    double phase_since;       /* since when */
    gb_step_watch watch;      /* the step's clock */
    gb_iteration_fn on_iteration; /* gb_run_on_iteration's (an output with solver.history: history.csv) */
    void *on_iteration_user;
    gb_run_output *out;       /* the output of the call in progress (NULL: none) */
};

/* A load step starts now: its limit and when its progress is reported. */
void gb_run_watch_step(gb_run *run, double now);
/* A step ended after `seconds`: one more for the median (GB_ENOMEM: not recorded). */
gb_status gb_run_watch_done(gb_run *run, double seconds);
/* The step's clock (a relaxation's poll, with run as user): GB_STOP_TIME past its limit, with a
 * progress report if one is due; GB_STOP_CONVERGED (go on) otherwise. step_sweeps: the smoother's
 * steps in the step so far; max_force NaN: the last one given. */
gb_solve_stop gb_run_poll(void *run, long step_sweeps, double max_force);

#endif
