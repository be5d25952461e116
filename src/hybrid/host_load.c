/* Loading the host in steps (the coupling of docs/method.md section 10): f0 of the condensed
 * cavity is linear in the boundary values of the other groups and in the remote stress, so the
 * condensation computes, once and with the same factorisation, f0's response to a unit value of
 * each (and the groups' resultants' responses, for host_steps.csv); a load step then only adds up
 * those responses. */
#include <stdlib.h>
#include <string.h>

#include "hybrid/host.h"

int gb_host_group_values(const gb_host *h, int g)
{
    if (g < 0 || g >= h->mesh.n_groups || g == h->cavity) return 0;
    return gb_bem_bc_n_values(&h->prob.bc[g]);
}

static double *load_value(gb_bem_problem *p, const gb_host_load *l)
{
    return l->group < 0 ? &p->remote_stress[l->comp] : &p->bc[l->group].value[l->comp];
}

/* How far load j is from its value at creation. */
static double load_change(const gb_host *h, const gb_host_vars *v, int j)
{
    const gb_host_load *l = &h->loads[j];
    double now = l->group < 0 ? v->remote[l->comp] : v->bc[l->group][l->comp];
    return now - h->load0[j];
}

gb_bem_problem gb_host_problem_change(const gb_host *h, const gb_host_vars *v)
{
    gb_bem_problem p = gb_host_problem(h, v);
    if (!h->rebases) return p; /* the body at rest carries no load: the values since rest are the whole values */
    for (int j = 0; j < h->n_loads; j++) *load_value(&p, &h->loads[j]) = load_change(h, v, j);
    return p;
}

gb_status gb_host_condense(gb_host *h, gb_error *err)
{
    int n = 0;
    for (int g = 0; g < h->mesh.n_groups; g++) n += gb_host_group_values(h, g);
    if (h->mesh.unbounded) n += 3;
    h->n_loads = n;
    h->loads = malloc((size_t)(n > 0 ? n : 1) * sizeof *h->loads);
    h->load0 = malloc((size_t)(n > 0 ? n : 1) * sizeof(double));
    gb_bem_problem *probs = calloc((size_t)n + 1, sizeof *probs);
    if (!h->loads || !h->load0 || !probs) {
        free(probs);
        return gb_fail(err, GB_ENOMEM, "out of memory for the host's loads");
    }
    int j = 0;
    for (int g = 0; g < h->mesh.n_groups; g++)
        for (int c = 0; c < gb_host_group_values(h, g); c++) h->loads[j].group = g, h->loads[j++].comp = c;
    for (int c = 0; j < n; c++) h->loads[j].group = -1, h->loads[j++].comp = c;
    /* load case 0: the host as it is; load case 1 + j: the same kinds of condition, every value
     * zero but load j's, which is one */
    probs[0] = h->prob;
    gb_bem_problem zero = h->prob;
    memset(zero.remote_stress, 0, sizeof zero.remote_stress);
    for (int g = 0; g < h->mesh.n_groups; g++) zero.bc[g].value[0] = zero.bc[g].value[1] = 0;
    for (j = 0; j < n; j++) {
        h->load0[j] = *load_value(&h->prob, &h->loads[j]);
        probs[1 + j] = zero;
        *load_value(&probs[1 + j], &h->loads[j]) = 1;
    }
    /* the cavity's size is known only after condensing: count its elements for the unit responses */
    int mm = 0, nd = 2 * h->mesh.n, no = 4 * h->mesh.n_groups;
    for (int e = 0; e < h->mesh.n; e++) mm += 2 * (h->mesh.group[e] == h->cavity);
    h->f0_unit = malloc((size_t)(n > 0 ? n : 1) * (size_t)mm * sizeof(double));
    h->f0_base = malloc((size_t)(mm > 0 ? mm : 1) * sizeof(double));
    h->resultant_unit = malloc((size_t)no * (size_t)(mm + n + 1) * sizeof(double));
    /* resultant weights: per group, its force (sum of L t) and mean displacement (sum of L u / its length) */
    double *wu = calloc((size_t)no * (size_t)nd, sizeof(double)), *wt = calloc((size_t)no * (size_t)nd, sizeof(double)),
           *glen = calloc((size_t)h->mesh.n_groups, sizeof(double));
    gb_status st = !h->f0_unit || !h->f0_base || !h->resultant_unit || !wu || !wt || !glen
                       ? gb_fail(err, GB_ENOMEM, "out of memory for the host's loads")
                       : GB_OK;
    for (int e = 0; !st && e < h->mesh.n; e++) glen[h->mesh.group[e]] += h->mesh.length[e];
    for (int e = 0; !st && e < h->mesh.n; e++) {
        int g = h->mesh.group[e];
        double L = h->mesh.length[e];
        for (int c = 0; c < 2; c++) {
            wt[(size_t)(4 * g + c) * (size_t)nd + (size_t)(2 * e + c)] = L;
            wu[(size_t)(4 * g + 2 + c) * (size_t)nd + (size_t)(2 * e + c)] = L / glen[g];
        }
    }
    gb_bem_outputs outs = {no, wu, wt, h->resultant_unit};
    if (!st) st = gb_bem_condense_loads(&h->mesh, &h->sys, probs, n + 1, h->cavity, NULL, &h->K, h->f0_unit, &outs, err);
    if (!st) memcpy(h->f0_base, h->K.f0, (size_t)mm * sizeof(double));
    free(probs), free(wu), free(wt), free(glen);
    return st;
}

void gb_host_group_resultant(const gb_host *h, const gb_host_vars *v, int g, double force[2], double disp[2])
{
    int no = 4 * h->mesh.n_groups, m = h->m;
    double r[4];
    const double *base = h->resultant_unit + (size_t)m * (size_t)no;
    for (int c = 0; c < 4; c++) r[c] = base[4 * g + c];
    for (int j = 0; j < m; j++) {
        const double *col = h->resultant_unit + (size_t)j * (size_t)no;
        for (int c = 0; c < 4; c++) r[c] += v->u[j] * col[4 * g + c];
    }
    for (int j = 0; j < h->n_loads; j++) {
        double dv = load_change(h, v, j);
        const double *col = h->resultant_unit + (size_t)(m + 1 + j) * (size_t)no;
        for (int c = 0; c < 4; c++) r[c] += dv * col[4 * g + c];
    }
    force[0] = r[0], force[1] = r[1], disp[0] = r[2], disp[1] = r[3];
}

void gb_host_update_f0(gb_host *h, gb_host_vars *v)
{
    memcpy(v->f0, h->f0_base, (size_t)h->m * sizeof(double));
    for (int j = 0; j < h->n_loads; j++) {
        double dv = load_change(h, v, j);
        if (dv == 0) continue;
        const double *r = h->f0_unit + (size_t)j * (size_t)h->m;
        for (int q = 0; q < h->m; q++) v->f0[q] += dv * r[q];
    }
    gb_host_update_force(h, v);
}

gb_status gb_host_add_load(gb_host *h, gb_host_vars *v, const char *group, const double inc[2], gb_error *err)
{
    int g = gb_bem_mesh_group(&h->mesh, group), n = gb_host_group_values(h, g);
    if (n == 0)
        return gb_fail(err, GB_EINPUT, "host: '%s' is not a group whose condition has values to load", group);
    for (int c = 0; c < n; c++) v->bc[g][c] += inc[c];
    gb_host_update_f0(h, v);
    return GB_OK;
}

gb_status gb_host_add_remote(gb_host *h, gb_host_vars *v, const double inc[3], gb_error *err)
{
    if (!h->mesh.unbounded) return gb_fail(err, GB_EINPUT, "host: a remote stress applies to an unbounded host only");
    for (int c = 0; c < 3; c++) v->remote[c] += inc[c];
    gb_host_update_f0(h, v);
    return GB_OK;
}
