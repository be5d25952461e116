/* The granular element method (Kishino 1989): a simulation of rigid discs with contact springs in a
 * box of four walls, driven through the scene's loading program by the reference iteration. */
#ifndef GEMBEM_GEM_H
#define GEMBEM_GEM_H

#include "gembem/scene.h"

typedef struct gb_sim gb_sim;

/* A contact that carries force (mirrored by the Python binding, python/gembem/library.py). */
typedef struct {
    int i, j;          /* grains; j < 0 is the wall -1 - j (GB_WALL_xxx) or a boundary particle (GB_IS_PARTICLE) */
    double nx, ny;     /* unit normal from i towards j */
    double overlap;    /* > 0 */
    double pn, pt;     /* normal (compression positive) and tangential force (K section 2.2) */
    double diss;       /* energy dissipated at the contact in the last load step (K 28) */
    double mr;         /* rolling moment on grain i, -mr on j (docs/method.md section 3.1) */
} gb_contact;

/* The global solver's work (zero for the reference iteration). */
typedef struct {
    long trials;          /* moves tried: Newton iterations plus rejected moves (damped: retried with more
                             damping; line_search: shorter trial lengths) */
    long factorisations;  /* of the sparse tangent */
    long sweeps;          /* line_search: steps of its inertial smoother (src/solver/inertial.c), where Newton's
                             whole step did not lower the merit tenfold */
} gb_solver_work;

/* How the walls move during one relaxation. */
typedef enum {
    GB_WALLS_FIXED = 0,  /* strain control: the step's displacement was imposed, walls stay */
    GB_WALLS_STRESS,     /* each axis moves to reach target stresses s1 (vertical), s2 (horizontal) */
    GB_WALLS_MEAN        /* an isotropic strain moves the walls to reach the mean stress */
} gb_wall_mode;

typedef struct gb_wall_control_s {
    gb_wall_mode mode;
    double s1, s2;  /* GB_WALLS_STRESS targets */
    double mean;    /* GB_WALLS_MEAN target */
} gb_wall_control;

/* Why a load step's relaxation stopped (steps.csv's stop, a failed step's message). */
typedef enum {
    GB_STOP_CONVERGED = 0, /* every fixing force and the walls' residual within the accuracy (K 14) */
    GB_STOP_ITERATIONS,    /* solver.max_iterations spent */
    GB_STOP_STALLED,       /* the largest fixing force stopped falling (gb_solver_relax's stall window) */
    GB_STOP_TIME,          /* solver.max_step_seconds passed */
    GB_STOP_ERROR          /* an error: non-finite forces, out of memory, an output that failed */
} gb_solve_stop;

/* "converged", "iterations", "stalled", "time", "error". */
const char *gb_solve_stop_name(gb_solve_stop stop);

/* One converged (or failed) load step (mirrored by the Python binding, python/gembem/library.py).
 * Stresses and strains: compression positive, 1 = vertical. */
typedef struct {
    int stage;           /* 0-based stage of the loading program; -1 for the initial state */
    int step;            /* global step number, 0 = the initial state */
    int total_steps;
    double e1, e2, ev;   /* strains since the strain reference; ev = e1 + e2 */
    double s1, s2;       /* boundary stresses (K section 4.1) */
    double stress_ratio; /* (s1 - s2)/(s1 + s2), 0 when both vanish */
    long iterations;     /* of all attempts, sub-steps included */
    int substeps;        /* 1, or the sub-steps a cut-back step took (solver.cutbacks); 0 for step 0 */
    gb_solver_work work; /* of all attempts, sub-steps included */
    gb_solve_stop cut_by; /* why the first attempt that was cut back stopped; GB_STOP_CONVERGED if none was */
    double max_fixing_force;  /* largest |F| over the grains (K 14) */
    double seconds;           /* wall-clock time of the step */
    int n_contacts;
    double width, height;     /* the box; NaN with a host (no walls) */
    /* The step's error (docs/run-directory.md, steps.csv): the force scale and accuracy the step was
     * solved to, and what it reached. */
    double force_scale;       /* mean normal force of the contacts at the step's start (src/gem/accuracy.c) */
    double accuracy;          /* a of the step: given, or the relative accuracy times force_scale */
    double wall_residual;     /* the walls' force error at the end under stress control; NaN otherwise */
    double max_particle_force; /* largest |K u + f0 - grains' force| over the boundary particles; NaN without
                                  a host or with a rigid one */
    double coulomb_excess;    /* max over contacts of |pt| - (pn tan phi + c), <= 0; NaN without contacts */
    double mean_normal_force; /* mean pn of the contacts at the step's end (0 without) */
    double coordination;      /* contacts per grain over the grains with two or more (rattlers excluded) */
    int rattlers;             /* grains with fewer than two contacts */
} gb_step_report;

/* Where a run's time went, by phase (seconds of this process, summed over its steps, step 0
 * included), as Box2D's b2Profile or LAMMPS's timers. */
typedef struct {
    double control;  /* the steps' set-up: accuracy, loads, states saved and restored, work accounts */
    double solve;    /* relaxations (gb_solver_relax); a checkpoint taken within a step is here too */
    double measure;  /* the steps' reports and, with an output, their measures (docs/measures.md) */
    double output;   /* the steps' files and checkpoints, and the on_step callback */
} gb_run_profile;

/* Called after the initial state (step 0) and after every converged step, after its output
 * (gb_run_program, gembem/run.h). A non-OK status stops the run with that error. */
typedef gb_status (*gb_step_fn)(void *user, const gb_sim *sim, const gb_step_report *rep, gb_error *err);

/* One iteration of a load step (solver.history). */
typedef struct {
    int step;                /* the load step it belongs to */
    int attempt;             /* 1, then 2, 3... for the relaxations of a cut-back step's sub-steps */
    long iteration;          /* within the attempt, from 1 */
    double max_fixing_force; /* largest |F| at the iteration's start (K 14) */
    double wall_residual;    /* the walls' distance from their targets then */
    double largest_move;     /* largest grain move of the iteration over its radius */
    double damping;          /* global, newton: damped: the Levenberg-Marquardt damping after it; else 0 */
    double length;           /* global, newton: line_search: the share of Newton's step taken, 0 when its
                                smoother took over; else 0 */
    long sweeps;             /* the smoother's steps in the iteration (so far, in a smoother row) */
    int smoother;            /* 1: the smoother's progress within iteration `iteration`, every
                                GB_HISTORY_SWEEPS of its steps (max_fixing_force then, largest_move 0);
                                0: the iteration's own report */
} gb_iteration_report;

/* How often a long stretch of the smoother reports its progress to solver.history. */
enum { GB_HISTORY_SWEEPS = 1000 };

typedef void (*gb_iteration_fn)(void *user, const gb_iteration_report *rep);

/* A load step that runs far longer than the run's others, as it goes (gb_run_on_progress). */
typedef struct {
    int step, stage_step, stage_steps; /* the step, and its place in its stage (stage_steps steps) */
    int attempt;             /* its relaxations so far (cut-backs start new ones) */
    long iterations;         /* of all its attempts so far */
    long sweeps;             /* the smoother's steps so far (global, newton: line_search) */
    double max_fixing_force; /* largest |F| at the last iteration's start */
    double accuracy;         /* the step's a */
    double seconds;          /* since the step started (in this process) */
    double median_seconds;   /* the median of the run's earlier steps in this process (0 before any) */
} gb_step_progress;

typedef void (*gb_progress_fn)(void *user, const gb_step_progress *p);

const gb_scene *gb_sim_scene(const gb_sim *sim);
int gb_sim_n_grains(const gb_sim *sim);
/* Grain i, numbered as in the scene (the simulation keeps its grains in another order). */
gb_grain gb_sim_grain(const gb_sim *sim, int i);
/* All the grains into out (gb_sim_n_grains of them), numbered as in the scene. */
void gb_sim_grains(const gb_sim *sim, gb_grain *out);
/* The walls' places (where their faces are). */
gb_box gb_sim_box(const gb_sim *sim);
/* The normal force of the grains on each wall (GB_WALL_xxx order, compression positive), of the
 * forces as the last balance left them (a step's end); zero with a host. */
void gb_sim_wall_forces(const gb_sim *sim, double force[GB_N_WALLS]);
/* Copies up to `cap` force-carrying contacts into out (may be NULL) and returns how many there are:
 * grains numbered as in the scene, i < j between grains, sorted by (i, j) when all fit. */
int gb_sim_contacts(const gb_sim *sim, gb_contact *out, int cap);
/* A newly allocated copy of the force-carrying contacts as gb_sim_contacts gives them (free() it),
 * their count in *n; NULL on failure (err says why). */
gb_contact *gb_sim_contacts_copy(const gb_sim *sim, int *n, gb_error *err);
/* Total elastic energy of the contact springs, sum of (pn^2/kn + pt^2/kt)/2 (K 22). */
double gb_sim_elastic_energy(const gb_sim *sim);
/* The fixing force (fx, fy, m/r) of grain i (K 5), numbered as in the scene. */
void gb_sim_fixing_force(const gb_sim *sim, int i, double F[3]);
/* The boundary stresses s1 (vertical) and s2 (horizontal) of the walls (K section 4.1), from the
 * forces of the current contacts (recomputed: F, S and the walls' forces). */
void gb_sim_stress(gb_sim *sim, double *s1, double *s2);
/* Seconds spent on contact detection (the pair list's staleness tests and rebuilds) so far. */
double gb_sim_detect_seconds(const gb_sim *sim);
/* The whole state mapped onto box `to`, of the box's shape, by one uniform scaling of positions,
 * radii, overlaps and contact forces: a balanced state stays balanced, at the same stress (a
 * packing's walls that moved to its target stress put back; src/gem/fit_box.c). Refused with a
 * host or another shape. The forces recomputed. */
gb_status gb_sim_fit_box(gb_sim *sim, const gb_box *to, gb_error *err);

#endif
