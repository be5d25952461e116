/* (H 7): the condensed stiffness K = L G^-1 H of one boundary group, the other groups' conditions
 * condensed out. Unknowns of the mixed system: the group's tractions (its displacements are the
 * inputs) and the unknown half of every other DOF. One LU (dgetrf) and 2m + 1 right-hand sides
 * (dgetrs): column j of K is L times the group's tractions for a unit displacement of DOF j, which
 * is the Schur complement of the other DOFs; f0 is the same with the group held fixed and the
 * other groups loaded. With every other group fixed, K is the block K_ii of L G^-1 H. Several load
 * cases with the same kinds of condition share the factorisation: one more right-hand side each. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bem/bc.h"
#include "bem/mixed.h"
#include "bem/remote.h"
#include "gembem/bem.h"

void gb_bem_stiffness_free(gb_bem_stiffness *k)
{
    if (!k) return;
    free(k->elem);
    free(k->K);
    free(k->f0);
    memset(k, 0, sizeof *k);
}

/* One load case's right-hand side: the given halves of every DOF outside the group. */
static void load_rhs(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_mixed *mx, double lambda, int group,
                     const unsigned char *tu, const double *given, double *b0)
{
    int nd = 2 * m->n;
    for (int d = 0; d < nd; d++) {
        if (given[d] == 0) continue;
        if (m->group[d / 2] == group) continue; /* the group's own (remote) displacement: below */
        if (tu[d]) {
            const double *h = sys->H + (size_t)d * (size_t)nd;
            for (int i = 0; i < nd; i++) b0[i] -= h[i] * given[d];
        } else {
            gb_bem_mixed_gcol(mx, lambda, d, given[d], b0);
        }
    }
}

/* remote field: F = L (t_pert + s_inf n) with u_pert = u - u_inf on the group */
static gb_status add_remote(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_problem *prob,
                            const gb_bem_stiffness *k, double *f0, gb_error *err)
{
    if (!gb_bem_remote_active(m, prob)) return GB_OK;
    int mm = k->m;
    double *uinf = malloc(sizeof(double) * (size_t)mm);
    if (!uinf) return gb_fail(err, GB_ENOMEM, "out of memory");
    for (int q = 0; q < mm; q += 2) {
        int e = k->elem[q / 2];
        double rt[2];
        gb_bem_remote_u(&sys->material, prob, m->mid + 2 * e, uinf + q);
        gb_bem_remote_t(prob, m->normal + 2 * e, rt);
        f0[q] += m->length[e] * rt[0];
        f0[q + 1] += m->length[e] * rt[1];
    }
    for (int q = 0; q < mm; q++)
        for (int j = 0; j < mm; j++) f0[q] -= k->K[(size_t)j * (size_t)mm + (size_t)q] * uinf[j];
    free(uinf);
    return GB_OK;
}

/* The outputs of every right-hand side's whole state (see gb_bem_outputs). Column j of B holds the
 * unknown half of every DOF (z: traction where the displacement is given, else displacement). */
static gb_status case_outputs(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_problem *probs, int n_probs,
                              int group, const unsigned char *tu, const double *given, const double *B,
                              const gb_bem_stiffness *k, gb_bem_outputs *o, gb_error *err)
{
    int nd = 2 * m->n, mm = k->m, no = o->n_out;
    double *u = malloc(sizeof(double) * (size_t)nd), *t = malloc(sizeof(double) * (size_t)nd),
           *uinf = malloc(sizeof(double) * (size_t)mm);
    if (!u || !t || !uinf) {
        free(u), free(t), free(uinf);
        return gb_fail(err, GB_ENOMEM, "out of memory for the condensation's outputs");
    }
    for (int j = 0; j < mm + n_probs; j++) {
        const double *z = B + (size_t)j * (size_t)nd;
        const double *gv = j < mm ? NULL : given + (size_t)(j - mm) * (size_t)nd;
        int unit = j < mm ? 2 * k->elem[j / 2] + j % 2 : -1;
        for (int d = 0; d < nd; d++) {
            int in_group = m->group[d / 2] == group; /* held at zero in a load case */
            double g = gv && !in_group ? gv[d] : d == unit ? 1 : 0;
            u[d] = tu[d] ? g : z[d];
            t[d] = tu[d] ? z[d] : g;
        }
        const gb_bem_problem *p = j < mm ? NULL : &probs[j - mm];
        int remote = p && gb_bem_remote_active(m, p);
        for (int e = 0; remote && e < m->n; e++) { /* total fields */
            double ru[2], rt[2];
            gb_bem_remote_u(&sys->material, p, m->mid + 2 * e, ru);
            gb_bem_remote_t(p, m->normal + 2 * e, rt);
            u[2 * e] += ru[0], u[2 * e + 1] += ru[1], t[2 * e] += rt[0], t[2 * e + 1] += rt[1];
        }
        double *col = o->out + (size_t)j * (size_t)no;
        for (int q = 0; q < no; q++) {
            const double *a = o->wu + (size_t)q * (size_t)nd, *b = o->wt + (size_t)q * (size_t)nd;
            double s = 0;
            for (int d = 0; d < nd; d++) s += a[d] * u[d] + b[d] * t[d];
            col[q] = s;
        }
        if (remote) { /* the group now moves with the remote field: take those unit states back out */
            for (int q = 0; q < mm; q += 2) gb_bem_remote_u(&sys->material, p, m->mid + 2 * k->elem[q / 2], uinf + q);
            for (int i = 0; i < mm; i++)
                for (int q = 0; q < no; q++) col[q] -= uinf[i] * o->out[(size_t)i * (size_t)no + (size_t)q];
        }
    }
    free(u), free(t), free(uinf);
    return GB_OK;
}

gb_status gb_bem_condense(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_problem *prob, int group,
                          const gb_bem_guard *guard, gb_bem_stiffness *out, gb_error *err)
{
    return gb_bem_condense_loads(m, sys, prob, 1, group, guard, out, NULL, NULL, err);
}

/* Each load case's halves with the group's condition replaced by "displacement given" (the other
 * groups keep theirs): the known half per DOF into tu, the given values into given (nd per case);
 * every case must give the same halves, so that one factorisation serves them all. */
static gb_status case_dofs(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_problem *probs, int n_probs,
                           int group, unsigned char *tu, unsigned char *tu_j, double *given, gb_error *err)
{
    size_t nd = 2 * (size_t)m->n;
    gb_status st = GB_OK;
    for (int j = 0; !st && j < n_probs; j++) {
        gb_bem_problem p = probs[j];
        p.bc[group].kind = GB_BEM_BC_FIXED;
        st = gb_bem_bc_dofs(m, &sys->material, &p, j ? tu_j : tu, given + (size_t)j * nd, err);
        if (!st && j && memcmp(tu, tu_j, nd))
            st = gb_fail(err, GB_EINPUT, "load case %d does not give the same halves (displacement or traction) as "
                                         "the first", j);
    }
    return st;
}

/* The right-hand sides, nd each: minus H's column of each of the group's mm DOFs, then each load
 * case's loads (the other groups, a remote field). */
static void condensed_rhs(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_mixed *mx, double lambda,
                          int group, const unsigned char *tu, const double *given, int n_probs,
                          const gb_bem_stiffness *out, double *B)
{
    int nd = 2 * m->n, mm = out->m;
    for (int j = 0; j < mm; j++) {
        int d = 2 * out->elem[j / 2] + j % 2;
        const double *h = sys->H + (size_t)d * (size_t)nd;
        double *b = B + (size_t)j * (size_t)nd;
        for (int i = 0; i < nd; i++) b[i] = -h[i];
    }
    for (int j = 0; j < n_probs; j++)
        load_rhs(m, sys, mx, lambda, group, tu, given + (size_t)j * (size_t)nd, B + (size_t)(mm + j) * (size_t)nd);
}

/* The solutions' tractions on the group as forces (F = L t): K's columns, f0, and the further
 * cases' f0 into f0_more. */
static void solutions_to_forces(const gb_bem_mesh *m, const double *B, int n_probs, gb_bem_stiffness *out,
                                double *f0_more)
{
    int nd = 2 * m->n, mm = out->m;
    for (int j = 0; j < mm + n_probs; j++) {
        const double *z = B + (size_t)j * (size_t)nd;
        double *col = j < mm ? out->K + (size_t)j * (size_t)mm
                             : j == mm ? out->f0 : f0_more + (size_t)(j - mm - 1) * (size_t)mm;
        for (int q = 0; q < mm; q++) {
            int e = out->elem[q / 2];
            col[q] = m->length[e] * z[2 * e + q % 2];
        }
    }
}

/* ||K - K^T|| / ||K|| (Frobenius) of an mm x mm K. */
static double asymmetry(const double *K, int mm)
{
    double num = 0, den = 0;
    for (int i = 0; i < mm; i++)
        for (int j = 0; j < mm; j++) {
            double a = K[(size_t)j * (size_t)mm + (size_t)i], b = K[(size_t)i * (size_t)mm + (size_t)j];
            num += (a - b) * (a - b);
            den += a * a;
        }
    return den > 0 ? sqrt(num / den) : 0;
}

gb_status gb_bem_condense_loads(const gb_bem_mesh *m, const gb_bem_system *sys, const gb_bem_problem *probs,
                                int n_probs, int group, const gb_bem_guard *guard, gb_bem_stiffness *out,
                                double *f0_more, gb_bem_outputs *outs, gb_error *err)
{
    memset(out, 0, sizeof *out);
    if (group < 0 || group >= m->n_groups) return gb_fail(err, GB_EINPUT, "no boundary group %d to condense on", group);
    if (n_probs < 1) return gb_fail(err, GB_EINPUT, "no load case to condense");
    int nd = 2 * m->n, ne = 0;
    for (int e = 0; e < m->n; e++) ne += m->group[e] == group;
    if (ne == 0) return gb_fail(err, GB_EINPUT, "boundary group '%s' has no elements", m->group_name[group]);
    int mm = 2 * ne;
    unsigned char *tu = malloc((size_t)nd), *tu_j = malloc((size_t)nd);
    double *given = malloc(sizeof(double) * (size_t)nd * (size_t)n_probs), *B = NULL;
    gb_bem_lu lu;
    memset(&lu, 0, sizeof lu);
    gb_status st = (!tu || !tu_j || !given) ? gb_fail(err, GB_ENOMEM, "out of memory") : GB_OK;
    if (!st) st = case_dofs(m, sys, probs, n_probs, group, tu, tu_j, given, err);
    gb_bem_mixed mx;
    double lambda = 0;
    if (!st) st = gb_bem_mixed_init(&mx, m, sys, tu, 0, err);
    if (!st) st = gb_bem_mixed_factor(&mx, guard, &lu, &lambda, &out->rcond_first, err);
    if (!st) {
        out->m = mm;
        out->elem = malloc(sizeof(int) * (size_t)ne);
        out->K = malloc(sizeof(double) * (size_t)mm * (size_t)mm);
        out->f0 = malloc(sizeof(double) * (size_t)mm);
        B = calloc((size_t)nd * (size_t)(mm + n_probs), sizeof(double));
        if (!out->elem || !out->K || !out->f0 || !B) st = gb_fail(err, GB_ENOMEM, "out of memory for the stiffness");
    }
    if (!st) {
        for (int e = 0, q = 0; e < m->n; e++)
            if (m->group[e] == group) out->elem[q++] = e;
        condensed_rhs(m, sys, &mx, lambda, group, tu, given, n_probs, out, B);
        st = gb_bem_lu_solve(&lu, mm + n_probs, B, err);
    }
    if (!st) solutions_to_forces(m, B, n_probs, out, f0_more);
    for (int j = 0; !st && j < n_probs; j++)
        st = add_remote(m, sys, &probs[j], out, j ? f0_more + (size_t)(j - 1) * (size_t)mm : out->f0, err);
    if (!st && outs) st = case_outputs(m, sys, probs, n_probs, group, tu, given, B, out, outs, err);
    if (!st) {
        out->asymmetry = asymmetry(out->K, mm);
        out->rcond = lu.rcond;
        out->scale = exp(lambda);
    }
    if (st) gb_bem_stiffness_free(out);
    gb_bem_lu_free(&lu);
    free(tu);
    free(tu_j);
    free(given);
    free(B);
    return st;
}
