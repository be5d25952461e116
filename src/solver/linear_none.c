/* gembem without PETSc: no distributed linear solver. The scene reader refuses
 * solver.linear: petsc (gb_petsc_available), so that these are never reached by a run. */
#include "gembem/petsc.h"
#include "solver/linear_petsc.h"

int gb_petsc_available(void) { return 0; }

int gb_petsc_ranks(void) { return 1; }

int gb_petsc_serve(int *code)
{
    *code = 0;
    return 0;
}

gb_status gb_petsc_create(const gb_petsc_settings *s, int symmetric, gb_petsc **out, gb_error *err)
{
    (void)s, (void)symmetric;
    *out = NULL;
    return gb_fail(err, GB_EINPUT, "this gembem was built without PETSc; install libpetsc-real-dev and rebuild");
}

void gb_petsc_free(gb_petsc *ps) { (void)ps; }

int gb_petsc_solve_on_factor(gb_petsc *ps, const double *Ax, const double *rhs, double *x, double *t_solve,
                             long *iterations, gb_error *err, gb_status *st)
{
    (void)ps, (void)Ax, (void)rhs, (void)x, (void)t_solve, (void)iterations, (void)err;
    *st = GB_OK;
    return 0;
}

gb_status gb_petsc_pattern(gb_petsc *ps, int n, const int *Ap, const int *Ai, gb_error *err)
{
    (void)ps, (void)n, (void)Ap, (void)Ai;
    return gb_fail(err, GB_EINPUT, "this gembem was built without PETSc");
}

int gb_petsc_solve(gb_petsc *ps, const double *Ax, const double *rhs, double *x, double *t_setup, double *t_solve,
                   long *iterations, gb_error *err, gb_status *st)
{
    (void)ps, (void)Ax, (void)rhs, (void)x, (void)t_setup, (void)t_solve, (void)iterations;
    *st = gb_fail(err, GB_EINPUT, "this gembem was built without PETSc");
    return 0;
}
