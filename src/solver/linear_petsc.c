/* The PETSc linear solver (solver.linear: petsc): the matrix that global.c assembles on rank 0
 * (compressed columns), its rows distributed over the MPI ranks, solved by a KSP (MUMPS's Cholesky
 * or LU by default; CG with GAMG or hypre, GMRES, ...), the solution gathered back to rank 0
 * (docs/scaling.md). Each operation is one function run by every rank (system_*): rank 0 calls it
 * after broadcasting a command, the workers (gb_petsc_serve) when they receive it, so that both
 * sides make the same collective calls in the same order. Without PETSc: linear_none.c. */
#define _POSIX_C_SOURCE 199309L
#include <petscksp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "gembem/petsc.h"
#include "solver/linear.h"

enum { CMD_STOP = 0, CMD_CREATE = 1, CMD_PATTERN = 2, CMD_SOLVE = 3, CMD_FREE = 4, CMD_ON_FACTOR = 5, CMD_FACTOR = 6 };

typedef struct gb_petsc gb_petsc;

/* MPI and PETSc are started once per process, and the workers keep their systems by id: this
 * process-wide state mirrors theirs. */
static struct {
    int started; /* PETSc initialised (here) and not finalised */
    int rank, size;
    int next_id;
    int broken;  /* rank 0 left a collective operation half-made: the workers are aborted, not stopped */
    gb_petsc **table; /* workers: the systems by id */
    int n_table;
} proc;

struct gb_petsc {
    int id, symmetric;
    int direct;               /* preonly with a factorisation: its factor can precondition a Krylov solve */
    gb_petsc_settings s;
    PetscInt n, m, rstart;    /* global size, this rank's rows [rstart, rstart + m) */
    PetscInt *ri, *cj;        /* this rank's rows, compressed (global columns) */
    PetscScalar *v;
    Mat A;
    KSP ksp;
    Vec b, x, x0;             /* x0: the whole solution, on rank 0 */
    VecScatter to0;
    /* rank 0: the CSR of the compressed columns it is given, and each rank's share */
    int *perm;                /* per CSC entry: its CSR entry */
    PetscScalar *csr;
    int *cnt, *dsp, *rcnt, *rdsp; /* per rank: entries and first entry, rows and first row */
    gb_linear_stats last;     /* rank 0 */
};

/* What a worker needs of a new system. */
typedef struct {
    int symmetric;
    gb_petsc_settings s;
} wire_settings;

int gb_petsc_available(void) { return 1; }

int gb_petsc_ranks(void) { return proc.started ? proc.size : 1; }

static void rows_of(PetscInt n, int r, int size, PetscInt *m, PetscInt *start)
{
    PetscInt base = n / size, rem = n % size;
    *m = base + (r < rem);
    *start = r * base + (r < rem ? r : rem);
}

/* The commands go by a non-blocking broadcast, so that an idle worker sleeps (next_command)
 * instead of spinning on a core while rank 0 runs the serial rest of the simulation. */
static void command(int cmd, int id)
{
    int h[2] = {cmd, id};
    MPI_Request rq;
    (void)MPI_Ibcast(h, 2, MPI_INT, 0, PETSC_COMM_WORLD, &rq);
    (void)MPI_Wait(&rq, MPI_STATUS_IGNORE);
}

static void next_command(int h[2])
{
    MPI_Request rq;
    int done = 0;
    (void)MPI_Ibcast(h, 2, MPI_INT, 0, PETSC_COMM_WORLD, &rq);
    struct timespec nap = {0, 200000}; /* 0.2 ms: nothing next to a solve */
    while (MPI_Test(&rq, &done, MPI_STATUS_IGNORE) == MPI_SUCCESS && !done) nanosleep(&nap, NULL);
}

static PetscErrorCode system_setup(gb_petsc *ps)
{
    PC pc;
    PetscCall(KSPCreate(PETSC_COMM_WORLD, &ps->ksp));
    PetscCall(KSPSetType(ps->ksp, ps->s.ksp));
    PetscCall(KSPGetPC(ps->ksp, &pc));
    const char *type = ps->s.pc[0] ? ps->s.pc : ps->symmetric ? PCCHOLESKY : PCLU;
    PetscCall(PCSetType(pc, type));
    if (!strcmp(type, PCLU) || !strcmp(type, PCCHOLESKY)) PetscCall(PCFactorSetMatSolverType(pc, ps->s.factor));
    PetscCall(KSPSetTolerances(ps->ksp, ps->s.rtol, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
    /* The scene's options, then the environment's again, so that PETSC_OPTIONS has the last word. */
    if (ps->s.options[0]) PetscCall(PetscOptionsInsertString(NULL, ps->s.options));
    const char *env = getenv("PETSC_OPTIONS");
    if (env) PetscCall(PetscOptionsInsertString(NULL, env));
    /* GAMG's default smoother, Chebyshev on Jacobi, is sized by an estimate of the largest
     * eigenvalue that these systems (stiffness ratios of 1e5, identity rows of held DOFs) can
     * underestimate: CG then meets an indefinite preconditioner (tests/hybrid/load_grains.yaml's
     * first step). Symmetric SOR sweeps keep it positive definite; options given win. */
    if (!strcmp(type, PCGAMG)) {
        PetscBool set;
        PetscCall(PetscOptionsHasName(NULL, NULL, "-mg_levels_ksp_type", &set));
        if (!set) PetscCall(PetscOptionsSetValue(NULL, "-mg_levels_ksp_type", "richardson"));
        PetscCall(PetscOptionsHasName(NULL, NULL, "-mg_levels_pc_type", &set));
        if (!set) PetscCall(PetscOptionsSetValue(NULL, "-mg_levels_pc_type", "sor"));
    }
    PetscCall(KSPSetFromOptions(ps->ksp));
    PetscBool preonly, factor;
    PetscCall(PetscObjectTypeCompare((PetscObject)ps->ksp, KSPPREONLY, &preonly));
    PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, &factor, PCLU, PCCHOLESKY, ""));
    ps->direct = preonly && factor;
    return 0;
}

/* A correction's system (a few contacts given kt back) by CG (GMRES if unsymmetric) preconditioned
 * by the previous factorisation, kept (PCSetReusePreconditioner): as CHOLMOD's (linear_pcg.c),
 * converged to 1e-6 of |rhs| within max_it steps or not at all.
 * `on` switches the KSP to it, then back to the scene's solver. */
typedef struct {
    char type[64];
    PetscReal rtol, atol, dtol;
    PetscInt max_it;
    KSPNormType norm;
} saved_ksp;

static PetscErrorCode krylov_on_factor(gb_petsc *ps, int on, int max_it, saved_ksp *sv)
{
    PC pc;
    PetscCall(KSPGetPC(ps->ksp, &pc));
    if (on) {
        KSPType type;
        PetscCall(KSPGetType(ps->ksp, &type));
        snprintf(sv->type, sizeof sv->type, "%s", type);
        PetscCall(KSPGetTolerances(ps->ksp, &sv->rtol, &sv->atol, &sv->dtol, &sv->max_it));
        PetscCall(KSPGetNormType(ps->ksp, &sv->norm));
        PetscCall(PCSetReusePreconditioner(pc, PETSC_TRUE));
        PetscCall(KSPSetType(ps->ksp, ps->symmetric ? KSPCG : KSPGMRES));
        PetscCall(KSPSetNormType(ps->ksp, ps->symmetric ? KSP_NORM_UNPRECONDITIONED : KSP_NORM_PRECONDITIONED));
        PetscCall(KSPSetTolerances(ps->ksp, 1e-6, 0, PETSC_DEFAULT, max_it));
        return 0;
    }
    PetscCall(PCSetReusePreconditioner(pc, PETSC_FALSE));
    PetscCall(KSPSetType(ps->ksp, sv->type));
    PetscCall(KSPSetNormType(ps->ksp, sv->norm));
    PetscCall(KSPSetTolerances(ps->ksp, sv->rtol, sv->atol, sv->dtol, sv->max_it));
    return 0;
}

static PetscErrorCode release_matrix(gb_petsc *ps)
{
    PetscCall(VecScatterDestroy(&ps->to0));
    PetscCall(VecDestroy(&ps->x0));
    PetscCall(VecDestroy(&ps->x));
    PetscCall(VecDestroy(&ps->b));
    PetscCall(MatDestroy(&ps->A));
    PetscCall(PetscFree(ps->ri));
    PetscCall(PetscFree(ps->cj));
    PetscCall(PetscFree(ps->v));
    PetscCall(PetscFree(ps->perm));
    PetscCall(PetscFree(ps->csr));
    PetscCall(PetscFree4(ps->cnt, ps->dsp, ps->rcnt, ps->rdsp));
    return 0;
}

/* Rank 0: the rows of the compressed columns (Ap, Ai), where each entry goes (ps->perm), and each
 * rank's share of rows and entries. */
static PetscErrorCode transpose(gb_petsc *ps, const int *Ap, const int *Ai, PetscInt **len, PetscInt **cols)
{
    PetscInt n = ps->n, *start;
    int nnz = Ap[n];
    PetscCall(PetscCalloc1(n, len));
    PetscCall(PetscMalloc1(nnz, cols));
    PetscCall(PetscMalloc1(nnz, &ps->perm));
    PetscCall(PetscMalloc1(nnz, &ps->csr));
    PetscCall(PetscMalloc1(n + 1, &start));
    for (int q = 0; q < nnz; q++) (*len)[Ai[q]]++;
    start[0] = 0;
    for (PetscInt r = 0; r < n; r++) start[r + 1] = start[r] + (*len)[r];
    PetscCall(PetscMalloc4(proc.size, &ps->cnt, proc.size, &ps->dsp, proc.size, &ps->rcnt, proc.size, &ps->rdsp));
    for (int r = 0; r < proc.size; r++) {
        PetscInt m, first;
        rows_of(n, r, proc.size, &m, &first);
        ps->rcnt[r] = (int)m, ps->rdsp[r] = (int)first;
        ps->dsp[r] = (int)start[first], ps->cnt[r] = (int)(start[first + m] - start[first]);
    }
    /* Columns in increasing order: each row's entries come sorted. */
    for (PetscInt c = 0; c < n; c++)
        for (int q = Ap[c]; q < Ap[c + 1]; q++) {
            PetscInt at = start[Ai[q]]++;
            (*cols)[at] = c;
            ps->perm[q] = (int)at;
        }
    PetscCall(PetscFree(start));
    return 0;
}

/* A new pattern: each rank receives its rows' columns and builds its block of the matrix. */
static PetscErrorCode system_pattern(gb_petsc *ps, PetscInt n, const int *Ap, const int *Ai)
{
    MPI_Comm comm = PETSC_COMM_WORLD;
    PetscInt *len = NULL, *cols = NULL, *mylen;
    int nnz;
    PetscCall(release_matrix(ps));
    ps->n = n;
    rows_of(n, proc.rank, proc.size, &ps->m, &ps->rstart);
    if (proc.rank == 0) PetscCall(transpose(ps, Ap, Ai, &len, &cols));
    PetscCallMPI(MPI_Scatter(ps->cnt, 1, MPI_INT, &nnz, 1, MPI_INT, 0, comm));
    PetscCall(PetscMalloc1(ps->m + 1, &mylen));
    PetscCall(PetscMalloc1(ps->m + 1, &ps->ri));
    PetscCall(PetscMalloc1(nnz + 1, &ps->cj));
    PetscCall(PetscCalloc1(nnz + 1, &ps->v));
    PetscCallMPI(MPI_Scatterv(len, ps->rcnt, ps->rdsp, MPIU_INT, mylen, (int)ps->m, MPIU_INT, 0, comm));
    PetscCallMPI(MPI_Scatterv(cols, ps->cnt, ps->dsp, MPIU_INT, ps->cj, nnz, MPIU_INT, 0, comm));
    ps->ri[0] = 0;
    for (PetscInt r = 0; r < ps->m; r++) ps->ri[r + 1] = ps->ri[r] + mylen[r];
    PetscCall(PetscFree(mylen));
    PetscCall(PetscFree(len));
    PetscCall(PetscFree(cols));
    PetscCall(MatCreateMPIAIJWithArrays(comm, ps->m, ps->m, n, n, ps->ri, ps->cj, ps->v, &ps->A));
    PetscCall(MatSetOption(ps->A, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE));
    if (ps->symmetric) {
        PetscCall(MatSetOption(ps->A, MAT_SYMMETRIC, PETSC_TRUE));
        PetscCall(MatSetOption(ps->A, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
    }
    PetscCall(MatCreateVecs(ps->A, &ps->x, &ps->b));
    PetscCall(VecScatterCreateToZero(ps->x, &ps->to0, &ps->x0));
    PetscCall(KSPSetOperators(ps->ksp, ps->A, ps->A));
    return 0;
}

/* New values, sent from rank 0 by rows. The pattern is unchanged, so that a direct solver keeps
 * its symbolic analysis. */
static PetscErrorCode system_values(gb_petsc *ps, const double *Ax)
{
    int nnz = (int)ps->ri[ps->m];
    if (proc.rank == 0)
        for (int q = 0; q < ps->cnt[proc.size - 1] + ps->dsp[proc.size - 1]; q++) ps->csr[ps->perm[q]] = Ax[q];
    PetscCallMPI(MPI_Scatterv(ps->csr, ps->cnt, ps->dsp, MPIU_SCALAR, ps->v, nnz, MPIU_SCALAR, 0, PETSC_COMM_WORLD));
    for (PetscInt r = 0; r < ps->m; r++) {
        PetscInt row = ps->rstart + r;
        PetscCall(MatSetValues(ps->A, 1, &row, ps->ri[r + 1] - ps->ri[r], ps->cj + ps->ri[r], ps->v + ps->ri[r],
                               INSERT_VALUES));
    }
    PetscCall(MatAssemblyBegin(ps->A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(ps->A, MAT_FINAL_ASSEMBLY));
    return 0;
}

/* New values and the set-up (a direct solver's numerical factorisation), done here rather than
 * inside KSPSolve so that it is timed as the factorisation. A factorisation that fails leaves its
 * preconditioner failed: the solve says so (KSP_DIVERGED_PC_FAILED). */
static PetscErrorCode system_factor(gb_petsc *ps, const double *Ax)
{
    PetscCall(system_values(ps, Ax));
    PetscCall(KSPSetOperators(ps->ksp, ps->A, ps->A));
    PetscCall(KSPSetUp(ps->ksp));
    return 0;
}

/* The right-hand side, sent from rank 0 by rows; the solve; the solution gathered to rank 0. */
static PetscErrorCode system_solve(gb_petsc *ps, const double *rhs, double *x, int *failed, PetscInt *its)
{
    PetscScalar *b;
    PetscCall(VecGetArray(ps->b, &b));
    PetscCallMPI(MPI_Scatterv(rhs, ps->rcnt, ps->rdsp, MPIU_SCALAR, b, (int)ps->m, MPIU_SCALAR, 0, PETSC_COMM_WORLD));
    PetscCall(VecRestoreArray(ps->b, &b));
    PetscCall(KSPSolve(ps->ksp, ps->b, ps->x));
    KSPConvergedReason reason;
    PetscCall(KSPGetConvergedReason(ps->ksp, &reason));
    PetscCall(KSPGetIterationNumber(ps->ksp, its));
    *failed = reason < 0 ? (int)reason : 0;
    PetscCall(VecScatterBegin(ps->to0, ps->x, ps->x0, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(ps->to0, ps->x, ps->x0, INSERT_VALUES, SCATTER_FORWARD));
    if (proc.rank == 0) {
        const PetscScalar *xa;
        PetscCall(VecGetArrayRead(ps->x0, &xa));
        memcpy(x, xa, (size_t)ps->n * sizeof(double));
        PetscCall(VecRestoreArrayRead(ps->x0, &xa));
    }
    return 0;
}

/* New values solved by the Krylov method on the previous factorisation (krylov_on_factor). */
static PetscErrorCode system_on_factor(gb_petsc *ps, const double *Ax, const double *rhs, double *x, int *failed,
                                       PetscInt *its)
{
    saved_ksp sv;
    PetscCall(system_values(ps, Ax));
    PetscCall(krylov_on_factor(ps, 1, GB_LINEAR_ON_FACTOR_MAX, &sv));
    PetscCall(KSPSetOperators(ps->ksp, ps->A, ps->A));
    PetscCall(KSPSetUp(ps->ksp));
    PetscCall(system_solve(ps, rhs, x, failed, its));
    PetscCall(krylov_on_factor(ps, 0, 0, &sv));
    return 0;
}

static PetscErrorCode system_free(gb_petsc *ps)
{
    PetscCall(release_matrix(ps));
    PetscCall(KSPDestroy(&ps->ksp));
    free(ps);
    return 0;
}

/* ---- rank 0 ---- */

static void finish(void)
{
    if (!proc.started) return;
    if (proc.rank == 0) {
        if (proc.broken) MPI_Abort(PETSC_COMM_WORLD, 1);
        command(CMD_STOP, 0);
    }
    PetscFinalize();
    free(proc.table);
    proc.started = 0;
}

/* PETSc without its signal handlers (a crash stays the program's, as without PETSc) and without
 * the command line (gembem's options are not PETSc's: PETSC_OPTIONS and the scene give those). */
static int start(void)
{
    if (PetscOptionsSetValue(NULL, "-no_signal_handler", NULL) || PetscInitializeNoArguments()) return 1;
    (void)MPI_Comm_rank(PETSC_COMM_WORLD, &proc.rank);
    (void)MPI_Comm_size(PETSC_COMM_WORLD, &proc.size);
    proc.started = 1;
    atexit(finish);
    return 0;
}

static gb_status petsc_failed(const char *what, PetscErrorCode e, gb_error *err)
{
    proc.broken = 1;
    return gb_fail(err, GB_ENUMERIC, "PETSc: %s failed (error %d; PETSc's message above)", what, (int)e);
}

static gb_petsc *state_of(gb_linear *ls) { return (gb_petsc *)(void *)ls; }

static gb_status create(const gb_solver_settings *set, int symmetric, gb_linear **out, gb_error *err)
{
    *out = NULL;
    if (!proc.started && start()) return gb_fail(err, GB_ENUMERIC, "PETSc: cannot start MPI and PETSc");
    gb_petsc *ps = calloc(1, sizeof *ps);
    if (!ps) return gb_fail(err, GB_ENOMEM, "out of memory");
    ps->id = proc.next_id++;
    ps->symmetric = symmetric;
    ps->s = set->petsc;
    command(CMD_CREATE, ps->id);
    wire_settings w = {symmetric, set->petsc};
    (void)MPI_Bcast(&w, (int)sizeof w, MPI_BYTE, 0, PETSC_COMM_WORLD);
    PetscErrorCode e = system_setup(ps);
    *out = (gb_linear *)(void *)ps;
    return e ? petsc_failed("the solver's set-up", e, err) : GB_OK;
}

static void free_state(gb_linear *ls)
{
    gb_petsc *ps = state_of(ls);
    if (proc.broken) return; /* the workers are not listening any more */
    command(CMD_FREE, ps->id);
    if (system_free(ps)) proc.broken = 1;
}

static gb_status analyse(gb_linear *ls, const gb_linear_matrix *M, gb_error *err)
{
    gb_petsc *ps = state_of(ls);
    int n = M->n;
    command(CMD_PATTERN, ps->id);
    (void)MPI_Bcast(&n, 1, MPI_INT, 0, PETSC_COMM_WORLD);
    PetscErrorCode e = system_pattern(ps, n, M->Ap, M->Ai);
    return e ? petsc_failed("the matrix's distribution", e, err) : GB_OK;
}

static gb_status factorise(gb_linear *ls, const gb_linear_matrix *M, int *singular, gb_error *err)
{
    gb_petsc *ps = state_of(ls);
    *singular = 0;
    command(CMD_FACTOR, ps->id);
    PetscErrorCode e = system_factor(ps, M->Ax);
    return e ? petsc_failed("the factorisation (the preconditioner's set-up)", e, err) : GB_OK;
}

/* A factorisation or preconditioner that failed or met an indefinite matrix shows here: *singular,
 * so that the caller regularises. */
static gb_status solve(gb_linear *ls, const gb_linear_matrix *M, const double *rhs, double *x, int *singular,
                       gb_error *err)
{
    (void)M;
    gb_petsc *ps = state_of(ls);
    int failed;
    PetscInt its = 0;
    *singular = 0;
    ps->last.iterations = 0;
    command(CMD_SOLVE, ps->id);
    PetscErrorCode e = system_solve(ps, rhs, x, &failed, &its);
    if (e) return petsc_failed("the solve", e, err);
    ps->last.iterations = its;
    if (failed == KSP_DIVERGED_PC_FAILED || failed == KSP_DIVERGED_INDEFINITE_PC ||
        failed == KSP_DIVERGED_INDEFINITE_MAT || failed == KSP_DIVERGED_BREAKDOWN)
        return *singular = 1, GB_OK;
    if (failed)
        return gb_fail(err, GB_ENUMERIC, "PETSc: the %s solve did not converge (%s after %d iterations, rtol %g)",
                       ps->s.ksp, KSPConvergedReasons[failed], (int)its, ps->s.rtol);
    return GB_OK;
}

/* With a direct solver only: an iterative KSP has no factorisation to reuse. */
static gb_status solve_on_factor(gb_linear *ls, const gb_linear_matrix *M, const double *rhs, double *x,
                                 int *converged, gb_error *err)
{
    gb_petsc *ps = state_of(ls);
    int failed;
    PetscInt its = 0;
    *converged = 0;
    ps->last.iterations = 0;
    if (!ps->direct) return GB_OK;
    command(CMD_ON_FACTOR, ps->id);
    PetscErrorCode e = system_on_factor(ps, M->Ax, rhs, x, &failed, &its);
    if (e) return petsc_failed("the solve on the previous factor", e, err);
    ps->last.iterations = its;
    *converged = !failed;
    return GB_OK;
}

static gb_linear_stats statistics(const gb_linear *ls) { return ((const struct gb_petsc *)(const void *)ls)->last; }

const gb_linear_backend gb_linear_petsc = {
    .name = "petsc",
    .kind = GB_LINEAR_PETSC,
    .symmetry = GB_SYMMETRIC_IF_DAMPED,
    .create = create,
    .analyse = analyse,
    .factorise = factorise,
    .solve = solve,
    .solve_on_factor = solve_on_factor,
    .statistics = statistics,
    .free = free_state,
};

/* ---- the workers ---- */

static PetscErrorCode serve_one(int cmd, int id)
{
    gb_petsc *ps = id >= 0 && id < proc.n_table ? proc.table[id] : NULL;
    if (cmd == CMD_CREATE) {
        wire_settings w;
        PetscCallMPI(MPI_Bcast(&w, (int)sizeof w, MPI_BYTE, 0, PETSC_COMM_WORLD));
        if (id >= proc.n_table) {
            gb_petsc **t = realloc(proc.table, (size_t)(id + 16) * sizeof *t);
            PetscCheck(t, PETSC_COMM_SELF, PETSC_ERR_MEM, "out of memory");
            memset(t + proc.n_table, 0, (size_t)(id + 16 - proc.n_table) * sizeof *t);
            proc.table = t, proc.n_table = id + 16;
        }
        PetscCheck(ps = calloc(1, sizeof *ps), PETSC_COMM_SELF, PETSC_ERR_MEM, "out of memory");
        ps->id = id, ps->symmetric = w.symmetric, ps->s = w.s;
        proc.table[id] = ps;
        return system_setup(ps);
    }
    PetscCheck(ps, PETSC_COMM_SELF, PETSC_ERR_PLIB, "gembem: no linear system %d on this rank", id);
    if (cmd == CMD_PATTERN) {
        int n;
        PetscCallMPI(MPI_Bcast(&n, 1, MPI_INT, 0, PETSC_COMM_WORLD));
        return system_pattern(ps, n, NULL, NULL);
    }
    int failed;
    PetscInt its;
    if (cmd == CMD_FACTOR) return system_factor(ps, NULL);
    if (cmd == CMD_SOLVE) return system_solve(ps, NULL, NULL, &failed, &its);
    if (cmd == CMD_ON_FACTOR) return system_on_factor(ps, NULL, NULL, NULL, &failed, &its);
    proc.table[id] = NULL;
    return system_free(ps);
}

static int launched_by_mpi(void)
{
    return getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMI_SIZE") || getenv("PMIX_RANK");
}

int gb_petsc_serve(int *code)
{
    *code = 0;
    if (!launched_by_mpi()) return 0;
    if (start()) {
        *code = 1;
        return 1;
    }
    if (proc.rank == 0) return 0;
    for (;;) {
        int h[2];
        next_command(h);
        if (h[0] == CMD_STOP) break;
        if (serve_one(h[0], h[1])) MPI_Abort(PETSC_COMM_WORLD, 1);
    }
    finish();
    return 1;
}
