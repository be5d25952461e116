/* Boundary conditions per DOF: which half is given and its value, as the perturbation of the
 * remote field for an unbounded body with a remote stress. */
#ifndef GB_BEM_BC_H
#define GB_BEM_BC_H

#include "gembem/bem.h"

/* t_unknown[d] = 1 where the displacement is given (value in given[d]), 0 where the traction is.
 * Checks that every group has a condition and that a remote stress goes with an unbounded body. */
gb_status gb_bem_bc_dofs(const gb_bem_mesh *mesh, const gb_bem_material *mat, const gb_bem_problem *prob,
                         unsigned char *t_unknown, double *given, gb_error *err);

#endif
