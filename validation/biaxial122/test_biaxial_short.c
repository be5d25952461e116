/* Validation B, short version (ctest validation_biaxial122_short): 20 constant mean stress shear steps of
 * the 122-disc packing in test_shear.yaml. At every step:
 *  - the iteration's energy books close: |W_iter + W_body - D - L - dE| <= 2 % of the work
 *    (W_iter: the walls' work as moved, D: Coulomb dissipation (K 28), L: energy absorbed by the
 *    fixing forces, dE: change of the springs' energy (K 22)); the paper's balance W - D - dE with
 *    the quasi-static work is printed beside it;
 *  - the mean stress is within 1 % of s0 = 1.5e5 dyn/cm;
 *  - the trace of the coordination tensor (K 23) equals the mean coordination number counted
 *    directly from the contacts;
 *  - the rose diagrams' totals equal the number of contacts seen from the grains and their energy. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "gembem/run.h"
#include "gembem/measure.h"

static const double S0 = 1.5e5;

static gb_status check_step(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    (void)err;
    gb_micro m;
    gb_work_accounts work = gb_run_work(user);
    gb_micro_measure(sim, &work, &m);
    const gb_scene *sc = gb_sim_scene(sim);
    /* Direct count of force-carrying contacts and of their energy. */
    int n = gb_sim_contacts(sim, NULL, 0), gg = 0, gw = 0;
    gb_contact *c = malloc((size_t)(n > 0 ? n : 1) * sizeof *c);
    gb_sim_contacts(sim, c, n);
    double energy_seen = 0;
    for (int k = 0; k < n; k++) {
        if (!(c[k].pn > 0)) continue;
        const gb_material *mat = c[k].j >= 0 ? &sc->grain_grain : &sc->grain_wall;
        double e = 0.5 * c[k].pn * c[k].pn / mat->kn + 0.5 * c[k].pt * c[k].pt / mat->kt;
        if (c[k].j >= 0) gg++, energy_seen += 2 * e;
        else gw++, energy_seen += e;
    }
    free(c);
    double coordination = (2.0 * gg + gw) / gb_sim_n_grains(sim);
    CHECK_NEAR(m.fabric.xx + m.fabric.yy, coordination, 1e-12);
    double count[36], energy[36], total = 0, total_e = 0;
    gb_micro_rose(sim, 36, count, energy);
    for (int b = 0; b < 36; b++) total += count[b], total_e += energy[b];
    CHECK_NEAR(total, 2.0 * gg + gw, 0);
    CHECK_NEAR(total_e, energy_seen, 1e-9 * energy_seen);
    if (r->step == 0) return GB_OK;
    CHECK_NEAR(0.5 * (r->s1 + r->s2), S0, 0.01 * S0);
    double w_iter = m.work_walls_iter + m.work_body;
    printf("step %2d  ratio %.4f  books %+.4f %%  paper's balance %+.3f %%  P_max %.2f\n", r->step, r->stress_ratio,
           100 * m.balance_iter / w_iter, 100 * m.balance / m.work, m.p_max);
    CHECK(fabs(m.balance_iter) <= 0.02 * w_iter);
    return GB_OK;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s test_shear.yaml\n", argv[0]);
        return 2;
    }
    gb_error err = {0};
    gb_scene sc;
    gb_sim *sim = NULL;
    gb_run *run = NULL;
    if (gb_scene_load(argv[1], &sc, &err) || gb_sim_create(&sc, &sim, &err) || gb_run_create(sim, &run, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return 1;
    }
    gb_status st = gb_run_program(run, NULL, check_step, run, &err);
    if (st) fprintf(stderr, "%s\n", err.msg);
    CHECK(st == GB_OK);
    gb_run_free(run);
    gb_sim_free(sim);
    gb_scene_free(&sc);
    TEST_END();
}
