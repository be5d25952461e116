/* The linear solvers' interface (src/solver/linear.h): the registry gives every backend that
 * core/config.h lists under its name and kind, and each backend, called only through its table,
 * solves small systems whose solutions are known exactly, reports a singular matrix as such, and
 * (where it can) solves a changed matrix on the previous factorisation.
 *   test_linear            the registry; CHOLMOD and UMFPACK
 *   test_linear petsc      PETSc (in this process, one rank), in a build with it */
#include <math.h>
#include <string.h>

#include "check.h"
#include "core/config.h"
#include "solver/linear.h"

/* Systems in compressed columns, both triangles stored, with their exact solutions (1, 2, 3):
 * symmetric positive definite, [[4 1 0] [1 3 1] [0 1 2]], b = (6, 10, 8); the same with its
 * (1, 0) entry 2 (unsymmetric), b = (6, 11, 8); the symmetric one with its (0, 0) entry 5, b =
 * (7, 10, 8). */
static const int AP[] = {0, 2, 5, 7}, AI[] = {0, 1, 0, 1, 2, 1, 2};
static const double SPD[] = {4, 1, 1, 3, 1, 1, 2}, UNSYM[] = {4, 2, 1, 3, 1, 1, 2}, CHANGED[] = {5, 1, 1, 3, 1, 1, 2};
static const double B_SPD[] = {6, 10, 8}, B_UNSYM[] = {6, 11, 8}, B_CHANGED[] = {7, 10, 8};
static const double EXACT[] = {1, 2, 3};
/* [[1 1 0] [1 1 0] [0 0 1]] (its first two rows equal): singular */
static const double SINGULAR[] = {1, 1, 1, 1, 0, 0, 1}, B_SINGULAR[] = {1, 1, 1};

static gb_linear_matrix matrix3(const double *Ax) { return (gb_linear_matrix){3, 7, AP, AI, Ax}; }

static void check_solution(const char *what, const double *x)
{
    for (int k = 0; k < 3; k++) CHECK_NEAR(x[k], EXACT[k], 1e-12);
    if (fabs(x[0] - 1) + fabs(x[1] - 2) + fabs(x[2] - 3) > 3e-12) fprintf(stderr, "  (%s)\n", what);
}

/* Analyses, factorises and solves A x = b: the solution, or -1 if it failed, 1 if singular. */
static int solve(const gb_linear_backend *b, gb_linear *ls, const gb_linear_matrix *A, const double *rhs, double *x)
{
    gb_error err = {0};
    int singular = 0;
    if (b->analyse(ls, A, &err) || b->factorise(ls, A, &singular, &err)) return fprintf(stderr, "%s\n", err.msg), -1;
    if (singular) return 1;
    if (b->solve(ls, A, rhs, x, &singular, &err)) return fprintf(stderr, "%s\n", err.msg), -1;
    return singular;
}

static void check_backend(const gb_linear_backend *b)
{
    gb_solver_settings set = gb_solver_defaults();
    set.method = GB_METHOD_GLOBAL;
    set.linear = (int)b->kind;
    gb_error err = {0};
    for (int newton = GB_NEWTON_DAMPED; newton <= GB_NEWTON_LINE_SEARCH; newton++) {
        if (newton == GB_NEWTON_LINE_SEARCH && b->symmetry != GB_SYMMETRIC_IF_DAMPED) break; /* the same matrix */
        set.newton = newton;
        int symmetric = gb_linear_symmetric(b, &set);
        gb_linear *ls = NULL;
        int st = b->create(&set, symmetric, &ls, &err);
        CHECK(st == GB_OK);
        if (st) {
            fprintf(stderr, "%s: %s\n", b->name, err.msg);
            if (ls) b->free(ls);
            return;
        }
        double x[3] = {0, 0, 0};
        gb_linear_matrix A = matrix3(symmetric ? SPD : UNSYM);
        CHECK(solve(b, ls, &A, symmetric ? B_SPD : B_UNSYM, x) == 0);
        check_solution(b->name, x);
        gb_linear_stats s = b->statistics(ls);
        if (b->kind == GB_LINEAR_CHOLMOD) CHECK(s.factor_entries == 5); /* L of a tridiagonal: no fill */
        if (symmetric && b->solve_on_factor) {
            /* a changed matrix (a rank-one change) on A's factor: CG converges in at most 2 steps */
            gb_linear_matrix C = matrix3(CHANGED);
            int converged = 0;
            memset(x, 0, sizeof x);
            CHECK(b->solve_on_factor(ls, &C, B_CHANGED, x, &converged, &err) == GB_OK);
            CHECK(converged);
            long its = b->statistics(ls).iterations;
            CHECK(its >= 1 && its <= 2);
            for (int k = 0; k < 3; k++) CHECK_NEAR(x[k], EXACT[k], 1e-9);
        }
        /* singular, analysed anew (as for a new pattern) */
        gb_linear_matrix S = matrix3(SINGULAR);
        CHECK(solve(b, ls, &S, B_SINGULAR, x) == 1);
        b->free(ls);
    }
}

int main(int argc, char **argv)
{
#define GB_LINEAR_NAME(name) #name,
    static const char *const names[] = {GB_LINEAR_SOLVERS(GB_LINEAR_NAME)};
    int n = (int)(sizeof names / sizeof names[0]);
    if (argc > 1 && !strcmp(argv[1], "petsc")) {
        CHECK(GB_HAVE_PETSC);
        check_backend(gb_linear_backend_of(GB_LINEAR_PETSC));
        TEST_END();
    }
    /* the registry: every listed name at its kind, and the public kinds at theirs */
    for (int k = 0; k < n; k++) {
        const gb_linear_backend *b = gb_linear_backend_of(k);
        CHECK(b && b->kind == (gb_linear_kind)k && !strcmp(b->name, names[k]));
        CHECK(b && b->create && b->name);
    }
    CHECK(gb_linear_backend_of(n) == NULL && gb_linear_backend_of(-1) == NULL);
    CHECK(!strcmp(gb_linear_backend_of(GB_LINEAR_CHOLMOD)->name, "cholmod"));
    CHECK(!strcmp(gb_linear_backend_of(GB_LINEAR_UMFPACK)->name, "umfpack"));
    CHECK(!strcmp(gb_linear_backend_of(GB_LINEAR_PETSC)->name, "petsc"));
    /* which matrix each is given */
    gb_solver_settings set = gb_solver_defaults();
    for (int newton = GB_NEWTON_DAMPED; newton <= GB_NEWTON_LINE_SEARCH; newton++) {
        set.newton = newton;
        CHECK(gb_linear_symmetric(gb_linear_backend_of(GB_LINEAR_CHOLMOD), &set) == 1);
        CHECK(gb_linear_symmetric(gb_linear_backend_of(GB_LINEAR_UMFPACK), &set) == 0);
        CHECK(gb_linear_symmetric(gb_linear_backend_of(GB_LINEAR_PETSC), &set) == (newton == GB_NEWTON_DAMPED));
    }
    if (!GB_HAVE_PETSC) { /* the stand-in refuses, saying how to get PETSc */
        gb_linear *ls = (gb_linear *)&set;
        gb_error err = {0};
        CHECK(gb_linear_backend_of(GB_LINEAR_PETSC)->create(&set, 1, &ls, &err) == GB_EINPUT && ls == NULL);
        CHECK(strstr(err.msg, "built without PETSc; install libpetsc-real-dev") != NULL);
    }
    check_backend(gb_linear_backend_of(GB_LINEAR_CHOLMOD));
    check_backend(gb_linear_backend_of(GB_LINEAR_UMFPACK));
    TEST_END();
}
