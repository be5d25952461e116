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
 * The FIRE relaxation is the library's (src/pack/fire.c, that of gembem pack), on its contact module.
 *
 * IN.csv: x,y,r (gb_packgen's file). Prints the new box as a scene line and a summary on stderr.
 * Exit status: 0 converged, 3 not converged (OUT.csv written all the same, as the last state),
 * 2 bad arguments, 4 a file could not be read or written, 5 out of memory. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pack/fire.h" /* the library's FIRE (gembem pack's), on its contact module */

#define PI 3.14159265358979323846

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p) fprintf(stderr, "gb_jam: out of memory\n"), exit(5);
    return p;
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
    int cap = 1024, n = 0;
    gb_grain *g = xmalloc((size_t)cap * sizeof *g);
    for (int ln = 2; fgets(line, sizeof line, f); ln++) {
        double x, y, r;
        if (sscanf(line, "%lf,%lf,%lf", &x, &y, &r) != 3 || !(r > 0) || !isfinite(x) || !isfinite(y)) {
            fclose(f);
            return fprintf(stderr, "gb_jam: %s:%d: expected x,y,r with r > 0\n", in, ln), 2;
        }
        if (n == cap && !(g = realloc(g, (size_t)(cap *= 2) * sizeof *g)))
            return fprintf(stderr, "gb_jam: out of memory\n"), 5;
        gb_grain q = {x, y, r, 0};
        g[n++] = q;
    }
    fclose(f);
    if (n < 1) return fprintf(stderr, "gb_jam: %s holds no disc\n", in), 2;

    /* Shrink to the porosity: neighbours overlap, the packing is jammed. */
    double area = 0;
    for (int i = 0; i < n; i++) area += PI * g[i].r * g[i].r;
    double p0 = 1 - area / ((box[1] - box[0]) * (box[3] - box[2]));
    if (!(porosity < p0))
        return fprintf(stderr, "gb_jam: the packing's porosity is %.4f; expected a target below it\n", p0), 2;
    double s = sqrt((1 - p0) / (1 - porosity)), cx = 0.5 * (box[0] + box[1]), cy = 0.5 * (box[2] + box[3]);
    gb_box b = {cx + s * (box[0] - cx), cx + s * (box[1] - cx), cy + s * (box[2] - cy), cy + s * (box[3] - cy)};
    for (int i = 0; i < n; i++) g[i].x = cx + s * (g[i].x - cx), g[i].y = cy + s * (g[i].y - cy);

    gb_fire_world w = {g, n, &b, NULL, kn, have_wall_kn ? kn_wall : kn, 0, {0, 0}, NULL, 0, 1};
    gb_fire_report rep;
    gb_error err = {0};
    gb_status st = gb_fire_relax(&w, tol, max_iter, &rep, &err);
    if (st == GB_ENOMEM) return fprintf(stderr, "gb_jam: %s\n", err.msg), 5;
    if (st == GB_ENUMERIC) return fprintf(stderr, "gb_jam: %s\n", err.msg), 3;
    /* Written beside and renamed: a failed write leaves no half file under the final name. */
    char tmp[4096];
    if (snprintf(tmp, sizeof tmp, "%s.part", out) >= (int)sizeof tmp) return fprintf(stderr, "gb_jam: path too long\n"), 2;
    FILE *o = fopen(tmp, "w");
    if (!o) return fprintf(stderr, "gb_jam: cannot write %s\n", tmp), 4;
    int bad = fprintf(o, "x,y,r\n") < 0;
    for (int i = 0; i < n && !bad; i++) bad = fprintf(o, "%.17g,%.17g,%.17g\n", g[i].x, g[i].y, g[i].r) < 0;
    if (fclose(o) || bad || rename(tmp, out)) {
        remove(tmp);
        return fprintf(stderr, "gb_jam: cannot write %s\n", out), 4;
    }
    double W = b.right - b.left, H = b.top - b.bottom;
    printf("box: {left: %.17g, right: %.17g, bottom: %.17g, top: %.17g}\n", b.left, b.right, b.bottom, b.top);
    int contacts = rep.contacts - rep.wall_contacts;
    fprintf(stderr, "gb_jam: %d discs, porosity %.4f, %s after %ld FIRE iterations: largest "
                    "force %.3g, %d contacts between discs and %d with walls (%.2f per disc), wall stresses s_x %.4g s_y %.4g\n",
            n, porosity, st ? "NOT converged" : "converged", rep.iterations, rep.max_force, contacts,
            rep.wall_contacts, (2.0 * contacts + rep.wall_contacts) / n, 0.5 * (rep.wall[0] + rep.wall[1]) / H,
            0.5 * (rep.wall[2] + rep.wall[3]) / W);
    free(g);
    return st ? 3 : 0;
}
