/* An elastic body filling a cavity of a boundary element host (validation programs only).
 *
 * The filling is a second BEM body whose only loop is the cavity's polygon, vertex for vertex
 * (gb_bem_mesh_from_polygons), condensed over its whole boundary with no load of its own:
 * F_f = K_f u (K_f keeps the filling's three rigid modes; the host holds them). Its loop runs
 * counter-clockwise where the host's cavity runs clockwise, so its elements are matched to the
 * host's by their midpoints and K_f is permuted into the host's cavity DOF order. With the host
 * condensed on the cavity, F_h = K_h u + f0_h (bem.h: the force the outside puts on the host), the
 * same displacement on both sides and the filling pushing the host with -F_f:
 *     K_h u + f0_h = -K_f u   ->   (K_h + K_f) u = -f0_h      (dgesv: K_h is not symmetric). */
#ifndef GB_VALIDATION_FILLING_H
#define GB_VALIDATION_FILLING_H

#include "gembem/bem.h"

typedef struct {
    gb_bem_mesh mesh;   /* the filling: one loop, group "wall" */
    gb_bem_system sys;  /* its H and G, with its own material */
    gb_bem_stiffness K; /* condensed over its whole boundary, in its own element order */
    int m;              /* 2 x the cavity's elements */
    int *match;         /* match[q]: the filling element on the host's q-th cavity element (mesh order) */
    double *K_host;     /* K_f in the host's cavity DOF order, m x m, column-major */
} v_filling;

/* Builds, assembles and condenses the filling of the host's group `cavity` (one whole loop). */
gb_status v_filling_setup(const gb_bem_mesh *host, int cavity, const gb_bem_material *mat, v_filling *f,
                          gb_error *err);
/* The interface displacement u (m, the host's cavity order = Kh->elem's) of the coupled bodies;
 * f NULL: the empty cavity, K_h u = -f0_h. */
gb_status v_filling_couple(const v_filling *f, const gb_bem_stiffness *Kh, double *u, gb_error *err);
/* The filling's whole boundary state for the interface displacement u (the host's cavity order):
 * for its interior fields (gb_bem_interior with f->sys.material and an empty problem). */
gb_status v_filling_solve(const v_filling *f, const double *u, gb_bem_solution *sol, gb_error *err);
void v_filling_free(v_filling *f);

#endif
