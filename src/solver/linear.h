/* The global solver's linear solvers (solver.linear): one interface, one backend per file
 * (linear_cholmod.c, linear_umfpack.c, linear_petsc.c; linear_none.c stands for PETSc in a build
 * without it). global.c assembles the matrix and calls a backend only through its table. The
 * backends are listed once, in src/solver/CMakeLists.txt (GB_LINEAR_SOLVERS), which CMake turns
 * into core/config.h's GB_LINEAR_SOLVERS(X): the registry here and the scene reader's names come
 * from it. Private to src/solver. */
#ifndef GB_SOLVER_LINEAR_H
#define GB_SOLVER_LINEAR_H

#include "core/config.h"
#include "gembem/scene.h"
#include "gembem/status.h"

/* The matrix: n x n in compressed columns (rows sorted within a column, both triangles stored),
 * nnz entries. The pattern (Ap, Ai) is the one last analysed; the values change between calls. */
typedef struct {
    int n, nnz;
    const int *Ap, *Ai;
    const double *Ax;
} gb_linear_matrix;

/* Which matrix a backend is given: the symmetric part of the tangent (a Cholesky factorisation),
 * the exact tangent (unsymmetric, whatever the iteration), or the symmetric part for newton:
 * damped and the exact tangent for newton: line_search. */
typedef enum { GB_SYMMETRIC, GB_UNSYMMETRIC, GB_SYMMETRIC_IF_DAMPED } gb_linear_symmetry;

/* What the last call did, for gb_global_stats. */
typedef struct {
    double factor_entries, factor_flops; /* the last factorisation's (0: the backend does not say) */
    long iterations;                     /* the last solve's Krylov iterations (0: a direct solve) */
} gb_linear_stats;

/* A backend's state for one system: opaque, each backend's own struct behind the pointer. */
typedef struct gb_linear gb_linear;

/* A correction's system solved on the previous factorisation converges within this many Krylov
 * steps or is factorised (global.c solves one on a factor for at most half as many contacts). */
enum { GB_LINEAR_ON_FACTOR_MAX = 20 };

typedef struct {
    const char *name;           /* solver.linear */
    gb_linear_kind kind;        /* gb_solver_settings.linear: the backend's place in GB_LINEAR_SOLVERS */
    gb_linear_symmetry symmetry;
    /* A solver for a symmetric (or not) matrix of the settings `set` (which outlive it). */
    gb_status (*create)(const gb_solver_settings *set, int symmetric, gb_linear **out, gb_error *err);
    /* A new pattern, with its first values (UMFPACK's analysis reads them). */
    gb_status (*analyse)(gb_linear *ls, const gb_linear_matrix *A, gb_error *err);
    /* The factorisation of A's values (a preconditioner's set-up). *singular: the matrix was not
     * positive definite (Cholesky) or was singular, so that the caller regularises. */
    gb_status (*factorise)(gb_linear *ls, const gb_linear_matrix *A, int *singular, gb_error *err);
    /* x = A^-1 rhs on the last factorisation; *singular as factorise's (an iterative solver may
     * find the preconditioner indefinite only here). */
    gb_status (*solve)(gb_linear *ls, const gb_linear_matrix *A, const double *rhs, double *x, int *singular,
                       gb_error *err);
    /* NULL, or a solve of A x = rhs by a Krylov method preconditioned by the previous factorisation
     * (of a matrix that differs from A by a few contacts' kt): *converged 1 if it reached 1e-6 of
     * |rhs| within GB_LINEAR_ON_FACTOR_MAX steps (x holds the solution), 0 if A needs a
     * factorisation. */
    gb_status (*solve_on_factor)(gb_linear *ls, const gb_linear_matrix *A, const double *rhs, double *x,
                                 int *converged, gb_error *err);
    gb_linear_stats (*statistics)(const gb_linear *ls);
    void (*free)(gb_linear *ls);
} gb_linear_backend;

/* Each backend's table, gb_linear_<name>, defined by its file. */
#define GB_LINEAR_DECLARE(name) extern const gb_linear_backend gb_linear_##name;
GB_LINEAR_SOLVERS(GB_LINEAR_DECLARE)
#undef GB_LINEAR_DECLARE

/* The backend of kind `kind` (gb_solver_settings.linear), or NULL (linear.c: the registry). */
const gb_linear_backend *gb_linear_backend_of(int kind);
/* 1 if b is given the tangent's symmetric part under the settings `set`, 0 for the exact tangent. */
int gb_linear_symmetric(const gb_linear_backend *b, const gb_solver_settings *set);

#endif
