/* The `solver:` section of a scene: its defaults (gb_solver_defaults) and its reading. */
#include <stdio.h>
#include <string.h>

#include "core/config.h"
#include "gembem/scene.h"
#include "scene/petsc_read.h"
#include "scene/solver_read.h"
#include "scene/yaml_read.h"

gb_solver_settings gb_solver_defaults(void)
{
    gb_solver_settings s = {.alpha = 0.75, .alpha1 = 0.5, .beta = 20.0, .beta1 = 20.0, .max_iterations = 100000,
                            .method = GB_METHOD_REFERENCE, .global_alpha = 1.0, .max_move = 0.1, .cutbacks = 4,
                            .newton = GB_NEWTON_DAMPED, .threads = 1,
                            .petsc = {.ksp = "preonly", .factor = "mumps", .rtol = 1e-12}};
    return s;
}

/* solver.accuracy: a force (the absolute form, K 14), or {relative: r}, a share of each step's force
 * scale (src/gem/accuracy.c); absent: the relative default. */
static gb_status read_accuracy(gb_ymap *m, gb_solver_settings *sv, gb_error *err)
{
    struct fy_node *v;
    gb_status st = gb_ymap_find(m, "accuracy", 0, &v, err);
    if (st) return st;
    if (!v) {
        sv->accuracy_relative = GB_ACCURACY_RELATIVE_DEFAULT;
        sv->accuracy_default = 1;
        return GB_OK;
    }
    if (fy_node_get_type(v) != FYNT_MAPPING)
        return gb_ymap_number(m, "accuracy", GB_Y_REQUIRED | GB_Y_POSITIVE, &sv->accuracy, err);
    gb_ymap r;
    if ((st = gb_ymap_map(m, "accuracy", GB_Y_REQUIRED, &r, err)) ||
        (st = gb_ymap_number(&r, "relative", GB_Y_REQUIRED | GB_Y_POSITIVE, &sv->accuracy_relative, err)))
        return st;
    if (!(sv->accuracy_relative < 1)) {
        gb_ymap_find(&r, "relative", 0, &v, err);
        return gb_yaml_fail(m->doc, v, err, "solver.accuracy.relative: expected a share of the force scale in (0, 1), "
                                            "e.g. 1e-4");
    }
    return gb_ymap_close(&r, err);
}

/* The linear solvers that this gembem has, by name, in the order of their kinds (core/config.h). */
#define GB_LINEAR_NAME(name) #name,
static const char *const LINEAR[] = {GB_LINEAR_SOLVERS(GB_LINEAR_NAME)};
#undef GB_LINEAR_NAME
enum { N_LINEAR = (int)(sizeof LINEAR / sizeof LINEAR[0]) };

/* solver.linear's kind (gb_linear_kind), or -1 if it names none. */
static int linear_kind(const char *name)
{
    for (int k = 0; k < N_LINEAR; k++)
        if (!strcmp(name, LINEAR[k])) return k;
    return -1;
}

/* The refusal of an unknown solver.linear at node v, with every name it could have been. */
static gb_status unknown_linear(gb_ymap *m, struct fy_node *v, const char *linear, gb_error *err)
{
    char names[256] = "";
    for (int k = 0; k < N_LINEAR; k++) {
        size_t used = strlen(names);
        snprintf(names + used, sizeof names - used, "%s'%s'", k == 0 ? "" : k == N_LINEAR - 1 ? " or " : ", ",
                 LINEAR[k]);
    }
    return gb_yaml_fail(m->doc, v, err, "solver.linear: expected %s, found '%s'", names, linear);
}

gb_status gb_solver_section_read(gb_ymap *top, gb_solver_settings *sv, gb_error *err)
{
    gb_ymap m;
    gb_status st;
    *sv = gb_solver_defaults();
    if ((st = gb_ymap_map(top, "solver", 0, &m, err))) return st;
    char method[32] = "reference", linear[32] = "", newton[32] = "";
    if ((st = gb_ymap_string(&m, "method", 0, method, sizeof method, err)) ||
        (st = gb_ymap_string(&m, "linear", 0, linear, sizeof linear, err)) ||
        (st = gb_ymap_string(&m, "newton", 0, newton, sizeof newton, err)))
        return st;
    struct fy_node *v;
    if (!strcmp(method, "global")) sv->method = GB_METHOD_GLOBAL;
    else if (strcmp(method, "reference")) {
        gb_ymap_find(&m, "method", 0, &v, err);
        return gb_yaml_fail(m.doc, v, err, "solver.method: expected 'reference' (the GEM iteration) or 'global' "
                                           "(one sparse system), found '%s'", method);
    }
    /* The defaults (docs/solvers.md): the line search on UMFPACK, which converged where the damped
     * iteration did not (docs/solver-design.md); the damped iteration with CHOLMOD (symmetric:
     * it cannot factor the line search's exact tangent) and PETSc (whose CG needs symmetry). */
    int kind = linear[0] ? linear_kind(linear) : -1;
    if (!strcmp(newton, "line_search")) sv->newton = GB_NEWTON_LINE_SEARCH;
    else if (!newton[0] && sv->method == GB_METHOD_GLOBAL && (!linear[0] || kind == GB_LINEAR_UMFPACK))
        sv->newton = GB_NEWTON_LINE_SEARCH;
    else if (newton[0] && strcmp(newton, "damped")) {
        gb_ymap_find(&m, "newton", 0, &v, err);
        return gb_yaml_fail(m.doc, v, err, "solver.newton: expected 'damped' or 'line_search', found '%s'", newton);
    }
    gb_ymap_find(&m, "linear", 0, &v, err);
    if (linear[0] && kind < 0) return unknown_linear(&m, v, linear, err);
    sv->linear = linear[0] ? kind : sv->newton == GB_NEWTON_LINE_SEARCH ? GB_LINEAR_UMFPACK : GB_LINEAR_CHOLMOD;
    if ((st = gb_read_petsc(&m, sv->linear == GB_LINEAR_PETSC ? v : NULL, sv, err))) return st;
    /* (a linear solver that factors only the symmetric part, as CHOLMOD, is refused here too) */
    if (sv->newton == GB_NEWTON_LINE_SEARCH && (sv->method != GB_METHOD_GLOBAL || sv->linear == GB_LINEAR_CHOLMOD)) {
        gb_ymap_find(&m, "newton", 0, &v, err);
        return gb_yaml_fail(m.doc, v, err, "solver.newton: line_search is an iteration of method: global with "
                                           "linear: umfpack or petsc (its exact tangent is not symmetric)");
    }
    if ((st = gb_ymap_number(&m, "global_alpha", GB_Y_POSITIVE, &sv->global_alpha, err)) ||
        (st = gb_ymap_number(&m, "max_move", GB_Y_POSITIVE, &sv->max_move, err)))
        return st;
    if ((st = gb_ymap_number(&m, "alpha", GB_Y_POSITIVE, &sv->alpha, err)) ||
        (st = gb_ymap_number(&m, "alpha1", GB_Y_POSITIVE, &sv->alpha1, err)) ||
        (st = gb_ymap_number(&m, "beta", GB_Y_NONNEG, &sv->beta, err)) ||
        (st = gb_ymap_number(&m, "beta1", GB_Y_NONNEG, &sv->beta1, err)) ||
        (st = read_accuracy(&m, sv, err)) ||
        (st = gb_ymap_int(&m, "max_iterations", 0, 1, 2000000000L, &sv->max_iterations, err)) ||
        (st = gb_ymap_number(&m, "max_step_seconds", GB_Y_POSITIVE, &sv->max_step_seconds, err)))
        return st;
    if ((st = gb_ymap_bool(&m, "history", 0, &sv->history, err))) return st;
    long cutbacks = sv->cutbacks, threads = sv->threads;
    if ((st = gb_ymap_int(&m, "cutbacks", 0, 0, 20, &cutbacks, err)) ||
        (st = gb_ymap_int(&m, "threads", 0, 1, 1024, &threads, err)))
        return st;
    sv->cutbacks = (int)cutbacks, sv->threads = (int)threads;
    if (!(sv->alpha <= 1.5) || !(sv->alpha1 <= 1.5))
        return gb_yaml_fail(m.doc, m.node, err, "solver: expected alpha and alpha1 in (0, 1.5]; the paper uses "
                                                "alpha < 1 because neighbours move too");
    return gb_ymap_close(&m, err);
}
