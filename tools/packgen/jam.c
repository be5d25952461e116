/* gb_jam - a jammed packing from a loose one: the box and the disc centres are shrunk about the
 * box's centre to a target porosity (neighbours then overlap), and the frictionless discs are
 * relaxed with the walls fixed by FIRE (Bitzek, Koskinen, Gaehler, Moseler and Gumbsch, Phys. Rev.
 * Lett. 97, 170201, 2006) until every disc's out-of-balance force is below a tolerance.
 *
 * Why: a granular solver's load steps should start from equilibrium. Frictionless discs in
 * equilibrium are also in equilibrium with friction (zero tangential forces), and FIRE, a damped
 * inertial descent of the contact energy sum kn d^2 / 2, reaches it in a number of iterations that
 * grows like the packing's side, where a Jacobi-like iteration (the reference GEM) needs its square.
 *
 *   gb_jam IN.csv --box L,R,B,T --porosity P --kn K --tol F --out OUT.csv [--max-iter N] [--wall-kn KW]
 *
 * --wall-kn: the walls' stiffness (default kn). With 2 kn the packing can be mirrored across its
 * walls (tools/mirrored_packing.sh): a disc pressing a wall by d then presses its mirror image by
 * 2 d with the same force 2 kn d, so the copies together are in equilibrium as well.
 *
 * IN.csv: x,y,r (gb_packgen's file). Prints the new box as a scene line and a summary on stderr.
 * Exit status: 0 converged, 3 not converged (OUT.csv written all the same, as the last state),
 * 2 bad arguments, 4 a file could not be read or written, 5 out of memory. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

typedef struct {
    int n;
    double *x, *y, *r, *vx, *vy, *fx, *fy, *m;
    double left, right, bottom, top, kn, kn_wall;
    /* Verlet list on a cell grid: pairs closer than their radii plus the skin */
    double skin, *x0, *y0;
    int *pi, *pj, npairs, cap;
    int *head, *next, ncx, ncy;
    double cell;
} jam;

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p) fprintf(stderr, "gb_jam: out of memory\n"), exit(5);
    return p;
}

static void build_list(jam *J)
{
    int n = J->n;
    J->ncx = (int)fmax(1, floor((J->right - J->left) / J->cell));
    J->ncy = (int)fmax(1, floor((J->top - J->bottom) / J->cell));
    int nc = J->ncx * J->ncy;
    if (!J->head) J->head = xmalloc((size_t)nc * sizeof(int));
    for (int c = 0; c < nc; c++) J->head[c] = -1;
    double wx = (J->right - J->left) / J->ncx, wy = (J->top - J->bottom) / J->ncy;
    int *cx = xmalloc((size_t)n * sizeof(int)), *cy = xmalloc((size_t)n * sizeof(int));
    for (int i = 0; i < n; i++) {
        int a = (int)floor((J->x[i] - J->left) / wx), b = (int)floor((J->y[i] - J->bottom) / wy);
        cx[i] = a < 0 ? 0 : a >= J->ncx ? J->ncx - 1 : a;
        cy[i] = b < 0 ? 0 : b >= J->ncy ? J->ncy - 1 : b;
        int c = cx[i] + J->ncx * cy[i];
        J->next[i] = J->head[c], J->head[c] = i;
        J->x0[i] = J->x[i], J->y0[i] = J->y[i];
    }
    J->npairs = 0;
    for (int i = 0; i < n; i++)
        for (int b = cy[i] - 1; b <= cy[i] + 1; b++)
            for (int a = cx[i] - 1; a <= cx[i] + 1; a++) {
                if (a < 0 || b < 0 || a >= J->ncx || b >= J->ncy) continue;
                for (int j = J->head[a + J->ncx * b]; j >= 0; j = J->next[j]) {
                    if (j <= i) continue;
                    double dx = J->x[j] - J->x[i], dy = J->y[j] - J->y[i], reach = J->r[i] + J->r[j] + J->skin;
                    if (dx * dx + dy * dy >= reach * reach) continue;
                    if (J->npairs == J->cap) {
                        J->cap = J->cap ? 2 * J->cap : 1024;
                        J->pi = realloc(J->pi, (size_t)J->cap * sizeof(int));
                        J->pj = realloc(J->pj, (size_t)J->cap * sizeof(int));
                        if (!J->pi || !J->pj) fprintf(stderr, "gb_jam: out of memory\n"), exit(5);
                    }
                    J->pi[J->npairs] = i, J->pj[J->npairs++] = j;
                }
            }
    free(cx), free(cy);
}

/* Forces of the springs kn d on every disc; returns the largest |F|, fills the walls' forces and
 * counts the contacts between discs and with walls. */
static double forces(jam *J, double wall[4], int *contacts, int *walls)
{
    int n = J->n;
    memset(J->fx, 0, (size_t)n * sizeof(double));
    memset(J->fy, 0, (size_t)n * sizeof(double));
    wall[0] = wall[1] = wall[2] = wall[3] = 0;
    *contacts = *walls = 0;
    for (int k = 0; k < J->npairs; k++) {
        int i = J->pi[k], j = J->pj[k];
        double dx = J->x[j] - J->x[i], dy = J->y[j] - J->y[i], l = sqrt(dx * dx + dy * dy);
        double d = J->r[i] + J->r[j] - l;
        if (!(d > 0) || !(l > 0)) continue;
        double f = J->kn * d / l;
        J->fx[i] -= f * dx, J->fy[i] -= f * dy, J->fx[j] += f * dx, J->fy[j] += f * dy;
        (*contacts)++;
    }
    for (int i = 0; i < n; i++) {
        double d;
        double kw = J->kn_wall;
        if ((d = J->left + J->r[i] - J->x[i]) > 0) J->fx[i] += kw * d, wall[0] += kw * d, (*walls)++;
        if ((d = J->x[i] + J->r[i] - J->right) > 0) J->fx[i] -= kw * d, wall[1] += kw * d, (*walls)++;
        if ((d = J->bottom + J->r[i] - J->y[i]) > 0) J->fy[i] += kw * d, wall[2] += kw * d, (*walls)++;
        if ((d = J->y[i] + J->r[i] - J->top) > 0) J->fy[i] -= kw * d, wall[3] += kw * d, (*walls)++;
    }
    double worst = 0;
    for (int i = 0; i < n; i++) worst = fmax(worst, hypot(J->fx[i], J->fy[i]));
    return worst;
}

static int parse4(const char *s, double v[4])
{
    return sscanf(s, "%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3]) == 4;
}

int main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    double box[4] = {0}, porosity = -1, kn = -1, tol = -1, kn_wall = -1;
    long max_iter = 10000000;
    int have_box = 0, have_wall_kn = 0;
    for (int a = 1; a < argc; a++) {
        const char *v = a + 1 < argc ? argv[a + 1] : NULL;
        if (!strcmp(argv[a], "--box") && v) have_box = parse4(v, box), a++;
        else if (!strcmp(argv[a], "--porosity") && v) porosity = atof(v), a++;
        else if (!strcmp(argv[a], "--kn") && v) kn = atof(v), a++;
        else if (!strcmp(argv[a], "--tol") && v) tol = atof(v), a++;
        else if (!strcmp(argv[a], "--out") && v) out = v, a++;
        else if (!strcmp(argv[a], "--max-iter") && v) max_iter = atol(v), a++;
        else if (!strcmp(argv[a], "--wall-kn") && v) kn_wall = atof(v), have_wall_kn = 1, a++;
        else if (argv[a][0] != '-' && !in) in = argv[a];
        else {
            fprintf(stderr, "gb_jam: unexpected argument '%s'\nusage: gb_jam IN.csv --box L,R,B,T --porosity P --kn K "
                            "--tol F --out OUT.csv [--max-iter N] [--wall-kn K]\n", argv[a]);
            return 2;
        }
    }
    if (!in || !out || !have_box || !(porosity > 0 && porosity < 1) || !(kn > 0) || !(tol > 0) || max_iter < 1 ||
        (have_wall_kn && !(kn_wall > 0)) ||
        !(box[1] > box[0]) || !(box[3] > box[2])) {
        fprintf(stderr, "gb_jam: expected IN.csv, --box L,R,B,T (R > L, T > B), --porosity in (0, 1), --kn > 0, "
                        "--tol > 0, --out, and --wall-kn > 0 if given\n");
        return 2;
    }
    FILE *f = fopen(in, "r");
    if (!f) return fprintf(stderr, "gb_jam: cannot read %s\n", in), 4;
    char line[512];
    if (!fgets(line, sizeof line, f) || strncmp(line, "x,y,r", 5)) {
        fclose(f);
        return fprintf(stderr, "gb_jam: %s:1: expected the header x,y,r\n", in), 2;
    }
    jam J;
    memset(&J, 0, sizeof J);
    int cap = 1024;
    J.x = xmalloc((size_t)cap * sizeof(double)), J.y = xmalloc((size_t)cap * sizeof(double));
    J.r = xmalloc((size_t)cap * sizeof(double));
    for (int ln = 2; fgets(line, sizeof line, f); ln++) {
        double x, y, r;
        if (sscanf(line, "%lf,%lf,%lf", &x, &y, &r) != 3 || !(r > 0) || !isfinite(x) || !isfinite(y)) {
            fclose(f);
            return fprintf(stderr, "gb_jam: %s:%d: expected x,y,r with r > 0\n", in, ln), 2;
        }
        if (J.n == cap) {
            cap *= 2;
            J.x = realloc(J.x, (size_t)cap * sizeof(double)), J.y = realloc(J.y, (size_t)cap * sizeof(double));
            J.r = realloc(J.r, (size_t)cap * sizeof(double));
            if (!J.x || !J.y || !J.r) return fprintf(stderr, "gb_jam: out of memory\n"), 5;
        }
        J.x[J.n] = x, J.y[J.n] = y, J.r[J.n++] = r;
    }
    fclose(f);
    int n = J.n;
    if (n < 1) return fprintf(stderr, "gb_jam: %s holds no disc\n", in), 2;

    /* Shrink to the porosity: neighbours overlap, the packing is jammed. */
    double area = 0, rmax = 0, rmin = HUGE_VAL;
    for (int i = 0; i < n; i++) area += PI * J.r[i] * J.r[i], rmax = fmax(rmax, J.r[i]), rmin = fmin(rmin, J.r[i]);
    double p0 = 1 - area / ((box[1] - box[0]) * (box[3] - box[2]));
    if (!(porosity < p0))
        return fprintf(stderr, "gb_jam: the packing's porosity is %.4f; expected a target below it\n", p0), 2;
    double s = sqrt((1 - p0) / (1 - porosity)), cx = 0.5 * (box[0] + box[1]), cy = 0.5 * (box[2] + box[3]);
    J.left = cx + s * (box[0] - cx), J.right = cx + s * (box[1] - cx);
    J.bottom = cy + s * (box[2] - cy), J.top = cy + s * (box[3] - cy);
    for (int i = 0; i < n; i++) J.x[i] = cx + s * (J.x[i] - cx), J.y[i] = cy + s * (J.y[i] - cy);

    J.kn = kn;
    J.kn_wall = have_wall_kn ? kn_wall : kn;
    J.vx = calloc((size_t)n, sizeof(double)), J.vy = calloc((size_t)n, sizeof(double));
    J.fx = xmalloc((size_t)n * sizeof(double)), J.fy = xmalloc((size_t)n * sizeof(double));
    J.m = xmalloc((size_t)n * sizeof(double));
    J.x0 = xmalloc((size_t)n * sizeof(double)), J.y0 = xmalloc((size_t)n * sizeof(double));
    J.next = xmalloc((size_t)n * sizeof(int));
    if (!J.vx || !J.vy) return fprintf(stderr, "gb_jam: out of memory\n"), 5;
    for (int i = 0; i < n; i++) J.m[i] = PI * J.r[i] * J.r[i]; /* unit density: only the dynamics' pace */
    J.skin = 0.2 * rmin;
    J.cell = 2 * rmax + J.skin;
    build_list(&J);

    /* FIRE with the published parameters; the time step from the stiffest, lightest disc. */
    const double dt_max = 0.3 * sqrt(PI * rmin * rmin / kn), f_inc = 1.1, f_dec = 0.5, a_start = 0.1, f_a = 0.99;
    const int n_min = 5;
    double dt = 0.1 * dt_max, alpha = a_start, wall[4];
    int contacts = 0, walls = 0, since_neg = 0, converged = 0;
    long it = 0, rebuilds = 1;
    double worst = forces(&J, wall, &contacts, &walls);
    for (; it < max_iter; it++) {
        if (worst <= tol) {
            converged = 1;
            break;
        }
        double P = 0, vv = 0, ff = 0;
        for (int i = 0; i < n; i++) {
            P += J.fx[i] * J.vx[i] + J.fy[i] * J.vy[i];
            vv += J.vx[i] * J.vx[i] + J.vy[i] * J.vy[i];
            ff += J.fx[i] * J.fx[i] + J.fy[i] * J.fy[i];
        }
        if (P > 0) {
            double mix = ff > 0 ? alpha * sqrt(vv / ff) : 0;
            for (int i = 0; i < n; i++) {
                J.vx[i] = (1 - alpha) * J.vx[i] + mix * J.fx[i];
                J.vy[i] = (1 - alpha) * J.vy[i] + mix * J.fy[i];
            }
            if (++since_neg > n_min) dt = fmin(dt * f_inc, dt_max), alpha *= f_a;
        } else {
            since_neg = 0;
            dt *= f_dec;
            alpha = a_start;
            memset(J.vx, 0, (size_t)n * sizeof(double));
            memset(J.vy, 0, (size_t)n * sizeof(double));
        }
        double moved = 0;
        for (int i = 0; i < n; i++) {
            J.vx[i] += dt * J.fx[i] / J.m[i], J.vy[i] += dt * J.fy[i] / J.m[i];
            J.x[i] += dt * J.vx[i], J.y[i] += dt * J.vy[i];
            double dx = J.x[i] - J.x0[i], dy = J.y[i] - J.y0[i];
            moved = fmax(moved, dx * dx + dy * dy);
        }
        if (4 * moved >= J.skin * J.skin) build_list(&J), rebuilds++;
        worst = forces(&J, wall, &contacts, &walls);
        if (!isfinite(worst)) return fprintf(stderr, "gb_jam: the forces became non-finite at iteration %ld\n", it), 3;
    }
    /* Written beside and renamed: a failed write leaves no half file under the final name. */
    char tmp[4096];
    if (snprintf(tmp, sizeof tmp, "%s.part", out) >= (int)sizeof tmp) return fprintf(stderr, "gb_jam: path too long\n"), 2;
    FILE *o = fopen(tmp, "w");
    if (!o) return fprintf(stderr, "gb_jam: cannot write %s\n", tmp), 4;
    int bad = fprintf(o, "x,y,r\n") < 0;
    for (int i = 0; i < n && !bad; i++) bad = fprintf(o, "%.17g,%.17g,%.17g\n", J.x[i], J.y[i], J.r[i]) < 0;
    if (fclose(o) || bad || rename(tmp, out)) {
        remove(tmp);
        return fprintf(stderr, "gb_jam: cannot write %s\n", out), 4;
    }
    double W = J.right - J.left, H = J.top - J.bottom;
    printf("box: {left: %.17g, right: %.17g, bottom: %.17g, top: %.17g}\n", J.left, J.right, J.bottom, J.top);
    fprintf(stderr, "gb_jam: %d discs, porosity %.4f, %s after %ld FIRE iterations (%ld list rebuilds): largest "
                    "force %.3g, %d contacts between discs and %d with walls (%.2f per disc), wall stresses s_x %.4g s_y %.4g\n",
            n, porosity, converged ? "converged" : "NOT converged", it, rebuilds, worst, contacts, walls,
            (2.0 * contacts + walls) / n, 0.5 * (wall[0] + wall[1]) / H, 0.5 * (wall[2] + wall[3]) / W);
    free(J.x), free(J.y), free(J.r), free(J.vx), free(J.vy), free(J.fx), free(J.fy), free(J.m);
    free(J.x0), free(J.y0), free(J.pi), free(J.pj), free(J.head), free(J.next);
    return converged ? 0 : 3;
}
