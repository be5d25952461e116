/* UMFPACK's LU factorisation (solver.linear: umfpack): the exact tangent, unsymmetric (the line
 * search's, and the host's whole K). */
#include <stdlib.h>
#include <umfpack.h>

#include "core/blas.h"
#include "solver/linear.h"

typedef struct {
    void *symbolic, *numeric;
    /* the pattern in 64-bit indices: the int version (umfpack_di) failed "out of memory" on the
     * 1e6-disc system with 4 GB in use and 11 GB free (its workspace is indexed by int), the long
     * version (umfpack_dl) does not have that limit */
    SuiteSparse_long *lp, *li;
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    gb_linear_stats last;
} umfpack_state;

static umfpack_state *state_of(gb_linear *ls) { return (umfpack_state *)(void *)ls; }

static void free_factors(umfpack_state *u)
{
    if (u->symbolic) umfpack_dl_free_symbolic(&u->symbolic);
    if (u->numeric) umfpack_dl_free_numeric(&u->numeric);
}

static gb_status create(const gb_solver_settings *set, int symmetric, gb_linear **out, gb_error *err)
{
    (void)set, (void)symmetric;
    umfpack_state *u = calloc(1, sizeof *u);
    *out = (gb_linear *)(void *)u;
    if (!u) return gb_fail(err, GB_ENOMEM, "out of memory");
    umfpack_dl_defaults(u->control);
    return GB_OK;
}

static void free_state(gb_linear *ls)
{
    umfpack_state *u = state_of(ls);
    free_factors(u);
    free(u->lp), free(u->li);
    free(u);
}

/* The symbolic analysis reads the values too: the caller gives the assembled matrix. */
static gb_status analyse(gb_linear *ls, const gb_linear_matrix *M, gb_error *err)
{
    umfpack_state *u = state_of(ls);
    free_factors(u);
    int n = M->n;
    SuiteSparse_long *lp = realloc(u->lp, ((size_t)n + 1) * sizeof *lp);
    if (lp) u->lp = lp;
    SuiteSparse_long *li = lp ? realloc(u->li, ((size_t)M->nnz + 1) * sizeof *li) : NULL;
    if (!li) return gb_fail(err, GB_ENOMEM, "UMFPACK: out of memory for the pattern of %d unknowns", n);
    u->li = li;
    for (int k = 0; k <= n; k++) lp[k] = M->Ap[k];
    for (int k = 0; k < M->nnz; k++) li[k] = M->Ai[k];
    SuiteSparse_long st = umfpack_dl_symbolic(n, n, lp, li, M->Ax, &u->symbolic, u->control, u->info);
    if (st != UMFPACK_OK) return gb_fail(err, GB_ENUMERIC, "UMFPACK symbolic analysis failed (status %ld)", (long)st);
    return GB_OK;
}

/* The frontal factorisation and the solve call OpenBLAS (dgemm, dgemv, ...) on one thread
 * (core/blas.h): its threads add the parts in another order. */
static gb_status factorise(gb_linear *ls, const gb_linear_matrix *M, int *singular, gb_error *err)
{
    umfpack_state *u = state_of(ls);
    if (u->numeric) umfpack_dl_free_numeric(&u->numeric);
    int threads = gb_blas_single();
    SuiteSparse_long s = umfpack_dl_numeric(u->lp, u->li, M->Ax, u->symbolic, &u->numeric, u->control, u->info);
    gb_blas_restore(threads);
    u->last = (gb_linear_stats){.factor_entries = u->info[UMFPACK_LNZ] + u->info[UMFPACK_UNZ],
                                .factor_flops = u->info[UMFPACK_FLOPS]};
    *singular = s == UMFPACK_WARNING_singular_matrix;
    if (*singular || s == UMFPACK_OK) return GB_OK;
    return gb_fail(err, GB_ENUMERIC, "UMFPACK factorisation failed (status %ld%s)", (long)s,
                   s == UMFPACK_ERROR_out_of_memory ? ": out of memory" : "");
}

static gb_status solve(gb_linear *ls, const gb_linear_matrix *M, const double *rhs, double *x, int *singular,
                       gb_error *err)
{
    umfpack_state *u = state_of(ls);
    *singular = 0;
    int threads = gb_blas_single();
    SuiteSparse_long s = umfpack_dl_solve(UMFPACK_A, u->lp, u->li, M->Ax, x, rhs, u->numeric, u->control, u->info);
    gb_blas_restore(threads);
    if (s != UMFPACK_OK) return gb_fail(err, GB_ENUMERIC, "UMFPACK solve failed (status %ld)", (long)s);
    return GB_OK;
}

static gb_linear_stats statistics(const gb_linear *ls) { return ((const umfpack_state *)(const void *)ls)->last; }

const gb_linear_backend gb_linear_umfpack = {
    .name = "umfpack",
    .kind = GB_LINEAR_UMFPACK,
    .symmetry = GB_UNSYMMETRIC,
    .create = create,
    .analyse = analyse,
    .factorise = factorise,
    .solve = solve,
    .solve_on_factor = NULL, /* a correction's system is factorised anew */
    .statistics = statistics,
    .free = free_state,
};
