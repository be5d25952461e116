#include "bem/linalg.h"

#include "core/blas.h"

#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

gb_status gb_bem_lu_alloc(gb_bem_lu *lu, int n, gb_error *err)
{
    memset(lu, 0, sizeof *lu);
    lu->n = n;
    lu->a = malloc(sizeof(double) * (size_t)n * (size_t)n);
    lu->ipiv = malloc(sizeof(int) * (size_t)n);
    lu->cs = malloc(sizeof(double) * (size_t)n);
    if (!lu->a || !lu->ipiv || !lu->cs) {
        gb_bem_lu_free(lu);
        return gb_fail(err, GB_ENOMEM, "out of memory for a %d x %d dense matrix", n, n);
    }
    return GB_OK;
}

void gb_bem_lu_free(gb_bem_lu *lu)
{
    if (!lu) return;
    free(lu->a);
    free(lu->ipiv);
    free(lu->cs);
    memset(lu, 0, sizeof *lu);
}

/* The LAPACK calls on one BLAS thread: the same bytes whatever OPENBLAS_NUM_THREADS (core/blas.h). */
gb_status gb_bem_lu_factor(gb_bem_lu *lu, gb_error *err)
{
    size_t n = (size_t)lu->n;
    for (size_t j = 0; j < n; j++) {
        double *c = lu->a + j * n, mx = 0;
        for (size_t i = 0; i < n; i++) mx = fmax(mx, fabs(c[i]));
        if (!isfinite(mx)) return gb_fail(err, GB_ENUMERIC, "the boundary element system has non-finite entries");
        lu->cs[j] = mx > 0 ? 1 / mx : 1;
        for (size_t i = 0; i < n; i++) c[i] *= lu->cs[j];
    }
    double anorm = LAPACKE_dlange(LAPACK_COL_MAJOR, '1', lu->n, lu->n, lu->a, lu->n);
    int threads = gb_blas_single();
    lapack_int info = LAPACKE_dgetrf(LAPACK_COL_MAJOR, lu->n, lu->n, lu->a, lu->n, lu->ipiv);
    gb_blas_restore(threads);
    if (info < 0) return gb_fail(err, GB_EINTERNAL, "dgetrf: bad argument %d", (int)-info);
    lu->singular = info > 0;
    lu->rcond = 0;
    if (!lu->singular) {
        info = LAPACKE_dgecon(LAPACK_COL_MAJOR, '1', lu->n, lu->a, lu->n, anorm, &lu->rcond);
        if (info < 0) return gb_fail(err, GB_EINTERNAL, "dgecon: bad argument %d", (int)-info);
    }
    return GB_OK;
}

gb_status gb_bem_lu_solve(const gb_bem_lu *lu, int nrhs, double *b, gb_error *err)
{
    if (lu->singular) return gb_fail(err, GB_ENUMERIC, "the boundary element system is singular");
    int threads = gb_blas_single();
    lapack_int info = LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'N', lu->n, nrhs, lu->a, lu->n, lu->ipiv, b, lu->n);
    gb_blas_restore(threads);
    if (info < 0) return gb_fail(err, GB_EINTERNAL, "dgetrs: bad argument %d", (int)-info);
    size_t n = (size_t)lu->n;
    for (int r = 0; r < nrhs; r++)
        for (size_t i = 0; i < n; i++) b[(size_t)r * n + i] *= lu->cs[i];
    return GB_OK;
}
