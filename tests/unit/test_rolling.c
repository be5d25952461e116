/* Rolling resistance (docs/method.md section 3.1), against references computed here:
 *  1. the law on one grain-grain pair of unequal radii: mr = -kr (theta_i - theta_j) below the
 *     limit, eta R* pn at it (R* = r_i r_j / (r_i + r_j)), elastic unloading from it, opposite
 *     moments on the two grains in their fixing forces (K 5), the dissipation of a plastic step;
 *  2. the global solver's tangent (exact: solver.newton line_search, and damped) against central
 *     finite differences of the fixing forces, with one rolling contact below its limit and one
 *     beyond it (its moment then follows the overlap);
 *  3. a disc sheared between two walls (the top wall moved sideways by s), solved to equilibrium
 *     by each solver: the walls' normals are fixed, so the springs are linear and the equilibrium
 *     is exact: u = s/2, w = -kt s r / (2 (kt r^2 + kr)), mr = -kr w on each wall (below the
 *     limit); at the limit mr = eta r pn and w = (2 mr / r - kt s) / (2 kt r).
 *     Without rolling resistance the disc rolls freely (w = -s / 2r, no force);
 *  4. a disc on the bottom wall alone under its weight, its contact holding a moment m0 (from a lost
 *     neighbour): one contact with rolling resistance holds the disc (case a, not c), and each solver
 *     brings it to pt = 0 and mr = 0; the wall's normal is fixed, so the springs are linear and the
 *     path is exact: w = m0 / kr, x moved by -r w. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "gembem/run.h"
#include "solver/global_impl.h"
#include "scene_fixture.h"

static const double KN = 1e8, KT = 7e7;

static gb_pair *pair_of(gb_sim *sim, int i, int j)
{
    for (int k = 0; k < sim->state.pairs.n; k++)
        if (sim->state.pairs.p[k].i == i && sim->state.pairs.p[k].j == j) return &sim->state.pairs.p[k];
    return NULL;
}

/* Moves grain g by (dx, dy, r dw) = d, everything else held, and updates the contacts (K 6). */
static void move(gb_sim *sim, int g, const double d[3])
{
    gb_error err;
    memset(sim->scratch.dX, 0, 3 * (size_t)sim->state.n * sizeof(double));
    memcpy(&sim->scratch.dX[3 * g], d, 3 * sizeof(double));
    CHECK(gb_gem_apply_moves(sim, &err) == GB_OK);
    gb_gem_forces(sim);
}

static void law(void)
{
    /* Grains 0 (r 1) and 1 (r 0.5) overlapping by 1e-3: pn = 1e5, R* = 1/3, limit eta R* pn. */
    double ri = 1, rj = 0.5, d = 1e-3, kr = 2e6, eta = 0.3;
    gb_grain g[2] = {{0, 0, ri, 0}, {ri + rj - d, 0, rj, 0}};
    gb_box box = {-5, 5, -5, 5};
    gb_scene s = fixture_scene(g, 2, box, KN, 0, 30); /* kt = 0: the moment alone */
    s.grain_grain.kr = kr, s.grain_grain.eta = eta;
    gb_error err;
    gb_sim *sim;
    CHECK(gb_sim_create(&s, &sim, &err) == GB_OK);
    gb_gem_forces(sim);
    gb_pair *p = pair_of(sim, 0, 1);
    CHECK(p && p->d > 0);
    double pn = KN * d, limit = eta * (ri * rj / (ri + rj)) * pn; /* 1e4 dyn cm */
    /* grain 0 turns by 1e-3 rad: mr = -kr 1e-3 = -2e3 */
    double a[3] = {0, 0, ri * 1e-3};
    move(sim, 0, a);
    CHECK_NEAR(p->mr, -kr * 1e-3, 1e-9 * limit);
    /* grain 1 turns by 1e-3 too: both turned alike, no relative rolling, no moment */
    double b[3] = {0, 0, rj * 1e-3};
    move(sim, 1, b);
    CHECK_NEAR(p->mr, 0, 1e-9 * limit);
    /* grain 1 turns back by 2e-3: theta_0 - theta_1 = 2e-3, mr = -kr 2e-3 */
    double c[3] = {0, 0, -2 * rj * 1e-3};
    move(sim, 1, c);
    CHECK_NEAR(p->mr, -kr * 2e-3, 1e-9 * limit);
    /* The fixing forces' third rows (moment / r, K 5): -mr / r_i on 0, +mr / r_j on 1; no force. */
    CHECK_NEAR(sim->scratch.F[2], -p->mr / ri, 1e-9 * limit);
    CHECK_NEAR(sim->scratch.F[5], p->mr / rj, 1e-9 * limit);
    CHECK_NEAR(sim->scratch.F[0] + sim->scratch.F[3], 0, 1e-9 * pn);
    CHECK_NEAR(sim->scratch.F[1], 0, 0);
    /* grain 0 turns by -1e-2: theta_r = -8e-3, elastic mr would be 1.6e4 > limit: capped */
    double e[3] = {0, 0, -ri * 1e-2};
    move(sim, 0, e);
    CHECK_NEAR(p->mr, limit, 1e-12 * limit);
    /* a further plastic step of 1e-3 rad dissipates limit x 1e-3 (K 28's rule on the moment) */
    double diss0 = p->diss, f[3] = {0, 0, -ri * 1e-3};
    move(sim, 0, f);
    CHECK_NEAR(p->mr, limit, 1e-12 * limit);
    CHECK_NEAR(p->diss - diss0, limit * 1e-3, 1e-9 * limit * 1e-3);
    /* back by 1e-3: elastic unloading from the limit */
    double h[3] = {0, 0, ri * 1e-3};
    move(sim, 0, h);
    CHECK_NEAR(p->mr, limit - kr * 1e-3, 1e-9 * limit);
    /* the spring's energy mr^2 / (2 kr) counts in the elastic energy (K 22 with rolling) */
    CHECK_NEAR(gb_sim_elastic_energy(sim), 0.5 * pn * pn / KN + 0.5 * p->mr * p->mr / kr, 1e-9 * pn * pn / KN);
    /* The reference iteration's S: kr / r^2 on each grain's rotational diagonal (here kt = 0). */
    CHECK_NEAR(sim->scratch.S[5], kr / (ri * ri), 1e-9 * kr);
    CHECK_NEAR(sim->scratch.S[6 + 5], kr / (rj * rj), 1e-9 * kr);
    /* opening drops the moment */
    double o[3] = {-2 * d, 0, 0};
    move(sim, 0, o);
    CHECK(!(p->d > 0) && p->mr == 0);
    gb_sim_free(sim);
}

/* Entry (row: node u DOF a, column: node v DOF b) of the assembled global matrix. */
static double K_at(const gb_global *gl, int u, int a, int v, int b)
{
    int q = entry_of(gl, v, u);
    return q < 0 ? 0 : gl->Ax[gl->colstart[v] + b * gl->collen[v] + gl->adj_off[q] + a];
}

static gb_sim *triangle(gb_scene *s, gb_grain *g, gb_contact_init *ci, int newton)
{
    gb_box box = {-10, 10, -10, 10};
    *s = fixture_scene(g, 3, box, KN, KT, 30);
    s->grain_grain.kr = 0.5 * KT * 0.25, s->grain_grain.eta = 0.2;
    s->restart.contacts = ci, s->restart.n_contacts = 3;
    s->solver.method = GB_METHOD_GLOBAL;
    s->solver.linear = GB_LINEAR_UMFPACK;
    s->solver.newton = newton;
    gb_error err;
    gb_sim *sim = NULL;
    CHECK(gb_sim_create(s, &sim, &err) == GB_OK);
    if (!sim) fprintf(stderr, "%s\n", err.msg);
    gb_gem_forces(sim);
    return sim;
}

static void tangent(int newton)
{
    /* Three grains in a triangle, overlaps of about 2e-3; pair (0, 1): mr at half its limit;
     * (0, 2): mr at 1.5 its limit (it stays at the limit in every perturbed state); (1, 2): 0. */
    double l02 = 1.7 - 2e-3, l12 = 1.5 - 2.5e-3, x2 = (l02 * l02 - l12 * l12 + 1.798 * 1.798) / (2 * 1.798);
    gb_grain g[3] = {{0, 0, 1, 0}, {1.798, 0, 0.8, 0}, {x2, sqrt(l02 * l02 - x2 * x2), 0.7, 0}};
    double lim01 = 0.2 * (1 * 0.8 / 1.8) * KN * 2e-3, lim02 = 0.2 * (0.7 / 1.7) * KN * 2e-3;
    gb_contact_init ci[3] = {{0, 1, 3e3, 0.5 * lim01}, {2, 0, -2e3, -1.5 * lim02}, {1, 2, 1e3, 0}};
    gb_scene s;
    gb_sim *sim = triangle(&s, g, ci, newton);
    CHECK(sim->scratch.nc[0] == 2 && sim->scratch.nc[1] == 2 && sim->scratch.nc[2] == 2);
    CHECK(pair_of(sim, 0, 2)->mr == 1.5 * lim02); /* seen from grain 0: the sign turns */
    gb_error err;
    gb_wall_control wc = {GB_WALLS_FIXED, 0, 0, 0};
    unsigned char in_system[3];
    memset(in_system, GB_IN_SYSTEM, sizeof in_system);
    CHECK(gb_global_moves(sim->solver->global, sim, in_system, &wc, 0, &err) == GB_OK);
    double h = 1e-7, worst = 0, rolling = 0;
    for (int v = 0; v < 3; v++)
        for (int b = 0; b < 3; b++) {
            /* the damped solver's tangent leaves out the geometric and sliding terms: only its
             * rotational columns are the forces' derivatives */
            if (newton == GB_NEWTON_DAMPED && b != 2) continue;
            double Fp[9], Fm[9];
            for (int sg = 0; sg < 2; sg++) {
                gb_scene t;
                gb_grain gt[3];
                memcpy(gt, g, sizeof gt);
                gb_sim *q = triangle(&t, gt, ci, newton);
                double d[3] = {0, 0, 0};
                d[b] = sg ? -h : h;
                move(q, v, d);
                memcpy(sg ? Fm : Fp, q->scratch.F, sizeof Fp);
                gb_sim_free(q);
            }
            for (int u = 0; u < 3; u++)
                for (int a = 0; a < 3; a++) {
                    double fd = (Fp[3 * u + a] - Fm[3 * u + a]) / (2 * h), k = K_at(sim->solver->global, u, a, v, b);
                    worst = fmax(worst, fabs(fd - k));
                    if (a == 2 || b == 2) rolling = fmax(rolling, fabs(k));
                    CHECK_NEAR(k, fd, 1e-5 * KN);
                }
        }
    printf("tangent (%s): largest |K - finite differences| %.3g, kn %.3g\n",
           newton == GB_NEWTON_DAMPED ? "damped" : "exact", worst, KN);
    CHECK(rolling > 1e6); /* the entries tested are not all zero */
    /* The rolling blocks by their formulas: below the limit, K_01 (rotations) = kt - kr / (r0 r1)
     * (the tangential spring couples them by +kt: T_c^t S_c T'_c, K 25); at the limit no kr. */
    double kr = s.grain_grain.kr;
    CHECK_NEAR(K_at(sim->solver->global, 0, 2, 1, 2), KT - kr / (1 * 0.8), 1e-9 * KT);
    CHECK_NEAR(K_at(sim->solver->global, 0, 2, 2, 2), KT, 1e-9 * KT);
    gb_sim_free(sim);
}

static void sheared_disc(int solver, double kr, double eta, double tol_w)
{
    static const char *const NAMES[3] = {"reference", "global", "global line search"};
    double r = 1, delta = 1e-3, shear = 1e-4;
    gb_grain g[1] = {{5, r - delta, r, 0}};
    gb_box box = {0, 10, 0, 2 * r - 2 * delta};
    gb_scene s = fixture_scene(g, 1, box, KN, KT, 30);
    s.grain_wall.kr = kr, s.grain_wall.eta = eta;
    s.solver.accuracy = 1e-4;
    s.solver.method = solver ? GB_METHOD_GLOBAL : GB_METHOD_REFERENCE;
    s.solver.linear = GB_LINEAR_UMFPACK;
    s.solver.newton = solver == 2 ? GB_NEWTON_LINE_SEARCH : GB_NEWTON_DAMPED;
    gb_error err;
    gb_sim *sim;
    CHECK(gb_sim_create(&s, &sim, &err) == GB_OK);
    /* the top wall moves sideways by s: its contact's tangential spring and nothing else sees it */
    memset(sim->scratch.dX, 0, 3 * sizeof(double));
    memset(sim->scratch.wall_dx, 0, sizeof sim->scratch.wall_dx);
    sim->scratch.wall_dx[GB_WALL_TOP][0] = shear;
    CHECK(gb_gem_apply_moves(sim, &err) == GB_OK);
    gb_wall_control wc = {GB_WALLS_FIXED, 0, 0, 0};
    gb_solve_result res;
    gb_status st = gb_solver_relax(sim, &wc, 100000, &res, &err);
    long it = res.iterations;
    CHECK(st == GB_OK);
    if (st) fprintf(stderr, "%s: %s\n", NAMES[solver], err.msg);
    double pn = KN * delta, u = sim->state.g[0].x - 5, w = sim->state.g[0].rot;
    double w_el = kr > 0 ? -KT * shear * r / (2 * (KT * r * r + kr)) : -shear / (2 * r);
    double limit = eta * r * pn, w_want = w_el, mr_want = -kr * w_el;
    if (kr > 0 && kr * fabs(w_el) > limit) /* at the limit: mr = +-limit, the rest on the springs kt */
        mr_want = w_el < 0 ? limit : -limit, w_want = (2 * mr_want / r - KT * shear) / (2 * KT * r);
    gb_pair *bot = pair_of(sim, 0, -1 - GB_WALL_BOTTOM), *top = pair_of(sim, 0, -1 - GB_WALL_TOP);
    printf("sheared disc, %s, kr %g, eta %g: %ld iterations, w %.10g (analytic %.10g), mr %.6g %.6g (%.6g)\n",
           NAMES[solver], kr, eta, it, w, w_want, bot->mr, top->mr, mr_want);
    CHECK_NEAR(u, shear / 2, 1e-3 * shear);
    CHECK_NEAR(w, w_want, tol_w);
    CHECK_NEAR(bot->mr, mr_want, 1e-3 * fabs(mr_want) + 1e-9);
    CHECK_NEAR(top->mr, mr_want, 1e-3 * fabs(mr_want) + 1e-9);
    gb_sim_free(sim);
}

static void single_contact(int solver)
{
    double r = 1, W = 1e5, kr = 2e6, m0 = 500;
    gb_grain g[1] = {{5, r - W / KN, r, 0}};
    gb_box box = {0, 10, 0, 10};
    gb_scene s = fixture_scene(g, 1, box, KN, KT, 30);
    s.grain_wall.kr = kr, s.grain_wall.eta = 0.1;
    s.body_force_per_area[1] = -W / (3.14159265358979323846 * r * r);
    gb_contact_init ci[1] = {{0, -1 - GB_WALL_BOTTOM, 0, m0}};
    s.restart.contacts = ci, s.restart.n_contacts = 1;
    s.solver.accuracy = 1e-3;
    s.solver.method = solver ? GB_METHOD_GLOBAL : GB_METHOD_REFERENCE;
    s.solver.linear = GB_LINEAR_UMFPACK;
    gb_error err;
    gb_sim *sim;
    CHECK(gb_sim_create(&s, &sim, &err) == GB_OK);
    gb_wall_control wc = {GB_WALLS_FIXED, 0, 0, 0};
    gb_solve_result res;
    CHECK(gb_solver_relax(sim, &wc, 100000, &res, &err) == GB_OK);
    long it = res.iterations;
    gb_pair *p = pair_of(sim, 0, -1 - GB_WALL_BOTTOM);
    printf("single contact with a moment, %s: %ld iterations, w %.10g (analytic %.10g), mr %.3g, pt %.3g\n",
           solver ? "global" : "reference", it, sim->state.g[0].rot, m0 / kr, p->mr, p->pt);
    CHECK_NEAR(sim->state.g[0].rot, m0 / kr, 1e-3 * m0 / kr);
    CHECK_NEAR(sim->state.g[0].x - 5, -r * m0 / kr, 1e-3 * r * m0 / kr);
    CHECK_NEAR(p->mr, 0, 1e-3 * m0);
    gb_sim_free(sim);
}

int main(void)
{
    law();
    tangent(GB_NEWTON_LINE_SEARCH);
    tangent(GB_NEWTON_DAMPED);
    for (int solver = 0; solver < 3; solver++) {
        /* |w| ~ 4e-5 rad; the accuracy 1e-4 dyn over kt r = 7e7 moves it by ~1e-12 */
        sheared_disc(solver, 0.5 * KT, 0.1, 1e-9);   /* below the limit: mr = 1167 < 1e4 */
        sheared_disc(solver, 0.5 * KT, 0.005, 1e-9); /* at the limit 500 */
        sheared_disc(solver, 0, 0, 1e-9);            /* none: rolls freely */
    }
    single_contact(0);
    single_contact(1);
    TEST_END();
}
