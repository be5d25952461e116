/* The uniform remote field of an unbounded body: stress s_inf, strain from Hooke's law (plane
 * strain, or plane stress through nu/(1+nu)), displacement eps x (no rigid part). */
#ifndef GB_BEM_REMOTE_H
#define GB_BEM_REMOTE_H

#include "gembem/bem.h"

int gb_bem_remote_active(const gb_bem_mesh *mesh, const gb_bem_problem *prob);
void gb_bem_remote_u(const gb_bem_material *mat, const gb_bem_problem *prob, const double x[2], double u[2]);
/* Traction s_inf n on a surface of normal n. */
void gb_bem_remote_t(const gb_bem_problem *prob, const double n[2], double t[2]);

#endif
