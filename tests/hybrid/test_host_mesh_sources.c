/* Hosts as gmsh users make them: one body, the annulus 1 < r < 2 of meshes/annulus.geo
 * (its own size lc = 0.2), read by gb_scene_load three ways: the .geo with its own sizes (no
 * host.elements), the .msh files gmsh wrote from it (MSH 2.2 and 4.1, ASCII and binary, made at
 * test time by ctest hybrid_msh_fixtures), and the .geo with element counts. Checks:
 *  - a .msh is the mesh gmsh made of the .geo: the same elements (1e-12 of the radius; measured
 *    4.4e-16 in ASCII, 0 in binary) and the same condensed cavity stiffness K to round-off (1e-12
 *    of max |K|, measured 1.3e-15: BLAS differ, so not bitwise);
 *  - the .geo with counts equal to gmsh's own gives that mesh again (gmsh's transfinite nodes lie
 *    1.0e-11 from its own: 1e-10) and K to round-off (measured 2.6e-15);
 *  - Lamé (independent reference, validation/bem/vcommon.h): the cavity displaced radially by d
 *    with the outer circle fixed needs the radial traction s_rr(a) of the thick cylinder; every
 *    cavity element's K u / length, from every source, within the first-order error of constant
 *    elements, 0.6 / N of it for N cavity elements (measured 0.49 / N at N = 32), and the .geo
 *    with twice the counts closer by a factor 2^(0.7 .. 1.3) (measured 2^1.10);
 *  - a gmsh user's own sizes honoured: a size field that refines towards the cavity (size 0.1 on
 *    it: 135 elements instead of 16; its .msh gives the same K) and Transfinite Curve in the file (12 per arc: 48);
 *  - run_info's numbers: the counts per group and the cavity's shortest and longest element; the
 *    warning for cavity elements longer than 2.5 grain radii, and none below.
 * Usage: test_host_mesh_sources SOURCE_DIR MSH_DIR (any working directory). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "gembem/scene.h"
#include "hybrid/host.h"
#include "vcommon.h"

typedef struct {
    gb_scene sc;
    gb_host *h;
} source;

/* A scene of a host with groups outer and cavity read from `mesh` (with `elements`, or none), one
 * grain in its cavity. */
static int load(const char *dir, const char *mesh, const char *elements, source *s)
{
    static int count = 0;
    char path[1200];
    snprintf(path, sizeof path, "%s/scene_%d.yaml", dir, count++);
    FILE *f = fopen(path, "w");
    if (!f) return 1;
    fprintf(f, "gembem: 1\nunits: {length: cm, force: kgf}\nmaterials:\n"
               "  grain_grain: {kn: 1000, kt: 0, friction_deg: 0}\n  grain_wall: {kn: 1000, kt: 0, friction_deg: 0}\n"
               "host:\n  mesh: %s\n%s  material: {shear_modulus: 1, poisson: 0.3, plane: strain}\n"
               "  boundary: {outer: fixed}\n  cavity: cavity\ngrains: {list: [[0, 0, 0.2]]}\n"
               "solver: {method: global, accuracy: 1e-6}\nloading: [{relax: {steps: 1}}]\n",
            mesh, elements);
    fclose(f);
    gb_error err = {0};
    gb_status st = gb_scene_load(path, &s->sc, &err);
    if (!st) st = gb_host_create(&s->sc.host, &s->h, &err);
    remove(path);
    if (st) fprintf(stderr, "%s (elements '%s'): %s\n", mesh, elements, err.msg);
    return st != GB_OK;
}

static void drop(source *s)
{
    gb_host_free(s->h);
    gb_scene_free(&s->sc);
}

/* The largest relative error of K u / length against Lamé's s_rr(a) over the cavity's elements,
 * for the cavity displaced radially by d (outer circle fixed, mu = 1, nu = 0.3, plane strain). */
static double lame_error(const gb_host *h)
{
    double d = 1e-3;
    v_lame L = v_lame_solve(1.0, 0.3, 0, 0, 1.0, 2.0, 1.0); /* unit pressure: s_rr(a) = -1 */
    double srr = -d / v_lame_ur(&L, 1.0), worst = 0;
    int m = h->m;
    double *u = malloc(sizeof(double) * (size_t)m), *F = calloc((size_t)m, sizeof(double));
    for (int k = 0; k < m / 2; k++) {
        const double *x = h->mesh.mid + 2 * h->K.elem[k];
        double r = hypot(x[0], x[1]);
        u[2 * k] = d * x[0] / r, u[2 * k + 1] = d * x[1] / r;
    }
    for (int c = 0; c < m; c++)
        for (int r = 0; r < m; r++) F[r] += h->K.K[r + (size_t)c * m] * u[c];
    for (int k = 0; k < m / 2; k++) {
        int e = h->K.elem[k];
        const double *n = h->mesh.normal + 2 * e;
        double tn = (F[2 * k] * n[0] + F[2 * k + 1] * n[1]) / h->mesh.length[e];
        worst = fmax(worst, fabs(tn - srr) / fabs(srr));
    }
    free(u);
    free(F);
    return worst;
}

/* The same elements (nodes within tol) and K to round-off. */
static void same_mesh(const source *a, const source *b, double tol, const char *what)
{
    const gb_bem_mesh *p = &a->h->mesh, *q = &b->h->mesh;
    CHECK(p->n == q->n && a->h->m == b->h->m);
    if (p->n != q->n || a->h->m != b->h->m) return;
    double dx = 0, dk = 0, kmax = 0;
    for (int i = 0; i < 2 * p->n; i++) dx = fmax(dx, fmax(fabs(p->p0[i] - q->p0[i]), fabs(p->p1[i] - q->p1[i])));
    size_t mm = (size_t)a->h->m * (size_t)a->h->m;
    for (size_t i = 0; i < mm; i++) {
        dk = fmax(dk, fabs(a->h->K.K[i] - b->h->K.K[i]));
        kmax = fmax(kmax, fabs(a->h->K.K[i]));
    }
    printf("%-28s %d elements, nodes %.2e apart, K %.2e of max |K|\n", what, q->n, dx, dk / kmax);
    CHECK(dx <= tol);
    CHECK(dk <= 1e-12 * kmax);
}

/* A gmsh user's own sizes are honoured: a size field refining towards the cavity (and the .msh
 * gmsh wrote of it: the same K), Transfinite Curve in the file. */
static void gmsh_users_sizes(const char *src, const char *dir)
{
    char geo[1100], msh[1100];
    source field, other;
    snprintf(geo, sizeof geo, "%s/tests/hybrid/refined_cavity.geo", src);
    if (!load(dir, geo, "", &field)) {
        const gb_host_def *h = &field.sc.host;
        int nc = field.h->m / 2;
        printf("a size field: %d cavity elements of %.4f to %.4f, %d on the outer boundary\n", nc, h->cavity_min,
               h->cavity_max, field.h->mesh.n - nc);
        /* without the field: 16 cavity elements of 0.98 (MeshSizeMax 1); gmsh 4.8 gives 135 of 0.0994
         * to 0.256 (its 1D mesher samples the field along the closed curve) */
        CHECK(nc > 100 && fabs(h->cavity_min - 0.1) < 0.002 && h->cavity_max < 0.3 && field.h->mesh.n - nc <= 48);
        snprintf(msh, sizeof msh, "%s/refined_cavity_msh41_bin.msh", dir);
        if (!load(dir, msh, "", &other)) {
            same_mesh(&field, &other, 1e-12, "its msh41_bin");
            drop(&other);
        } else {
            CHECK(!"the size field's .msh was read");
        }
        drop(&field);
    } else {
        CHECK(!"the .geo with a size field was read");
    }
    snprintf(geo, sizeof geo, "%s/tests/hybrid/transfinite_cavity.geo", src);
    if (!load(dir, geo, "", &other)) {
        const gb_host_def *h = &other.sc.host;
        int c = gb_bem_mesh_group(&other.h->mesh, "cavity"), o = gb_bem_mesh_group(&other.h->mesh, "outer");
        printf("Transfinite Curve: %d cavity and %d outer elements\n", h->group_elements[c], h->group_elements[o]);
        CHECK(h->group_elements[c] == 48 && h->group_elements[o] == 40);
        drop(&other);
    } else {
        CHECK(!"the .geo with Transfinite Curve was read");
    }
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: test_host_mesh_sources SOURCE_DIR MSH_DIR\n");
        return 2;
    }
    char geo[1100], msh[1100], counts[256];
    snprintf(geo, sizeof geo, "%s/meshes/annulus.geo", argv[1]);
    source own, other;
    if (load(argv[2], geo, "", &own)) return 1;
    const gb_host_def *hd = &own.sc.host;
    int g_cav = gb_bem_mesh_group(&own.h->mesh, "cavity"), g_out = gb_bem_mesh_group(&own.h->mesh, "outer");
    int nc = hd->group_elements[g_cav], no = hd->group_elements[g_out];
    double e_own = lame_error(own.h);
    printf("the .geo's own sizes:        %d cavity and %d outer elements, Lame error %.3e (bound %.3e)\n", nc, no,
           e_own, 0.6 / nc);
    /* run_info's numbers: the cavity is a regular polygon of nc chords of the unit circle */
    CHECK(!hd->counts_given && hd->n_groups == 2 && nc == own.h->m / 2);
    CHECK_NEAR(hd->cavity_min, 2 * sin(V_PI / nc), 1e-9);
    CHECK_NEAR(hd->cavity_max, 2 * sin(V_PI / nc), 1e-9);
    CHECK(nc >= 24 && e_own < 0.6 / nc);

    static const char *const formats[4] = {"msh22", "msh22_bin", "msh41", "msh41_bin"};
    for (int k = 0; k < 4; k++) {
        snprintf(msh, sizeof msh, "%s/annulus_%s.msh", argv[2], formats[k]);
        if (load(argv[2], msh, "", &other)) {
            CHECK(!"the .msh was read");
            continue;
        }
        same_mesh(&own, &other, 1e-12, formats[k]);
        CHECK(lame_error(other.h) < 0.6 / nc);
        drop(&other);
    }

    snprintf(counts, sizeof counts, "  elements: {cavity: %d, outer: %d}\n", nc, no);
    if (!load(argv[2], geo, counts, &other)) {
        same_mesh(&own, &other, 1e-10, "the .geo with its counts"); /* transfinite: 1.0e-11 apart */
        CHECK(other.sc.host.counts_given);
        drop(&other);
    } else {
        CHECK(!"the .geo with counts was read");
    }
    /* the warning: 8 cavity elements of 2 sin(pi/8) = 0.765 are 3.83 radii of the 0.2 grain */
    CHECK(own.sc.warning[0] == '\0');
    if (!load(argv[2], geo, "  elements: {cavity: 8}\n", &other)) {
        printf("8 cavity elements: %s\n", other.sc.warning);
        CHECK(strstr(other.sc.warning, "is 3.83 mean grain radii (0.2) long, more than 2.5") != NULL);
        CHECK_NEAR(other.sc.host.cavity_max / 0.2, 10 * sin(V_PI / 8), 1e-7); /* gmsh's nodes: 1e-8 */
        drop(&other);
    } else {
        CHECK(!"the .geo with 8 cavity elements was read");
    }
    snprintf(counts, sizeof counts, "  elements: {cavity: %d, outer: %d}\n", 2 * nc, 2 * no);
    if (!load(argv[2], geo, counts, &other)) {
        double e2 = lame_error(other.h), order = log(e_own / e2) / log(2.0);
        printf("the .geo with twice the counts: Lame error %.3e, order %.2f\n", e2, order);
        CHECK(e2 < 0.6 / (2 * nc) && order > 0.7 && order < 1.3);
        drop(&other);
    } else {
        CHECK(!"the .geo with twice the counts was read");
    }
    drop(&own);
    gmsh_users_sizes(argv[1], argv[2]);
    (void)v_failures; /* vcommon.h's own counter: this test counts with check.h */
    TEST_END();
}
