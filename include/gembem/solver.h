/* Solving a simulation's problem outside a loading program (src/solver): relaxations to
 * equilibrium under a wall control, another solver for a simulation, and the solver's statistics
 * (benchmarks, tests). A run (gembem/run.h) calls the same functions for each load step. */
#ifndef GEMBEM_SOLVER_H
#define GEMBEM_SOLVER_H

#include "gembem/gem.h"

/* The global solver's time and counts (seconds, cumulative over the process). */
typedef struct {
    double assemble, analyse, factorise, solve;
    long analyses, factorisations, regularised;
    long corrections; /* iterations solved twice: sliding contacts that the first solution unloads */
    long moves;       /* calls of gb_global_moves: iterations plus moves retried with more damping */
    long pcg_solves;  /* systems solved by conjugate gradients on an earlier factor (CHOLMOD, PETSc direct) */
    long pcg_steps;   /* their conjugate-gradient steps */
    long ksp_iterations; /* PETSc: the KSP's iterations (1 per solve for a direct solver) */
    /* The last system factorised: its unknowns and stored entries (CHOLMOD: the lower triangle);
     * CHOLMOD's factor entries and flops of its last analysis (0 with another solver). */
    int unknowns;
    long entries;
    double factor_entries, factor_flops;
} gb_global_stats;

/* A solver for sim by the settings `set` (which must outlive it); it replaces (and frees) the one
 * sim had. With the reference method it holds no system. The damping starts from the scene's
 * restart state (scene->restart.solver) when it has one: a restart continues the run it continues. */
gb_status gb_solver_create(gb_sim *sim, const gb_solver_settings *set, gb_error *err);

/* What one relaxation did (gb_solver_relax): that call's work alone, and where it ended. */
typedef struct {
    gb_solve_stop stop;      /* why it stopped: GB_STOP_CONVERGED, or why not */
    long iterations;         /* its iterations (resumed from a checkpoint within it: those before too) */
    gb_solver_work work;     /* the moves tried, factorisations and smoother steps of this call */
    double max_force;        /* the largest fixing force of a grain at its end (K 14) */
    double wall_residual;    /* the walls' force error at its end (0 with walls held) */
    double seconds;          /* its wall time */
} gb_solve_result;

/* Relaxes sim to equilibrium under the wall control, at most `cap` iterations; what it did in
 * *res. The accuracy is the load step's (outside a run: as for a first step). GB_ENOCONV when
 * it stops unconverged (res->stop says why: the cap, a stall, the step's time limit). */
gb_status gb_solver_relax(gb_sim *sim, const gb_wall_control *wc, long cap, gb_solve_result *res, gb_error *err);

/* Calls fn after every iteration of gb_solver_relax that did not converge (a run's relaxations call
 * the run's: gb_run_on_iteration); NULL: none. */
void gb_solver_on_iteration(gb_sim *sim, gb_iteration_fn fn, void *user);

/* The solver's work since it was created (all zero for the reference iteration): its relaxations'
 * work summed (a benchmark's totals). */
gb_solver_work gb_solver_work_done(const gb_sim *sim);
/* The global system's statistics, or NULL for the reference iteration. */
const gb_global_stats *gb_solver_statistics(const gb_sim *sim);

#endif
