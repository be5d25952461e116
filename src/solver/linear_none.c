/* gembem without PETSc: the petsc backend only refuses (the scene reader already refuses
 * solver.linear: petsc with its place, from core/config.h's GB_HAVE_PETSC), and the processes are
 * one. */
#include "gembem/petsc.h"
#include "solver/linear.h"

int gb_petsc_available(void) { return 0; }

int gb_petsc_ranks(void) { return 1; }

int gb_petsc_serve(int *code)
{
    *code = 0;
    return 0;
}

static gb_status create(const gb_solver_settings *set, int symmetric, gb_linear **out, gb_error *err)
{
    (void)set, (void)symmetric;
    *out = NULL;
    return gb_fail(err, GB_EINPUT, "this gembem was built without PETSc; install libpetsc-real-dev and rebuild");
}

/* No system is ever created: create is all global.c calls. */
const gb_linear_backend gb_linear_petsc = {
    .name = "petsc",
    .kind = GB_LINEAR_PETSC,
    .symmetry = GB_SYMMETRIC_IF_DAMPED,
    .create = create,
};
