/* The solver's state, shared by its iterations (relax.c, damped.c, line_search.c, inertial.c);
 * private to src/solver. */
#ifndef GB_SOLVER_IMPL_H
#define GB_SOLVER_IMPL_H

#include "solver/solver.h"

/* in_system: 0 moved by the reference cases, else by the global system, its rotation held or not */
#define GB_IN_SYSTEM 1
#define GB_IN_SYSTEM_NO_ROTATION 2
/* a grain with a single contact that has rolling resistance: in the system with its rotation (the
 * rolling spring holds it), the contact's kt and kr kept in K (gb_solver_mark_system) */
#define GB_IN_SYSTEM_SINGLE 3

struct gb_solver {
    const gb_solver_settings *set;
    gb_global *global;          /* the global system, NULL for the reference iteration */
    unsigned char *in_system;   /* per grain: moved by the global system in this iteration (GB_IN_SYSTEM...) */
    gb_state trial;         /* the configuration before a trial move */
    gb_state smoothed;      /* newton: line_search: the smoother's, while shorter steps are tried */
    gb_solver_damping damping;  /* newton: damped */
    double *direction;          /* newton: line_search: the Newton direction of grains, particles, walls */
    double *velocity, *acceleration; /* its smoother's: 3 per grain, 2 per boundary particle */
    double *block_sums;         /* its smoother's sums over blocks of grains (inertial.c) */
    double length;              /* the share of Newton's step the last line search took (0: the smoother) */
    gb_solve_stop stop;         /* why the last relaxation stopped */
    long sweeps0;               /* work.sweeps at the start of the iteration in progress */
    gb_solver_work work;        /* since the solver was created (gb_solver_work_done) */
    gb_solver_work relax_work;  /* gb_solver_work_done at the start of the relaxation in progress */
    const gb_relax_context *ctx; /* that relaxation's (gb_solver_relax_within) */
    gb_iteration_fn on_iteration; /* gb_solver_relax's (gb_solver_on_iteration) */
    void *on_iteration_user;
};

/* The smoother's sums over the grains run on solver.threads threads in blocks of
 * GB_SMOOTHER_BLOCK grains, each summed in its order, then the blocks in theirs: the same bits on
 * any thread count (and, below a block's size, the grains' order). GB_SMOOTHER_SUMS per block. */
enum { GB_SMOOTHER_BLOCK = 512, GB_SMOOTHER_SUMS = 6 };
static inline int gb_smoother_blocks(int n) { return (n + GB_SMOOTHER_BLOCK - 1) / GB_SMOOTHER_BLOCK; }
/* The end of block b's grains (it starts at b GB_SMOOTHER_BLOCK). */
static inline int gb_smoother_block_end(int b, int n) { return b < n / GB_SMOOTHER_BLOCK ? (b + 1) * GB_SMOOTHER_BLOCK : n; }

/* Which grains the global system moves (s->in_system), from the current contacts. */
void gb_solver_mark_system(gb_solver *s, const gb_sim *sim);

/* One iteration of the global solver from the current forces, whose merit (gb_gem_merit over
 * s->in_system) is m0, with the configuration saved in s->trial: the damped iteration (damped.c),
 * and the line search (line_search.c). */
gb_status gb_solver_damped_move(gb_solver *s, gb_sim *sim, const gb_wall_control *wc, double m0, gb_error *err);
gb_status gb_solver_line_search_move(gb_solver *s, gb_sim *sim, const gb_wall_control *wc, double m0,
                                     gb_error *err);

/* The line search's smoother (inertial.c): every grain and boundary particle moves, servo walls
 * follow, until the merit is at most `target`, after max_steps, or when every grain, particle and
 * wall is balanced. With stall_check > 0, also when it stalls (*stalled set): checked every
 * stall_check steps, at the rate of the merit's fall over them it would take more than as many
 * again to reach the target. The forces are current on return. */
gb_status gb_solver_inertial(gb_solver *s, gb_sim *sim, const gb_wall_control *wc, double target, int max_steps,
                             double stall_check, int *stalled, gb_error *err);

/* The step's clock, between iterations and every GB_POLL_SWEEPS smoother steps (the context's poll): a
 * stop other than GB_STOP_CONVERGED ends the relaxation with GB_ENOCONV and s->stop set. */
enum { GB_POLL_SWEEPS = 32 };
gb_status gb_solver_poll(gb_solver *s, gb_sim *sim, double max_force);
/* solver.history: the smoother's progress within the iteration in progress (a row every
 * GB_HISTORY_SWEEPS of its steps): the largest fixing force of a grain or particle now. */
void gb_solver_report_smoother(const gb_solver *s, gb_sim *sim, double wall_residual);

#endif
