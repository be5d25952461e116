/* The PETSc linear solver behind the global solver (solver.linear: petsc): the matrix that
 * global.c assembles on rank 0 (compressed columns), its rows distributed over the MPI ranks,
 * solved by a KSP (MUMPS's Cholesky or LU by default; CG with GAMG or hypre, GMRES, ...), the
 * solution gathered back to rank 0. Every function here is called on rank 0 only; the workers
 * (gb_petsc_serve) make the same collective calls on their side. Without PETSc: linear_none.c. */
#ifndef GB_LINEAR_PETSC_H
#define GB_LINEAR_PETSC_H

#include "gembem/scene.h"
#include "gembem/status.h"

typedef struct gb_petsc gb_petsc;

/* A solver for a symmetric (CHOLMOD's matrix, newton: damped) or unsymmetric (newton:
 * line_search) system; starts PETSc in this process if no launcher did. */
gb_status gb_petsc_create(const gb_petsc_settings *s, int symmetric, gb_petsc **out, gb_error *err);
void gb_petsc_free(gb_petsc *ps);
/* A new sparsity pattern: n x n, compressed columns Ap, Ai (sorted rows). */
gb_status gb_petsc_pattern(gb_petsc *ps, int n, const int *Ap, const int *Ai, gb_error *err);
/* Solves A x = rhs for the values Ax of the pattern. Returns 1 if the factorisation or the
 * preconditioner failed or met an indefinite matrix (the caller regularises), else 0 with *st
 * set (GB_OK, or a failure in err). Adds the set-up (factorisation) and solve times, and the KSP's
 * iterations. */
int gb_petsc_solve(gb_petsc *ps, const double *Ax, const double *rhs, double *x, double *t_setup, double *t_solve,
                   long *iterations, gb_error *err, gb_status *st);
/* A correction's system solved by CG (GMRES if unsymmetric) preconditioned by the previous
 * factorisation (a direct solver only), to 1e-6 of |rhs| within GB_PETSC_ON_FACTOR_MAX steps.
 * Returns 1 if it converged (x holds the solution), 0 if a factorisation is needed (or *st set). */
enum { GB_PETSC_ON_FACTOR_MAX = 20 };
int gb_petsc_solve_on_factor(gb_petsc *ps, const double *Ax, const double *rhs, double *x, double *t_solve,
                             long *iterations, gb_error *err, gb_status *st);

#endif
