/* solver.petsc: the PETSc solver's KSP, preconditioner, direct solver and tolerance, named from
 * short lists so that a misspelling is refused with its line and column, not deep in a run. */
#include <stdio.h>
#include <string.h>

#include "core/config.h"
#include "scene/petsc_read.h"

static const char *const KSPS[] = {"preonly", "cg", "gmres", "fgmres", "bcgs", "minres"};
static const char *const PCS[] = {"cholesky", "lu", "gamg", "hypre", "jacobi", "bjacobi", "asm", "ilu", "icc", "none"};
static const char *const FACTORS[] = {"mumps", "superlu_dist", "petsc"};
#define COUNT(a) ((int)(sizeof a / sizeof a[0]))

static gb_status one_of(gb_ymap *m, const char *key, const char *const *names, int n, char *buf, size_t cap,
                        gb_error *err)
{
    struct fy_node *v;
    gb_status st = gb_ymap_find(m, key, 0, &v, err);
    if (st || !v || (st = gb_ymap_string(m, key, 0, buf, cap, err))) return st;
    for (int k = 0; k < n; k++)
        if (!strcmp(buf, names[k])) return GB_OK;
    char list[160] = "";
    for (int k = 0; k < n; k++) {
        size_t used = strlen(list);
        snprintf(list + used, sizeof list - used, "%s'%s'", k ? ", " : "", names[k]);
    }
    return gb_yaml_fail(m->doc, v, err, "solver.petsc.%s: expected one of %s, found '%s' (other PETSc types: "
                        "solver.petsc.options)", key, list, buf);
}

gb_status gb_read_petsc(gb_ymap *solver, struct fy_node *linear_node, gb_solver_settings *sv, gb_error *err)
{
    struct fy_node *section;
    gb_status st = gb_ymap_find(solver, "petsc", 0, &section, err);
    if (st) return st;
    if (!linear_node) {
        if (!section) return GB_OK;
        return gb_yaml_fail(solver->doc, section, err, "solver.petsc: applies to linear: petsc only");
    }
    if (!GB_HAVE_PETSC)
        return gb_yaml_fail(solver->doc, linear_node, err, "solver.linear: this gembem was built without PETSc; "
                                                           "install libpetsc-real-dev and rebuild");
    gb_ymap m;
    gb_petsc_settings *p = &sv->petsc;
    if ((st = gb_ymap_map(solver, "petsc", 0, &m, err)) ||
        (st = one_of(&m, "ksp", KSPS, COUNT(KSPS), p->ksp, sizeof p->ksp, err)) ||
        (st = one_of(&m, "pc", PCS, COUNT(PCS), p->pc, sizeof p->pc, err)) ||
        (st = one_of(&m, "factor", FACTORS, COUNT(FACTORS), p->factor, sizeof p->factor, err)) ||
        (st = gb_ymap_number(&m, "rtol", GB_Y_POSITIVE, &p->rtol, err)) ||
        (st = gb_ymap_string(&m, "options", 0, p->options, sizeof p->options, err)))
        return st;
    if (!(p->rtol < 1)) return gb_yaml_fail(m.doc, m.node, err, "solver.petsc.rtol: expected below 1, found %g", p->rtol);
    return gb_ymap_close(&m, err);
}
