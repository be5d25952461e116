/* Validation: an elastic elliptic inclusion in an infinite plane under a remote uniform stress.
 *
 * Eshelby (1957) showed that the stress inside an ellipsoidal inhomogeneity in an infinite body
 * under a uniform remote load is uniform; Hardiman (1954, Q. J. Mech. Appl. Math. 7, 226) showed
 * it for the elliptic inclusion in a plate. The reference here is Eshelby's equivalent inclusion
 * (Mura 1987, Micromechanics of Defects in Solids, section 22): with the host's stiffness C, the
 * inclusion's C_i, the remote strain e0 and the elliptic cylinder's Eshelby tensor S (Mura
 * eq. 11.22, plane strain, the host's nu), the eigenstrain e* solves
 *     C_i (e0 + S e*) = C (e0 + S e* - e*),      and the inclusion's stress is C_i (e0 + S e*).
 * Plane stress is the same plane problem with nu -> nu / (1 + nu) for both materials
 * (Muskhelishvili's kappa = (3 - nu) / (1 + nu) = 3 - 4 nu / (1 + nu)). The reference is checked
 * against three independent limits before use: a circle (Muskhelishvili's circular inclusion), the
 * homogeneous body (the remote stress), and a vanishing inclusion modulus (Inglis's hole: hoop
 * stress S (1 + 2 a / b) and -S at the ends of the axes under S across the major axis).
 *
 * The boundary element model: meshes/ellipse_infinite.geo (a = 2, b = 1, major axis at 30 deg to
 * x), an unbounded host condensed on the cavity, the cavity filled with a second body on the same
 * polygon and coupled on the interface (filling.h); the inclusion's stress at 9 interior points
 * (its center and 8 points at half its semi-axes) from the filling's solution (gb_bem_interior).
 * Error: max over the points of |s - s_ref|_F / |s_ref|_F (Frobenius norms of the in-plane stress);
 * spread: max over the points of |s - mean s|_F / |s_ref|_F.
 * Usage: bem_inclusion [--full]      (the ctest runs it without --full: N = 32 to 256; --full: to 512)
 *        bem_inclusion --reference   the reference alone, as CSV, for inclusion_reference.py (an
 *                                    independent solution by complex potentials, ctest
 *                                    validation_bem_inclusion_reference) */
#include <lapacke.h>

#include "filling.h"
#include "vcommon.h"

/* The geometry of meshes/ellipse_infinite.geo */
static const double A_AXIS = 2, B_AXIS = 1, ANGLE = V_PI / 6;

/* ---------------------------------------------------------------- the reference */

/* Mandel components (11, 22, 33, sqrt2 12) of the plane problem: 13 and 23 decouple (and vanish
 * under an in-plane load), 33 carries the plane strain constraint (S_33kl = 0). Row-major 4 x 4. */
static void eshelby_tensor(double nu, double a, double b, double S[16])
{
    double c = 1 / (2 * (1 - nu)), t = a + b, q = 1 - 2 * nu;
    memset(S, 0, 16 * sizeof *S);
    S[0] = c * ((b * b + 2 * a * b) / (t * t) + q * b / t);  /* S1111 */
    S[1] = c * (b * b / (t * t) - q * b / t);                /* S1122 */
    S[2] = c * 2 * nu * b / t;                               /* S1133 */
    S[4] = c * (a * a / (t * t) - q * a / t);                /* S2211 */
    S[5] = c * ((a * a + 2 * a * b) / (t * t) + q * a / t);  /* S2222 */
    S[6] = c * 2 * nu * a / t;                               /* S2233 */
    S[15] = 2 * c * ((a * a + b * b) / (2 * t * t) + q / 2); /* 2 S1212 (Mandel) */
}

static void stiffness(double mu, double nu, double C[16])
{
    double lam = 2 * mu * nu / (1 - 2 * nu);
    memset(C, 0, 16 * sizeof *C);
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) C[4 * i + j] = lam;
        C[5 * i] += 2 * mu;
    }
    C[15] = 2 * mu;
}

static void matmul4(const double *A, const double *B, double *AB)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            AB[4 * i + j] = 0;
            for (int k = 0; k < 4; k++) AB[4 * i + j] += A[4 * i + k] * B[4 * k + j];
        }
}

/* The inclusion's uniform stress s_in and strain e_in (xx, yy, xy) for the remote stress s (xx, yy,
 * xy); host (mu, nu), inclusion (mu_i, nu_i), semi-axes a, b, the a axis at `angle` to x. */
static void reference(double mu, double nu, double mu_i, double nu_i, int plane_stress, double a, double b,
                      double angle, const double s[3], double s_in[3], double e_in[3])
{
    if (plane_stress) nu /= 1 + nu, nu_i /= 1 + nu_i;
    double c = cos(angle), sn = sin(angle), r2 = sqrt(2);
    /* the remote stress in the ellipse's axes, then the plane strain stress and strain there */
    double s11 = c * c * s[0] + sn * sn * s[1] + 2 * c * sn * s[2], s22 = sn * sn * s[0] + c * c * s[1] - 2 * c * sn * s[2],
           s12 = c * sn * (s[1] - s[0]) + (c * c - sn * sn) * s[2];
    double e0[4] = {((1 - nu) * s11 - nu * s22) / (2 * mu), ((1 - nu) * s22 - nu * s11) / (2 * mu), 0,
                    r2 * s12 / (2 * mu)};
    double S[16], C[16], Ci[16], dC[16], M[16], rhs[4], e[4], si[4];
    eshelby_tensor(nu, a, b, S);
    stiffness(mu, nu, C), stiffness(mu_i, nu_i, Ci);
    for (int i = 0; i < 16; i++) dC[i] = Ci[i] - C[i];
    matmul4(dC, S, M); /* ((C_i - C) S + C) e* = -(C_i - C) e0 */
    for (int i = 0; i < 16; i++) M[i] += C[i];
    for (int i = 0; i < 4; i++) {
        rhs[i] = 0;
        for (int k = 0; k < 4; k++) rhs[i] -= dC[4 * i + k] * e0[k];
    }
    int ipiv[4];
    if (LAPACKE_dgesv(LAPACK_ROW_MAJOR, 4, 1, M, 4, ipiv, rhs, 1)) {
        fprintf(stderr, "singular equivalent inclusion system\n");
        exit(1);
    }
    for (int i = 0; i < 4; i++) {
        e[i] = e0[i];
        for (int k = 0; k < 4; k++) e[i] += S[4 * i + k] * rhs[k];
    }
    for (int i = 0; i < 4; i++) {
        si[i] = 0;
        for (int k = 0; k < 4; k++) si[i] += Ci[4 * i + k] * e[k];
    }
    /* back to x, y: T' = R T R^t for the in-plane tensors */
    double t[2][3] = {{si[0], si[1], si[3] / r2}, {e[0], e[1], e[3] / r2}}, *out[2] = {s_in, e_in};
    for (int k = 0; k < 2; k++) {
        double p = t[k][0], q = t[k][1], r = t[k][2];
        out[k][0] = c * c * p + sn * sn * q - 2 * c * sn * r;
        out[k][1] = sn * sn * p + c * c * q + 2 * c * sn * r;
        out[k][2] = c * sn * (p - q) + (c * c - sn * sn) * r;
    }
}

static double frob(const double s[3])
{
    return sqrt(s[0] * s[0] + s[1] * s[1] + 2 * s[2] * s[2]);
}

static double frob_diff(const double s[3], const double r[3])
{
    double d[3] = {s[0] - r[0], s[1] - r[1], s[2] - r[2]};
    return frob(d);
}

/* The limits the reference must meet, independently of Eshelby's tensor. */
static void check_reference(void)
{
    double mu = 1, nu = 0.3, loads[3][3] = {{1, 0, 0}, {0.3, -0.8, 0.45}, {1, 1, 0}};
    double mods[3][2] = {{0.1, 0.2}, {10, 0.45}, {2.5, 0.3}}, worst_circle = 0, worst_homog = 0;
    for (int ps = 0; ps < 2; ps++)
        for (int im = 0; im < 3; im++)
            for (int il = 0; il < 3; il++) {
                /* circle (Muskhelishvili): the mean stress scales by mu_i (k + 1) / (2 mu_i + mu (k_i - 1)),
                 * the deviator by mu_i (k + 1) / (mu + k mu_i), k = 3 - 4 nu or (3 - nu) / (1 + nu) */
                const double *s = loads[il];
                double mi = mods[im][0], ni = mods[im][1];
                double k = ps ? (3 - nu) / (1 + nu) : 3 - 4 * nu, ki = ps ? (3 - ni) / (1 + ni) : 3 - 4 * ni;
                double fh = mi * (k + 1) / (2 * mi + mu * (ki - 1)), fd = mi * (k + 1) / (mu + k * mi), p = (s[0] + s[1]) / 2;
                double want[3] = {p * fh + (s[0] - p) * fd, p * fh + (s[1] - p) * fd, s[2] * fd}, got[3], e[3];
                reference(mu, nu, mi, ni, ps, 1.3, 1.3, 0.7, s, got, e);
                worst_circle = fmax(worst_circle, frob_diff(got, want) / frob(want));
                /* homogeneous: the remote stress */
                reference(mu, nu, mu, nu, ps, A_AXIS, B_AXIS, ANGLE, s, got, e);
                worst_homog = fmax(worst_homog, frob_diff(got, s) / frob(s));
            }
    /* Inglis: S across the major axis, an inclusion 1e-9 times as stiff; the host's hoop stress at
     * the ends of the axes from the inclusion's strain (continuity of the tangential strain and of
     * the traction, plane strain Hooke). Axes here along x (a) and y (b). */
    double ratios[3] = {2, 1, 0.25}, worst_inglis = 0;
    printf("### The reference: limits (Eshelby's equivalent inclusion, Mura eq. 11.22)\n\n");
    printf("| a / b | hoop at (a, 0), G_i = 1e-9 G | Inglis 1 + 2 a / b | hoop at (0, b) | Inglis |\n");
    printf("|---:|---:|---:|---:|---:|\n");
    for (int i = 0; i < 3; i++) {
        double s[3] = {0, 1, 0}, si[3], e[3], a = ratios[i], b = 1;
        reference(mu, nu, 1e-9 * mu, 0.2, 0, a, b, 0, s, si, e);
        double hoop_a = (2 * mu * e[1] + nu * si[0]) / (1 - nu), hoop_b = (2 * mu * e[0] + nu * si[1]) / (1 - nu);
        printf("| %g | %.9f | %g | %.9f | -1 |\n", a / b, hoop_a, 1 + 2 * a / b, hoop_b);
        worst_inglis = fmax(worst_inglis, fmax(fabs(hoop_a - (1 + 2 * a / b)), fabs(hoop_b + 1)));
    }
    printf("\nCircle (a = b) against Muskhelishvili's circular inclusion: max relative difference %.1e; "
           "G_i = G, nu_i = nu: max relative difference from the remote stress %.1e (plane strain and stress, "
           "G_i / G = 0.1, 10, 2.5, three loads).\n\n",
           worst_circle, worst_homog);
    V_CHECK(worst_circle < 1e-12, "circle limit %.2e", worst_circle);
    V_CHECK(worst_homog < 1e-12, "homogeneous limit %.2e", worst_homog);
    V_CHECK(worst_inglis < 1e-7, "Inglis limit %.2e", worst_inglis);
}

/* ---------------------------------------------------------------- the boundary element model */

#define NPTS 9
#define NLOADS 2
#define NINCL 2
static const double LOADS[NLOADS][3] = {{1, 0, 0}, {0.5, -1, 0.4}};
static const char *LOAD_NAMES[NLOADS] = {"uniaxial s_xx", "biaxial + shear"};
static const double INCL[NINCL][2] = {{0.1, 0.2}, {10, 0.45}}; /* G_i / G, nu_i; host G = 1, nu = 0.3 */

/* error and spread of the inclusion's stress, per plane, inclusion and load */
typedef struct {
    double err, spread, ref[3];
} outcome;

static void interior_points(double *xy)
{
    double c = cos(ANGLE), s = sin(ANGLE);
    xy[0] = xy[1] = 0;
    for (int k = 0; k < 8; k++) {
        double X = 0.5 * A_AXIS * cos(k * V_PI / 4), Y = 0.5 * B_AXIS * sin(k * V_PI / 4);
        xy[2 + 2 * k] = c * X - s * Y, xy[3 + 2 * k] = s * X + c * Y;
    }
}

/* The host with n elements on the cavity: every inclusion and load; also the distance of the
 * mesh's vertices from the ellipse, which guards the constants above against the .geo. */
static void run_mesh(int n, int plane_stress, outcome out[NINCL][NLOADS])
{
    gb_error err = {0};
    gb_bem_mesh m;
    v_mesh("meshes/ellipse_infinite.geo", 1, "cavity", n, NULL, 0, &m);
    for (int e = 0; e < m.n; e++) {
        double x = m.p0[2 * e], y = m.p0[2 * e + 1], X = cos(ANGLE) * x + sin(ANGLE) * y,
               Y = -sin(ANGLE) * x + cos(ANGLE) * y;
        V_CHECK(fabs(X * X / (A_AXIS * A_AXIS) + Y * Y / (B_AXIS * B_AXIS) - 1) < 1e-9, "vertex %d off the ellipse", e);
    }
    gb_bem_material mat = {1, 0.3, plane_stress ? GB_BEM_PLANE_STRESS : GB_BEM_PLANE_STRAIN};
    gb_bem_system sys;
    if (gb_bem_assemble(&m, &mat, &sys, &err)) v_die(&err);
    gb_bem_problem pr[NLOADS];
    memset(pr, 0, sizeof pr);
    for (int l = 0; l < NLOADS; l++) {
        pr[l].bc[0].kind = GB_BEM_BC_FREE; /* the cavity: condensed */
        memcpy(pr[l].remote_stress, LOADS[l], sizeof LOADS[l]);
    }
    /* one factorisation for every load: f0 of load l at f0[l mm] */
    gb_bem_stiffness Kh;
    size_t mm = 2 * (size_t)m.n;
    double *f0 = malloc(sizeof(double) * mm * NLOADS);
    if (gb_bem_condense_loads(&m, &sys, pr, NLOADS, 0, NULL, &Kh, f0 + mm, NULL, &err)) v_die(&err);
    memcpy(f0, Kh.f0, sizeof(double) * mm);
    double *f0_own = Kh.f0;
    double xy[2 * NPTS], st[3 * NPTS], *u = malloc(sizeof(double) * 2 * (size_t)m.n);
    interior_points(xy);
    for (int i = 0; i < NINCL; i++) {
        gb_bem_material imat = {INCL[i][0], INCL[i][1], mat.plane};
        v_filling fill;
        if (v_filling_setup(&m, 0, &imat, &fill, &err)) v_die(&err);
        for (int l = 0; l < NLOADS; l++) {
            Kh.f0 = f0 + mm * (size_t)l;
            gb_bem_solution sol;
            gb_bem_problem none;
            memset(&none, 0, sizeof none);
            if (v_filling_couple(&fill, &Kh, u, &err) || v_filling_solve(&fill, u, &sol, &err) ||
                gb_bem_interior(&fill.mesh, &imat, &none, &sol, NPTS, xy, NULL, st, &err))
                v_die(&err);
            outcome *o = &out[i][l];
            double e_in[3], mean[3] = {0, 0, 0};
            reference(1, 0.3, INCL[i][0], INCL[i][1], plane_stress, A_AXIS, B_AXIS, ANGLE, LOADS[l], o->ref, e_in);
            o->err = o->spread = 0;
            for (int p = 0; p < NPTS; p++)
                for (int c = 0; c < 3; c++) mean[c] += st[3 * p + c] / NPTS;
            for (int p = 0; p < NPTS; p++) {
                o->err = fmax(o->err, frob_diff(st + 3 * p, o->ref) / frob(o->ref));
                o->spread = fmax(o->spread, frob_diff(st + 3 * p, mean) / frob(o->ref));
            }
            gb_bem_solution_free(&sol);
        }
        v_filling_free(&fill);
    }
    Kh.f0 = f0_own;
    gb_bem_stiffness_free(&Kh);
    free(f0), free(u);
    gb_bem_system_free(&sys);
    gb_bem_mesh_free(&m);
}

/* The reference on a spread of cases, for inclusion_reference.py. */
static void print_reference(void)
{
    double geo[3][3] = {{A_AXIS, B_AXIS, ANGLE}, {1, 3, -0.9}, {1.5, 1.5, 0}}, mods[3][2] = {{0.1, 0.2}, {10, 0.45}, {2.5, 0.3}};
    double loads[3][3] = {{1, 0, 0}, {0, 1, 0}, {0.5, -1, 0.4}};
    printf("plane_stress,mu,nu,mu_i,nu_i,a,b,angle,sxx,syy,sxy,in_sxx,in_syy,in_sxy\n");
    for (int ps = 0; ps < 2; ps++)
        for (int g = 0; g < 3; g++)
            for (int i = 0; i < 3; i++)
                for (int l = 0; l < 3; l++) {
                    double r[3], e[3];
                    const double *s = loads[l];
                    reference(1, 0.3, mods[i][0], mods[i][1], ps, geo[g][0], geo[g][1], geo[g][2], s, r, e);
                    printf("%d,1,0.3,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", ps, mods[i][0],
                           mods[i][1], geo[g][0], geo[g][1], geo[g][2], s[0], s[1], s[2], r[0], r[1], r[2]);
                }
}

int main(int argc, char **argv)
{
    if (argc > 1 && !strcmp(argv[1], "--reference")) {
        print_reference();
        return 0;
    }
    int full = argc > 1 && !strcmp(argv[1], "--full");
    check_reference();
    enum { MAXL = 5 };
    int nl = full ? 5 : 4, ns[MAXL] = {32, 64, 128, 256, 512};
    static outcome res[2][MAXL][NINCL][NLOADS];
    for (int ps = 0; ps < 2; ps++)
        for (int k = 0; k < nl; k++) run_mesh(ns[k], ps, res[ps][k]);

    printf("### Elliptic inclusion (a = 2, b = 1, major axis at 30 deg) in an infinite plane, host G = 1, "
           "nu = 0.3; N elements on the interface\n\n");
    printf("| plane | G_i / G | nu_i | remote (sxx, syy, sxy) | reference inside (sxx, syy, sxy) |");
    for (int k = 0; k < nl; k++) printf(" err N = %d |%s", ns[k], k ? " order |" : "");
    printf(" spread N = %d | spread N = %d |\n|---|---:|---:|---|---|", ns[0], ns[nl - 1]);
    for (int k = 0; k < 2 * nl + 1; k++) printf("---:|");
    printf("\n");
    for (int ps = 0; ps < 2; ps++)
        for (int i = 0; i < NINCL; i++)
            for (int l = 0; l < NLOADS; l++) {
                const double *r = res[ps][0][i][l].ref, *s = LOADS[l];
                printf("| %s | %g | %g | %s (%g, %g, %g) | (%.4f, %.4f, %.4f) |", ps ? "stress" : "strain", INCL[i][0],
                       INCL[i][1], LOAD_NAMES[l], s[0], s[1], s[2], r[0], r[1], r[2]);
                for (int k = 0; k < nl; k++) {
                    printf(" %.3e |", res[ps][k][i][l].err);
                    if (k) printf(" %.2f |", v_order(res[ps][k - 1][i][l].err, res[ps][k][i][l].err, 2));
                }
                printf(" %.2e | %.2e |\n", res[ps][0][i][l].spread, res[ps][nl - 1][i][l].spread);
            }
    printf("\n");
    /* Constant elements: first order (README). Measured (2026-11-24, validation/bem/regenerate.sh):
     * N err at N = 256 at most 0.730 (G_i / G = 0.1) and 0.411 (G_i / G = 10), tending to 0.73 and
     * 0.40 at N = 512: the bounds are 1.25 times these, rounded. The order is 0.97-1.29 from 64 to
     * 128 (the stiff inclusion comes to 1 from above: 1.5 from 32 to 64) and 0.99-1.16 from 128 to
     * 256: the windows leave 0.1-0.15 either side. A kernel coefficient off by 1-2 % in the
     * assembly or the interior stress kernels fails them (README); the spread over the points falls
     * with the mesh (at most 3.6e-4 at N = 256). */
    const double C[NINCL] = {0.9, 0.52};
    for (int ps = 0; ps < 2; ps++)
        for (int i = 0; i < NINCL; i++)
            for (int l = 0; l < NLOADS; l++) {
                const outcome *o64 = &res[ps][1][i][l], *o128 = &res[ps][2][i][l], *o256 = &res[ps][3][i][l];
                double p1 = v_order(o64->err, o128->err, 2), p2 = v_order(o128->err, o256->err, 2);
                V_CHECK(256 * o256->err < C[i], "plane %d, G_i %g, load %d: N err %.3f at N = 256", ps, INCL[i][0], l,
                        256 * o256->err);
                V_CHECK(p1 > 0.85 && p1 < 1.45 && p2 > 0.9 && p2 < 1.25,
                        "plane %d, G_i %g, load %d: orders %.2f (64 to 128), %.2f (128 to 256)", ps, INCL[i][0], l, p1,
                        p2);
                V_CHECK(o256->spread < 5e-4 && o256->spread < o128->spread && o128->spread < o64->spread,
                        "plane %d, G_i %g, load %d: spread %.2e, %.2e, %.2e at N = 64, 128, 256", ps, INCL[i][0], l,
                        o64->spread, o128->spread, o256->spread);
            }
    fflush(stdout);
    if (v_failures) fprintf(stderr, "%d check(s) failed\n", v_failures);
    return v_failures ? 1 : 0;
}
