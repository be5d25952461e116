/* CHOLMOD's supernodal Cholesky factorisation (solver.linear: cholmod): the symmetric part of the
 * tangent; a correction's system solved by conjugate gradients on the previous factor. */
#include <cholmod.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "core/blas.h"
#include "solver/linear.h"
#include "solver/linear_pcg.h"

typedef struct {
    cholmod_common cc;
    cholmod_sparse *A; /* the pattern and values, CHOLMOD's copy */
    cholmod_factor *L;
    gb_linear_stats last;
} cholmod_state;

static cholmod_state *state_of(gb_linear *ls) { return (cholmod_state *)(void *)ls; }

static void free_factors(cholmod_state *c)
{
    if (c->L) cholmod_free_factor(&c->L, &c->cc);
    if (c->A) cholmod_free_sparse(&c->A, &c->cc);
}

static gb_status create(const gb_solver_settings *set, int symmetric, gb_linear **out, gb_error *err)
{
    (void)set, (void)symmetric;
    cholmod_state *c = calloc(1, sizeof *c);
    *out = (gb_linear *)(void *)c;
    if (!c) return gb_fail(err, GB_ENOMEM, "out of memory");
    cholmod_start(&c->cc);
    c->cc.print = 0;
    c->cc.error_handler = NULL;
    return GB_OK;
}

static void free_state(gb_linear *ls)
{
    cholmod_state *c = state_of(ls);
    free_factors(c);
    cholmod_finish(&c->cc);
    free(c);
}

static gb_status analyse(gb_linear *ls, const gb_linear_matrix *M, gb_error *err)
{
    cholmod_state *c = state_of(ls);
    free_factors(c);
    size_t n = (size_t)M->n;
    c->A = cholmod_allocate_sparse(n, n, (size_t)M->nnz, 1, 1, 1, CHOLMOD_REAL, &c->cc);
    if (!c->A) return gb_fail(err, GB_ENOMEM, "CHOLMOD: cannot allocate the matrix");
    memcpy(c->A->p, M->Ap, (n + 1) * sizeof(int));
    memcpy(c->A->i, M->Ai, (size_t)M->nnz * sizeof(int));
    memcpy(c->A->x, M->Ax, (size_t)M->nnz * sizeof(double));
    c->L = cholmod_analyze(c->A, &c->cc);
    if (!c->L) return gb_fail(err, GB_ENUMERIC, "CHOLMOD analysis failed (status %d)", c->cc.status);
    return GB_OK;
}

/* CHOLMOD 3 (SuiteSparse 5.12, Debian 12) runs the assembly loops of its supernodal factorisation
 * in OpenMP regions of a compiled-in 4 threads (CHOLMOD_OMP_NUM_THREADS), whatever the cores and
 * OMP_NUM_THREADS: on this 2-core machine its threads spent most of a factorisation in futex
 * waits (94 factorisations of the 1e4-disc benchmark: 9.3 s, 3.0 s serialised). The dense work is
 * BLAS, on one thread (core/blas.h: OpenBLAS's threads add the parts of dpotrf and dgemv in another
 * order, and a 1000-grain relaxation took 212 iterations with OPENBLAS_NUM_THREADS=1 and 202 with
 * 2); the regions are made inactive (max-active-levels 0) for the factorisation and the caller's
 * setting restored. */
static gb_status factorise(gb_linear *ls, const gb_linear_matrix *M, int *singular, gb_error *err)
{
    cholmod_state *c = state_of(ls);
    memcpy(c->A->x, M->Ax, (size_t)M->nnz * sizeof(double));
    int threads = gb_blas_single(), levels = omp_get_max_active_levels();
    omp_set_max_active_levels(0);
    cholmod_factorize(c->A, c->L, &c->cc);
    omp_set_max_active_levels(levels);
    gb_blas_restore(threads);
    c->last = (gb_linear_stats){.factor_entries = c->cc.lnz, .factor_flops = c->cc.fl};
    *singular = c->cc.status == CHOLMOD_NOT_POSDEF;
    if (*singular || c->cc.status == CHOLMOD_OK) return GB_OK;
    return gb_fail(err, GB_ENUMERIC, "CHOLMOD factorisation failed (status %d)", c->cc.status);
}

/* out = M^-1 v, M the factorised matrix (on one BLAS thread, as the factorisation); 0 on failure. */
static int apply(void *ctx, const double *v, double *out)
{
    cholmod_state *c = ctx;
    size_t n = c->L->n;
    cholmod_dense B = {n, 1, n, n, (void *)v, NULL, CHOLMOD_REAL, CHOLMOD_DOUBLE};
    int threads = gb_blas_single();
    cholmod_dense *X = cholmod_solve(CHOLMOD_A, c->L, &B, &c->cc);
    gb_blas_restore(threads);
    if (!X) return 0;
    memcpy(out, X->x, n * sizeof(double));
    cholmod_free_dense(&X, &c->cc);
    return 1;
}

static gb_status solve(gb_linear *ls, const gb_linear_matrix *M, const double *rhs, double *x, int *singular,
                       gb_error *err)
{
    (void)M;
    cholmod_state *c = state_of(ls);
    *singular = 0;
    c->last.iterations = 0;
    if (!apply(c, rhs, x)) return gb_fail(err, GB_ENUMERIC, "CHOLMOD solve failed (status %d)", c->cc.status);
    return GB_OK;
}

static gb_status solve_on_factor(gb_linear *ls, const gb_linear_matrix *M, const double *rhs, double *x,
                                 int *converged, gb_error *err)
{
    (void)err;
    cholmod_state *c = state_of(ls);
    c->last.iterations = 0;
    *converged = c->L && gb_linear_pcg(M, rhs, x, apply, c, &c->last.iterations);
    return GB_OK;
}

static gb_linear_stats statistics(const gb_linear *ls) { return ((const cholmod_state *)(const void *)ls)->last; }

const gb_linear_backend gb_linear_cholmod = {
    .name = "cholmod",
    .kind = GB_LINEAR_CHOLMOD,
    .symmetry = GB_SYMMETRIC,
    .create = create,
    .analyse = analyse,
    .factorise = factorise,
    .solve = solve,
    .solve_on_factor = solve_on_factor,
    .statistics = statistics,
    .free = free_state,
};
