/* The elastic host of a hybrid scene (docs/method.md sections 9-10; hybrid paper H 1-7): its boundary
 * meshed by gmsh, condensed by the boundary element module to the stiffness of its cavity,
 * F = K u + f0 (forces F = L t that the grains must put on the cavity's elements for element
 * displacements u), and the boundary particles that carry those DOFs. */
#ifndef GB_HOST_H
#define GB_HOST_H

#include "gembem/bem.h"
#include "gembem/scene.h"

/* A loadable datum of the host: one value of a group's condition (displacement, traction,
 * pressure, component-wise), or one remote stress component of an unbounded host. */
typedef struct {
    int group; /* mesh group, or -1: the remote stress */
    int comp;  /* value[comp] of the group's condition, or remote_stress[comp] */
} gb_host_load;

/* What loading and iterations change in a host: a simulation's state holds it (src/gem/sim.h's
 * gb_state), the host (below) what stays. */
typedef struct {
    double *u;     /* cavity element displacements, m */
    double *f0;    /* the loads' part of the cavity force F = K u + f0, m (linear in bc and remote) */
    double bc[GB_BEM_MAX_GROUPS][2]; /* each group's condition values now */
    double remote[3];                /* the remote stress now (an unbounded host) */
} gb_host_vars;

typedef struct {
    gb_bem_mesh mesh;
    gb_bem_system sys;
    gb_bem_problem prob;  /* the conditions, with their values at creation (now: gb_host_vars) */
    gb_bem_stiffness K;  /* on the cavity group, in its element order; K.f0: f0 at creation (now: gb_host_vars) */
    double *Ksym;        /* (K + K^t)/2, for the symmetric (CHOLMOD) solve */
    int cavity;          /* the cavity's group index */
    int m;               /* 2 x cavity elements */
    double *force;       /* K u + f0 of the vars last passed to gb_host_update_force, m */
    /* f0 is linear in the loads: f0 = f0_base + sum_j (value_j - load0_j) f0_unit_j, so a load step
     * costs O(m n_loads) instead of a condensation. */
    int n_loads;
    gb_host_load *loads;
    double *load0;       /* the values at creation */
    double *f0_base;     /* f0 at creation, m */
    double *f0_unit;     /* m per load: f0 for a unit value of that load alone */
    /* Each group's force and mean displacement (4 per group) are linear too: their values for a
     * unit displacement of each cavity DOF (m columns), for the loads at creation (1) and for a
     * unit value of each load (n_loads); gb_host_group_resultant sums them, no solve per step. */
    double *resultant_unit;
    /* Followed boundary (gb_host_rebase): mesh, sys, K and the loads' unit responses are those of
     * the moved body; rest and rest_sys keep the body at rest, the frame of the host's whole state
     * (gb_host_solve); u_acc and t_acc (2 per element) each element's displacement and traction
     * summed over the rebases. Unset (rebases = 0) for a host at rest. */
    int rebases;
    int rebase_step;        /* the load step after which the last rebase came */
    gb_bem_mesh rest;
    gb_bem_system rest_sys;
    double *u_acc, *t_acc;
} gb_host;

/* Meshes, assembles and condenses the host, with the unit responses of f0 to every loadable value
 * (one factorisation); refuses a mesh or a condition it cannot use (GB_EINPUT). */
gb_status gb_host_create(const gb_host_def *def, gb_host **out, gb_error *err);
void gb_host_free(gb_host *h);
/* The vars of the host as created: u = 0, f0 and the values at creation. */
gb_status gb_host_vars_create(const gb_host *h, gb_host_vars *v, gb_error *err);
void gb_host_vars_free(gb_host_vars *v);
/* force = K u + f0 */
void gb_host_update_force(gb_host *h, const gb_host_vars *v);
/* Condenses the host on its cavity (h->K) and the unit responses of f0 (src/hybrid/host_load.c). */
gb_status gb_host_condense(gb_host *h, gb_error *err);
/* What gb_host_condense allocates, freed (before it runs again, or with the host). */
void gb_host_free_condensed(gb_host *h);
/* Ksym = (K + K^t) / 2, for the symmetric solve. */
void gb_host_symmetrise(gb_host *h);
/* f0 from the loads' values now (v->bc, v->remote), then the force. */
void gb_host_update_f0(gb_host *h, gb_host_vars *v);
/* Number of values of a group's condition that loading may change: 2 (displacement, traction,
 * component-wise), 1 (pressure, normal displacement) or 0 (fixed, free, the cavity). */
int gb_host_group_values(const gb_host *h, int group);
/* Adds increments to a group's condition values (inc[0..n), n = gb_host_group_values), or to the
 * remote stress of an unbounded host (sxx, syy, sxy), then updates f0 and the force. */
gb_status gb_host_add_load(gb_host *h, gb_host_vars *v, const char *group, const double inc[2], gb_error *err);
gb_status gb_host_add_remote(gb_host *h, gb_host_vars *v, const double remote_inc[3], gb_error *err);
/* The conditions with the values of v. */
gb_bem_problem gb_host_problem(const gb_host *h, const gb_host_vars *v);
/* The same with each loadable value's change since the last gb_host_rebase (before the first: the
 * values themselves, their change since the body at rest): with the cavity's u, the problem whose
 * solution is every element's displacement since then. */
gb_bem_problem gb_host_problem_change(const gb_host *h, const gb_host_vars *v);
/* The host's whole boundary state for the cavity displacements and loads of v (one solve): of a
 * followed host, the state since the last rebase plus u_acc and t_acc, in the frame of the body at
 * rest (gb_host_rest_mesh). */
gb_status gb_host_solve(const gb_host *h, const gb_host_vars *v, gb_bem_solution *sol, gb_error *err);
/* Cavity element k's displacement since rest (2): v's u, plus the sum over a followed host's rebases. */
void gb_host_cavity_displacement(const gb_host *h, const gb_host_vars *v, int k, double u[2]);
/* The body at rest: the mesh that gb_host_solve's state goes with (the host's own mesh until its
 * first rebase), and its system. */
const gb_bem_mesh *gb_host_rest_mesh(const gb_host *h);
const gb_bem_system *gb_host_rest_system(const gb_host *h);
/* A group's total force (sum of traction x length over its elements: what the outside puts on the
 * body) and its mean displacement (length-weighted), from a solution of gb_host_solve. */
void gb_host_group_sum(const gb_host *h, const gb_bem_solution *sol, int group, double force[2], double disp[2]);
/* The same for the cavity displacements and loads of v, from the unit responses: O(m + n_loads). */
void gb_host_group_resultant(const gb_host *h, const gb_host_vars *v, int group, double force[2], double disp[2]);
/* The same by name, solving for it. */
gb_status gb_host_group_force(const gb_host *h, const gb_host_vars *v, const char *group, double force[2],
                              double disp[2], gb_error *err);
/* The host follows its deformed boundary (updated Lagrangian, docs/hybrid.md): its mesh moved by
 * the displacements of every element since the last rebase (gb_host_solve, gb_bem_mesh_move), G,
 * H, K and the loads' unit responses recomputed on it, the values of the loads now taken as the
 * new values at creation; then u = 0 and f0 = the force K u + f0 of before, so that the grains'
 * equilibrium is carried over exactly, and the groups' resultants go on from their values before.
 * step: the load step it follows (rebase_step). On an error the host is unusable (free it). */
gb_status gb_host_rebase(gb_host *h, gb_host_vars *v, int step, gb_error *err);
/* What a rebase leaves, as a checkpoint holds it: the moved mesh's end points (p0, p1, 2 per
 * element each), the loads' values at the last rebase (bc and remote, as gb_host_vars), f0 then
 * (m), the groups' resultants then (4 per group), u_acc and t_acc. */
typedef struct {
    int rebases, rebase_step;
    double *p0, *p1;
    double bc[GB_BEM_MAX_GROUPS][2], remote[3];
    double *f0, *resultant, *u_acc, *t_acc;
} gb_host_followed;
/* The host's record (arrays pointing into the host: valid until it changes); rebases = 0 for a
 * host at rest. */
gb_host_followed gb_host_followed_of(const gb_host *h);
/* A host as created (never rebased) put where a record says: its mesh moved to the record's, G, H,
 * K and the unit responses recomputed, the rest as recorded, bit for bit what the rebases left. */
gb_status gb_host_follow_again(gb_host *h, const gb_host_followed *r, gb_error *err);

#endif
