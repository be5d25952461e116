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
#include "gembem/gembem.h"

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
    int n;
    gb_error err = {0};
    gb_contact *c = gb_sim_contacts_copy(sim, &n, &err);
    CHECK(c != NULL);
    for (int k = 0; c && k < n; k++) {
        if (c[k].overlap > worst) worst = c[k].overlap;
        *n_boundary += GB_IS_PARTICLE(c[k].j);
    }
    free(c);
    return worst;
}

/* The cavity's displacements u, the host's forces and the particles' fixing forces (3 m values). */
static double *host_cavity(const gb_sim *sim)
{
    int m = gb_sim_host_dofs(sim);
    double *v = malloc(3 * (size_t)(m > 0 ? m : 1) * sizeof *v);
    CHECK(v != NULL && m > 0);
    if (v) gb_sim_host_cavity(sim, v, v + m, v + 2 * m);
    return v;
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
    int m = gb_sim_host_dofs(sim);
    double *h = host_cavity(sim);
    for (int k = 0; h && k < m; k++) reaction = fmax(reaction, fabs(h[m + k]));
    for (int k = 0; h && k < m; k++) worst = fmax(worst, fabs(h[2 * m + k])); /* (K u + f0) - grains' force */
    free(h);
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
    for (int i = 0; i < gb_sim_n_grains(stiff); i++) {
        gb_grain gs = gb_sim_grain(stiff, i), gr = gb_sim_grain(rigid, i);
        dx = fmax(dx, hypot(gs.x - gr.x, gs.y - gr.y));
    }
    double *hs = host_cavity(stiff);
    for (int k = 0; hs && k < gb_sim_host_dofs(stiff); k++) umax = fmax(umax, fabs(hs[k]));
    free(hs);
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
    int same = gb_sim_n_grains(a) == gb_sim_n_grains(b) && gb_sim_host_dofs(a) == gb_sim_host_dofs(b);
    for (int i = 0; same && i < gb_sim_n_grains(a); i++) {
        gb_grain ga = gb_sim_grain(a, i), gb = gb_sim_grain(b, i);
        same = ga.x == gb.x && ga.y == gb.y;
    }
    double *ha = host_cavity(a), *hb = host_cavity(b);
    for (int k = 0; same && ha && hb && k < gb_sim_host_dofs(a); k++) same = ha[k] == hb[k];
    free(ha), free(hb);
    printf("run twice: %s\n", same ? "identical" : "DIFFERENT");
    CHECK(same);
    gb_sim_free(a);
    gb_sim_free(b);
    gb_scene_free(&r1);
    gb_scene_free(&r2);
    TEST_END();
}
