#include "bem/bc.h"

#include "bem/remote.h"

int gb_bem_bc_n_values(const gb_bem_bc *bc)
{
    switch (bc->kind) {
    case GB_BEM_BC_DISPLACEMENT:
    case GB_BEM_BC_TRACTION:
    case GB_BEM_BC_COMPONENTS: return 2;
    case GB_BEM_BC_PRESSURE:
    case GB_BEM_BC_NORMAL_DISPLACEMENT: return 1;
    default: return 0;
    }
}

gb_status gb_bem_bc_dofs(const gb_bem_mesh *m, const gb_bem_material *mat, const gb_bem_problem *prob,
                         unsigned char *t_unknown, double *given, gb_error *err)
{
    const double *s = prob->remote_stress;
    if (!m->unbounded && (s[0] != 0 || s[1] != 0 || s[2] != 0))
        return gb_fail(err, GB_EINPUT,
                       "a remote stress applies to an unbounded body (a cavity in an infinite plane) only");
    for (int g = 0; g < m->n_groups; g++)
        if (prob->bc[g].kind <= GB_BEM_BC_NONE || prob->bc[g].kind > GB_BEM_BC_COMPONENTS)
            return gb_fail(err, GB_EINPUT, "boundary group '%s' has no condition", m->group_name[g]);
    int remote = gb_bem_remote_active(m, prob);
    for (int e = 0; e < m->n; e++) {
        const gb_bem_bc *bc = &prob->bc[m->group[e]];
        const double *n = m->normal + 2 * e;
        double v[2] = {0, 0}, r[2] = {0, 0};
        int disp = bc->kind == GB_BEM_BC_FIXED || bc->kind == GB_BEM_BC_DISPLACEMENT ||
                   bc->kind == GB_BEM_BC_NORMAL_DISPLACEMENT;
        if (bc->kind == GB_BEM_BC_DISPLACEMENT || bc->kind == GB_BEM_BC_TRACTION || bc->kind == GB_BEM_BC_COMPONENTS)
            v[0] = bc->value[0], v[1] = bc->value[1];
        if (bc->kind == GB_BEM_BC_PRESSURE) v[0] = -bc->value[0] * n[0], v[1] = -bc->value[0] * n[1];
        if (bc->kind == GB_BEM_BC_NORMAL_DISPLACEMENT) v[0] = bc->value[0] * n[0], v[1] = bc->value[0] * n[1];
        int ug[2] = {disp, disp};
        if (bc->kind == GB_BEM_BC_COMPONENTS) ug[0] = bc->u_given & 1, ug[1] = (bc->u_given >> 1) & 1;
        double ru[2] = {0, 0}, rt[2] = {0, 0};
        if (remote) {
            gb_bem_remote_u(mat, prob, m->mid + 2 * e, ru);
            gb_bem_remote_t(prob, n, rt);
        }
        for (int c = 0; c < 2; c++) {
            r[c] = ug[c] ? ru[c] : rt[c];
            t_unknown[2 * e + c] = (unsigned char)ug[c];
            given[2 * e + c] = v[c] - r[c];
        }
    }
    return GB_OK;
}
