/* The two reference fillings of the localisation study, from the boundary element module alone:
 * the empty cavity, and the cavity filled with a homogeneous elastic disc of its own modulus.
 *
 * Host: a body with a cavity (a .geo with groups bottom, right, top, left, cavity), condensed to
 * its cavity, F_h = K_h u + f0_h (bem.h: F_h is the force the outside puts on the host). Disc: a
 * second BEM body on the cavity's polygon, condensed over its whole boundary, F_d = K_d u, and
 * coupled by continuity of the displacement and action-reaction, (K_h + K_d) u = -f0_h
 * (validation/bem/filling.h, shared with the elliptic inclusion check validation/bem/inclusion.c).
 * A disc modulus of 0 leaves K_d out: the traction-free cavity. The host is then solved with its
 * cavity displaced by u (gb_bem_solve_group_displacement) and the hoop stress t.s.t of the host
 * side taken at each cavity element's midpoint (gb_bem_boundary_stress), as the run output does
 * for the granular fillings (src/measure/host_measure.c), with the same reference stress: the
 * largest mean traction |sum t L| / sum L of a loaded group.
 *
 * Usage: elastic_disc key=value ...     (defaults in brackets)
 *   mesh=FILE [meshes/square_cavity_sides.geo]  side=N [16] elements per side  cavity=N [64]
 *   mu=G [95000] nu=v [0.1]  plane=strain|stress [strain]          the host
 *   disc_mu=G [0: empty cavity] disc_nu=v [nu]                      the filling
 *   top_uy=d [-0.05] pressure=p [0] on left and right (t = -p n)   the load, reached in `steps`
 *   ends=clamped|rollers [clamped]: clamped: bottom fixed, top displaced (ux = 0);
 *       rollers: bottom and top tx = 0 with uy given, left ux = 0 (no confining pressure there)
 *   pressure_first=0|1 [1]: the pressure is applied first with the top held (steps_p steps), then
 *       the top moves; 0: both grow together
 *   steps=n [20] steps_p=n [0]   out=PREFIX (PREFIX_wall.csv: every step, PREFIX_curve.csv)
 *   check=1: the ctest (a disc of the host's own modulus under rollers makes the body homogeneous;
 *       a disc of modulus 1e-9 mu gives the empty cavity); exit 1 on a failed check. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "filling.h"
#include "gembem/bem.h"

#define PI 3.14159265358979323846

typedef struct {
    char mesh[512], out[512];
    int side, cavity, plane_stress, rollers, steps, steps_p, check;
    double mu, nu, disc_mu, disc_nu, top_uy, pressure;
} opts;

static void die(const char *what, const gb_error *err)
{
    fprintf(stderr, "elastic_disc: %s: %s\n", what, err ? err->msg : "");
    exit(2);
}

static void parse(int argc, char **argv, opts *o)
{
    memset(o, 0, sizeof *o);
    snprintf(o->mesh, sizeof o->mesh, "meshes/square_cavity_sides.geo");
    o->side = 16, o->cavity = 64, o->mu = 95000, o->nu = 0.1, o->disc_nu = -1, o->top_uy = -0.05, o->steps = 20;
    for (int i = 1; i < argc; i++) {
        char *eq = strchr(argv[i], '=');
        if (!eq) die(argv[i], NULL);
        *eq = 0;
        const char *k = argv[i], *v = eq + 1;
        if (!strcmp(k, "mesh")) snprintf(o->mesh, sizeof o->mesh, "%s", v);
        else if (!strcmp(k, "out")) snprintf(o->out, sizeof o->out, "%s", v);
        else if (!strcmp(k, "side")) o->side = atoi(v);
        else if (!strcmp(k, "cavity")) o->cavity = atoi(v);
        else if (!strcmp(k, "mu")) o->mu = atof(v);
        else if (!strcmp(k, "nu")) o->nu = atof(v);
        else if (!strcmp(k, "plane")) o->plane_stress = !strcmp(v, "stress");
        else if (!strcmp(k, "disc_mu")) o->disc_mu = atof(v);
        else if (!strcmp(k, "disc_nu")) o->disc_nu = atof(v);
        else if (!strcmp(k, "top_uy")) o->top_uy = atof(v);
        else if (!strcmp(k, "pressure")) o->pressure = atof(v);
        else if (!strcmp(k, "ends")) o->rollers = !strcmp(v, "rollers");
        else if (!strcmp(k, "steps")) o->steps = atoi(v);
        else if (!strcmp(k, "steps_p")) o->steps_p = atoi(v);
        else if (!strcmp(k, "check")) o->check = atoi(v);
        else die(k, NULL);
    }
    if (o->disc_nu < 0) o->disc_nu = o->nu;
    if (o->steps < 1 || o->steps_p < 0 || o->side < 1 || o->cavity < 3) die("bad counts", NULL);
}

/* The host and the disc, set up once. */
typedef struct {
    gb_bem_mesh mesh;
    gb_bem_system sys;
    v_filling disc; /* validation/bem/filling.h */
    int filled;     /* 0: the empty cavity */
    int cav, m;
    int g_bottom, g_right, g_top, g_left;
} model;

static void setup(const opts *o, double disc_mu, model *M)
{
    gb_error err = {0};
    memset(M, 0, sizeof *M);
    gb_bem_mesh_opts mo = gb_bem_mesh_opts_default();
    const char *sides[4] = {"bottom", "right", "top", "left"};
    for (int s = 0; s < 4; s++) {
        snprintf(mo.group_sizes[mo.n_group_sizes].group, GB_BEM_NAME_MAX, "%s", sides[s]);
        mo.group_sizes[mo.n_group_sizes++].count = o->side;
    }
    snprintf(mo.group_sizes[mo.n_group_sizes].group, GB_BEM_NAME_MAX, "cavity");
    mo.group_sizes[mo.n_group_sizes++].count = o->cavity;
    if (gb_bem_mesh_load(o->mesh, &mo, &M->mesh, &err)) die("host mesh", &err);
    M->g_bottom = gb_bem_mesh_group(&M->mesh, "bottom"), M->g_right = gb_bem_mesh_group(&M->mesh, "right");
    M->g_top = gb_bem_mesh_group(&M->mesh, "top"), M->g_left = gb_bem_mesh_group(&M->mesh, "left");
    M->cav = gb_bem_mesh_group(&M->mesh, "cavity");
    if (M->g_bottom < 0 || M->g_right < 0 || M->g_top < 0 || M->g_left < 0 || M->cav < 0)
        die("the mesh needs groups bottom, right, top, left, cavity", NULL);
    gb_bem_material mat = {o->mu, o->nu, o->plane_stress ? GB_BEM_PLANE_STRESS : GB_BEM_PLANE_STRAIN};
    if (gb_bem_assemble(&M->mesh, &mat, &M->sys, &err)) die("host assembly", &err);
    for (int e = 0; e < M->mesh.n; e++) M->m += 2 * (M->mesh.group[e] == M->cav);
    if (disc_mu <= 0) return;
    gb_bem_material dmat = {disc_mu, o->disc_nu, mat.plane};
    M->filled = 1;
    if (v_filling_setup(&M->mesh, M->cav, &dmat, &M->disc, &err)) die("disc", &err);
}

static void model_free(model *M)
{
    gb_bem_system_free(&M->sys), gb_bem_mesh_free(&M->mesh);
    v_filling_free(&M->disc);
}

static void set_problem(const opts *o, const model *M, double uy, double p, gb_bem_problem *pr)
{
    memset(pr, 0, sizeof *pr);
    if (!o->rollers) {
        pr->bc[M->g_bottom].kind = GB_BEM_BC_FIXED;
        pr->bc[M->g_top].kind = GB_BEM_BC_DISPLACEMENT, pr->bc[M->g_top].value[1] = uy;
        pr->bc[M->g_left].kind = pr->bc[M->g_right].kind = GB_BEM_BC_PRESSURE;
        pr->bc[M->g_left].value[0] = pr->bc[M->g_right].value[0] = p;
    } else {
        pr->bc[M->g_bottom].kind = pr->bc[M->g_top].kind = GB_BEM_BC_COMPONENTS;
        pr->bc[M->g_bottom].u_given = pr->bc[M->g_top].u_given = 2; /* tx = 0, uy given */
        pr->bc[M->g_top].value[1] = uy;
        pr->bc[M->g_left].kind = GB_BEM_BC_COMPONENTS, pr->bc[M->g_left].u_given = 1; /* ux = 0, ty = 0 */
        pr->bc[M->g_right].kind = GB_BEM_BC_PRESSURE, pr->bc[M->g_right].value[0] = p;
    }
    pr->bc[M->cav].kind = GB_BEM_BC_FREE;
}

/* One load: the coupled cavity displacement u (m), the host's solution, hoop stress per cavity
 * element (in K's elem order), the reference stress, the top's force. */
typedef struct {
    double *u, *hoop, *nstress, s_ref, top_f[2], top_len, max_conc;
    int *elem;
    gb_bem_solution sol;
} result;

static void solve(const opts *o, const model *M, double uy, double p, result *r)
{
    gb_error err = {0};
    gb_bem_problem pr;
    set_problem(o, M, uy, p, &pr);
    gb_bem_stiffness Kh;
    if (gb_bem_condense(&M->mesh, &M->sys, &pr, M->cav, NULL, &Kh, &err)) die("host condensation", &err);
    int m = M->m;
    r->u = malloc((size_t)m * sizeof *r->u);
    r->elem = malloc((size_t)m / 2 * sizeof *r->elem);
    memcpy(r->elem, Kh.elem, (size_t)m / 2 * sizeof *r->elem);
    if (v_filling_couple(M->filled ? &M->disc : NULL, &Kh, r->u, &err)) die("coupled system", &err);
    gb_bem_stiffness_free(&Kh);
    memset(&r->sol, 0, sizeof r->sol);
    if (gb_bem_solve_group_displacement(&M->mesh, &M->sys, &pr, M->cav, r->u, NULL, &r->sol, &err))
        die("host solve", &err);
    int n = M->mesh.n;
    double *bs = malloc(3 * (size_t)n * sizeof *bs);
    if (gb_bem_boundary_stress(&M->mesh, &M->sys.material, &r->sol, bs, &err)) die("boundary stress", &err);
    r->hoop = malloc((size_t)m / 2 * sizeof *r->hoop);
    r->nstress = malloc((size_t)m / 2 * sizeof *r->nstress);
    double hmax = 0;
    for (int k = 0; k < m / 2; k++) {
        int e = r->elem[k];
        const double *s = bs + 3 * e, *t = M->mesh.tangent + 2 * e, *nn = M->mesh.normal + 2 * e;
        r->hoop[k] = t[0] * t[0] * s[0] + t[1] * t[1] * s[1] + 2 * t[0] * t[1] * s[2];
        r->nstress[k] = nn[0] * nn[0] * s[0] + nn[1] * nn[1] * s[1] + 2 * nn[0] * nn[1] * s[2];
        if (fabs(r->hoop[k]) > fabs(hmax)) hmax = r->hoop[k];
    }
    free(bs);
    /* The reference stress as src/measure/host_measure.c: the largest mean traction of a group
     * with a non-zero prescribed value. */
    r->s_ref = 0, r->top_f[0] = r->top_f[1] = 0, r->top_len = 0;
    for (int g = 0; g < M->mesh.n_groups; g++) {
        const gb_bem_bc *bc = &pr.bc[g];
        int has = (bc->kind == GB_BEM_BC_DISPLACEMENT || bc->kind == GB_BEM_BC_COMPONENTS) ?
                      (bc->value[0] != 0 || bc->value[1] != 0) :
                      bc->kind == GB_BEM_BC_PRESSURE ? bc->value[0] != 0 : 0;
        double f[2] = {0, 0}, len = 0;
        for (int e = 0; e < n; e++)
            if (M->mesh.group[e] == g) {
                f[0] += r->sol.t[2 * e] * M->mesh.length[e], f[1] += r->sol.t[2 * e + 1] * M->mesh.length[e];
                len += M->mesh.length[e];
            }
        if (g == M->g_top) r->top_f[0] = f[0], r->top_f[1] = f[1], r->top_len = len;
        if (g != M->cav && has && len > 0 && hypot(f[0], f[1]) / len > r->s_ref) r->s_ref = hypot(f[0], f[1]) / len;
    }
    r->max_conc = r->s_ref > 0 ? hmax / r->s_ref : 0;
}

static void result_free(result *r)
{
    free(r->u), free(r->hoop), free(r->nstress), free(r->elem);
    gb_bem_solution_free(&r->sol);
}

/* The load of step k: the pressure first (steps_p steps, top held), then the top. */
static void load_of_step(const opts *o, int k, double *uy, double *p)
{
    if (o->steps_p > 0) {
        *p = o->pressure * (k < o->steps_p ? (double)k / o->steps_p : 1.0);
        *uy = k <= o->steps_p ? 0 : o->top_uy * (k - o->steps_p) / o->steps;
    } else {
        *p = o->pressure * k / o->steps, *uy = o->top_uy * k / o->steps;
    }
}

static int run(const opts *o)
{
    model M;
    setup(o, o->disc_mu, &M);
    char path[600];
    snprintf(path, sizeof path, "%s_curve.csv", o->out);
    FILE *fc = fopen(path, "w");
    if (!fc) die(path, NULL);
    fprintf(fc, "step,pressure,top_uy,top_fx,top_fy,top_length,s_ref,max_concentration\n");
    snprintf(path, sizeof path, "%s_wall.csv", o->out);
    FILE *fw = fopen(path, "w");
    if (!fw) die(path, NULL);
    fprintf(fw, "step,element,x,y,angle_deg,ux,uy,hoop,normal,concentration\n");
    int last = o->steps + o->steps_p;
    for (int k = 0; k <= last; k++) {
        double uy, p;
        load_of_step(o, k, &uy, &p);
        result r;
        solve(o, &M, uy, p, &r);
        fprintf(fc, "%d,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e\n", k, p, uy, r.top_f[0], r.top_f[1], r.top_len,
                r.s_ref, r.max_conc);
        for (int q = 0; q < M.m / 2; q++) {
            int e = r.elem[q];
            double x = M.mesh.mid[2 * e], y = M.mesh.mid[2 * e + 1];
            fprintf(fw, "%d,%d,%.10e,%.10e,%.6f,%.10e,%.10e,%.10e,%.10e,%.10e\n", k, e, x, y, atan2(y, x) * 180 / PI,
                    r.u[2 * q], r.u[2 * q + 1], r.hoop[q], r.nstress[q], r.s_ref > 0 ? r.hoop[q] / r.s_ref : 0);
        }
        result_free(&r);
    }
    fclose(fc);
    fclose(fw);
    model_free(&M);
    return 0;
}

/* ---------------------------------------------------------------- the ctest */

static int failures = 0;
#define CHECK(cond, ...)                                                                                               \
    do {                                                                                                               \
        if (!(cond)) {                                                                                                 \
            fprintf(stderr, "check failed: %s: ", #cond);                                                              \
            fprintf(stderr, __VA_ARGS__);                                                                              \
            fprintf(stderr, "\n");                                                                                     \
            failures++;                                                                                                \
        }                                                                                                              \
    } while (0)

static int check(opts *o)
{
    /* Rollers on bottom, top and left, a pressure p on the right: a homogeneous body carries the
     * uniform stress sxx = -p, syy from eyy = d / L (plane strain), and its displacement is linear. */
    o->rollers = 1, o->pressure = 0.3 * o->mu * 1e-3, o->top_uy = -0.01;
    double L = 10, lam = o->plane_stress ? 2 * o->mu * o->nu / (1 - o->nu) : 2 * o->mu * o->nu / (1 - 2 * o->nu);
    double eyy = o->top_uy / L, exx = (-o->pressure - lam * eyy) / (2 * o->mu + lam);
    double sxx = -o->pressure, syy = lam * exx + (2 * o->mu + lam) * eyy, smax = fmax(fabs(sxx), fabs(syy));
    int ns[3] = {32, 64, 128};
    double err_hoop[3], err_u[3], err_empty[3];
    printf("Homogeneous body (disc of the host's modulus), rollers, sxx = %.4g, syy = %.4g:\n", sxx, syy);
    printf("| cavity elements | side elements | max |hoop - t.s.t| / max|s| | max |u - u_exact| / (|eyy| R) | "
           "empty limit: max |hoop(1e-9 mu) - hoop(empty)| / max|hoop(empty)| |\n|---:|---:|---:|---:|---:|\n");
    for (int l = 0; l < 3; l++) {
        o->cavity = ns[l], o->side = ns[l] / 4;
        model M;
        setup(o, o->mu, &M);
        result r;
        solve(o, &M, o->top_uy, o->pressure, &r);
        double eh = 0, eu = 0, R = 0;
        for (int q = 0; q < M.m / 2; q++) {
            int e = r.elem[q];
            const double *t = M.mesh.tangent + 2 * e, *x = M.mesh.mid + 2 * e;
            double exact = t[0] * t[0] * sxx + t[1] * t[1] * syy;
            eh = fmax(eh, fabs(r.hoop[q] - exact) / smax);
            /* left at x = -5 held, bottom at y = -5 held */
            double ux = exx * (x[0] + 5), uy = eyy * (x[1] + 5);
            eu = fmax(eu, hypot(r.u[2 * q] - ux, r.u[2 * q + 1] - uy));
            R = fmax(R, hypot(x[0], x[1]));
        }
        err_hoop[l] = eh, err_u[l] = eu / (fabs(eyy) * R);
        result_free(&r);
        model_free(&M);
        /* modulus -> 0: the empty cavity */
        model M0, Me;
        setup(o, 1e-9 * o->mu, &M0);
        setup(o, 0, &Me);
        result r0, re;
        solve(o, &M0, o->top_uy, o->pressure, &r0);
        solve(o, &Me, o->top_uy, o->pressure, &re);
        double d = 0, hm = 0;
        for (int q = 0; q < M0.m / 2; q++) d = fmax(d, fabs(r0.hoop[q] - re.hoop[q])), hm = fmax(hm, fabs(re.hoop[q]));
        err_empty[l] = d / hm;
        result_free(&r0), result_free(&re);
        model_free(&M0), model_free(&Me);
        printf("| %d | %d | %.3e | %.3e | %.3e |\n", ns[l], ns[l] / 4, err_hoop[l], err_u[l], err_empty[l]);
    }
    /* Measured (2026-11-22): see README; the bounds are about twice the measured errors. */
    CHECK(err_hoop[1] < 0.007, "hoop error %.3e at 64 cavity elements", err_hoop[1]);
    CHECK(err_hoop[2] < err_hoop[0], "hoop error does not decrease with the mesh: %.3e -> %.3e", err_hoop[0],
          err_hoop[2]);
    CHECK(err_u[1] < 0.05 && err_u[2] < err_u[0], "displacement error %.3e at 64 cavity elements", err_u[1]);
    for (int l = 0; l < 3; l++) CHECK(err_empty[l] < 1e-6, "empty limit %.3e at level %d", err_empty[l], l);
    return failures ? 1 : 0;
}

int main(int argc, char **argv)
{
    opts o;
    parse(argc, argv, &o);
    if (o.check) return check(&o);
    if (!o.out[0]) die("out=PREFIX is required", NULL);
    return run(&o);
}
