/* Dense LU through LAPACKE (OpenBLAS kernels): column equilibration, factorisation, condition. */
#ifndef GB_BEM_LINALG_H
#define GB_BEM_LINALG_H

#include "gembem/status.h"

typedef struct {
    int n;
    double *a; /* n x n column-major; the caller fills it, gb_bem_lu_factor overwrites it */
    int *ipiv;
    double *cs;   /* column scale factors: A diag(cs) is factorised */
    double rcond; /* 1-norm reciprocal condition estimate of A diag(cs) (dgecon) */
    int singular; /* dgetrf met an exact zero pivot */
} gb_bem_lu;

gb_status gb_bem_lu_alloc(gb_bem_lu *lu, int n, gb_error *err);
/* Equilibrates the columns to unit max-norm, factorises (dgetrf), estimates rcond (dgecon). */
gb_status gb_bem_lu_factor(gb_bem_lu *lu, gb_error *err);
/* Solves A X = B in place (B n x nrhs, column-major, leading dimension n). */
gb_status gb_bem_lu_solve(const gb_bem_lu *lu, int nrhs, double *b, gb_error *err);
void gb_bem_lu_free(gb_bem_lu *lu);

#endif
