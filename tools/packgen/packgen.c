/* gb_packgen - seeded, reproducible packings of discs in a box at a target porosity.
 *
 * --method deposit (the default):
 * 1. counts per size from the area shares (the rounding that matches the shares best);
 * 2. the discs in a random order (seeded shuffle);
 * 3. sequential deposition under gravity in a box of width W (deposit.c), repeated with W adjusted
 *    to fit the pile under the box top aspect * W; the densest attempt that fits is kept;
 * 4. homogeneous dilation of the centres (radii unchanged, box scaled by the same factor) to the
 *    requested porosity = 1 - (disc area) / (box area); the box is then [0, W] x [0, H].
 * --method push (the solver benchmark's packings, which gembem did not make): steps 1 and 2, a box
 * of the requested porosity, random sequential addition and push-apart sweeps (push.c) until every
 * overlap is at most --max-overlap times the smaller radius.
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
#include "gembem/rng.h"
#include "push.h"

#define PG_PI 3.14159265358979323846
#define PG_MAX_N 100000000L
#define PG_MAX_SIZES 64
#define PG_REL_PAD 1e-12 /* contact radii are r (1 + 1e-12): touching discs stay strictly apart */
#define PG_MAX_ATTEMPTS 8
#define PG_PHI_GUESS 0.18 /* first guess of the pile's porosity, for the first width */
#define PG_MAX_OVERLAP 0.015 /* push: default allowed overlap / smaller radius */
#define PG_MAX_SWEEPS 100000L /* push: default cap on the sweeps */

enum { EXIT_INTERNAL = 1, EXIT_INPUT = 2, EXIT_IO = 4, EXIT_NOMEM = 5 };
enum { PG_DEPOSIT = 0, PG_PUSH = 1 };

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
    int have_min_gap;
    int method;          /* PG_DEPOSIT or PG_PUSH */
    double max_overlap;  /* push only */
    long max_sweeps;     /* push only */
    int have_push_opts;  /* --max-overlap or --max-sweeps given */
} pg_opts;

static const char *usage_text =
    "usage: gb_packgen --n N --diameters d1,d2,... --out FILE.csv [options]\n"
    "       gb_packgen --method push --n N --diameters d1,d2,... --porosity P --out FILE.csv\n"
    "\n"
    "Random packing of N discs in a box (floor y = 0, walls x = 0 and x = W, top y = H), built by\n"
    "sequential deposition under gravity, then dilated homogeneously to the requested porosity\n"
    "(method deposit), or by random sequential addition in the box of the requested porosity and\n"
    "push-apart sweeps until every overlap is small (method push).\n"
    "\n"
    "  --method M          deposit (default) or push\n"
    "  --n N               number of discs (>= 1)\n"
    "  --diameters LIST    disc diameters, comma separated, > 0 (any length unit; the box uses "
    "it)\n"
    "  --fractions LIST    area fraction of each size, >= 0, summing to 1 (default: equal areas)\n"
    "  --porosity P        target porosity 1 - (disc area)/(box area), 0 < P < 1; deposit: refused\n"
    "                      if below the deposition's (the densest it makes), default that densest;\n"
    "                      push: required\n"
    "  --aspect A          box height / width, a number or a ratio like 3/2 (default 1)\n"
    "  --seed S            random seed, an unsigned 64-bit integer (default 1)\n"
    "  --min-gap g         every pair of discs at least g apart, every disc at least g/2 from the\n"
    "                      box sides, already in the deposition (default 0; deposit only)\n"
    "  --max-overlap t     push: every overlap at most t times the smaller radius of the pair\n"
    "                      (disc-wall: t times the disc's radius), 0 < t < 1 (default 0.015)\n"
    "  --max-sweeps K      push: give up (exit 1) after K sweeps (default 100000)\n"
    "  --out FILE.csv      discs: header x,y,r then one line per disc (%.17g)\n"
    "                      the box goes to FILE.box.yaml: box: {left:, right:, bottom:, top:}\n"
    "  --scene-box         also print the box line on standard output\n"
    "  --help              this text\n"
    "\n"
    "Exit status: 0 done; 2 impossible or malformed request (nothing written); 1 internal error\n"
    "or (push) the overlaps not reached in --max-sweeps; 4, 5 write or memory failure.\n";

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

/* --method, --max-overlap and --max-sweeps. An allowance of 0 is refused: exact contact is
 * reached by the sweeps only in the limit, so they would never stop. */
static void parse_push_option(const char *name, const char *val, pg_opts *o)
{
    if (!strcmp(name, "--method")) {
        if (!strcmp(val, "deposit"))
            o->method = PG_DEPOSIT;
        else if (!strcmp(val, "push"))
            o->method = PG_PUSH;
        else
            fail_input("--method expects deposit or push, got '%s'", val);
    } else if (!strcmp(name, "--max-overlap")) {
        o->max_overlap = parse_double(name, val);
        if (!(o->max_overlap > 0.0 && o->max_overlap < 1.0))
            fail_input("--max-overlap expects a number strictly between 0 and 1, got '%s'", val);
        o->have_push_opts = 1;
    } else if (!strcmp(name, "--max-sweeps")) {
        char *end = NULL;
        errno = 0;
        const long long v = strtoll(val, &end, 10);
        if (end == val || *end != '\0' || errno == ERANGE || v < 1 || v > 1000000000LL)
            fail_input("--max-sweeps expects an integer from 1 to 1000000000, got '%s'", val);
        o->max_sweeps = (long)v;
        o->have_push_opts = 1;
    }
}

static void parse_args(int argc, char **argv, pg_opts *o)
{
    memset(o, 0, sizeof *o);
    o->n = -1;
    o->porosity = -1.0;
    o->aspect = 1.0;
    o->seed = 1;
    o->max_overlap = PG_MAX_OVERLAP;
    o->max_sweeps = PG_MAX_SWEEPS;
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
        static const char *valued[] = {"--n",         "--diameters",    "--fractions",
                                       "--porosity",  "--aspect",       "--seed",
                                       "--out",       "--min-gap",      "--method",
                                       "--max-overlap", "--max-sweeps"};
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
            o->have_min_gap = 1;
        } else {
            parse_push_option(name, val, o);
        }
    }
    if (o->n < 1)
        fail_input("--n is required: the number of discs, an integer >= 1");
    if (o->method == PG_PUSH && o->porosity < 0.0)
        fail_input("--method push needs --porosity: the box is made for it");
    if (o->method == PG_PUSH && o->have_min_gap)
        fail_input("--min-gap is for --method deposit; push bounds overlaps by --max-overlap");
    if (o->method == PG_DEPOSIT && o->have_push_opts)
        fail_input("--max-overlap and --max-sweeps are for --method push");
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

/* The packing made by either method: what main checks and writes. */
typedef struct {
    pg_disc *d;        /* n discs, owned */
    double area;       /* total disc area */
    double right, top; /* the box [0, right] x [0, top] */
    double bestphi;    /* deposit: the deposition's lowest porosity */
    double lambda;     /* deposit: the dilation */
    int attempts;      /* deposit: depositions made */
    pg_push_stats push;
} pg_result;

/* What the final check measured. */
typedef struct {
    double gap;  /* smallest gap / (r_i + r_j), negative for an overlap */
    double pair; /* largest overlap / smaller radius (0 if none) */
    double wall; /* largest overlap with a wall / radius (0 if none) */
} pg_check;

/* A disc's overlap with the box, the largest of its four sides (<= 0: inside). */
static double wall_overlap(const pg_disc *p, double W, double H)
{
    const double o[4] = {p->r - p->x, p->x + p->r - W, p->r - p->y, p->y + p->r - H};
    double m = o[0];
    for (int k = 1; k < 4; ++k)
        m = o[k] > m ? o[k] : m;
    return m;
}

/* One pair of the final check. tol = 0 (deposit): ok only if the discs do not overlap in floating
 * point; tol > 0 (push): ok if the overlap is at most tol times the smaller radius, computed as
 * push.c computes it, so that a packing the sweeps accepted passes. */
static int check_pair(const pg_disc *a, const pg_disc *b, double tol, pg_check *c)
{
    const double dx = a->x - b->x, dy = a->y - b->y, s = a->r + b->r;
    const double dist2 = dx * dx + dy * dy, dist = sqrt(dist2);
    const double rmin = a->r < b->r ? a->r : b->r;
    if ((dist - s) / s < c->gap)
        c->gap = (dist - s) / s;
    if (dist2 < s * s && (s - dist) / rmin > c->pair)
        c->pair = (s - dist) / rmin;
    if (tol == 0.0)
        return !(dist2 < s * s);
    return !(dist2 < s * s) || s - dist <= tol * rmin;
}

/* Brute-force-free check of the result on a cell grid: every pair and every disc against the
 * box, within the allowance tol (see check_pair; against the walls tol times the radius).
 * Returns 1 if all hold, 0 if not, -1 out of memory. */
static int verify(const pg_disc *d, size_t n, double W, double H, double tol, pg_check *c)
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
    c->gap = INFINITY;
    c->pair = 0.0;
    c->wall = 0.0;
    if (!head || !next) {
        free(head);
        free(next);
        return -1;
    }
    for (long q = 0; q < nc * nr; ++q)
        head[q] = -1;
    for (size_t i = 0; i < n; ++i) {
        const double w = wall_overlap(&d[i], W, H);
        if (w > 0.0 && w / d[i].r > c->wall)
            c->wall = w / d[i].r;
        if (tol == 0.0 ? !(d[i].x - d[i].r >= 0.0 && d[i].x + d[i].r <= W &&
                           d[i].y - d[i].r >= 0.0 && d[i].y + d[i].r <= H)
                       : !(w <= tol * d[i].r))
            ok = 0;
        long cx = (long)(d[i].x / h), cy = (long)(d[i].y / h);
        cx = cx < 0 ? 0 : cx >= nc ? nc - 1 : cx;
        cy = cy < 0 ? 0 : cy >= nr ? nr - 1 : cy;
        for (long y = cy - 1; y <= cy + 1; ++y)
            for (long x = cx - 1; x <= cx + 1; ++x) {
                if (x < 0 || y < 0 || x >= nc || y >= nr)
                    continue;
                for (int j = head[y * nc + x]; j >= 0; j = next[j])
                    if (!check_pair(&d[i], &d[j], tol, c))
                        ok = 0;
            }
        next[i] = head[cy * nc + cx];
        head[cy * nc + cx] = (int)i;
    }
    free(head);
    free(next);
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

/* The radii in size order, then a seeded Fisher-Yates shuffle (stream 0): both methods place the
 * discs in this order. Returns the total disc area. */
static double shuffled_radii(const pg_opts *o, const long *count, pg_disc *d, size_t n)
{
    size_t m = 0;
    double area = 0.0;
    for (int k = 0; k < o->nsize; ++k) {
        const double r = 0.5 * o->diam[k];
        for (long q = 0; q < count[k]; ++q)
            d[m++].r = r;
        area += (double)count[k] * PG_PI * r * r;
    }
    gb_rng rng;
    gb_rng_seed(&rng, o->seed, 0);
    for (size_t i = n - 1; i > 0; --i) {
        const size_t j = gb_rng_below(&rng, i + 1);
        const double t = d[i].r;
        d[i].r = d[j].r;
        d[j].r = t;
    }
    return area;
}

/* Method deposit: steps 3-5 of the file comment. d holds the shuffled radii and is scratch;
 * res->d (allocated by the caller) gets the packing. Returns an exit status. */
static int make_deposit(const pg_opts *o, const long *count, pg_disc *d, pg_result *res)
{
    const size_t n = (size_t)o->n;
    double amax = 0.0, acontact = 0.0;
    for (int k = 0; k < o->nsize; ++k) {
        const double r = 0.5 * o->diam[k];
        const double a = r + r * PG_REL_PAD + 0.5 * o->min_gap;
        if (count[k] > 0 && a > amax)
            amax = a;
        acontact += (double)count[k] * PG_PI * a * a;
    }
    pg_disc *best = res->d;
    gb_rng rng;

    /* deposition, with the width adjusted so that the pile fits under the box top aspect * W.
     * W' = W sqrt(Hp / H) keeps the area W Hp; `margin` (extra height aimed for) grows by half a
     * radius after each attempt whose pile is too high and halves after one that fits. All
     * PG_MAX_ATTEMPTS attempts are made, each with its own random stream; the densest one that
     * fits is kept; if none fits, the densest one, centred in a box widened to Hp / aspect. */
    double W = sqrt(acontact / ((1.0 - PG_PHI_GUESS) * o->aspect));
    double bestW = 0.0, bestphi = INFINITY, shift = 0.0, margin = 0.0;
    int attempts = 0, bestfits = 0;
    for (int att = 0; att < PG_MAX_ATTEMPTS; ++att) {
        if (W < 2.0 * amax)
            W = 2.0 * amax;
        double Hp = 0.0;
        gb_rng_seed(&rng, o->seed, 1u + (uint64_t)att);
        const pg_dep_status st = pg_deposit(d, n, W, PG_REL_PAD, 0.5 * o->min_gap, &rng, &Hp);
        ++attempts;
        if (st == PG_DEP_NOMEM) {
            fprintf(stderr, "gb_packgen: out of memory in the deposition\n");
            return EXIT_NOMEM;
        }
        if (st != PG_DEP_OK) {
            fprintf(stderr, "gb_packgen: internal error: a disc did not come to rest\n");
            return EXIT_INTERNAL;
        }
        const double H = o->aspect * W;
        const int fits = Hp <= H;
        const double Wbox = fits ? W : Hp / o->aspect;
        const double phi = 1.0 - res->area / (o->aspect * Wbox * Wbox);
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
        W = W * sqrt(Hp / H) + margin / (2.0 * o->aspect);
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
    if (o->porosity >= 0.0) {
        if (o->porosity < bestphi - 1e-12) {
            fprintf(stderr,
                    "gb_packgen: porosity %g is below the lowest this generator reaches for these "
                    "sizes and shares, n = %ld, aspect %g, seed %llu: %.6f (sequential deposition, "
                    "then dilation only). Ask for a porosity >= %.6f, or compress the packing "
                    "under stress in the solver.\n",
                    o->porosity, o->n, o->aspect, (unsigned long long)o->seed, bestphi,
                    ceil(bestphi * 1e6) / 1e6);
            return EXIT_INPUT;
        }
        lambda = sqrt(res->area / ((1.0 - o->porosity) * o->aspect * bestW * bestW));
        if (lambda < 1.0)
            lambda = 1.0;
    }
    res->right = lambda * bestW;
    res->top = lambda * (o->aspect * bestW);
    for (size_t i = 0; i < n; ++i) {
        best[i].x *= lambda;
        best[i].y *= lambda;
    }
    res->bestphi = bestphi;
    res->lambda = lambda;
    res->attempts = attempts;
    return 0;
}

/* Method push: the box of the requested porosity and aspect, random sequential addition (stream
 * 1), push-apart sweeps. d holds the shuffled radii; the packing goes to res->d. */
static int make_push(const pg_opts *o, const pg_disc *d, pg_result *res)
{
    const size_t n = (size_t)o->n;
    double rmax = 0.0;
    for (int k = 0; k < o->nsize; ++k)
        if (0.5 * o->diam[k] > rmax)
            rmax = 0.5 * o->diam[k];
    const double W = sqrt(res->area / ((1.0 - o->porosity) * o->aspect)), H = o->aspect * W;
    if (W < 2.0 * rmax || H < 2.0 * rmax) {
        fprintf(stderr,
                "gb_packgen: the box of porosity %g for these discs (%.6g x %.6g) is narrower "
                "than the largest diameter %g: ask for more discs or an aspect nearer 1\n",
                o->porosity, W, H, 2.0 * rmax);
        return EXIT_INPUT;
    }
    memcpy(res->d, d, n * sizeof *d);
    gb_rng rng;
    gb_rng_seed(&rng, o->seed, 1);
    pg_rsa_place(res->d, n, W, H, &rng);
    const pg_push_status st =
        pg_push_apart(res->d, n, W, H, o->max_overlap, o->max_sweeps, &res->push);
    if (st == PG_PUSH_NOMEM) {
        fprintf(stderr, "gb_packgen: out of memory in the push-apart sweeps\n");
        return EXIT_NOMEM;
    }
    if (st == PG_PUSH_CAPPED) {
        fprintf(stderr,
                "gb_packgen: push-apart did not bring every overlap within --max-overlap %g in %ld "
                "sweeps (the last sweep's largest overlap / smaller radius %.4g, against a wall "
                "%.4g). Porosity %g may be too low for these sizes: ask for a higher porosity, a "
                "larger --max-overlap or more --max-sweeps. Nothing written.\n",
                o->max_overlap, res->push.sweeps, res->push.worst_pair, res->push.worst_wall,
                o->porosity);
        return EXIT_INTERNAL;
    }
    res->right = W;
    res->top = H;
    return 0;
}

/* The box file's comment lines: what was asked and what was reached. */
static int write_box_comments(FILE *g, const pg_opts *o, const long *count, double phi,
                              const pg_result *res, const pg_check *c)
{
    char sizes[2048] = "";
    size_t used = 0;
    for (int k = 0; k < o->nsize && used < sizeof sizes; ++k)
        used += (size_t)snprintf(sizes + used, sizeof sizes - used, "%s%g:%ld", k ? " " : "",
                                 o->diam[k], count[k]);
    if (o->method == PG_PUSH)
        return fprintf(g,
                       "# gb_packgen: method push, n = %ld, seed = %llu, aspect = %.17g, "
                       "max_overlap = %.17g\n"
                       "# discs per diameter (diameter:count): %s\n"
                       "# porosity %.17g (requested %.17g); random sequential addition, then %ld "
                       "push-apart sweeps; largest overlap / smaller radius %.17g, against a "
                       "wall / radius %.17g\n",
                       o->n, (unsigned long long)o->seed, o->aspect, o->max_overlap, sizes, phi,
                       o->porosity, res->push.sweeps, c->pair, c->wall);
    char req[64];
    if (o->porosity >= 0.0)
        snprintf(req, sizeof req, "%.17g", o->porosity);
    else
        snprintf(req, sizeof req, "none, so the densest");
    return fprintf(g,
                   "# gb_packgen: n = %ld, seed = %llu, aspect = %.17g, min_gap = %.17g\n"
                   "# discs per diameter (diameter:count): %s\n"
                   "# porosity %.17g (requested %s); deposition's lowest %.17g; dilation %.17g\n",
                   o->n, (unsigned long long)o->seed, o->aspect, o->min_gap, sizes, phi, req,
                   res->bestphi, res->lambda);
}

/* Writes FILE.tmp and FILE.box.yaml.tmp, then renames both; on any failure no file is left. */
static int write_files(const pg_opts *o, const long *count, double phi, const pg_result *res,
                       const pg_check *c, const char *boxname)
{
    const size_t n = (size_t)o->n;
    char *tmp1 = concat(o->out, ".tmp"), *tmp2 = concat(boxname, ".tmp");
    int rc = 0, werr = 0;
    if (!tmp1 || !tmp2) {
        free(tmp1);
        free(tmp2);
        return EXIT_NOMEM;
    }
    FILE *f = fopen(tmp1, "w");
    if (!f) {
        fprintf(stderr, "gb_packgen: cannot write %s: %s\n", tmp1, strerror(errno));
        free(tmp1);
        free(tmp2);
        return EXIT_IO;
    }
    if (fputs("x,y,r\n", f) < 0)
        werr = 1;
    for (size_t i = 0; i < n && !werr; ++i)
        if (fprintf(f, "%.17g,%.17g,%.17g\n", res->d[i].x, res->d[i].y, res->d[i].r) < 0)
            werr = 1;
    if (fclose(f) != 0)
        werr = 1;
    FILE *g = werr ? NULL : fopen(tmp2, "w");
    if (g) {
        if (write_box_comments(g, o, count, phi, res, c) < 0 ||
            fprintf(g, "box: {left: 0, right: %.17g, bottom: 0, top: %.17g}\n", res->right,
                    res->top) < 0)
            werr = 1;
        if (fclose(g) != 0)
            werr = 1;
    } else {
        werr = 1;
    }
    int moved = 0; /* the CSV is renamed first: on a failure after it, it goes too */
    if (werr || !(moved = rename(tmp1, o->out) == 0) || rename(tmp2, boxname) != 0) {
        fprintf(stderr, "gb_packgen: cannot write %s or %s: %s\n", o->out, boxname,
                strerror(errno));
        remove(tmp1);
        remove(tmp2);
        if (moved)
            remove(o->out);
        rc = EXIT_IO;
    }
    free(tmp1);
    free(tmp2);
    return rc;
}

static void print_summary(const pg_opts *o, double phi, const pg_result *res, const pg_check *c,
                          const char *boxname)
{
    if (o->method == PG_PUSH)
        printf("gb_packgen: %ld discs -> %s, box %s (%.6g x %.6g), porosity %.6f (random "
               "sequential addition, %ld push-apart sweeps), largest overlap / smaller radius "
               "%.3g, against a wall / radius %.3g\n",
               o->n, o->out, boxname, res->right, res->top, phi, res->push.sweeps, c->pair,
               c->wall);
    else
        printf("gb_packgen: %ld discs -> %s, box %s (%.6g x %.6g), porosity %.6f (deposition "
               "%.6f, %d attempt%s), smallest gap / (r_i + r_j) %.3g\n",
               o->n, o->out, boxname, res->right, res->top, phi, res->bestphi, res->attempts,
               res->attempts > 1 ? "s" : "", c->gap);
    if (o->scene_box)
        printf("box: {left: 0, right: %.17g, bottom: 0, top: %.17g}\n", res->right, res->top);
}

/* FILE.box.yaml from FILE.csv (or FILE.box.yaml appended when there is no .csv suffix). */
static char *box_name(const char *out)
{
    const size_t lo = strlen(out);
    char *stem = malloc(lo + 1);
    if (!stem)
        return NULL;
    memcpy(stem, out, lo + 1);
    if (lo > 4 && !strcmp(stem + lo - 4, ".csv"))
        stem[lo - 4] = '\0';
    char *b = concat(stem, ".box.yaml");
    free(stem);
    return b;
}

int main(int argc, char **argv)
{
    pg_opts o;
    parse_args(argc, argv, &o);
    const size_t n = (size_t)o.n;

    long count[PG_MAX_SIZES];
    choose_counts(&o, count);

    int rc = 0;
    char *boxname = NULL;
    pg_result res = {0};
    pg_disc *d = malloc(n * sizeof *d);
    res.d = malloc(n * sizeof *res.d);
    if (!d || !res.d) {
        fprintf(stderr, "gb_packgen: out of memory for %zu discs\n", n);
        rc = EXIT_NOMEM;
        goto done;
    }
    res.area = shuffled_radii(&o, count, d, n);
    rc = o.method == PG_PUSH ? make_push(&o, d, &res) : make_deposit(&o, count, d, &res);
    if (rc != 0)
        goto done;
    const double phi = 1.0 - res.area / (res.right * res.top);

    pg_check chk;
    const double tol = o.method == PG_PUSH ? o.max_overlap : 0.0;
    const int ok = verify(res.d, n, res.right, res.top, tol, &chk);
    if (ok < 0) {
        fprintf(stderr, "gb_packgen: out of memory in the final check\n");
        rc = EXIT_NOMEM;
        goto done;
    }
    if (!ok) {
        fprintf(stderr, "gb_packgen: internal error: the packing overlaps or leaves the box%s\n",
                tol > 0.0 ? " by more than --max-overlap" : "");
        rc = EXIT_INTERNAL;
        goto done;
    }
    boxname = box_name(o.out);
    if (!boxname) {
        rc = EXIT_NOMEM;
        goto done;
    }
    rc = write_files(&o, count, phi, &res, &chk, boxname);
    if (rc == 0)
        print_summary(&o, phi, &res, &chk, boxname);
done:
    free(boxname);
    free(d);
    free(res.d);
    return rc;
}
