/* The elastic host: a 2D elastostatic boundary element module (H 1-7; docs/method.md sections 9, 12).
 *
 * A body (bounded, or an infinite plane with cavities) is described by its boundary only: closed
 * polygonal loops of straight constant elements, one displacement and one traction per element,
 * collocated at element midpoints. Loops are oriented by the body's outward normal (outer boundary
 * counter-clockwise, cavities clockwise); the normal of an element is its tangent turned clockwise.
 *
 * Signs: stresses and tractions are tension-positive (elasticity convention, not the granular
 * solver's compression-positive); a pressure p pushes on the surface, t = -p n. Units are the
 * scene's: lengths in the length unit, tractions and stresses in force per length^2 (per unit depth).
 *
 * Typical use:
 *   gb_bem_mesh_load("meshes/annulus.geo", &opts, &mesh, &err);
 *   gb_bem_assemble(&mesh, &material, &sys, &err);        H and G (dense, column-major)
 *   gb_bem_solve(&mesh, &sys, &problem, &sol, &err);      mixed boundary conditions per group
 *   gb_bem_interior(&mesh, &sys, &problem, &sol, n, xy, u, s, &err);
 *   gb_bem_condense(&mesh, &sys, &problem, group, &stiff, &err);   K = L G^-1 H on one group
 * Every call returns a gb_status and fills a gb_error; nothing prints. Free with the _free calls. */
#ifndef GEMBEM_BEM_H
#define GEMBEM_BEM_H

#include <stddef.h>

#include "gembem/status.h"

#define GB_BEM_NAME_MAX   64
#define GB_BEM_MAX_GROUPS 32

/* ---------------------------------------------------------------- material */

typedef enum { GB_BEM_PLANE_STRAIN = 0, GB_BEM_PLANE_STRESS = 1 } gb_bem_plane;

typedef struct {
    double shear_modulus; /* mu > 0 */
    double poisson;       /* -1 < nu < 0.5 */
    gb_bem_plane plane;   /* plane stress uses nu/(1+nu) in the kernels */
} gb_bem_material;

/* ---------------------------------------------------------------- boundary mesh */

typedef struct {
    int n;           /* number of elements */
    double *p0, *p1; /* end points, 2n each, in loop order (body on the left) */
    double *mid;     /* midpoints (collocation points), 2n */
    double *tangent; /* unit tangent p1 - p0, 2n */
    double *normal;  /* unit outward normal of the body, 2n */
    double *length;  /* n */
    int *group;      /* physical group index of each element, n */
    int *loop;       /* loop index of each element, n */
    int n_loops;
    int *loop_start; /* elements of loop k: loop_start[k] .. loop_start[k+1]-1 */
    int *loop_outer; /* 1 for the outer boundary, 0 for a cavity */
    int n_groups;
    char (*group_name)[GB_BEM_NAME_MAX];
    int unbounded; /* 1: an infinite plane with cavities (no outer loop) */
} gb_bem_mesh;

/* Meshing options: a global element size and/or a size or element count per physical group. */
#define GB_BEM_MAX_COUNT 1000000 /* elements a group's count may ask, or a size give (gb_bem_mesh_load) */
typedef struct {
    char group[GB_BEM_NAME_MAX];
    double size; /* target element length (0: not set) */
    int count;   /* number of elements on the whole group (0: not set) */
} gb_bem_group_size;

typedef struct {
    double size; /* target element length everywhere (0: the .geo file's own sizes) */
    int n_group_sizes;
    gb_bem_group_size group_sizes[GB_BEM_MAX_GROUPS];
    int unbounded; /* every loop is a cavity in an infinite plane */
} gb_bem_mesh_opts;

gb_bem_mesh_opts gb_bem_mesh_opts_default(void);

/* Meshes a .geo file to 1D through the gmsh API (or reads a .msh). Every physical group of
 * dimension 1 becomes a group; every loop is oriented from its signed area. Refused (GB_EINPUT):
 * a missing file, a gmsh error, an open or branching loop, a self-crossing or touching boundary, a
 * zero-length element, a group of `opts` that the file does not define, a bounded body without a
 * single outer loop enclosing the others. gmsh is global: do not call this from two threads at
 * once. The caller's LC_NUMERIC is restored after gmsh (which sets it to "C"). */
gb_status gb_bem_mesh_load(const char *path, const gb_bem_mesh_opts *opts, gb_bem_mesh *mesh, gb_error *err);
/* 1 if gb_bem_mesh_load reads the file as a mesh (.msh), which takes no sizes or counts. */
int gb_bem_mesh_file_is_msh(const char *path);

/* Builds a mesh from closed polygons: loop k has loop_n[k] vertices (xy, concatenated, 2 per
 * vertex; the closing edge is implied) and edge e of all loops lies in group edge_group[e] (edge
 * e of a loop goes from its vertex e to vertex e+1). Any orientation; the same checks as
 * gb_bem_mesh_load. `names` gives n_groups group names (NULL: "group0", "group1", ...). */
gb_status gb_bem_mesh_from_polygons(int n_loops, const int *loop_n, const double *xy, const int *edge_group,
                                    int n_groups, const char *const *names, int unbounded, gb_bem_mesh *mesh,
                                    gb_error *err);

/* A regular polygon of n elements on a circle (center cx, cy, radius r): a test helper. */
gb_status gb_bem_mesh_circle(double cx, double cy, double r, int n, int unbounded, gb_bem_mesh *mesh, gb_error *err);

/* Index of a group by name, or -1. */
int gb_bem_mesh_group(const gb_bem_mesh *mesh, const char *name);

/* 1 if the point lies inside the body (outside every cavity, inside the outer loop if any). */
int gb_bem_mesh_inside(const gb_bem_mesh *mesh, double x, double y);

/* 1 if the point lies in a cavity bounded by the group: not in the body, and within the group's
 * bounding box (gb_bem_mesh_group_box: xmin, xmax, ymin, ymax). */
int gb_bem_mesh_in_cavity(const gb_bem_mesh *mesh, int group, double x, double y);
void gb_bem_mesh_group_box(const gb_bem_mesh *mesh, int group, double box[4]);

/* Distance from a point to the nearest boundary element. */
double gb_bem_mesh_distance(const gb_bem_mesh *mesh, double x, double y);

void gb_bem_mesh_free(gb_bem_mesh *mesh);

/* Moves the mesh with the body: every node by the displacement u (2 per element, at the midpoints)
 * interpolated linearly along the boundary between the midpoints of its two elements; lengths,
 * midpoints, tangents and normals follow. Refused (GB_EINPUT, the mesh left as it was): an element
 * that shrinks to nothing or turns by more than a right angle, a loop that turns inside out, a
 * boundary that crosses or touches itself. */
gb_status gb_bem_mesh_move(gb_bem_mesh *mesh, const double *u, gb_error *err);
/* The element end points p0, p1 (2n each, in the mesh's element order) in place of the mesh's, as
 * gb_bem_mesh_move leaves them (a moved mesh read back); refused as gb_bem_mesh_move refuses, and
 * where an element does not end where the next in its loop starts. */
gb_status gb_bem_mesh_place(gb_bem_mesh *mesh, const double *p0, const double *p1, gb_error *err);
/* A copy of src in dst (its own arrays: gb_bem_mesh_free). */
gb_status gb_bem_mesh_copy(const gb_bem_mesh *src, gb_bem_mesh *dst, gb_error *err);

/* ---------------------------------------------------------------- H and G */

/* Dense influence matrices of size 2n x 2n, column-major (LAPACK order), DOF 2e+c is component c
 * (0: x, 1: y) of element e. (H 3-5): H U = G P, with H's diagonal blocks 1/2 I (smooth midpoint)
 * plus the principal value (zero on a straight element) and G's diagonal in closed form. All
 * element integrals are closed-form for straight elements, exact also for nearly singular points.
 * H carries a rank-one correction per loop that makes the flux identities of its incompressible
 * part exact (O(h^2); it keeps nearly incompressible traction problems accurate, see
 * validation/bem/README.md). The columns are filled by as many threads as there are cores. */
typedef struct {
    int ndof;
    double *H, *G;
    gb_bem_material material;
} gb_bem_system;

gb_status gb_bem_assemble(const gb_bem_mesh *mesh, const gb_bem_material *mat, gb_bem_system *sys, gb_error *err);
void gb_bem_system_free(gb_bem_system *sys);

/* ---------------------------------------------------------------- boundary conditions */

typedef enum {
    GB_BEM_BC_NONE = 0,            /* not set: an error when solving */
    GB_BEM_BC_FREE,                /* traction zero */
    GB_BEM_BC_FIXED,               /* displacement zero */
    GB_BEM_BC_DISPLACEMENT,        /* displacement value[0..1] */
    GB_BEM_BC_TRACTION,            /* traction value[0..1] */
    GB_BEM_BC_PRESSURE,            /* traction -value[0] n */
    GB_BEM_BC_NORMAL_DISPLACEMENT, /* displacement value[0] n (outward of the body; tangential 0) */
    GB_BEM_BC_COMPONENTS           /* per component c: displacement value[c] if bit c of
                                      u_given is set, else traction value[c] (rollers, symmetry) */
} gb_bem_bc_kind;

typedef struct {
    gb_bem_bc_kind kind;
    double value[2];
    int u_given; /* GB_BEM_BC_COMPONENTS only: bit 0 x, bit 1 y */
} gb_bem_bc;

/* How many of value[] a condition uses: 2 (displacement, traction, component-wise), 1 (pressure,
 * normal displacement), 0 (fixed, free, none). */
int gb_bem_bc_n_values(const gb_bem_bc *bc);

typedef struct {
    gb_bem_bc bc[GB_BEM_MAX_GROUPS]; /* by mesh group index */
    double remote_stress[3];         /* sxx, syy, sxy at infinity (unbounded bodies only) */
} gb_bem_problem;

/* The degenerate-scale guard (docs/method.md section 9; defaults from gb_bem_guard_default, and NULL
 * means the defaults). A system holding G columns whose reciprocal condition (dgecon, 1-norm,
 * columns equilibrated) is below rcond_min is rebuilt at lengths where the body's half-diagonal
 * is 1/4 (exact scaling of G, no reassembly) and the better conditioned one is solved. */
typedef struct {
    double rcond_min; /* > 0: the threshold; 0 (default): 0.05 / n for n unknowns (a sound G has
                         about 1 / n); < 0: the guard is off */
} gb_bem_guard;

gb_bem_guard gb_bem_guard_default(void);

/* ---------------------------------------------------------------- solution */

typedef struct {
    int ndof;
    double *u;             /* boundary displacement, 2n (total field, remote part included) */
    double *t;             /* boundary traction, 2n (total field) */
    double rcond;          /* reciprocal condition number (1-norm, column-equilibrated) of the system solved */
    double rcond_first;    /* ... at the problem's own length scale */
    double scale;          /* length scale factor used (1: none; else the degenerate scale was avoided) */
    int rigid_constrained; /* 1: traction-only bounded body, rigid motions removed */
} gb_bem_solution;

/* Solves the mixed problem H u = G t for the unknown half of each DOF. A bounded body loaded by
 * tractions only is solved with its rigid motions constrained (zero mean displacement and
 * rotation); its tractions must be in equilibrium. Unbounded: the perturbation of the remote
 * field is solved, the outputs are total fields. */
gb_status gb_bem_solve(const gb_bem_mesh *mesh, const gb_bem_system *sys, const gb_bem_problem *prob,
                       const gb_bem_guard *guard, gb_bem_solution *sol, gb_error *err);
void gb_bem_solution_free(gb_bem_solution *sol);

/* The same with one group's displacements given element by element (u_group: 2 per element of
 * the group, in mesh order, which is gb_bem_stiffness.elem's order; total displacements, remote
 * part included): the host's whole state after a coupled solve, for its tractions elsewhere and
 * its interior fields. The group's own condition in prob is ignored. */
gb_status gb_bem_solve_group_displacement(const gb_bem_mesh *mesh, const gb_bem_system *sys, const gb_bem_problem *prob,
                                          int group, const double *u_group, const gb_bem_guard *guard,
                                          gb_bem_solution *sol, gb_error *err);

/* Displacement (2 per point) and stress (sxx, syy, sxy per point) at points inside the body
 * (H 1 with c = 1 and the stress kernels D and S). Either output may be NULL. Points on or
 * outside the boundary are refused (GB_EINPUT). */
gb_status gb_bem_interior(const gb_bem_mesh *mesh, const gb_bem_material *mat, const gb_bem_problem *prob,
                          const gb_bem_solution *sol, int npts, const double *xy, double *u, double *stress,
                          gb_error *err);

/* Boundary stress at element midpoints (sxx, syy, sxy per element) from the traction and the
 * tangential strain of the boundary displacement (central differences along each loop). */
gb_status gb_bem_boundary_stress(const gb_bem_mesh *mesh, const gb_bem_material *mat, const gb_bem_solution *sol,
                                 double *stress, gb_error *err);

/* ---------------------------------------------------------------- large displacements */

/* Material points followed through an updated-Lagrangian solve (gb_bem_solve_updated), and the
 * boundary stress it sums. Any pointer may be NULL (not wanted); npts 0: no points. */
typedef struct {
    int npts;
    double *xy;              /* 2 per point, inside the body: moved with it to their current places */
    double *u;               /* 2 per point: the sum of the increments' displacements */
    double *stress;          /* 3 per point (sxx, syy, sxy): the sum of the increments' stresses */
    double *boundary_stress; /* 3 per element: the sum of the increments' gb_bem_boundary_stress */
} gb_bem_follow;

/* The body that follows its deformed boundary (updated Lagrangian, docs/method.md section 9): the
 * problem's values (every condition's and the remote stress) applied in `increments` equal parts;
 * each part is solved as a linear problem on the current mesh (H and G assembled on it), then the
 * mesh (gb_bem_mesh_move) and the followed points move by its displacement. A pressure pushes on
 * the current normal, a normal displacement goes along it, a traction or displacement keeps its
 * direction. On return the mesh is the deformed one, sol->u the sum of the increments'
 * displacements (each element's midpoint from its first place to its last) and sol->t the sum of
 * their tractions, each on the boundary it was solved on (the current, Cauchy tractions for loads
 * that keep their direction or follow the normal; the stress is summed without rotating it, as
 * incremental linear elasticity does). rcond and scale are those of the worst-conditioned
 * increment. increments 1 is one linear solve, then the mesh moved. The elastic law is linear in
 * each increment (hypoelastic): it is not a hyperelastic material (validation/bem/README.md says
 * how far the two are apart for a thick cylinder). On an error the mesh is that of the last
 * increment that succeeded. */
#define GB_BEM_MAX_INCREMENTS 100000 /* a scene's updated_lagrangian.increments at most */
gb_status gb_bem_solve_updated(gb_bem_mesh *mesh, const gb_bem_material *mat, const gb_bem_problem *prob,
                               int increments, const gb_bem_guard *guard, gb_bem_follow *follow, gb_bem_solution *sol,
                               gb_error *err);

/* ---------------------------------------------------------------- condensed stiffness */

/* (H 7): forces F = L t on the elements of one group as a function of their displacements,
 * F = K u + f0, with every other group's condition (fixed, free, loaded) condensed out (Schur
 * complement, one LU of the mixed system through LAPACKE). K is m x m, m = 2 x (elements of the
 * group), column-major, DOFs in the group's element order (elem[]). Signs: F is the force that the
 * outside (the grains) applies to the body on each element, acting at its midpoint, to hold the
 * displacement u; the body pushes back on the grains with -F. With every other group fixed and
 * unloaded, f0 = 0 and K = (L G^-1 H) restricted to the group. */
typedef struct {
    int m;            /* 2 x number of group elements */
    int *elem;        /* mesh element index of each group element, m/2 */
    double *K;        /* m x m, column-major */
    double *f0;       /* m: the forces with the group held at u = 0 (loads elsewhere, remote stress) */
    double asymmetry; /* ||K - K^t||_F / ||K||_F */
    double rcond;     /* of the system factorised */
    double rcond_first;
    double scale;
} gb_bem_stiffness;

gb_status gb_bem_condense(const gb_bem_mesh *mesh, const gb_bem_system *sys, const gb_bem_problem *prob, int group,
                          const gb_bem_guard *guard, gb_bem_stiffness *k, gb_error *err);
/* Linear outputs of the whole boundary state (resultants, means, ...) of every load case of a
 * condensation: output o = sum_d wu[o 2n + d] u[d] + wt[o 2n + d] t[d] (total fields, 2n DOFs;
 * row-major n_out x 2n weights). out (n_out x (m + n_probs), column-major, the caller allocates)
 * receives, in column j < m, the outputs of the state with the group's DOF j displaced by one and
 * every other value and the remote stress zero, and in column m + i those of load case i with the
 * group held at u = 0. The state for group displacements u and load case i is then
 * sum_j u_j column j + column m + i: no solve per step. */
typedef struct {
    int n_out;
    const double *wu, *wt;
    double *out;
} gb_bem_outputs;

/* The same for n_probs load cases that differ only in their values (the same condition kinds on
 * every group, so one factorisation serves all: m + n_probs right-hand sides): K and f0 of
 * probs[0] in k, the f0 of probs[j] (j >= 1) in f0_more[(j - 1) m .. j m) (the caller allocates
 * (n_probs - 1) m, m = 2 x group elements; NULL when n_probs is 1). f0 is linear in the values of
 * the conditions and the remote stress: unit load cases give the response of f0 to each. `outs`
 * (NULL: none) asks for linear outputs of every case's whole boundary state. */
gb_status gb_bem_condense_loads(const gb_bem_mesh *mesh, const gb_bem_system *sys, const gb_bem_problem *probs,
                                int n_probs, int group, const gb_bem_guard *guard, gb_bem_stiffness *k,
                                double *f0_more, gb_bem_outputs *outs, gb_error *err);
void gb_bem_stiffness_free(gb_bem_stiffness *k);

/* Kelvin's fundamental solution for plane elasticity (H 1-2) and its stress kernels, at a point
 * (src/bem/kernel.c). Convention: x is the source (collocation or interior) point, y the field
 * point on the boundary, r = |y - x|, r_,i = (y_i - x_i)/r, n the outward normal at y. Plane
 * stress uses nu/(1+nu). */
typedef struct {
    double mu, nu; /* shear modulus and the effective Poisson ratio of the kernels */
    double cu;     /* 1 / (8 pi mu (1 - nu)):  u* */
    double cp;     /* -1 / (4 pi (1 - nu)):    p* */
    double cd;     /* 1 / (4 pi (1 - nu)):     D */
    double cs;     /* mu / (2 pi (1 - nu)):    S */
} gb_bem_kconst;

/* Fails (GB_EINPUT) for mu <= 0 or nu outside (-1, 0.5). */
gb_status gb_bem_kconst_init(const gb_bem_material *mat, gb_bem_kconst *k, gb_error *err);

/* u*_lk and p*_lk as 2x2 row-major [l][k]: l the load direction at x, k the component at y. */
void gb_bem_kelvin_u(const gb_bem_kconst *k, const double x[2], const double y[2], double u[4]);
void gb_bem_kelvin_p(const gb_bem_kconst *k, const double x[2], const double y[2], const double n[2], double p[4]);

/* Stress kernels: sigma_ij(x) = int D_kij t_k - int S_kij u_k. Output [k][ij], ij = xx, yy, xy. */
void gb_bem_kelvin_ds(const gb_bem_kconst *k, const double x[2], const double y[2], const double n[2], double d[6],
                      double s[6]);

#endif
