/* A granular scene: the validated, immutable description of a run (materials, grains, box, body
 * force, solver settings, loading program, outputs). Read from YAML by gb_scene_load. */
#ifndef GEMBEM_SCENE_H
#define GEMBEM_SCENE_H

#include <stddef.h>

#include "gembem/bem.h"
#include "gembem/grain.h"
#include "gembem/status.h"

/* An initial tangential contact force (and rolling moment); the normal force follows from the
 * overlap (pn = kn d). */
typedef struct {
    int i, j;   /* grain indices; j < 0 names a wall: j = -1 - GB_WALL_xxx */
    double pt;
    double mr;  /* rolling moment on grain i (docs/method.md section 3.1); 0 if the file has none */
} gb_contact_init;

typedef enum {
    GB_STAGE_ISOTROPIC = 0,      /* stress-controlled isotropic compression to `stress` */
    GB_STAGE_STRAIN = 1,         /* strain-controlled: de1, de2 per step */
    GB_STAGE_SHEAR_MEAN = 2,     /* constant mean stress shear: d(e1 - e2) per step */
    GB_STAGE_BIAXIAL_STRESS = 3, /* stress-controlled: s1, s2 targets */
    GB_STAGE_RELAX = 4,          /* nothing imposed: equilibrium from the current placement (with
                                  * mean_stress > 0, the packer's: walls at that mean stress) */
    GB_STAGE_HOST_DISPLACEMENT = 5, /* the host's 'displacement' groups moved by increments per step */
    GB_STAGE_HOST_LOAD = 6          /* the host's condition values and remote stress grown per step */
} gb_stage_kind;
#define GB_STAGE_KINDS 7 /* the number of kinds above, numbered from 0 */

#define GB_HOST_MAX_BCS 16

typedef struct {
    gb_stage_kind kind;
    int steps;
    double stress;       /* GB_STAGE_ISOTROPIC: target stress */
    double s1, s2;       /* GB_STAGE_BIAXIAL_STRESS: target vertical and horizontal stress */
    double de1, de2;     /* GB_STAGE_STRAIN: strain increments per step (compression positive) */
    double d_shear;      /* GB_STAGE_SHEAR_MEAN: d(e1 - e2) per step */
    double mean_stress;  /* GB_STAGE_SHEAR_MEAN, and GB_STAGE_RELAX if > 0: the mean stress held */
    int reset_strain;    /* strains are measured from the box at the start of this stage */
    /* GB_STAGE_HOST_DISPLACEMENT, GB_STAGE_HOST_LOAD: per step, the values of group host_group[k]'s
     * condition grow by host_increment[k] (2 values, or 1 for a pressure or normal displacement),
     * and the remote stress of an unbounded host by host_remote_increment (sxx, syy, sxy) */
    int n_host_groups;
    char host_group[GB_HOST_MAX_BCS][GB_BEM_NAME_MAX];
    double host_increment[GB_HOST_MAX_BCS][2];
    double host_remote_increment[3];
} gb_stage;

/* solver.petsc: the PETSc linear solver of the global solver (solver.linear: petsc, docs/scaling.md). */
typedef struct {
    char ksp[16];         /* KSP type: preonly (a direct solve), cg, gmres, bcgs, minres */
    char pc[16];          /* PC type; "": cholesky for a symmetric system, lu otherwise */
    char factor[16];      /* the direct solver of lu and cholesky: mumps, superlu_dist or petsc */
    double rtol;          /* an iterative KSP's relative residual tolerance */
    char options[512];    /* more PETSc options, e.g. "-pc_gamg_threshold 0.01" (PETSC_OPTIONS wins) */
} gb_petsc_settings;

/* Correction factors of the reference iteration (K 9-12) and its convergence test (K 14). */
typedef struct {
    double alpha, alpha1;  /* alpha: case a) and d); alpha1 (alpha'): normal move of case c) */
    double beta, beta1;    /* beta: drift of a grain without contact, b); beta1 (beta'): rolling, c) */
    double accuracy;       /* a: every grain's |F| <= a [force]; with accuracy_relative, resolved per step */
    double accuracy_relative; /* > 0: a = this times the step's force scale (src/gem/accuracy.c); 0: a given */
    int accuracy_default;  /* the scene gave no accuracy: accuracy_relative is GB_ACCURACY_RELATIVE_DEFAULT */
    long max_iterations;   /* cap per load step */
    double max_step_seconds; /* > 0: a load step (all its attempts) fails once it has run this long; 0: no limit */
    int method;            /* GB_METHOD_REFERENCE (Jacobi-like, per grain) or GB_METHOD_GLOBAL */
    int linear;            /* global: GB_LINEAR_CHOLMOD, GB_LINEAR_UMFPACK or GB_LINEAR_PETSC */
    gb_petsc_settings petsc; /* linear: petsc */
    double global_alpha;   /* global: share of the solution taken per iteration (default 1) */
    double max_move;       /* global: largest move per iteration, as a share of the grain's radius */
    int cutbacks;          /* a load step that does not converge is retried in halves, down to 1/2^cutbacks */
    int newton;            /* global: GB_NEWTON_DAMPED or GB_NEWTON_LINE_SEARCH */
    int history;           /* write each iteration's largest force and move (history.csv) */
    int threads;           /* OpenMP threads of the contacts' update and the grains' moves (default 1: studies run several
                              scenes at once); the results are the same bits whatever the count */
} gb_solver_settings;

enum { GB_METHOD_REFERENCE = 0, GB_METHOD_GLOBAL = 1 };
/* The global solver's linear solver. PETSC: the matrix distributed over the MPI ranks
 * (src/solver/linear_petsc.c); symmetric with newton: damped. */
typedef enum { GB_LINEAR_CHOLMOD = 0, GB_LINEAR_UMFPACK = 1, GB_LINEAR_PETSC = 2 } gb_linear_kind;
/* The global solver's iteration. DAMPED: Levenberg-Marquardt damping with non-monotone acceptance
 * (src/solver/damped.c). LINE_SEARCH: the exact tangent (sliding contacts and the contacts' rotation
 * included, unsymmetric: UMFPACK); Newton's whole step where it lowers the merit tenfold, else an
 * inertial smoother (FIRE on the reference moves, src/solver/inertial.c) and, where that fails,
 * backtracking; an affine predictor for strain steps (src/solver/line_search.c). */
enum { GB_NEWTON_DAMPED = 0, GB_NEWTON_LINE_SEARCH = 1 };

/* An elastic host with a cavity that holds the grains (the hybrid method, docs/method.md sections 9-11). */
typedef struct {
    int present;
    char mesh[1024];              /* the .geo or .msh file */
    gb_bem_mesh_opts mesh_opts;   /* element counts or sizes per physical group */
    gb_bem_material material;
    char cavity[GB_BEM_NAME_MAX]; /* the group whose elements carry the boundary particles */
    int n_bcs;
    char bc_group[GB_HOST_MAX_BCS][GB_BEM_NAME_MAX];
    gb_bem_bc bc[GB_HOST_MAX_BCS]; /* the other groups: any condition of the BEM module */
    double remote_stress[3];      /* sxx, syy, sxy at infinity (unbounded meshes, mesh_opts.unbounded) */
    int rigid;                    /* the cavity does not deform: boundary particles held (a reference) */
    int follow_every;             /* updated_lagrangian.every: the host follows its deformed boundary
                                     after every this many load steps (0: the body at rest, linear) */
    /* The mesh as the scene's check read it (run_info.yaml): elements per group, the cavity's
     * shortest and longest element. counts_given: host.elements gave counts (else the .geo's own
     * sizes, or a .msh as gmsh wrote it). */
    int counts_given;
    int n_groups;
    char group[GB_BEM_MAX_GROUPS][GB_BEM_NAME_MAX];
    int group_elements[GB_BEM_MAX_GROUPS];
    double cavity_min, cavity_max;
} gb_host_def;

/* A hybrid run's host as a state file left it (`initial_state:` of a scene with a host): the
 * cavity's displacements and boundary particles, the current values of every group's condition
 * and the remote stress, checked against the scene's mesh and conditions when read. */
typedef struct {
    int present;
    int n_cavity;        /* cavity elements, in the host's (mesh) order */
    double *u;           /* their displacements, 2 per element */
    double *xy;          /* their boundary particles' centres now, 2 per element */
    gb_bem_bc bc[GB_HOST_MAX_BCS]; /* by the scene's host.bc_group index: the current values */
    double remote_stress[3];
} gb_host_state;

/* The global solver's Levenberg-Marquardt damping as a state file left it, so that a restart
 * follows the path of the run it continues. */
#define GB_SOLVER_HISTORY 10
#define GB_SOLVER_MU_START 1e-6 /* the damping a solver starts from, without a state's */
typedef struct {
    int present;
    double mu;
    double history[GB_SOLVER_HISTORY];
    int next;
    double smoother_first; /* newton: line_search: see src/solver/solver.h (0 and 0 if absent) */
    int newton_due;
} gb_solver_state;

/* Where a scene's run starts when it continues an earlier run, apart from the scene's definition
 * (a scene without it starts from rest): the contacts' tangential forces (and rolling moments) of
 * `grains.contacts` or `initial_state:`, and from a state the host and the solver as that run left
 * them. */
typedef struct {
    int n_contacts;
    gb_contact_init *contacts;
    gb_host_state host;
    gb_solver_state solver;
} gb_restart;

/* Grains may overlap each other and a wall or the cavity's boundary by at most this share of the
 * (smaller) radius unless the scene's grains.max_overlap says otherwise (src/scene/admit.c). */
#define GB_MAX_OVERLAP_DEFAULT 0.5
/* A host whose longest cavity element is longer than this many mean grain radii is run with a
 * warning (src/scene/admit.c). */
#define GB_ELEMENT_RATIO_WARN 2.5

/* The overlaps that the admission of a scene accepted (run_info.yaml). */
typedef struct {
    int grain_pairs;         /* pairs of grains that overlap */
    double grain_largest;    /* the largest, over the smaller radius */
    int boundary;            /* grains that cross a wall or the cavity's boundary */
    double boundary_largest; /* the largest crossing, over the grain's radius */
    int particles;           /* grains that overlap a host's boundary particle (not refused) */
    double particle_largest; /* the largest such overlap, over the grain's radius */
    double mean_radius;
} gb_overlaps;

typedef struct {
    char path[512];          /* the scene file */
    char length_unit[32], force_unit[32];
    gb_material grain_grain, grain_wall;
    gb_material grain_boundary;  /* grains against boundary particles: kt = 0 unless given */
    gb_host_def host;            /* instead of a box */
    gb_restart restart;          /* what an earlier run left (initial_state:, grains.contacts) */
    int n_grains;
    gb_grain *grains;
    char grains_file[1024];  /* where the grains were read: the scene, its CSV or a state's CSV */
    int *grain_line, *grain_col; /* each grain's line and column there (messages) */
    double max_overlap;      /* grains.max_overlap: the admission's tolerance */
    gb_overlaps overlaps;    /* what the admission accepted */
    char warning[2048];      /* "" or what the command should say before running (also in run_info.yaml) */
    gb_box box;
    double body_force_per_area[2]; /* force per unit disc area; B_i = this * pi r_i^2 */
    gb_solver_settings solver;
    int n_stages;
    gb_stage *stages;
    int snapshot_every;      /* write a VTK snapshot every k steps (0: none) */
    int n_snapshot_steps;
    int *snapshot_steps;     /* and at these global step numbers */
    int contacts_every;      /* write contacts/contacts_NNNNNN.csv every k steps (and at snapshots) */
    /* The per-step measures (src/measure): localisation.csv gets a row at every step unless
     * localisation is 0 (output.localisation: false); the files of fields/ are written at the steps
     * that are multiples of measures_every (step 0 included; 0: never). Default
     * GB_MEASURES_DEFAULT_EVERY below GB_MEASURES_DEFAULT_GRAINS grains, else 0. */
    int measures_every;
    int measures_every_given; /* the scene set it (else the default by size) */
    int localisation;
    /* The run directory's checkpoint.txt (`gembem run --resume`): after every checkpoint_every-th
     * step (0: none), and after any step that ends checkpoint_minutes after the last one. */
    int checkpoint_every;
    double checkpoint_minutes;
} gb_scene;

/* Some contact type has rolling resistance (docs/method.md section 3.1). */
static inline int gb_scene_rolling(const gb_scene *s) { return s->grain_grain.kr > 0 || s->grain_wall.kr > 0; }

#define GB_MEASURES_DEFAULT_GRAINS 5000
#define GB_MEASURES_DEFAULT_EVERY 1

/* The checkpoints' defaults (output.checkpoint_every, output.checkpoint_minutes). */
#define GB_CHECKPOINT_EVERY_DEFAULT 1
#define GB_CHECKPOINT_MINUTES_DEFAULT 10.0

/* A scene with every setting at its default and nothing else (no grains, box, materials, stages):
 * where a scene built in code starts, and where gb_scene_load starts before it reads a file. The
 * solver's accuracy is 0 (the code sets it; a file without one gets GB_ACCURACY_RELATIVE_DEFAULT);
 * measures_every is the default of a scene below GB_MEASURES_DEFAULT_GRAINS grains. */
gb_scene gb_scene_default(void);

/* The geometric admission of a scene, apart from reading it (gb_scene_load calls it; a scene built
 * in code calls it before gb_sim_create): refuses (GB_EINPUT, at the grain's file:line:column when
 * it was read) a grain larger than its space, a grain whose centre is outside it, a disc that
 * crosses a wall or the cavity's boundary by more than s->max_overlap of its radius, two grains
 * that overlap by more than s->max_overlap of the smaller radius; counts the overlaps it accepts in
 * s->overlaps. mesh: the host's (gb_bem_mesh_load of s->host; NULL: the box). */
gb_status gb_scene_admit(gb_scene *s, const gb_bem_mesh *mesh, gb_error *err);

/* Reads and validates a scene; on any error *out is left empty and err says file:line:column. */
gb_status gb_scene_load(const char *path, gb_scene *out, gb_error *err);
/* The same from len bytes of YAML in memory (a scene built by a program): `path` names it in
 * messages (path:line:column) and in run_info.yaml, and the file names it holds are read from
 * path's directory; the file need not exist (a run directory, which copies the scene, needs it). */
gb_status gb_scene_load_text(const char *text, size_t len, const char *path, gb_scene *out, gb_error *err);
void gb_scene_free(gb_scene *s);
/* sizeof(gb_scene), for a caller that cannot see this header (a ctypes binding) and allocates one. */
size_t gb_scene_sizeof(void);

/* Default solver settings: the paper's constants for 122 discs (alpha, alpha', beta, beta' =
 * 0.75, 0.5, 20, 20); the absolute form of the accuracy, 0: a scene built in code sets it (a scene
 * file without solver.accuracy gets the relative GB_ACCURACY_RELATIVE_DEFAULT instead). */
gb_solver_settings gb_solver_defaults(void);

/* A scene file without solver.accuracy: every fixing force at most 1e-4 of the force scale (the
 * mean normal contact force), a hundredth of the threshold above which a run is warned
 * (GB_WARN_ACCURACY, docs/solvers.md "Accuracy"). */
#define GB_ACCURACY_RELATIVE_DEFAULT 1e-4

/* The force that the loads of stage `stage` put on a grain, for the force scale of a load step
 * (src/scene/stage.c): the larger of the mean grain's body force and the stage's target stress
 * (isotropic, biaxial or mean stress) times the mean diameter; 0 when neither loads the grains (a
 * strain or host stage without body force). */
double gb_scene_load_force(const gb_scene *s, int stage);
/* A stage's name as a scene spells it ("isotropic", "host_load", ...). */
const char *gb_stage_name(gb_stage_kind k);

/* Total number of load steps of the loading program. */
int gb_scene_total_steps(const gb_scene *s);

/* The scene of `gembem bem`: an elastic body alone (YAML; see the scenes in validation/bem for the
 * commented format). */
typedef struct {
    char path[512];
    char length_unit[32], force_unit[32];
    gb_bem_material material;
    char mesh_path[512];
    gb_bem_mesh_opts mesh_opts;
    gb_bem_mesh mesh;
    gb_bem_problem problem;
    int npts;
    double *pts;          /* interior points, 2 per point */
    int grid_nx, grid_ny; /* >0: pts[0 .. nx*ny) is a grid, row by row (x fastest); may hold outside points */
    int *pt_inside;       /* 1 if pts[i] is inside the body */
    int increments; /* updated_lagrangian.increments: 0, one linear solve on the undeformed mesh;
                       n >= 1, the body follows its deformed boundary (gb_bem_solve_updated) */
    char stiffness_group[GB_BEM_NAME_MAX]; /* "" : no condensation */
    int stiffness_write;
    int write_boundary_csv, write_boundary_vtp, write_interior_vtu, write_interior_csv; /* output: default 1 */
} gb_bem_scene;

/* Reads and checks the scene, then meshes it; every error names file:line:column (GB_EINPUT). */
gb_status gb_bem_scene_load(const char *path, gb_bem_scene *scene, gb_error *err);
void gb_bem_scene_free(gb_bem_scene *scene);

#endif
