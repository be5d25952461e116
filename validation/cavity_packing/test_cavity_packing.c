/* Validation C as ctest (the hybrid method): the 27-grain cavity packing of scene.yaml.
 *  1. As given (UMFPACK and CHOLMOD): converges; no overlap above 1e-3 of the smaller radius.
 *  2. Confined (every radius x 1.15, so that the grains press on the cavity; a = 1e-9 kgf): converges;
 *     the force the grains put on each boundary particle equals the host's reaction K u + f0 to
 *     1e-8 of the largest reaction, element by element.
 *  3. The confined packing in a host 1e6 times stiffer gives the result of a rigid cavity wall
 *     (boundary particles held): grain positions within 1e-6 cm, particle displacements below
 *     1e-9 cm. Frictionless grains here: with friction the equilibrium reached depends on the path,
 *     and the two runs take different paths.
 *  4. The same confined scene run twice gives identical grain positions and cavity displacements.
 *   test_cavity_packing scene.yaml */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "gem/sim.h"

static gb_status run(const char *path, int linear, double radius_factor, double stiffness_factor, int rigid,
                     double accuracy, double friction, gb_scene *sc, gb_sim **sim)
{
    gb_error err = {0};
    if (gb_scene_load(path, sc, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return GB_EINPUT;
    }
    sc->solver.linear = linear;
    sc->solver.max_iterations = 2000;
    if (accuracy > 0) sc->solver.accuracy = accuracy;
    for (int i = 0; i < sc->n_grains; i++) sc->grains[i].r *= radius_factor;
    sc->host.material.shear_modulus *= stiffness_factor;
    sc->host.rigid = rigid;
    if (friction >= 0) sc->grain_grain.friction_deg = friction;
    gb_status st = gb_sim_create(sc, sim, &err);
    if (!st) st = gb_sim_run(*sim, NULL, NULL, NULL, &err);
    if (st) fprintf(stderr, "%s\n", err.msg);
    return st;
}

static double largest_overlap(const gb_sim *sim, int *n_boundary)
{
    double worst = 0;
    *n_boundary = 0;
    for (int k = 0; k < sim->pairs.n; k++) {
        const gb_pair *p = &sim->pairs.p[k];
        if (p->d > worst) worst = p->d;
        *n_boundary += p->d > 0 && GB_IS_PARTICLE(p->j);
    }
    return worst;
}

int main(int argc, char **argv)
{
    if (argc != 2) return fprintf(stderr, "usage: %s scene.yaml\n", argv[0]), 2;
    gb_scene sc;
    gb_sim *sim;
    int nb;
    for (int linear = 1; linear >= 0; linear--) {
        CHECK(run(argv[1], linear, 1.0, 1.0, 0, 0, -1, &sc, &sim) == GB_OK);
        double ov = largest_overlap(sim, &nb);
        printf("%s, as placed: largest overlap %.3g cm (limit %.3g)\n", linear ? "UMFPACK" : "CHOLMOD", ov, 1e-3 * 0.3);
        CHECK(ov <= 1e-3 * 0.3);
        gb_sim_free(sim);
        gb_scene_free(&sc);
    }

    /* 2. confined */
    CHECK(run(argv[1], 1, 1.15, 1.0, 0, 1e-9, -1, &sc, &sim) == GB_OK);
    double ov = largest_overlap(sim, &nb), reaction = 0, worst = 0;
    const gb_host *h = sim->host;
    for (int k = 0; k < h->m; k++) reaction = fmax(reaction, fabs(h->force[k]));
    for (int k = 0; k < h->m; k++) worst = fmax(worst, fabs(sim->bp_F[k])); /* (K u + f0) - grains' force */
    printf("confined: %d contacts with the boundary, largest overlap %.3g cm, largest reaction %.4g kgf, "
           "largest mismatch %.3g kgf\n", nb, ov, reaction, worst);
    CHECK(nb >= 5);
    CHECK(reaction > 0.1);
    CHECK(worst <= 1e-8 * reaction);
    gb_sim_free(sim);
    gb_scene_free(&sc);

    /* 3. stiff host against a rigid cavity */
    gb_scene s1, s2;
    gb_sim *stiff, *rigid;
    CHECK(run(argv[1], 1, 1.15, 1e6, 0, 1e-9, 0, &s1, &stiff) == GB_OK);
    CHECK(run(argv[1], 1, 1.15, 1.0, 1, 1e-9, 0, &s2, &rigid) == GB_OK);
    double dx = 0, umax = 0;
    for (int i = 0; i < stiff->n; i++)
        dx = fmax(dx, hypot(stiff->g[i].x - rigid->g[i].x, stiff->g[i].y - rigid->g[i].y));
    for (int k = 0; k < stiff->host->m; k++) umax = fmax(umax, fabs(stiff->host->u[k]));
    printf("host x 1e6 against a rigid cavity: grains differ by %.3g cm at most, cavity moves %.3g cm at most\n", dx,
           umax);
    CHECK(dx <= 1e-6);
    CHECK(umax <= 1e-9);
    gb_sim_free(stiff);
    gb_sim_free(rigid);
    gb_scene_free(&s1);
    gb_scene_free(&s2);

    /* 4. twice */
    gb_scene r1, r2;
    gb_sim *a, *b;
    CHECK(run(argv[1], 1, 1.15, 1.0, 0, 1e-9, -1, &r1, &a) == GB_OK);
    CHECK(run(argv[1], 1, 1.15, 1.0, 0, 1e-9, -1, &r2, &b) == GB_OK);
    int same = a->n == b->n && a->host->m == b->host->m;
    for (int i = 0; same && i < a->n; i++) same = a->g[i].x == b->g[i].x && a->g[i].y == b->g[i].y;
    for (int k = 0; same && k < a->host->m; k++) same = a->host->u[k] == b->host->u[k];
    printf("run twice: %s\n", same ? "identical" : "DIFFERENT");
    CHECK(same);
    gb_sim_free(a);
    gb_sim_free(b);
    gb_scene_free(&r1);
    gb_scene_free(&r2);
    TEST_END();
}
