/* The solver: iterations that bring a problem to equilibrium within a tolerance.
 *
 * A problem is a gb_sim (src/gem/sim.h): the grains, their contacts and the contact law, the walls
 * or the elastic host, and the loads of the step in progress. A solve is gb_solver_relax: iterations
 * until every fixing force is within the load step's accuracy (K 14), by the method the settings
 * name: the reference iteration of the granular element method (src/gem, the oracle), or the global
 * solver (one sparse system for every grain, boundary particle and servo wall: global.h), damped
 * (damped.c) or with a line search and an inertial smoother (line_search.c, inertial.c). Pure
 * granular and hybrid scenes go through the same calls. The solver depends on the problem, never
 * the reverse: src/gem knows a gb_sim's solver only as an opaque pointer. */
#ifndef GB_SOLVER_H
#define GB_SOLVER_H

#include "gem/sim.h"
#include "solver/global.h"

typedef struct gb_solver gb_solver;

/* The state of the global solver's iterations that a load step leaves for the next (state.yaml's
 * solver_state, checkpoints): the damped iteration's Levenberg-Marquardt damping, the merits before
 * the last accepted moves (non-monotone acceptance) and the stall detection of the step in
 * progress; the line search's smoother-first state. */
typedef struct {
    double mu;
    double history[GB_SOLVER_HISTORY];
    int next;
    long since; /* moves since one brought the merit below half the step's lowest */
    double best; /* the step's lowest merit (INFINITY before the step's first move) */
    /* newton: line_search: while its smoother goes first, a factorisation's cost in smoother steps
     * when Newton's whole step last failed (0: Newton first); whether Newton's step is due (the
     * smoother stalled); Newton's failed whole steps in this relaxation (each doubles the stretch
     * between the smoother's stall checks) */
    double smoother_first;
    int newton_due;
    int newton_failures;
    /* gb_solver_relax's stall window, in the load step's work (its iterations plus the smoother's
     * steps): the reference force, the work when it was set, and the work when the relaxation
     * began */
    double stall_ref;
    long stall_at, relax_work0;
} gb_solver_damping;

/* gb_solver_create, gb_solver_relax, gb_solver_work_done, gb_solver_statistics: gembem/solver.h. */
void gb_solver_free(gb_solver *s);

/* A relaxation within a loading program (src/run): where it stands in its load step, and the run's
 * hooks. attempt and iterations point into the run's record of the step, which the relaxation
 * keeps current, so that a checkpoint taken between two iterations holds them. */
typedef struct {
    int step;                /* the load step it belongs to (solver.history's rows) */
    int *attempt;            /* the step's relaxations so far: a new one adds one */
    long *iterations;        /* of the relaxation in progress: > 0 at the call, resumed within it from a
                                checkpoint (its iterations, attempt and stall detection go on); 0 after */
    long step_iterations;    /* the step's iterations in its relaxations that ended */
    long step_sweeps;        /* and their smoother steps (resumed within: also this one's before) */
    gb_iteration_fn on_iteration; /* after every iteration that did not converge (solver.history) */
    void *on_iteration_user;
    /* between two iterations, not after the last one allowed (checkpoints): an error ends it */
    gb_status (*between)(void *user, gb_error *err);
    void *between_user;
    /* the step's clock, given the step's smoother steps so far and the largest fixing force (NaN: not
     * known): a stop other than GB_STOP_CONVERGED ends the relaxation */
    gb_solve_stop (*poll)(void *user, long step_sweeps, double max_force);
    void *poll_user;
} gb_relax_context;

/* gb_solver_relax (gembem/solver.h) within a loading program: the same, in its context. */
gb_status gb_solver_relax_within(gb_sim *sim, const gb_wall_control *wc, long cap, const gb_relax_context *ctx,
                                 gb_solve_result *res, gb_error *err);
/* The work of the relaxation in progress so far (a checkpoint within it); zero outside one. */
gb_solver_work gb_solver_relaxation_work(const gb_sim *sim);

/* Whether sim is solved by the global solver (else by the reference iteration). */
int gb_solver_is_global(const gb_sim *sim);
/* The damping state, to read and to restore (checkpoints, state.yaml). */
gb_solver_damping *gb_solver_damping_of(const gb_sim *sim);
/* Whether the grains follow a strain step's box affinely before the relaxation (the line search's
 * predictor: src/run/program.c). */
int gb_solver_predicts_strain(const gb_sim *sim);
/* The global system's unloading flags of the pairs (gb_global_unloading), NULL without one; and a
 * resumed run's (gb_global_resume), nothing without one. */
const unsigned char *gb_solver_unloading(const gb_sim *sim);
gb_status gb_solver_resume(gb_sim *sim, const unsigned char *unloading, gb_error *err);

#endif
