/* The problem of a granular simulation: grains, contacts and their law, walls or an elastic host,
 * loads, the state and an iteration's scratch (private to the library; solved by src/solver, driven
 * through a loading program by a run, src/run). */
#ifndef GB_SIM_H
#define GB_SIM_H

#include "contact/pairs.h"
#include "gembem/gem.h"
#include "hybrid/host.h"

/* The energy accounts that iterations change (absolute since the run's start, force x length);
 * saved and restored with the state. */
typedef struct {
    double work_walls_iter;   /* done by the walls as the iterations move them */
    double relaxation;        /* absorbed by the fixing forces: -sum F.dX over the iterations */
    double dissipation;       /* (K 28) summed over contacts and iterations */
    double dissipation_step;  /* of the current load step */
    int half_pending;         /* the second half of the last move's relaxation is still due */
} gb_iteration_accounts;

/* What an iteration computes from the state and leaves for the next one's start: nothing here
 * outlives a converged step (checkpoints recompute it: gb_gem_forces). */
typedef struct {
    double *F;          /* fixing force per grain (K 5): fx, fy, m/r */
    double *S;          /* contact stiffness per grain (K 8): s00 s01 s02 s11 s12 s22 */
    double *dX;         /* move of the iteration: dx, dy, r dw */
    int *nc;            /* contacts per grain */
    double *one;        /* per grain, GB_ONE values of its last contact: normal towards the other side, kn, kr */
#define GB_ONE 4
    double *pair_diss;  /* a move's contact update (the reference iteration's): the energy each pair dissipated */
    int pair_diss_cap;
    /* The pair list in chunks, for the contacts' sums on threads (src/gem/relax.c): chunk c's
     * pairs are [chunk[c], chunk[c + 1]); edge[0 .. n_edges) the pairs with a wall or a particle;
     * built for the list of generation chunk_of. */
    int *chunk, n_chunks, chunk_cap, *edge, n_edges, edge_cap;
    long chunk_of;
    double *chunk_sums;   /* each chunk's sums (src/gem/relax.c's CHUNK_SUMS; chunk_cap of them) */
    /* The touching contacts' stiffness along the box's uniform strains, sum kn (n.E l)^2 + kt (t.E l)^2
     * for E = diag(1, 0) and diag(0, 1), and their cross term (l the branch vector: to the other
     * centre, or r n to a wall): kxx, kyy, kxy. Summed with the forces (the smoother's servo walls,
     * src/solver/inertial.c, read it at every step: a pass of its own over the pairs cost a quarter
     * of a 1e5-disc smoother step). */
    double affine_k[3];
    double wall_k[GB_N_WALLS];     /* wall contact stiffness: sum of kn of its contacts */
    double wall_dx[GB_N_WALLS][2]; /* wall translation of the current iteration */
    double *bp_F;       /* fixing force of each boundary particle: host force K u + f0 minus contacts */
    double *bp_S;       /* its contact stiffness: s00 s01 s11 */
} gb_sim_scratch;

/* The live state of a simulation: everything that iterations and load steps change, and nothing
 * they recompute from it (forces and stiffnesses: gb_sim_scratch; the host's force K u + f0:
 * gb_host). A rejected trial or a failed step goes back to a copy (gb_state_copy); a checkpoint
 * writes it (src/io/checkpoint.c). Every array is the state's own. */
typedef struct {
    int n;                    /* grains */
    gb_grain *g;
    gb_pair_set pairs;        /* candidate pairs with their contacts' forces, and where they were found */
    gb_box box;               /* the walls */
    double wall_force[GB_N_WALLS]; /* normal force of the grains on each wall (compression +) */
    int n_particles;          /* boundary particles (none without a host) */
    double *bp_x, *bp_y;      /* their centres (a simulation's sim->bp.x, .y point here) */
    int host_m;               /* the host's cavity DOFs (0 without a host) */
    gb_host_vars host;        /* its cavity displacements and loads */
    gb_iteration_accounts acc;
} gb_state;

/* The arrays of a state of n grains, np particles and m host DOFs, with room for `pairs` pairs. */
gb_status gb_state_alloc(gb_state *s, int n, int np, int m, int pairs, gb_error *err);
/* dst = src, allocating dst's arrays if it has none (gb_state_alloc) and growing its pair list if
 * short; copying into a state with the sizes and room needs no memory and cannot fail. */
gb_status gb_state_copy(gb_state *dst, const gb_state *src, gb_error *err);
void gb_state_free(gb_state *s);

struct gb_sim {
    const gb_scene *scene;
    gb_state state;     /* what iterations and load steps change */
    /* The state keeps its grains by cell (gb_grains_cell_order of the scene's, at creation), so that
     * a contact's two grains are near in memory: state grain k is the scene's grain_order[k], scene
     * grain i is the state's grain_place[i]. Everything a run writes or a caller reads numbers the
     * grains as the scene does (gb_sim_grain, gb_sim_contacts, src/measure/step.c). */
    int *grain_order, *grain_place;
    double *body;       /* B per grain: bx, by */
    gb_pair_search search; /* how the state's pairs are found */
    gb_world world;     /* what the grains touch: themselves, the box's walls, boundary particles */
    gb_particles bp;    /* boundary particles (none without a host): their centres are the state's */
    gb_host *host;      /* the elastic host of a hybrid scene, or NULL (its vars are the state's) */
    gb_sim_scratch scratch; /* an iteration's forces, stiffnesses and moves */
    struct gb_solver *solver; /* how it is solved (src/solver: the only code that looks inside) */
    double ref_width, ref_height;  /* strain reference */
    double tan_phi_gg, tan_phi_gw, tan_phi_gb;
    double detect_seconds;    /* spent on contact detection: the pair list's staleness and rebuilds */
    double force_scale;       /* of the load step in progress, from its start (src/gem/accuracy.c) */
    double accuracy;          /* a of the load step in progress: every test against the accuracy uses it */
};

/* solver.threads: below this many pairs (grains) a move's contact update (the grains' moves) stays
 * on one thread; a parallel region costs a few microseconds. */
enum { GB_PARALLEL_PAIRS = 1024, GB_PARALLEL_GRAINS = 512 };

/* The sum of two counts of the solver's work. */
static inline gb_solver_work gb_solver_work_plus(gb_solver_work a, gb_solver_work b)
{
    gb_solver_work d = {a.trials + b.trials, a.factorisations + b.factorisations, a.sweeps + b.sweeps};
    return d;
}

/* The problem of a scene: grains, contacts, walls or host, with no solver (sim->solver NULL):
 * gb_sim_create (src/run/simulation.c) adds it. */
gb_status gb_gem_problem_create(const gb_scene *scene, gb_sim **out, gb_error *err);
void gb_gem_problem_free(gb_sim *sim);

/* A copy of the simulation's state into st (allocated at the first save). */
gb_status gb_sim_state_save(const gb_sim *sim, gb_state *st, gb_error *err);
/* The simulation's state back to a copy made by gb_sim_state_save (or read from a checkpoint, with
 * room for its pairs): no memory needed, the host's force updated. */
void gb_sim_state_restore(gb_sim *sim, const gb_state *st);

/* The largest squared fixing force of a grain, and of a boundary particle (0 without a host or
 * with a rigid one); NaN if one is NaN. */
double gb_gem_largest_grain_force2(const gb_sim *sim);
double gb_gem_largest_particle_force2(const gb_sim *sim);

/* The start of an iteration (K section 2.5, Fig. 1): F and S of every grain, the largest fixing
 * force and the walls' moves (sim->scratch.wall_dx) and residual. Returns 1 when converged (every |F| <= a
 * and the walls at their targets: K 14), 0 otherwise (and sets *st if a force is not finite). */
int gb_gem_balance(gb_sim *sim, const gb_wall_control *wc, double *max_force, double *wall_residual, gb_error *err,
                   gb_status *st);
/* The rest of an iteration of the reference method: the simultaneous moves of the grains by their
 * cases (gb_gem_grain_move) and of the walls, and the contact update. */
gb_status gb_gem_reference_move(gb_sim *sim, gb_error *err);

/* The material and friction of the contact type of a pair's second side j. */
const gb_material *gb_sim_material(const gb_sim *sim, int j);
double gb_sim_tan_phi(const gb_sim *sim, int j);

/* F, S, contacts per grain and the walls' forces and stiffnesses, from the current contacts. */
void gb_gem_forces(gb_sim *sim);
/* The squared fixing force of grain i, and the fixing forces' work F.dX of its current move. */
static inline double gb_gem_force2(const gb_sim *sim, int i)
{
    const double *F = &sim->scratch.F[3 * i];
    return F[0] * F[0] + F[1] * F[1] + F[2] * F[2];
}
static inline double gb_gem_grain_work(const gb_sim *sim, int i)
{
    const double *F = &sim->scratch.F[3 * i], *d = &sim->scratch.dX[3 * i];
    return F[0] * d[0] + F[1] * d[1] + F[2] * d[2];
}


/* Moves grains by dX, boundary particles by bp.dx and walls by wall_dx simultaneously, then updates
 * every contact. */
gb_status gb_gem_apply_moves(gb_sim *sim, gb_error *err);
/* gb_gem_apply_moves then gb_gem_forces, bitwise the same, in one pass over the pairs: each contact
 * is updated and added to its ends at once (the smoother's step, src/solver/inertial.c, is mostly
 * this pass). */
gb_status gb_gem_move_and_forces(gb_sim *sim, gb_error *err);

/* The mean normal force of the pairs among p[0..n) whose overlap is more than the rounding of
 * coordinates of magnitude `extent` (0 without). */
double gb_pairs_mean_normal_force(const gb_pair *p, int n, double extent);
/* The magnitude of the coordinates: the box's (with a host, the grains' bounding box at the start). */
double gb_sim_extent(const gb_sim *sim);
/* The force scale of a load step of stage `stage` that starts with the pairs p[0..n) (the larger
 * of their mean normal force and the stage's load force, gb_scene_load_force) into
 * sim->force_scale, and the step's accuracy a into sim->accuracy: the scene's, or its relative
 * accuracy times the scale (0 when there is no scale). */
void gb_sim_resolve_accuracy(gb_sim *sim, const gb_pair *p, int n, int stage);
/* The error measures of gb_step_report from the current contacts (src/gem/step_error.c):
 * largest fixing forces of grains and particles, Coulomb excess, mean normal force, coordination.
 * Computes the forces (gb_gem_forces). */
void gb_sim_step_error(gb_sim *sim, gb_step_report *r);

/* Boundary stresses (K section 4.1) and strains from the walls. */
void gb_gem_stress(const gb_sim *sim, double *s1, double *s2);
void gb_gem_strain(const gb_sim *sim, double *e1, double *e2);

/* The move of one grain by cases a) to d) of K section 2.5, from its F, S and contacts. */
void gb_gem_grain_move(const gb_sim *sim, int i, double dX[3]);

/* sum over grains of F.dX with the current F and dX: the fixing forces' work of a move */
double gb_gem_fixing_work(const gb_sim *sim);
/* The walls' moves of an iteration (sim->scratch.wall_dx); returns their residual (0 for fixed walls). */
double gb_gem_wall_moves(gb_sim *sim, const gb_wall_control *wc);
/* Stress-controlled walls' residuals, each axis's target stress times its side minus its two walls'
 * mean force: t[0] the x axis (left and right walls), t[1] the y axis. */
void gb_gem_stress_residuals(const gb_sim *sim, const gb_wall_control *wc, double t[2]);
/* Constant-mean-stress walls' error: the target mean stress minus the walls' (s1 + s2) / 2. */
double gb_gem_mean_stress_error(const gb_sim *sim, const gb_wall_control *wc);
/* The global solver's merit (src/solver): squared fixing forces of the grains in the system, of the
 * boundary particles, and the walls' residual squared. */
double gb_gem_merit(const gb_sim *sim, const unsigned char *in_system, double wall_residual);
/* m plus the boundary particles' part of the merit. */
double gb_gem_particle_merit(const gb_sim *sim, double m);

#endif
