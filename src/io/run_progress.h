/* A run's progress through its loading program: what the run (gb_run, src/run) carries from one
 * load step to the next and, within a step, from one relaxation to the next, and so what a
 * checkpoint holds beyond the simulation's state (src/io/checkpoint.c). The run owns it; io reads
 * and writes it. */
#ifndef GB_RUN_PROGRESS_H
#define GB_RUN_PROGRESS_H

#include "gem/sim.h"
#include "gembem/measure.h"

/* The last completed load step (a checkpoint's place in the program). */
typedef struct {
    int stage;        /* its stage (0 with step 0, the initial state) */
    int stage_step;   /* its number in the stage, 1-based (0: none of the stage's steps yet) */
    int step;         /* overall, 0 = the initial state */
    double start[2];  /* the boundary stresses at the stage's start, where a stress ramp begins */
    int resume;       /* set by a checkpoint: the run continues after this step */
} gb_run_position;

/* Where the load step in progress stands. A step's sub-step applies its loads (phase LOAD), then
 * relaxes (RELAX), and a shear_mean_stress step relaxes a second time under mean-stress control
 * (MEAN): a sub-step resumed past LOAD does not apply its loads again. */
typedef enum { GB_PHASE_LOAD = 0, GB_PHASE_RELAX, GB_PHASE_MEAN } gb_step_phase;

typedef struct {
    int active;           /* a load step is in progress: the fields below are its */
    int stage, stage_step, step; /* as in gb_run_position */
    double start[2];      /* the stage's start stresses */
    double t, h;          /* the sub-step: from fraction t of the step's increment, h of it (powers of two) */
    int cuts;             /* cut-backs left; > 0: the progress's substep holds the sub-step's start */
    int substeps;         /* sub-steps converged */
    double finest;        /* the smallest sub-step tried */
    long iters;           /* iterations of the step's attempts that ended */
    gb_step_phase phase;
    long phase_iters;     /* iterations of the sub-step's relaxations that ended (shear_mean_stress: the first) */
    long relax_iters;     /* iterations done by the relaxation in progress; 0 outside one */
    int attempt;          /* the step's relaxations so far */
    gb_solve_stop cut_by; /* why the first attempt that was cut back stopped (GB_STOP_CONVERGED: none yet) */
    gb_solver_work work;  /* the solver's work in the step's relaxations that ended (resumed within a
                             relaxation: also its work before the checkpoint) */
} gb_run_step;

/* The iterations a step has done so far. */
static inline long gb_run_step_iterations(const gb_run_step *c) { return c->iters + c->phase_iters + c->relax_iters; }

typedef struct {
    gb_run_position pos;
    gb_run_step cur;         /* the load step in progress */
    gb_state saved;          /* the last converged state (the step in progress's start), restored when it fails */
    gb_state substep;        /* the start of a sub-step of a step being cut back */
    long iterations_total;   /* of the load steps completed */
    gb_work_accounts work;   /* external work since the run's start, and the initial elastic energy */
} gb_run_progress;

#endif
