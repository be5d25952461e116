/* Conjugate gradients preconditioned by an earlier factorisation: after a correction that gives kt
 * back to a few contacts the matrix differs from the factorised one by a matrix of low rank, and
 * CG converges in about that many steps, each a pair of triangular solves, far cheaper than a new
 * factorisation. The solution is an inexact Newton step: the next iteration corrects what it
 * leaves. */
#include <stdlib.h>
#include <string.h>

#include "solver/linear_pcg.h"

/* y = A v (both triangles are stored). */
static void matvec(const gb_linear_matrix *A, const double *v, double *y)
{
    memset(y, 0, (size_t)A->n * sizeof(double));
    for (int c = 0; c < A->n; c++)
        for (int q = A->Ap[c]; q < A->Ap[c + 1]; q++) y[A->Ai[q]] += A->Ax[q] * v[c];
}

int gb_linear_pcg(const gb_linear_matrix *A, const double *rhs, double *x, gb_linear_apply apply, void *ctx,
                  long *steps)
{
    size_t n = (size_t)A->n;
    double *r = malloc(n * sizeof(double)), *z = malloc(n * sizeof(double)), *p = malloc(n * sizeof(double)),
           *Ap = malloc(n * sizeof(double));
    int ok = 0;
    if (!r || !z || !p || !Ap || !apply(ctx, rhs, x)) goto done;
    double bb = 0, rz = 0;
    matvec(A, x, Ap);
    for (size_t k = 0; k < n; k++) r[k] = rhs[k] - Ap[k], bb += rhs[k] * rhs[k];
    double tol2 = 1e-12 * bb;
    for (int it = 0; it <= GB_LINEAR_ON_FACTOR_MAX; it++) {
        double rr = 0;
        for (size_t k = 0; k < n; k++) rr += r[k] * r[k];
        if (!(rr > tol2)) {
            ok = rr == rr;
            break;
        }
        if (it == GB_LINEAR_ON_FACTOR_MAX || !apply(ctx, r, z)) break;
        double rz1 = 0;
        for (size_t k = 0; k < n; k++) rz1 += r[k] * z[k];
        double beta = it ? rz1 / rz : 0;
        rz = rz1;
        /* (the first direction is z itself: p holds no value yet, and 0 times garbage may be NaN) */
        for (size_t k = 0; k < n; k++) p[k] = it ? z[k] + beta * p[k] : z[k];
        matvec(A, p, Ap);
        double pAp = 0;
        for (size_t k = 0; k < n; k++) pAp += p[k] * Ap[k];
        if (!(pAp > 0)) break; /* not positive definite: factorise */
        double alpha = rz / pAp;
        for (size_t k = 0; k < n; k++) x[k] += alpha * p[k], r[k] -= alpha * Ap[k];
        (*steps)++;
    }
done:
    free(r), free(z), free(p), free(Ap);
    return ok;
}
