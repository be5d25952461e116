/* Conjugate gradients preconditioned by a factorisation of an earlier matrix, for a backend that
 * can apply its factor (linear_cholmod.c). Private to src/solver. */
#ifndef GB_SOLVER_LINEAR_PCG_H
#define GB_SOLVER_LINEAR_PCG_H

#include "solver/linear.h"

/* out = M^-1 v with the factor M held by ctx; 0 on failure. */
typedef int (*gb_linear_apply)(void *ctx, const double *v, double *out);

/* Solves A x = rhs by CG preconditioned by apply, starting from M^-1 rhs. Returns 1 if the residual
 * reached 1e-6 of |rhs| within GB_LINEAR_ON_FACTOR_MAX steps (x holds the solution), 0 if not (A
 * not positive definite, the factor failed, out of memory). Adds its steps to *steps. */
int gb_linear_pcg(const gb_linear_matrix *A, const double *rhs, double *x, gb_linear_apply apply, void *ctx,
                  long *steps);

#endif
