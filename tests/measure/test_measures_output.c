/* The measures that the run output writes per step (src/io/measure_output.c), through
 * gb_run_output like `gembem run`:
 * - hybrid, empty granular zone (tests/hybrid/host_loading.yaml: one grain touching nothing, the
 *   host's top pushed down in 3 steps): the hoop stress along the cavity wall and the stress on the
 *   ring equal the boundary element module's own solution with a traction-free cavity, computed
 *   here (1e-8 of the largest value; the files hold 11 digits); the concentration is the hoop
 *   stress over s_ref = |force on the top| / its length 10 (1e-8); the strain follows from Hooke's
 *   law (1e-8); one grain: no triangles, all numbers finite.
 * - Kirsch's hole (tests/measure/plate_hole.yaml: a 40 x 40 plate, hole radius 2.5, top pushed,
 *   empty zone): the concentration along the hole within 0.08 of -(1 + 2 cos 2 theta) and the
 *   ring's stress within 0.05 s of Kirsch's field, s = s_ref the mean stress on the top.
 * - hybrid with grains (validation/cavity_packing, 27 grains): every file of both steps, finite;
 *   fields/triangles.pvd lists both steps.
 * - affine known answer: the 27 grains of validation/cavity_packing moved by x = (I + A) X + b in
 *   one "step": every grain's strain is the exact Green-Lagrange strain (1e-11, the files' digits),
 *   D2min <= 1e-20, the localisation index of the uniform strain is 0.1 (1e-9).
 * - granular (validation/biaxial122/test_shear.yaml, 20 steps of constant-mean-stress shear, no
 *   host): a row per step, every file of every step with finite numbers, the index in
 *   [0.1, 1] once the sample shears, the sliding contacts as many as counted here from the
 *   contacts (Coulomb limit to 1e-9), no host columns, and the triangulated zone's mean shear
 *   increment within 0.75 to 1.3 of the box's (a consistency check: the zone is the grains' hull). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "gem/sim.h"
#include "gembem/run.h"
#include "io/measure_output.h"

static const double PI = 3.14159265358979323846;

/* A CSV file as a table of strings; cell(t, row, "name") as a number. */
typedef struct {
    int rows, cols;
    char **head, **cell; /* cell[row * cols + col] */
} table;

static int table_read(const char *path, table *t)
{
    memset(t, 0, sizeof *t);
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    char line[8192];
    int cap = 0;
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = 0;
        char *fields[64];
        int nf = 0;
        for (char *p = line, *q; p && nf < 64; p = q) {
            q = strchr(p, ',');
            if (q) *q++ = 0;
            fields[nf++] = p;
        }
        if (!t->head) {
            t->cols = nf;
            t->head = malloc((size_t)nf * sizeof(char *));
            for (int k = 0; k < nf; k++) t->head[k] = strdup(fields[k]);
            continue;
        }
        if (nf != t->cols) {
            fclose(f);
            return 0;
        }
        if (t->rows == cap) {
            cap = cap ? 2 * cap : 64;
            t->cell = realloc(t->cell, (size_t)cap * (size_t)t->cols * sizeof(char *));
        }
        for (int k = 0; k < nf; k++) t->cell[t->rows * t->cols + k] = strdup(fields[k]);
        t->rows++;
    }
    fclose(f);
    return t->head != NULL;
}

static void table_free(table *t)
{
    for (int k = 0; k < t->cols; k++) free(t->head[k]);
    for (int k = 0; k < t->rows * t->cols; k++) free(t->cell[k]);
    free(t->head), free(t->cell);
}

static double cell(const table *t, int row, const char *name)
{
    for (int k = 0; k < t->cols; k++)
        if (!strcmp(t->head[k], name)) return strtod(t->cell[row * t->cols + k], NULL);
    fprintf(stderr, "no column %s\n", name);
    return NAN;
}

static int has_column(const table *t, const char *name)
{
    for (int k = 0; k < t->cols; k++)
        if (!strcmp(t->head[k], name)) return 1;
    return 0;
}

/* The ratios that are undefined (nan) where their reference is zero within its noise. */
static int may_be_undefined(const char *column)
{
    return !strcmp(column, "localisation_index") || !strcmp(column, "max_concentration") ||
           !strcmp(column, "concentration");
}

/* Every field a finite number or a word (a kind: "boundary", "grain", ...), never inf, and nan only
 * in a ratio whose reference can vanish. */
static int all_finite(const table *t)
{
    for (int k = 0; k < t->rows * t->cols; k++) {
        char *end;
        double v = strtod(t->cell[k], &end);
        if (isnan(v) && may_be_undefined(t->head[k % t->cols])) continue;
        if (*end == 0 && end != t->cell[k] ? !isfinite(v) : !(t->cell[k][0] >= 'a' && t->cell[k][0] <= 'z')) {
            fprintf(stderr, "not finite: '%s'\n", t->cell[k]);
            return 0;
        }
    }
    return 1;
}

static int read_step(const char *dir, const char *what, int step, table *t)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/fields/%s_%06d.csv", dir, what, step);
    int ok = table_read(path, t);
    if (!ok) fprintf(stderr, "%s: missing or unreadable\n", path);
    return ok && all_finite(t);
}

typedef struct {
    gb_run_output *out;
    const char *dir;
    int steps_seen;
} run_ctx;

/* ---------------------------------------------------------------- hybrid, empty zone */

static gb_status check_host_step(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    run_ctx *c = user; /* the loop has written the step's files */
    gb_status st = GB_OK;
    c->steps_seen++;
    const gb_host *h = sim->host;
    double ft[2], dt[2];
    if ((st = gb_host_group_force(h, &sim->state.host, "top", ft, dt, err))) return st;
    double s_ref = hypot(ft[0], ft[1]) / 10;
    gb_bem_problem pr = gb_host_problem(h, &sim->state.host);
    pr.bc[h->cavity].kind = GB_BEM_BC_FREE;
    gb_bem_solution sol;
    memset(&sol, 0, sizeof sol);
    double *bs = malloc(3 * (size_t)h->mesh.n * sizeof *bs);
    if ((st = gb_bem_solve(&h->mesh, &h->sys, &pr, NULL, &sol, err)) ||
        (st = gb_bem_boundary_stress(&h->mesh, &h->sys.material, &sol, bs, err))) {
        free(bs);
        gb_bem_solution_free(&sol);
        return st;
    }
    table w, ring;
    CHECK(read_step(c->dir, "host_wall", r->step, &w));
    CHECK(read_step(c->dir, "host_ring", r->step, &ring));
    CHECK(w.rows == h->m / 2);
    double hmax = 0, dh = 0, dh0 = 0, dc = 0, cmax = 0;
    for (int k = 0; k < w.rows; k++) {
        int e = (int)cell(&w, k, "element");
        double tx = h->mesh.tangent[2 * e], ty = h->mesh.tangent[2 * e + 1], *s = &bs[3 * e];
        double hoop = tx * tx * s[0] + ty * ty * s[1] + 2 * tx * ty * s[2];
        hmax = fmax(hmax, fabs(hoop));
        dh = fmax(dh, fabs(cell(&w, k, "hoop") - hoop));
        dh0 = fmax(dh0, fabs(cell(&w, k, "hoop_empty") - hoop));
        if (s_ref > 0) {
            dc = fmax(dc, fabs(cell(&w, k, "concentration") - hoop / s_ref));
            cmax = fmax(cmax, fabs(hoop / s_ref));
        } else {
            CHECK(isnan(cell(&w, k, "concentration"))); /* nothing loads the host: undefined, not a ratio */
        }
    }
    /* The ring against the module's interior stress of the empty cavity, and Hooke's law. */
    int n = ring.rows;
    double *xy = malloc(2 * (size_t)(n + 1) * sizeof *xy), *sr = malloc(3 * (size_t)(n + 1) * sizeof *sr);
    for (int q = 0; q < n; q++) xy[2 * q] = cell(&ring, q, "x"), xy[2 * q + 1] = cell(&ring, q, "y");
    if (n > 0) st = gb_bem_interior(&h->mesh, &h->sys.material, &pr, &sol, n, xy, NULL, sr, err);
    double smax = 0, ds = 0, de = 0, mu = h->sys.material.shear_modulus, nu = h->sys.material.poisson;
    for (int q = 0; q < n && !st; q++) {
        double s[3] = {cell(&ring, q, "sxx"), cell(&ring, q, "syy"), cell(&ring, q, "sxy")};
        for (int k = 0; k < 3; k++) smax = fmax(smax, fabs(sr[3 * q + k])), ds = fmax(ds, fabs(s[k] - sr[3 * q + k]));
        de = fmax(de, fabs(cell(&ring, q, "exx") - (s[0] - nu * (s[0] + s[1])) / (2 * mu)));
        de = fmax(de, fabs(cell(&ring, q, "exy") - s[2] / (2 * mu)));
    }
    printf("host step %d: hoop <= %.4g (off %.2g, empty off %.2g), largest concentration %.4f (s_ref %.4g, off "
           "%.2g); ring of %d points, stress <= %.4g (off %.2g)\n",
           r->step, hmax, dh, dh0, cmax, s_ref, dc, n, smax, ds);
    CHECK(n >= h->m / 4); /* most cavity elements have their ring point */
    CHECK_NEAR(dh, 0, 1e-8 * hmax + 1e-300);
    CHECK_NEAR(dh0, 0, 1e-8 * hmax + 1e-300);
    CHECK_NEAR(dc, 0, 1e-8 * cmax);
    CHECK_NEAR(ds, 0, 1e-8 * smax + 1e-300);
    CHECK_NEAR(de, 0, 1e-8 * smax / (2 * mu) + 1e-300);
    if (r->step > 0) CHECK(hmax > 0 && cmax > 1);
    table g;
    CHECK(read_step(c->dir, "grains", r->step, &g));
    CHECK(g.rows == 1 && cell(&g, 0, "triangles") == 0);
    table_free(&g);
    free(xy), free(sr), free(bs);
    table_free(&w), table_free(&ring);
    gb_bem_solution_free(&sol);
    return st;
}

/* ---------------------------------------------------------------- granular, no host */

static gb_status check_granular_step(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    (void)err;
    run_ctx *c = user; /* the loop has written the step's files */
    c->steps_seen++;
    /* Sliding contacts counted from the public contact list and the scene's materials. */
    const gb_scene *sc = gb_sim_scene(sim);
    int m, count = 0;
    gb_contact *ct = gb_sim_contacts_copy(sim, &m, err);
    if (!ct) return err->code;
    for (int k = 0; k < m; k++) {
        const gb_material *mat = ct[k].j >= 0 ? &sc->grain_grain : &sc->grain_wall;
        double limit = ct[k].pn * tan(mat->friction_deg * PI / 180) + mat->cohesion;
        count += mat->kt > 0 && limit > 0 && fabs(ct[k].pt) >= limit * (1 - 1e-9);
    }
    free(ct);
    table g, s;
    CHECK(read_step(c->dir, "grains", r->step, &g));
    CHECK(read_step(c->dir, "sliding", r->step, &s));
    CHECK(g.rows == gb_sim_n_grains(sim));
    CHECK(s.rows == count);
    char path[1200];
    snprintf(path, sizeof path, "%s/fields/triangles_%06d.vtu", c->dir, r->step);
    CHECK(access(path, F_OK) == 0);
    table_free(&g), table_free(&s);
    return GB_OK;
}

static int run(const char *scene, const char *dir, gb_step_fn fn)
{
    gb_error err = {0};
    gb_scene sc;
    gb_sim *sim = NULL;
    run_ctx c = {NULL, dir, 0};
    if (gb_scene_load(scene, &sc, &err) || gb_sim_create(&sc, &sim, &err) ||
        gb_run_output_open(dir, sim, 1, "test_measures_output", &c.out, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        return -1;
    }
    gb_status st = gb_sim_run(sim, c.out, fn, &c, &err);
    if (st) fprintf(stderr, "%s\n", err.msg);
    CHECK(st == GB_OK);
    CHECK(gb_run_output_close(c.out, sim, st, NULL, &err) == GB_OK);
    gb_sim_free(sim);
    gb_scene_free(&sc);
    return c.steps_seen;
}

static void check_localisation(const char *dir, int steps, int host)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/localisation.csv", dir);
    table t;
    CHECK(table_read(path, &t) && all_finite(&t));
    CHECK(t.rows == steps);
    CHECK(has_column(&t, "max_concentration") == host);
    for (int k = 0; k < t.rows; k++) {
        CHECK(cell(&t, k, "step") == k);
        double L = cell(&t, k, "localisation_index");
        if (!host && k > 0) CHECK(L >= 0.1 - 1e-9 && L <= 1 + 1e-9 && cell(&t, k, "mean_gamma") > 0);
    }
    if (t.rows > 1)
        printf("%s: %d rows; last: localisation index %.4f, mean gamma %.3g, %g sliding contacts\n", path, t.rows,
               cell(&t, t.rows - 1, "localisation_index"), cell(&t, t.rows - 1, "mean_gamma"),
               cell(&t, t.rows - 1, "sliding_contacts"));
    table_free(&t);
}

/* ---------------------------------------------------------------- affine known answer */

static void check_affine(const char *dir)
{
    gb_error err = {0};
    gb_scene sc;
    gb_sim *sim = NULL;
    gb_state start = {0};
    mkdir(dir, 0777);
    if (gb_scene_load("validation/cavity_packing/scene.yaml", &sc, &err) || gb_sim_create(&sc, &sim, &err) ||
        gb_sim_state_save(sim, &start, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        CHECK(0);
        return;
    }
    const double A[4] = {0.01, 0.003, -0.002, -0.015}, b[2] = {0.01, -0.02};
    for (int i = 0; i < sim->state.n; i++) {
        double X = start.g[i].x, Y = start.g[i].y;
        sim->state.g[i].x = X + A[0] * X + A[1] * Y + b[0], sim->state.g[i].y = Y + A[2] * X + A[3] * Y + b[1];
    }
    gb_step_measures m;
    CHECK(gb_step_measure(&start, sim, NULL, 0, 1, 1, &m, &err) == GB_OK);
    CHECK(gb_measure_write_step(dir, &m, &err) == GB_OK);
    gb_step_measures_free(&m);
    double e[3] = {-(A[0] + 0.5 * (A[0] * A[0] + A[2] * A[2])), -(A[3] + 0.5 * (A[1] * A[1] + A[3] * A[3])),
                   -0.5 * (A[1] + A[2] + A[0] * A[1] + A[2] * A[3])};
    double gamma = 2 * sqrt(0.25 * (e[0] - e[1]) * (e[0] - e[1]) + e[2] * e[2]);
    table g, t;
    CHECK(read_step(dir, "grains", 0, &g));
    int with = 0;
    double off = 0, d2 = 0;
    for (int i = 0; i < g.rows; i++) {
        d2 = fmax(d2, cell(&g, i, "d2min"));
        if (cell(&g, i, "triangles") == 0) continue;
        with++;
        off = fmax(off, fabs(cell(&g, i, "exx") - e[0]) + fabs(cell(&g, i, "eyy") - e[1]) +
                            fabs(cell(&g, i, "exy") - e[2]) + fabs(cell(&g, i, "gamma") - gamma));
    }
    char path[1200];
    snprintf(path, sizeof path, "%s/localisation.csv", dir);
    CHECK(table_read(path, &t) && t.rows == 1);
    printf("affine: %d of %d grains in triangles, strain off by %.2g, D2min <= %.2g, index %.12f\n", with, g.rows, off,
           d2, cell(&t, 0, "localisation_index"));
    CHECK(with >= 20);
    CHECK_NEAR(off, 0, 1e-11);
    CHECK_NEAR(d2, 0, 1e-20);
    CHECK_NEAR(cell(&t, 0, "localisation_index"), 0.1, 1e-9);
    CHECK_NEAR(cell(&t, 0, "mean_gamma"), gamma, 1e-11);
    CHECK_NEAR(cell(&t, 0, "zone_exx"), e[0], 1e-11);
    CHECK_NEAR(cell(&t, 0, "zone_eyy"), e[1], 1e-11);
    CHECK_NEAR(cell(&t, 0, "zone_exy"), e[2], 1e-11);
    CHECK(cell(&t, 0, "triangles") > 0);
    table_free(&g), table_free(&t);
    gb_state_free(&start);
    gb_sim_free(sim);
    gb_scene_free(&sc);
}

/* The triangulated zone's mean shear against the box's: the zone is the grains' hull, not the
 * box, so they agree only roughly (0.83 to 1.18 here, also in the step where the packing
 * rearranges); a consistency check. */
static void check_zone_follows_box(const char *dir)
{
    char path[1200];
    table L, S;
    snprintf(path, sizeof path, "%s/localisation.csv", dir);
    CHECK(table_read(path, &L));
    snprintf(path, sizeof path, "%s/steps.csv", dir);
    CHECK(table_read(path, &S));
    CHECK(L.rows == S.rows);
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 1; k < L.rows && k < S.rows; k++) {
        double box = cell(&S, k, "e1_minus_e2") - cell(&S, k - 1, "e1_minus_e2");
        double zone = cell(&L, k, "zone_eyy") - cell(&L, k, "zone_exx"); /* e1 vertical */
        lo = fmin(lo, zone / box), hi = fmax(hi, zone / box);
    }
    printf("zone's shear / box's shear per step: %.3f to %.3f\n", lo, hi);
    CHECK(lo > 0.75 && hi < 1.3);
    table_free(&L), table_free(&S);
}

/* Entries of fields/triangles.pvd (-1: no such file). */
static int pvd_entries(const char *dir)
{
    char path[1200], line[512];
    snprintf(path, sizeof path, "%s/fields/triangles.pvd", dir);
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    int n = 0, closed = 0;
    while (fgets(line, sizeof line, f)) n += strstr(line, "<DataSet ") != NULL, closed += !strcmp(line, "</VTKFile>\n");
    fclose(f);
    return closed == 1 ? n : -2;
}

/* A hybrid run with grains (the 27-grain cavity packing): finite files, a reference stress. */
static gb_status check_cavity_step(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    (void)sim, (void)err;
    run_ctx *c = user; /* the loop has written the step's files */
    c->steps_seen++;
    table g, w, ring;
    CHECK(read_step(c->dir, "grains", r->step, &g) && g.rows == 27);
    CHECK(read_step(c->dir, "host_wall", r->step, &w) && w.rows == 24);
    CHECK(read_step(c->dir, "host_ring", r->step, &ring) && ring.rows > 12);
    table_free(&g), table_free(&w), table_free(&ring);
    return GB_OK;
}

static gb_status count_step(void *user, const gb_sim *sim, const gb_step_report *r, gb_error *err)
{
    (void)sim, (void)r, (void)err;
    run_ctx *c = user;
    c->steps_seen++;
    return GB_OK;
}

/* Kirsch's stress around a hole of radius a under a remote uniaxial stress S along y (tension
 * positive), at (x, y): polar components with the angle p from the load's axis, then Cartesian. */
static void kirsch(double S, double a, double x, double y, double s[3])
{
    double r = hypot(x, y), t = atan2(y, x), p = t - PI / 2, q2 = a * a / (r * r), q4 = q2 * q2;
    double srr = S / 2 * (1 - q2) + S / 2 * (1 - 4 * q2 + 3 * q4) * cos(2 * p);
    double stt = S / 2 * (1 + q2) - S / 2 * (1 + 3 * q4) * cos(2 * p);
    double srt = -S / 2 * (1 + 2 * q2 - 3 * q4) * sin(2 * p);
    double c = cos(t), sn = sin(t);
    s[0] = srr * c * c + stt * sn * sn - 2 * srt * sn * c;
    s[1] = srr * sn * sn + stt * c * c + 2 * srt * sn * c;
    s[2] = (srr - stt) * sn * c + srt * (c * c - sn * sn);
}

/* The wide plate (tests/measure/plate_hole.yaml, d/W = 1/8, 64 elements on the hole): the
 * concentration along the hole against Kirsch's -(1 + 2 cos 2 theta) (0.08; measured 0.051: the
 * plate is finite, its bottom fixed, the elements constant) and the ring's stress against
 * Kirsch's field (0.05 s; measured 0.029 s). */
static void check_kirsch(const char *dir)
{
    char path[1200];
    table L, w, ring;
    snprintf(path, sizeof path, "%s/localisation.csv", dir);
    CHECK(table_read(path, &L) && L.rows == 2);
    double s_ref = cell(&L, 1, "s_ref");
    CHECK(!strcmp(L.cell[1 * L.cols + L.cols - 2], "boundary"));
    CHECK(read_step(dir, "host_wall", 1, &w) && w.rows == 64);
    CHECK(read_step(dir, "host_ring", 1, &ring) && ring.rows == 64);
    double ew = 0, er = 0;
    for (int k = 0; k < w.rows; k++) {
        double t = atan2(cell(&w, k, "y"), cell(&w, k, "x"));
        ew = fmax(ew, fabs(cell(&w, k, "concentration") + (1 + 2 * cos(2 * t))));
    }
    for (int q = 0; q < ring.rows; q++) {
        double s[3];
        kirsch(-s_ref, 2.5, cell(&ring, q, "x"), cell(&ring, q, "y"), s);
        er = fmax(er, fabs(cell(&ring, q, "sxx") - s[0]) / s_ref);
        er = fmax(er, fabs(cell(&ring, q, "syy") - s[1]) / s_ref);
        er = fmax(er, fabs(cell(&ring, q, "sxy") - s[2]) / s_ref);
    }
    printf("Kirsch: s_ref %.4g, largest concentration %.4f (Kirsch -3), off Kirsch by %.3f on the wall, %.3f s on "
           "the ring\n", s_ref, cell(&L, 1, "max_concentration"), ew, er);
    CHECK(s_ref > 0);
    CHECK(ew < 0.08);
    CHECK(er < 0.05);
    CHECK_NEAR(cell(&L, 1, "max_concentration"), -3, 0.08);
    table_free(&L), table_free(&w), table_free(&ring);
}

int main(void)
{
    char base[] = "/tmp/gembem_measures_XXXXXX";
    if (!mkdtemp(base)) return 1;
    char dir[256];
    snprintf(dir, sizeof dir, "%s/host", base);
    int n = run("tests/hybrid/host_loading.yaml", dir, check_host_step);
    CHECK(n == 4);
    check_localisation(dir, n, 1);
    CHECK(pvd_entries(dir) == -1); /* one grain: never a triangle */
    snprintf(dir, sizeof dir, "%s/kirsch", base);
    CHECK(run("tests/measure/plate_hole.yaml", dir, count_step) == 2);
    check_kirsch(dir);
    snprintf(dir, sizeof dir, "%s/cavity", base);
    n = run("validation/cavity_packing/scene.yaml", dir, check_cavity_step);
    CHECK(n == 2);
    check_localisation(dir, n, 1);
    CHECK(pvd_entries(dir) == 2);
    snprintf(dir, sizeof dir, "%s/affine", base);
    check_affine(dir);
    snprintf(dir, sizeof dir, "%s/granular", base);
    n = run("validation/biaxial122/test_shear.yaml", dir, check_granular_step);
    CHECK(n == 21);
    check_localisation(dir, n, 0);
    check_zone_follows_box(dir);
    CHECK(pvd_entries(dir) == 21);
    if (!gb_test_failures) {
        char cmd[300];
        snprintf(cmd, sizeof cmd, "rm -rf '%s'", base);
        if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", base);
    }
    TEST_END();
}
