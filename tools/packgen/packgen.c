/* gb_packgen - seeded, reproducible packings of discs in a box at a target porosity.
 *
 * 1. counts per size from the area shares (the rounding that matches the shares best);
 * 2. the discs in a random order (seeded shuffle);
 * 3. sequential deposition under gravity in a box of width W (deposit.c), repeated with W adjusted
 *    to fit the pile under the box top aspect * W; the densest attempt that fits is kept;
 * 4. homogeneous dilation of the centres (radii unchanged, box scaled by the same factor) to the
 *    requested porosity = 1 - (disc area) / (box area); the box is then [0, W] x [0, H].
 * See README.md. Exit status: 0 done, 2 impossible or malformed request, 1 internal error,
 * 4 a file could not be written, 5 out of memory. No output file is left unless the status is 0. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "deposit.h"
#include "pg_rng.h"

#define PG_PI 3.14159265358979323846
#define PG_MAX_N 100000000L
#define PG_MAX_SIZES 64
#define PG_REL_PAD 1e-12 /* contact radii are r (1 + 1e-12): touching discs stay strictly apart */
#define PG_MAX_ATTEMPTS 8
#define PG_PHI_GUESS 0.18 /* first guess of the pile's porosity, for the first width */

enum { EXIT_INTERNAL = 1, EXIT_INPUT = 2, EXIT_IO = 4, EXIT_NOMEM = 5 };

typedef struct {
    long n;
    int nsize;
    double diam[PG_MAX_SIZES];
    double frac[PG_MAX_SIZES];
    int have_frac;
    int nfrac;
    double porosity; /* < 0: not given, keep the deposition's density */
    double aspect;
    uint64_t seed;
    const char *out;
    int scene_box;
    double min_gap;
} pg_opts;

static const char *usage_text =
    "usage: gb_packgen --n N --diameters d1,d2,... --out FILE.csv [options]\n"
    "\n"
    "Random packing of N discs in a box (floor y = 0, walls x = 0 and x = W, top y = H), built by\n"
    "sequential deposition under gravity, then dilated homogeneously to the requested porosity.\n"
    "\n"
    "  --n N               number of discs (>= 1)\n"
    "  --diameters LIST    disc diameters, comma separated, > 0 (any length unit; the box uses "
    "it)\n"
    "  --fractions LIST    area fraction of each size, >= 0, summing to 1 (default: equal areas)\n"
    "  --porosity P        target porosity 1 - (disc area)/(box area), 0 < P < 1; refused if "
    "below\n"
    "                      the deposition's (the densest this tool makes). Default: that densest\n"
    "  --aspect A          box height / width, a number or a ratio like 3/2 (default 1)\n"
    "  --seed S            random seed, an unsigned 64-bit integer (default 1)\n"
    "  --min-gap g         every pair of discs at least g apart, every disc at least g/2 from the\n"
    "                      box sides, already in the deposition (default 0)\n"
    "  --out FILE.csv      discs: header x,y,r then one line per disc (%.17g)\n"
    "                      the box goes to FILE.box.yaml: box: {left:, right:, bottom:, top:}\n"
    "  --scene-box         also print the box line on standard output\n"
    "  --help              this text\n"
    "\n"
    "Exit status: 0 done; 2 impossible or malformed request (nothing written); 1, 4, 5 internal,\n"
    "write or memory failure.\n";

static void fail_input(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("gb_packgen: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputs("\n(gb_packgen --help for usage)\n", stderr);
    va_end(ap);
    exit(EXIT_INPUT);
}

static double parse_double(const char *flag, const char *s)
{
    char *end = NULL;
    errno = 0;
    const double v = strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE || !isfinite(v))
        fail_input("%s expects a finite number, got '%s'", flag, s);
    return v;
}

static int parse_list(const char *flag, const char *s, double *v, int max)
{
    int n = 0;
    const char *p = s;
    for (;;) {
        const char *comma = strchr(p, ',');
        const size_t len = comma ? (size_t)(comma - p) : strlen(p);
        char item[64];
        if (len == 0 || len >= sizeof item)
            fail_input("%s expects a comma-separated list of numbers, got '%s'", flag, s);
        if (n >= max)
            fail_input("%s: at most %d values", flag, max);
        memcpy(item, p, len);
        item[len] = '\0';
        v[n++] = parse_double(flag, item);
        if (!comma)
            break;
        p = comma + 1;
    }
    return n;
}

static void parse_args(int argc, char **argv, pg_opts *o)
{
    memset(o, 0, sizeof *o);
    o->n = -1;
    o->porosity = -1.0;
    o->aspect = 1.0;
    o->seed = 1;
    for (int i = 1; i < argc; ++i) {
        const char *arg = argv[i];
        char name[32];
        const char *val = NULL;
        if (strncmp(arg, "--", 2) != 0)
            fail_input("unexpected argument '%s': options start with --", arg);
        const char *eq = strchr(arg, '=');
        size_t len = eq ? (size_t)(eq - arg) : strlen(arg);
        if (len >= sizeof name)
            fail_input("unknown option '%s'", arg);
        memcpy(name, arg, len);
        name[len] = '\0';
        if (!strcmp(name, "--help")) {
            fputs(usage_text, stdout);
            exit(0);
        }
        if (!strcmp(name, "--scene-box")) {
            if (eq)
                fail_input("--scene-box takes no value");
            o->scene_box = 1;
            continue;
        }
        static const char *valued[] = {"--n",      "--diameters", "--fractions", "--porosity",
                                       "--aspect", "--seed",      "--out",       "--min-gap"};
        int known = 0;
        for (size_t k = 0; k < sizeof valued / sizeof *valued; ++k)
            known |= !strcmp(name, valued[k]);
        if (!known)
            fail_input("unknown option '%s'", name);
        if (eq)
            val = eq + 1;
        else if (i + 1 < argc)
            val = argv[++i];
        else
            fail_input("%s expects a value", name);
        if (*val == '\0')
            fail_input("%s expects a value, got an empty one", name);

        if (!strcmp(name, "--n")) {
            char *end = NULL;
            errno = 0;
            const long long v = strtoll(val, &end, 10);
            if (end == val || *end != '\0' || errno == ERANGE || v < 1 || v > PG_MAX_N)
                fail_input("--n expects an integer from 1 to %ld, got '%s'", PG_MAX_N, val);
            o->n = (long)v;
        } else if (!strcmp(name, "--diameters")) {
            o->nsize = parse_list(name, val, o->diam, PG_MAX_SIZES);
        } else if (!strcmp(name, "--fractions")) {
            o->nfrac = parse_list(name, val, o->frac, PG_MAX_SIZES);
            o->have_frac = 1;
        } else if (!strcmp(name, "--porosity")) {
            o->porosity = parse_double(name, val);
            if (!(o->porosity > 0.0 && o->porosity < 1.0))
                fail_input("--porosity expects a number strictly between 0 and 1, got '%s'", val);
        } else if (!strcmp(name, "--aspect")) {
            const char *slash = strchr(val, '/');
            if (slash) {
                char num[64];
                const size_t nl = (size_t)(slash - val);
                if (nl == 0 || nl >= sizeof num)
                    fail_input("--aspect expects a positive number or a ratio H/W, got '%s'", val);
                memcpy(num, val, nl);
                num[nl] = '\0';
                const double hgt = parse_double(name, num), wid = parse_double(name, slash + 1);
                o->aspect = wid > 0.0 ? hgt / wid : -1.0;
            } else {
                o->aspect = parse_double(name, val);
            }
            if (!(o->aspect > 0.0) || !isfinite(o->aspect))
                fail_input("--aspect expects a positive number or a ratio H/W, got '%s'", val);
        } else if (!strcmp(name, "--seed")) {
            char *end = NULL;
            errno = 0;
            const unsigned long long v = strtoull(val, &end, 10);
            if (end == val || *end != '\0' || errno == ERANGE || val[0] == '-' || val[0] == '+')
                fail_input("--seed expects an unsigned 64-bit integer, got '%s'", val);
            o->seed = (uint64_t)v;
        } else if (!strcmp(name, "--out")) {
            o->out = val;
        } else if (!strcmp(name, "--min-gap")) {
            o->min_gap = parse_double(name, val);
            if (o->min_gap < 0.0)
                fail_input("--min-gap expects a number >= 0, got '%s'", val);
        }
    }
    if (o->n < 1)
        fail_input("--n is required: the number of discs, an integer >= 1");
    if (o->nsize < 1)
        fail_input("--diameters is required: a comma-separated list of diameters > 0");
    if (!o->out)
        fail_input("--out is required: the CSV file to write");
    for (int k = 0; k < o->nsize; ++k)
        if (!(o->diam[k] > 0.0))
            fail_input("--diameters: every diameter must be > 0, got %g", o->diam[k]);
    if (o->have_frac) {
        if (o->nfrac != o->nsize)
            fail_input("--fractions: expected %d values (one per diameter), got %d", o->nsize,
                       o->nfrac);
        double sum = 0.0;
        for (int k = 0; k < o->nsize; ++k) {
            if (o->frac[k] < 0.0)
                fail_input("--fractions: every fraction must be >= 0, got %g", o->frac[k]);
            sum += o->frac[k];
        }
        if (fabs(sum - 1.0) > 1e-9)
            fail_input("--fractions must sum to 1 (within 1e-9), they sum to %.17g", sum);
    } else {
        for (int k = 0; k < o->nsize; ++k)
            o->frac[k] = 1.0 / o->nsize;
    }
}

/* Counts n_k summing to n whose area shares n_k d_k^2 / sum_j n_j d_j^2 best match the fractions:
 * each n_k is the floor or the ceiling of its ideal value; among those combinations (all of them
 * for up to 16 sizes, else largest remainders) the one with the smallest worst error measured in
 * discs of that size, |A_k - f_k A| / a_k, wins; ties go to the first found. */
static void choose_counts(const pg_opts *o, long *count)
{
    const int K = o->nsize;
    double ideal[PG_MAX_SIZES], w = 0.0;
    long lo[PG_MAX_SIZES];
    for (int k = 0; k < K; ++k)
        w += o->frac[k] / (o->diam[k] * o->diam[k]);
    long base = 0;
    for (int k = 0; k < K; ++k) {
        ideal[k] = (double)o->n * (o->frac[k] / (o->diam[k] * o->diam[k])) / w;
        lo[k] = (long)floor(ideal[k]);
        if (lo[k] > o->n)
            lo[k] = o->n;
        base += lo[k];
        count[k] = lo[k];
    }
    long extra = o->n - base; /* 0 <= extra < K: that many sizes take their ceiling */
    if (extra <= 0)
        return;
    int free_k[PG_MAX_SIZES], nf = 0;
    for (int k = 0; k < K; ++k)
        if ((double)lo[k] < ideal[k])
            free_k[nf++] = k;
    if (nf <= 16) {
        double best = INFINITY;
        unsigned long bestmask = 0;
        for (unsigned long mask = 0; mask < (1ul << nf); ++mask) {
            int bits = 0;
            for (int q = 0; q < nf; ++q)
                bits += (int)((mask >> q) & 1ul);
            if (bits != extra)
                continue;
            long c[PG_MAX_SIZES];
            double A = 0.0, worst = 0.0;
            for (int k = 0; k < K; ++k)
                c[k] = lo[k];
            for (int q = 0; q < nf; ++q)
                c[free_k[q]] += (long)((mask >> q) & 1ul);
            for (int k = 0; k < K; ++k)
                A += (double)c[k] * o->diam[k] * o->diam[k];
            for (int k = 0; k < K; ++k) {
                const double a = o->diam[k] * o->diam[k];
                const double e = fabs((double)c[k] * a - o->frac[k] * A) / a;
                if (e > worst)
                    worst = e;
            }
            if (worst < best) {
                best = worst;
                bestmask = mask;
            }
        }
        for (int q = 0; q < nf; ++q)
            count[free_k[q]] += (long)((bestmask >> q) & 1ul);
    } else {
        while (extra-- > 0) { /* largest remainder, first index on ties */
            int bk = -1;
            double br = -1.0;
            for (int k = 0; k < K; ++k) {
                const double rem = ideal[k] - (double)count[k];
                if (rem > br) {
                    br = rem;
                    bk = k;
                }
            }
            count[bk] += 1;
        }
    }
}

/* Brute-force-free check of the result: no pair closer than r_i + r_j, all inside the box. */
static int verify(const pg_disc *d, size_t n, double W, double H, double *worst_out)
{
    double rmax = 0.0;
    for (size_t i = 0; i < n; ++i)
        if (d[i].r > rmax)
            rmax = d[i].r;
    double h = sqrt(W * H / (double)n); /* about one disc per cell, and at least 2 rmax */
    if (h < 2.0 * rmax)
        h = 2.0 * rmax;
    const long nc = (long)(W / h) + 1, nr = (long)(H / h) + 1;
    int *head = malloc((size_t)nc * (size_t)nr * sizeof *head);
    int *next = malloc(n * sizeof *next);
    int ok = 1;
    double worst = INFINITY; /* smallest gap / (r_i + r_j) */
    if (!head || !next) {
        free(head);
        free(next);
        return -1;
    }
    for (long q = 0; q < nc * nr; ++q)
        head[q] = -1;
    for (size_t i = 0; i < n; ++i) {
        if (!(d[i].x - d[i].r >= 0.0 && d[i].x + d[i].r <= W && d[i].y - d[i].r >= 0.0 &&
              d[i].y + d[i].r <= H))
            ok = 0;
        long cx = (long)(d[i].x / h), cy = (long)(d[i].y / h);
        cx = cx < 0 ? 0 : cx >= nc ? nc - 1 : cx;
        cy = cy < 0 ? 0 : cy >= nr ? nr - 1 : cy;
        for (long y = cy - 1; y <= cy + 1; ++y)
            for (long x = cx - 1; x <= cx + 1; ++x) {
                if (x < 0 || y < 0 || x >= nc || y >= nr)
                    continue;
                for (int j = head[y * nc + x]; j >= 0; j = next[j]) {
                    const double dx = d[i].x - d[j].x, dy = d[i].y - d[j].y;
                    const double s = d[i].r + d[j].r;
                    const double dist = sqrt(dx * dx + dy * dy);
                    if (dx * dx + dy * dy < s * s)
                        ok = 0;
                    if ((dist - s) / s < worst)
                        worst = (dist - s) / s;
                }
            }
        next[i] = head[cy * nc + cx];
        head[cy * nc + cx] = (int)i;
    }
    free(head);
    free(next);
    *worst_out = worst;
    return ok;
}

static char *concat(const char *a, const char *b)
{
    const size_t la = strlen(a), lb = strlen(b);
    char *s = malloc(la + lb + 1);
    if (s) {
        memcpy(s, a, la);
        memcpy(s + la, b, lb + 1);
    }
    return s;
}

int main(int argc, char **argv)
{
    pg_opts o;
    parse_args(argc, argv, &o);
    const size_t n = (size_t)o.n;
    const int K = o.nsize;

    long count[PG_MAX_SIZES];
    choose_counts(&o, count);

    int rc = 0;
    char *stem = NULL, *boxname = NULL, *tmp1 = NULL, *tmp2 = NULL;
    pg_disc *d = malloc(n * sizeof *d), *best = malloc(n * sizeof *best);
    if (!d || !best) {
        fprintf(stderr, "gb_packgen: out of memory for %zu discs\n", n);
        rc = EXIT_NOMEM;
        goto done;
    }
    /* radii in size order, then a seeded Fisher-Yates shuffle (stream 0) */
    size_t m = 0;
    double area = 0.0, amax = 0.0, acontact = 0.0;
    for (int k = 0; k < K; ++k) {
        const double r = 0.5 * o.diam[k];
        for (long q = 0; q < count[k]; ++q)
            d[m++].r = r;
        area += (double)count[k] * PG_PI * r * r;
        const double a = r + r * PG_REL_PAD + 0.5 * o.min_gap;
        if (count[k] > 0 && a > amax)
            amax = a;
        acontact += (double)count[k] * PG_PI * a * a;
    }
    pg_rng rng;
    pg_rng_seed(&rng, o.seed, 0);
    for (size_t i = n - 1; i > 0; --i) {
        const size_t j = pg_rng_below(&rng, i + 1);
        const double t = d[i].r;
        d[i].r = d[j].r;
        d[j].r = t;
    }

    /* deposition, with the width adjusted so that the pile fits under the box top aspect * W.
     * W' = W sqrt(Hp / H) keeps the area W Hp; `margin` (extra height aimed for) grows by half a
     * radius after each attempt whose pile is too high and halves after one that fits. All
     * PG_MAX_ATTEMPTS attempts are made, each with its own random stream; the densest one that
     * fits is kept; if none fits, the densest one, centred in a box widened to Hp / aspect. */
    double W = sqrt(acontact / ((1.0 - PG_PHI_GUESS) * o.aspect));
    double bestW = 0.0, bestphi = INFINITY, shift = 0.0, margin = 0.0;
    int attempts = 0, bestfits = 0;
    for (int att = 0; att < PG_MAX_ATTEMPTS; ++att) {
        if (W < 2.0 * amax)
            W = 2.0 * amax;
        double Hp = 0.0;
        pg_rng_seed(&rng, o.seed, 1u + (uint64_t)att);
        const pg_dep_status st = pg_deposit(d, n, W, PG_REL_PAD, 0.5 * o.min_gap, &rng, &Hp);
        ++attempts;
        if (st == PG_DEP_NOMEM) {
            fprintf(stderr, "gb_packgen: out of memory in the deposition\n");
            rc = EXIT_NOMEM;
            goto done;
        }
        if (st != PG_DEP_OK) {
            fprintf(stderr, "gb_packgen: internal error: a disc did not come to rest\n");
            rc = EXIT_INTERNAL;
            goto done;
        }
        const double H = o.aspect * W;
        const int fits = Hp <= H;
        const double Wbox = fits ? W : Hp / o.aspect;
        const double phi = 1.0 - area / (o.aspect * Wbox * Wbox);
        if (getenv("PG_DEBUG"))
            fprintf(stderr, "attempt %d: W %.6g Hp %.6g H %.6g phi %.6f\n", att, W, Hp, H, phi);
        if ((fits && !bestfits) || (fits == bestfits && phi < bestphi)) {
            bestphi = phi;
            bestW = Wbox;
            bestfits = fits;
            shift = 0.5 * (Wbox - W);
            memcpy(best, d, n * sizeof *d);
        }
        margin = fits ? 0.5 * margin : margin + 0.5 * amax;
        W = W * sqrt(Hp / H) + margin / (2.0 * o.aspect);
    }
    for (size_t i = 0; i < n; ++i)
        best[i].x += shift;
    if (!bestfits)
        fprintf(stderr,
                "gb_packgen: note: no deposition fitted under the box top; the densest pile is "
                "centred in a box widened to its height / aspect (gaps of %g at both walls)\n",
                shift);

    /* dilation to the target porosity (about the box centre, then moved so the box starts at 0:
     * together, x -> lambda x) */
    double lambda = 1.0;
    if (o.porosity >= 0.0) {
        if (o.porosity < bestphi - 1e-12) {
            fprintf(stderr,
                    "gb_packgen: porosity %g is below the lowest this generator reaches for these "
                    "sizes and shares, n = %ld, aspect %g, seed %llu: %.6f (sequential deposition, "
                    "then dilation only). Ask for a porosity >= %.6f, or compress the packing "
                    "under stress in the solver.\n",
                    o.porosity, o.n, o.aspect, (unsigned long long)o.seed, bestphi,
                    ceil(bestphi * 1e6) / 1e6);
            rc = EXIT_INPUT;
            goto done;
        }
        lambda = sqrt(area / ((1.0 - o.porosity) * o.aspect * bestW * bestW));
        if (lambda < 1.0)
            lambda = 1.0;
    }
    const double right = lambda * bestW, top = lambda * (o.aspect * bestW);
    for (size_t i = 0; i < n; ++i) {
        best[i].x *= lambda;
        best[i].y *= lambda;
    }
    const double phi = 1.0 - area / (right * top);

    double worst = 0.0;
    const int ok = verify(best, n, right, top, &worst);
    if (ok < 0) {
        fprintf(stderr, "gb_packgen: out of memory in the final check\n");
        rc = EXIT_NOMEM;
        goto done;
    }
    if (!ok) {
        fprintf(stderr, "gb_packgen: internal error: the packing overlaps or leaves the box\n");
        rc = EXIT_INTERNAL;
        goto done;
    }

    /* write FILE.tmp and FILE.box.yaml.tmp, then rename both */
    const size_t lo = strlen(o.out);
    stem = malloc(lo + 1);
    if (!stem) {
        rc = EXIT_NOMEM;
        goto done;
    }
    memcpy(stem, o.out, lo + 1);
    if (lo > 4 && !strcmp(stem + lo - 4, ".csv"))
        stem[lo - 4] = '\0';
    boxname = concat(stem, ".box.yaml");
    tmp1 = concat(o.out, ".tmp");
    tmp2 = boxname ? concat(boxname, ".tmp") : NULL;
    if (!boxname || !tmp1 || !tmp2) {
        rc = EXIT_NOMEM;
        goto done;
    }

    int werr = 0;
    FILE *f = fopen(tmp1, "w");
    if (!f) {
        fprintf(stderr, "gb_packgen: cannot write %s: %s\n", tmp1, strerror(errno));
        rc = EXIT_IO;
        goto done;
    }
    if (fputs("x,y,r\n", f) < 0)
        werr = 1;
    for (size_t i = 0; i < n && !werr; ++i)
        if (fprintf(f, "%.17g,%.17g,%.17g\n", best[i].x, best[i].y, best[i].r) < 0)
            werr = 1;
    if (fclose(f) != 0)
        werr = 1;
    FILE *g = werr ? NULL : fopen(tmp2, "w");
    if (g) {
        char sizes[2048] = "";
        size_t used = 0;
        for (int k = 0; k < K && used < sizeof sizes; ++k)
            used += (size_t)snprintf(sizes + used, sizeof sizes - used, "%s%g:%ld", k ? " " : "",
                                     o.diam[k], count[k]);
        char req[64];
        if (o.porosity >= 0.0)
            snprintf(req, sizeof req, "%.17g", o.porosity);
        else
            snprintf(req, sizeof req, "none, so the densest");
        if (fprintf(g,
                    "# gb_packgen: n = %ld, seed = %llu, aspect = %.17g, min_gap = %.17g\n"
                    "# discs per diameter (diameter:count): %s\n"
                    "# porosity %.17g (requested %s); deposition's lowest %.17g; dilation %.17g\n"
                    "box: {left: 0, right: %.17g, bottom: 0, top: %.17g}\n",
                    o.n, (unsigned long long)o.seed, o.aspect, o.min_gap, sizes, phi, req, bestphi,
                    lambda, right, top) < 0)
            werr = 1;
        if (fclose(g) != 0)
            werr = 1;
    } else {
        werr = 1;
    }
    int moved = 0; /* the CSV is renamed first: on a failure after it, it goes too */
    if (werr || !(moved = rename(tmp1, o.out) == 0) || rename(tmp2, boxname) != 0) {
        fprintf(stderr, "gb_packgen: cannot write %s or %s: %s\n", o.out, boxname, strerror(errno));
        remove(tmp1);
        remove(tmp2);
        if (moved)
            remove(o.out);
        rc = EXIT_IO;
        goto done;
    }
    printf("gb_packgen: %ld discs -> %s, box %s (%.6g x %.6g), porosity %.6f (deposition %.6f, %d "
           "attempt%s), smallest gap / (r_i + r_j) %.3g\n",
           o.n, o.out, boxname, right, top, phi, bestphi, attempts, attempts > 1 ? "s" : "", worst);
    if (o.scene_box)
        printf("box: {left: 0, right: %.17g, bottom: 0, top: %.17g}\n", right, top);
done:
    free(stem);
    free(boxname);
    free(tmp1);
    free(tmp2);
    free(d);
    free(best);
    return rc;
}
