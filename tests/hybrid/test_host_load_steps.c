/* Loading the host in steps: a scene of tests/hybrid run through its loading program,
 * checked at every step against references computed apart from the run:
 *  - the host's boundary values and remote stress equal the scene's initial values plus the
 *    increments of the steps done (1e-12 relative);
 *  - f0 summed from the unit responses equals a fresh condensation (gb_bem_condense) of the
 *    expected problem (1e-10 of the largest |f0|);
 *  - the forces the grains put on the boundary particles (summed from the contacts) equal the
 *    host's K u + f0 (f0 fresh), element by element (1e-8 of the largest force, or of |f0|);
 *  - the host's state solved for the coupled cavity displacements (gb_bem_solve_group_displacement)
 *    puts on the cavity's elements the forces K u + f0 (1e-8), and their sum is the grains' total
 *    body force (zero here: 1e-8);
 *  - every group's force and mean displacement summed from the unit responses (host_steps.csv)
 *    equal those of the solve (1e-10 of the largest);
 *  - the body's boundary forces balance: the sum over every group, the cavity included, of
 *    traction x length is zero to the discretisation error of constant elements (collocation
 *    does not make it exact: 1.5 % of the largest group force with 5 elements a side and rollers
 *    at the corners, 0.2 % with 40; it is 1e-12 where the scene is symmetric). Tolerance 2 %;
 *    unbounded: the cavity's force, 1e-8;
 *  - with an empty granular zone (no contact with a boundary particle), the cavity displacements
 *    and every group's force equal the boundary element module's solution of the body with a
 *    traction-free cavity (gb_bem_solve, 1e-9 of the largest).
 * Then the scene runs again and every step is bit-identical (host u and f0, grains).
 * A host that follows its boundary (`follow`: rebased after every step, host.updated_lagrangian),
 * once rebased, is checked against what stays true of it: the grains' forces equal its K u + f0;
 * the state since the last rebase, solved on the moved mesh (G, H assembled apart from the
 * condensation), puts on the cavity's elements K u + f0 minus the force carried over (1e-8); with
 * an empty granular zone the cavity displacements summed over the rebases equal the body alone
 * followed in as many increments (gb_bem_solve_updated, 1e-9 of the largest).
 *   test_host_load_steps scene.yaml [line_search | follow]
 * line_search: the global solver's newton: line_search (UMFPACK) instead of the scene's solver. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "gem/sim.h"
#include "gembem/run.h"

typedef struct {
    int n_steps, cap;
    double *rec; /* per step: host u, f0, grains x, y, rot */
    int per_step;
    int empty_steps;
} run_log;

/* The problem the scene asks for after `step` steps: initial values plus increments. */
static void expected_problem(const gb_sim *sim, int step, gb_bem_problem *p)
{
    const gb_scene *sc = sim->scene;
    const gb_host *h = sim->host;
    memset(p, 0, sizeof *p);
    for (int k = 0; k < sc->host.n_bcs; k++) p->bc[gb_bem_mesh_group(&h->mesh, sc->host.bc_group[k])] = sc->host.bc[k];
    p->bc[h->cavity].kind = GB_BEM_BC_FREE;
    memcpy(p->remote_stress, sc->host.remote_stress, sizeof p->remote_stress);
    for (int s = 0, done = 0; s < sc->n_stages && done < step; s++) {
        const gb_stage *sg = &sc->stages[s];
        int n = step - done < sg->steps ? step - done : sg->steps;
        done += n;
        if (sg->kind != GB_STAGE_HOST_LOAD && sg->kind != GB_STAGE_HOST_DISPLACEMENT) continue;
        for (int q = 0; q < sg->n_host_groups; q++) {
            gb_bem_bc *bc = &p->bc[gb_bem_mesh_group(&h->mesh, sg->host_group[q])];
            for (int c = 0; c < gb_bem_bc_n_values(bc); c++) bc->value[c] += n * sg->host_increment[q][c];
        }
        for (int c = 0; c < 3; c++) p->remote_stress[c] += n * sg->host_remote_increment[c];
    }
}

static double max_abs(const double *v, int n)
{
    double m = 0;
    for (int k = 0; k < n; k++) m = fmax(m, fabs(v[k]));
    return m;
}

static gb_status record(run_log *log, const gb_sim *sim);

/* The forces the grains put on the boundary particles (2 per particle); the number of contacts. */
static int grain_forces(const gb_sim *sim, double *grain)
{
    int n = 0;
    for (int q = 0; q < sim->state.pairs.n; q++) {
        const gb_pair *pr = &sim->state.pairs.p[q];
        if (!(pr->d > 0) || !GB_IS_PARTICLE(pr->j)) continue;
        int e = GB_PARTICLE_OF(pr->j);
        grain[2 * e] += pr->nx * pr->pn - pr->ny * pr->pt;
        grain[2 * e + 1] += pr->ny * pr->pn + pr->nx * pr->pt;
        n++;
    }
    return n;
}

/* The body alone with a free cavity, followed step by step (each step's load change one increment
 * of gb_bem_solve_updated on the mesh the ones before moved; the first from rest, the scene's
 * initial values with it): every element's displacement since rest after `steps` steps, in u (2
 * per element). */
static gb_status followed_alone(const gb_sim *sim, int steps, double *u, gb_error *err)
{
    const gb_host *h = sim->host;
    gb_bem_mesh moved;
    gb_status st = gb_bem_mesh_copy(gb_host_rest_mesh(h), &moved, err);
    for (int j = 1; j <= steps && !st; j++) { /* j = 1: from rest, the scene's initial values with it */
        gb_bem_problem before, change;
        gb_bem_solution sol;
        expected_problem(sim, j - 1, &before);
        if (j == 1) memset(before.bc, 0, sizeof before.bc), memset(before.remote_stress, 0, sizeof before.remote_stress);
        expected_problem(sim, j, &change);
        for (int g = 0; g < GB_BEM_MAX_GROUPS; g++)
            for (int c = 0; c < 2; c++) change.bc[g].value[c] -= before.bc[g].value[c];
        for (int c = 0; c < 3; c++) change.remote_stress[c] -= before.remote_stress[c];
        if ((st = gb_bem_solve_updated(&moved, &h->sys.material, &change, 1, NULL, NULL, &sol, err))) break;
        for (int k = 0; k < 2 * moved.n; k++) u[k] += sol.u[k];
        gb_bem_solution_free(&sol);
    }
    gb_bem_mesh_free(&moved);
    return st;
}

/* A step of a host rebased after every step (see the top). */
static gb_status check_followed(run_log *log, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    const gb_host *h = sim->host;
    const gb_host_vars *v = &sim->state.host;
    int m = h->m;
    CHECK(h->rebases == r->step - 1 && h->rebase_step == r->step - 1);
    size_t mm = (size_t)(m > 0 ? m : 1);
    double *grain = calloc(mm, sizeof(double)), *host = malloc(mm * sizeof(double));
    if (!grain || !host) return gb_fail(err, GB_ENOMEM, "out of memory");
    int n_bp_contacts = grain_forces(sim, grain);
    for (int q = 0; q < m; q++) {
        host[q] = v->f0[q];
        for (int j = 0; j < m; j++) host[q] += h->K.K[q + (size_t)j * m] * v->u[j];
    }
    double scale = fmax(max_abs(host, m), max_abs(v->f0, m)), dforce = 0, dcav = 0;
    for (int q = 0; q < m; q++) dforce = fmax(dforce, fabs(grain[q] - host[q]));
    CHECK(scale > 0);
    CHECK(dforce <= 1e-8 * scale);
    /* the state since the last rebase on the moved mesh: tractions x current lengths + the force carried */
    gb_bem_solution inc;
    memset(&inc, 0, sizeof inc);
    gb_bem_problem change = gb_host_problem_change(h, v);
    gb_status st = gb_bem_solve_group_displacement(&h->mesh, &h->sys, &change, h->cavity, v->u, NULL, &inc, err);
    if (st) return st;
    for (int q = 0; q < m; q++) {
        int e = h->K.elem[q / 2];
        dcav = fmax(dcav, fabs(inc.t[2 * e + q % 2] * h->mesh.length[e] + h->f0_base[q] - host[q]));
    }
    CHECK(dcav <= 1e-8 * scale);
    /* an empty granular zone: the body alone, followed in as many increments as steps */
    double du = 0, umax = 0;
    if (n_bp_contacts == 0) {
        log->empty_steps++;
        double *alone = calloc(2 * (size_t)h->mesh.n, sizeof(double));
        if (!alone) return gb_fail(err, GB_ENOMEM, "out of memory");
        if ((st = followed_alone(sim, r->step, alone, err))) return st;
        for (int q = 0; q < m / 2; q++) {
            int e = h->K.elem[q];
            for (int c = 0; c < 2; c++) {
                umax = fmax(umax, fabs(alone[2 * e + c]));
                du = fmax(du, fabs(alone[2 * e + c] - (h->u_acc[2 * e + c] + v->u[2 * q + c])));
            }
        }
        free(alone);
        CHECK(umax > 1e-7);
        CHECK(du <= 1e-9 * umax);
    }
    printf("step %d (host rebased %d times): %d particle contacts; |K u + f0| %.4g, grains - host %.2g, "
           "tractions since the rebase - host %.2g; empty zone: u %.4g, coupled - body followed alone %.2g\n",
           r->step, h->rebases, n_bp_contacts, scale, dforce, dcav, umax, du);
    gb_bem_solution_free(&inc);
    free(grain), free(host);
    return record(log, sim);
}

static gb_status check(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    run_log *log = user;
    gb_host *h = sim->host;
    const gb_host_vars *v = &sim->state.host;
    int m = h->m;
    gb_bem_problem p;
    expected_problem(sim, r->step, &p);
    for (int g = 0; g < h->mesh.n_groups; g++)
        for (int c = 0; c < 2; c++)
            CHECK_NEAR(v->bc[g][c], p.bc[g].value[c], 1e-12 * fabs(p.bc[g].value[c]));
    for (int c = 0; c < 3; c++) CHECK_NEAR(v->remote[c], p.remote_stress[c], 1e-12 * fabs(p.remote_stress[c]));

    if (h->rebases) return check_followed(log, sim, r, err);
    /* f0 against a fresh condensation */
    gb_bem_stiffness k;
    gb_status st = gb_bem_condense(&h->mesh, &h->sys, &p, h->cavity, NULL, &k, err);
    if (st) return st;
    double f0max = max_abs(k.f0, m), df0 = 0;
    for (int q = 0; q < m; q++) df0 = fmax(df0, fabs(k.f0[q] - v->f0[q]));
    CHECK(df0 <= 1e-10 * f0max);
    if (r->step == 0) { /* the state as placed is not in equilibrium */
        gb_bem_stiffness_free(&k);
        return record(log, sim);
    }

    /* grains' forces on the particles against K u + f0 */
    size_t mm = (size_t)(m > 0 ? m : 1);
    double *grain = calloc(mm, sizeof(double)), *host = malloc(mm * sizeof(double));
    if (!grain || !host) return gb_fail(err, GB_ENOMEM, "out of memory");
    int n_bp_contacts = grain_forces(sim, grain);
    for (int q = 0; q < m; q++) {
        host[q] = k.f0[q];
        for (int j = 0; j < m; j++) host[q] += k.K[q + (size_t)j * m] * v->u[j];
    }
    double scale = fmax(max_abs(host, m), f0max), dforce = 0;
    for (int q = 0; q < m; q++) dforce = fmax(dforce, fabs(grain[q] - host[q]));
    CHECK(scale > 0);
    CHECK(dforce <= 1e-8 * scale);

    /* the host's whole state: its cavity tractions are K u + f0; the grains' total body force */
    gb_bem_solution sol, ref;
    if ((st = gb_host_solve(h, v, &sol, err))) return st;
    double dcav = 0, cav[2] = {0, 0}, body[2] = {0, 0};
    for (int q = 0; q < m; q++) {
        int e = h->K.elem[q / 2];
        dcav = fmax(dcav, fabs(sol.t[2 * e + q % 2] * h->mesh.length[e] - host[q]));
        cav[q % 2] += host[q];
    }
    for (int i = 0; i < sim->state.n; i++) body[0] += sim->body[2 * i], body[1] += sim->body[2 * i + 1];
    CHECK(dcav <= 1e-8 * scale);
    CHECK(hypot(cav[0] + body[0], cav[1] + body[1]) <= 1e-8 * scale);
    free(grain);
    free(host);
    gb_bem_stiffness_free(&k);

    /* the body's boundary forces balance */
    double total[2] = {0, 0}, fmaxg = 0, umaxg = 0, gf[GB_BEM_MAX_GROUPS][2], gu[GB_BEM_MAX_GROUPS][2];
    for (int g = 0; g < h->mesh.n_groups; g++) {
        gb_host_group_sum(h, &sol, g, gf[g], gu[g]);
        total[0] += gf[g][0], total[1] += gf[g][1];
        fmaxg = fmax(fmaxg, hypot(gf[g][0], gf[g][1]));
        umaxg = fmax(umaxg, hypot(gu[g][0], gu[g][1]));
    }
    /* the resultants of host_steps.csv, summed from unit responses, against the solve */
    double dres_f = 0, dres_u = 0;
    for (int g = 0; g < h->mesh.n_groups; g++) {
        double f[2], u[2];
        gb_host_group_resultant(h, v, g, f, u);
        for (int c = 0; c < 2; c++)
            dres_f = fmax(dres_f, fabs(f[c] - gf[g][c])), dres_u = fmax(dres_u, fabs(u[c] - gu[g][c]));
    }
    CHECK(dres_f <= 1e-10 * fmax(fmaxg, scale));
    CHECK(dres_u <= 1e-10 * fmax(umaxg, max_abs(v->u, m)));
    CHECK(hypot(total[0], total[1]) <= (h->mesh.unbounded ? 1e-8 * scale : 0.02 * fmaxg));

    /* an empty granular zone: the module's own solution with a traction-free cavity */
    double du = 0, umax = 0, dgf = 0;
    if (n_bp_contacts == 0) {
        log->empty_steps++;
        memset(&ref, 0, sizeof ref);
        if ((st = gb_bem_solve(&h->mesh, &h->sys, &p, NULL, &ref, err))) return st;
        for (int q = 0; q < m / 2; q++) {
            int e = h->K.elem[q];
            for (int c = 0; c < 2; c++) {
                umax = fmax(umax, fabs(ref.u[2 * e + c]));
                du = fmax(du, fabs(ref.u[2 * e + c] - v->u[2 * q + c]));
            }
        }
        for (int g = 0; g < h->mesh.n_groups; g++) {
            double f[2], u[2];
            gb_host_group_sum(h, &ref, g, f, u);
            dgf = fmax(dgf, fmax(fabs(f[0] - gf[g][0]), fabs(f[1] - gf[g][1])));
        }
        gb_bem_solution_free(&ref);
        CHECK(r->step == 0 || umax > 1e-7);
        CHECK(du <= 1e-9 * umax);
        CHECK(dgf <= 1e-9 * fmax(fmaxg, scale));
    }
    gb_bem_solution_free(&sol);
    printf("step %d: %d particle contacts; |f0| %.4g, f0 - fresh %.2g; |K u + f0| %.4g, grains - host %.2g, "
           "tractions - host %.2g; largest group force %.4g, resultant %.2g; summed resultants - solve %.2g, %.2g; empty zone: u %.4g, coupled - module "
           "%.2g, forces %.2g\n",
           r->step, n_bp_contacts, f0max, df0, scale, dforce, dcav, fmaxg, hypot(total[0], total[1]), dres_f, dres_u, umax,
           du, dgf);
    return record(log, sim);
}

/* The step's state, for the second run. */
static gb_status record(run_log *log, const gb_sim *sim)
{
    const gb_host *h = sim->host;
    int m = h->m;
    if (log->n_steps == log->cap) {
        log->cap = log->cap ? 2 * log->cap : 16;
        log->rec = realloc(log->rec, (size_t)log->cap * (size_t)log->per_step * sizeof(double));
    }
    double *rec = log->rec + (size_t)log->n_steps++ * (size_t)log->per_step;
    memcpy(rec, sim->state.host.u, (size_t)m * sizeof(double));
    memcpy(rec + m, sim->state.host.f0, (size_t)m * sizeof(double));
    for (int i = 0; i < sim->state.n; i++) {
        const gb_grain *g = &sim->state.g[i];
        rec[2 * m + 3 * i] = g->x, rec[2 * m + 3 * i + 1] = g->y, rec[2 * m + 3 * i + 2] = g->rot;
    }
    return GB_OK;
}

static int run(const char *path, int line_search, int follow, run_log *log)
{
    gb_error err = {0};
    gb_scene sc;
    gb_sim *sim = NULL;
    gb_status st0 = gb_scene_load(path, &sc, &err);
    if (!st0 && line_search) {
        sc.solver.method = GB_METHOD_GLOBAL;
        sc.solver.linear = GB_LINEAR_UMFPACK;
        sc.solver.newton = GB_NEWTON_LINE_SEARCH;
    }
    if (!st0 && follow) sc.host.follow_every = 1;
    if (st0 || gb_sim_create(&sc, &sim, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    memset(log, 0, sizeof *log);
    log->per_step = 2 * sim->host->m + 3 * sim->state.n;
    gb_status st = gb_sim_run(sim, NULL, check, log, &err);
    if (st) fprintf(stderr, "%s\n", err.msg);
    CHECK(st == GB_OK);
    CHECK(log->n_steps == gb_scene_total_steps(&sc) + 1);
    gb_sim_free(sim);
    gb_scene_free(&sc);
    return st != GB_OK;
}

int main(int argc, char **argv)
{
    if (argc < 2 || argc > 3 || (argc == 3 && strcmp(argv[2], "line_search") && strcmp(argv[2], "follow")))
        return fprintf(stderr, "usage: %s scene.yaml [line_search | follow]\n", argv[0]), 2;
    int line_search = argc == 3 && !strcmp(argv[2], "line_search"), follow = argc == 3 && !line_search;
    run_log a, b;
    if (run(argv[1], line_search, follow, &a)) return 1;
    printf("second run\n");
    if (run(argv[1], line_search, follow, &b)) return 1;
    int same = a.n_steps == b.n_steps && a.per_step == b.per_step &&
               !memcmp(a.rec, b.rec, (size_t)a.n_steps * (size_t)a.per_step * sizeof(double));
    printf("%d steps (%d with an empty granular zone), run twice: %s\n", a.n_steps, a.empty_steps,
           same ? "identical" : "DIFFERENT");
    CHECK(same);
    free(a.rec);
    free(b.rec);
    TEST_END();
}
