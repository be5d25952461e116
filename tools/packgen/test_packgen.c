/* test_packgen.c - black-box tests of gb_packgen: runs the program and checks its files
 * independently of its code.
 *
 * usage: test_packgen GB_PACKGEN WORKDIR CASE
 * cases: overlap, porosity, box, seed, shares, refuse, push */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#define PI 3.14159265358979323846

static const char *exe, *dir;
static int failures = 0;

#define CHECK(cond, ...)                                                                           \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__);                                   \
            fprintf(stderr, __VA_ARGS__);                                                          \
            fputc('\n', stderr);                                                                   \
            ++failures;                                                                            \
        }                                                                                          \
    } while (0)

typedef struct {
    size_t n;
    double *x, *y, *r;
    double left, right, bottom, top;
} packing;

static char *path(const char *name, const char *suffix)
{
    static char buf[8][1024];
    static int k = 0;
    char *b = buf[k++ % 8];
    snprintf(b, sizeof buf[0], "%s/%s%s", dir, name, suffix);
    return b;
}

/* runs gb_packgen with the arguments; returns its exit status (-1 if it did not exit) */
static int run(const char *args)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s' %s >/dev/null 2>&1", exe, args);
    const int st = system(cmd);
    if (st == -1 || !WIFEXITED(st))
        return -1;
    return WEXITSTATUS(st);
}

static int exists(const char *p)
{
    FILE *f = fopen(p, "rb");
    if (f)
        fclose(f);
    return f != NULL;
}

static void clean(const char *name)
{
    remove(path(name, ".csv"));
    remove(path(name, ".csv.tmp"));
    remove(path(name, ".box.yaml"));
    remove(path(name, ".box.yaml.tmp"));
}

static int load(const char *name, packing *p)
{
    memset(p, 0, sizeof *p);
    FILE *f = fopen(path(name, ".csv"), "r");
    if (!f)
        return 0;
    char line[512];
    size_t cap = 0;
    if (!fgets(line, sizeof line, f) || strcmp(line, "x,y,r\n") != 0) {
        fclose(f);
        return 0;
    }
    while (fgets(line, sizeof line, f)) {
        if (p->n == cap) {
            cap = cap ? 2 * cap : 1024;
            p->x = realloc(p->x, cap * sizeof(double));
            p->y = realloc(p->y, cap * sizeof(double));
            p->r = realloc(p->r, cap * sizeof(double));
        }
        if (sscanf(line, "%lf,%lf,%lf", &p->x[p->n], &p->y[p->n], &p->r[p->n]) != 3) {
            fclose(f);
            return 0;
        }
        ++p->n;
    }
    fclose(f);
    f = fopen(path(name, ".box.yaml"), "r");
    if (!f)
        return 0;
    int found = 0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "box: {left: %lf, right: %lf, bottom: %lf, top: %lf}", &p->left, &p->right,
                   &p->bottom, &p->top) == 4)
            found = 1;
    fclose(f);
    return found;
}

static void unload(packing *p)
{
    free(p->x);
    free(p->y);
    free(p->r);
}

static char *slurp(const char *p, long *len)
{
    FILE *f = fopen(p, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    *len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)*len + 1);
    if (b && fread(b, 1, (size_t)*len, f) != (size_t)*len) {
        free(b);
        b = NULL;
    }
    fclose(f);
    return b;
}

static int same_file(const char *a, const char *b)
{
    long la = 0, lb = 0;
    char *x = slurp(a, &la), *y = slurp(b, &lb);
    const int same = x && y && la == lb && memcmp(x, y, (size_t)la) == 0;
    free(x);
    free(y);
    return same;
}

/* brute force O(N^2): no pair closer than r_i + r_j */
static void check_no_overlap(const packing *p)
{
    size_t bad = 0;
    for (size_t i = 0; i < p->n; ++i)
        for (size_t j = i + 1; j < p->n; ++j) {
            const double dx = p->x[i] - p->x[j], dy = p->y[i] - p->y[j], s = p->r[i] + p->r[j];
            if (sqrt(dx * dx + dy * dy) < s)
                ++bad;
        }
    CHECK(bad == 0, "%zu overlapping pairs among %zu discs", bad, p->n);
}

static void check_inside(const packing *p)
{
    size_t bad = 0;
    for (size_t i = 0; i < p->n; ++i)
        if (!(p->x[i] - p->r[i] >= p->left && p->x[i] + p->r[i] <= p->right &&
              p->y[i] - p->r[i] >= p->bottom && p->y[i] + p->r[i] <= p->top))
            ++bad;
    CHECK(bad == 0, "%zu discs outside the box", bad);
}

static double porosity(const packing *p)
{
    double a = 0.0;
    for (size_t i = 0; i < p->n; ++i)
        a += PI * p->r[i] * p->r[i];
    return 1.0 - a / ((p->right - p->left) * (p->top - p->bottom));
}

/* area shares per diameter against the request, within one disc's area of that size */
static void check_shares(const packing *p, int K, const double *diam, const double *frac)
{
    double A = 0.0, Ak[16] = {0};
    size_t counted = 0;
    for (size_t i = 0; i < p->n; ++i) {
        const double a = PI * p->r[i] * p->r[i];
        A += a;
        for (int k = 0; k < K; ++k)
            if (fabs(2.0 * p->r[i] - diam[k]) <= 1e-12 * diam[k]) {
                Ak[k] += a;
                ++counted;
                break;
            }
    }
    CHECK(counted == p->n, "%zu of %zu radii are not among the requested sizes", p->n - counted,
          p->n);
    for (int k = 0; k < K; ++k) {
        const double one = PI * 0.25 * diam[k] * diam[k];
        CHECK(fabs(Ak[k] - frac[k] * A) <= one,
              "size %g: area %.6g, requested share %.6g of %.6g (one disc %.6g)", diam[k], Ak[k],
              frac[k], A, one);
    }
}

/* gb_packgen with these options into name.csv, its older files removed first: its exit status. */
static int make(const char *name, const char *options)
{
    char args[2048];
    clean(name);
    snprintf(args, sizeof args, "%s --out '%s'", options, path(name, ".csv"));
    return run(args);
}

static void case_overlap(void)
{
    packing p;
    CHECK(make("overlap_dense", "--n 500 --diameters 0.6,0.9,1.2 --seed 11") == 0,
          "densest 500-disc packing failed");
    CHECK(load("overlap_dense", &p) && p.n == 500, "cannot read the densest packing");
    check_no_overlap(&p);
    check_inside(&p);
    unload(&p);

    CHECK(make("overlap_dilated", "--n 500 --diameters 0.6,0.9,1.2 --porosity 0.35 --seed 12") == 0,
          "dilated 500-disc packing failed");
    CHECK(load("overlap_dilated", &p) && p.n == 500, "cannot read the dilated packing");
    check_no_overlap(&p);
    unload(&p);

    CHECK(make("overlap_gap", "--n 500 --diameters 0.6,0.9,1.2 --min-gap 0.05 --seed 13") == 0,
          "500-disc packing with --min-gap failed");
    CHECK(load("overlap_gap", &p) && p.n == 500, "cannot read the --min-gap packing");
    double gmin = INFINITY;
    for (size_t i = 0; i < p.n; ++i)
        for (size_t j = i + 1; j < p.n; ++j) {
            const double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j];
            const double g = sqrt(dx * dx + dy * dy) - p.r[i] - p.r[j];
            if (g < gmin)
                gmin = g;
        }
    CHECK(gmin >= 0.05 * (1.0 - 1e-12), "--min-gap 0.05: smallest gap %.17g", gmin);
    check_inside(&p);
    unload(&p);
}

static void case_porosity(void)
{
    const double targets[] = {0.3, 0.35, 0.5, 0.9};
    const char *aspects[] = {"1", "2", "1/3", "1.5"};
    for (int t = 0; t < 4; ++t) {
        char args[2048];
        clean("porosity");
        snprintf(
            args, sizeof args,
            "--n 300 --diameters 0.6,0.9,1.2 --porosity %.17g --aspect %s --seed %d --out '%s'",
            targets[t], aspects[t], 20 + t, path("porosity", ".csv"));
        CHECK(run(args) == 0, "porosity %g failed", targets[t]);
        packing p;
        CHECK(load("porosity", &p) && p.n == 300, "cannot read the packing");
        const double phi = porosity(&p);
        CHECK(fabs(phi - targets[t]) <= 1e-9, "porosity %.17g, requested %.17g", phi, targets[t]);
        double asp = strchr(aspects[t], '/') ? 1.0 / 3.0 : atof(aspects[t]);
        CHECK(fabs((p.top - p.bottom) / (p.right - p.left) - asp) <= 1e-12 * asp,
              "aspect %.17g, requested %s", (p.top - p.bottom) / (p.right - p.left), aspects[t]);
        check_inside(&p);
        check_no_overlap(&p);
        unload(&p);
    }
}

static void case_box(void)
{
    char args[2048];
    const char *runs[] = {"--n 1 --diameters 1", "--n 7 --diameters 0.6,0.9,1.2 --aspect 5",
                          "--n 400 --diameters 0.6,0.9,1.2 --aspect 0.2 --porosity 0.4",
                          "--n 2000 --diameters 1,2 --fractions 0.7,0.3"};
    for (int k = 0; k < 4; ++k) {
        clean("box");
        snprintf(args, sizeof args, "%s --seed 5 --out '%s'", runs[k], path("box", ".csv"));
        CHECK(run(args) == 0, "'%s' failed", runs[k]);
        packing p;
        CHECK(load("box", &p), "cannot read the output of '%s'", runs[k]);
        check_inside(&p);
        if (p.n <= 500)
            check_no_overlap(&p);
        unload(&p);
    }
}

static void case_seed(void)
{
    char args[2048];
    const char *names[] = {"seed_a", "seed_b", "seed_c"};
    const int seeds[] = {42, 42, 43};
    for (int k = 0; k < 3; ++k) {
        clean(names[k]);
        snprintf(args, sizeof args,
                 "--n 2000 --diameters 0.6,0.9,1.2 --porosity 0.3 --seed %d --out '%s'", seeds[k],
                 path(names[k], ".csv"));
        CHECK(run(args) == 0, "seed %d failed", seeds[k]);
    }
    CHECK(same_file(path("seed_a", ".csv"), path("seed_b", ".csv")),
          "same seed, different CSV files");
    CHECK(!same_file(path("seed_a", ".csv"), path("seed_c", ".csv")),
          "different seeds, identical CSV files");
    CHECK(same_file(path("seed_a", ".box.yaml"), path("seed_b", ".box.yaml")),
          "same seed, different box files");
    packing a, b;
    CHECK(load("seed_a", &a) && load("seed_b", &b), "cannot read the packings");
    CHECK(a.right == b.right && a.top == b.top, "same seed, different boxes");
    unload(&a);
    unload(&b);
}

static void case_shares(void)
{
    char args[2048];
    const double d3[] = {0.6, 0.9, 1.2}, eq[] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
    const int ns[] = {122, 500, 1001};
    for (int k = 0; k < 3; ++k) {
        clean("shares");
        snprintf(args, sizeof args, "--n %d --diameters 0.6,0.9,1.2 --seed 3 --out '%s'", ns[k],
                 path("shares", ".csv"));
        CHECK(run(args) == 0, "n = %d failed", ns[k]);
        packing p;
        CHECK(load("shares", &p) && p.n == (size_t)ns[k], "cannot read the packing");
        check_shares(&p, 3, d3, eq);
        unload(&p);
    }
    const double d4[] = {0.5, 1.0, 1.5, 2.0}, f4[] = {0.1, 0.2, 0.3, 0.4};
    clean("shares");
    snprintf(args, sizeof args,
             "--n 777 --diameters 0.5,1,1.5,2 --fractions 0.1,0.2,0.3,0.4 --seed 4 --out '%s'",
             path("shares", ".csv"));
    CHECK(run(args) == 0, "fractions run failed");
    packing p;
    CHECK(load("shares", &p) && p.n == 777, "cannot read the packing");
    check_shares(&p, 4, d4, f4);
    unload(&p);
}

/* The text after `key` on the first line of the box file that holds it, or NULL. */
static char *box_comment(const char *name, const char *key, char *line, size_t len)
{
    FILE *f = fopen(path(name, ".box.yaml"), "r");
    char *hit = NULL;
    while (f && !hit && fgets(line, (int)len, f))
        if ((hit = strstr(line, key)) != NULL)
            hit += strlen(key);
    if (f)
        fclose(f);
    return hit;
}

/* Brute force O(N^2) and the walls: the largest overlap / smaller radius and / radius against
 * a wall, and how many exceed tol (up to rounding: 1e-12 of the radius). */
static void push_bounds(const packing *p, double tol, double *pair, double *wall, size_t *bad)
{
    *pair = *wall = 0.0;
    *bad = 0;
    for (size_t i = 0; i < p->n; ++i) {
        const double r = p->r[i];
        const double o[4] = {p->left - (p->x[i] - r), p->x[i] + r - p->right,
                             p->bottom - (p->y[i] - r), p->y[i] + r - p->top};
        for (int k = 0; k < 4; ++k) {
            if (o[k] / r > *wall)
                *wall = o[k] / r;
            *bad += o[k] > (tol + 1e-12) * r;
        }
        for (size_t j = i + 1; j < p->n; ++j) {
            const double dx = p->x[i] - p->x[j], dy = p->y[i] - p->y[j];
            const double rmin = r < p->r[j] ? r : p->r[j];
            const double over = r + p->r[j] - sqrt(dx * dx + dy * dy);
            if (over / rmin > *pair)
                *pair = over / rmin;
            *bad += over > (tol + 1e-12) * rmin;
        }
    }
}

/* Counts per size from the CSV: each the floor or the ceiling of its ideal share of N (equal
 * area per size: N (1/d_k^2) / sum_j 1/d_j^2), and the same as the box file says. */
static void check_counts(const char *name, const packing *p, int K, const double *diam)
{
    long count[16] = {0};
    double w = 0.0;
    for (int k = 0; k < K; ++k)
        w += 1.0 / (diam[k] * diam[k]);
    for (size_t i = 0; i < p->n; ++i)
        for (int k = 0; k < K; ++k)
            count[k] += fabs(2.0 * p->r[i] - diam[k]) <= 1e-12 * diam[k];
    char line[1024], expect[256] = "", *got = box_comment(name, "(diameter:count): ", line,
                                                         sizeof line);
    size_t used = 0;
    for (int k = 0; k < K; ++k) {
        const double ideal = (double)p->n / (diam[k] * diam[k]) / w;
        CHECK(count[k] == (long)floor(ideal) || count[k] == (long)ceil(ideal),
              "size %g: %ld discs, ideal %.3f", diam[k], count[k], ideal);
        used += (size_t)snprintf(expect + used, sizeof expect - used, "%s%g:%ld", k ? " " : "",
                                 diam[k], count[k]);
    }
    CHECK(got && !strncmp(got, expect, strlen(expect)), "box file counts '%s', CSV '%s'",
          got ? got : "(none)", expect);
}

static void case_push(void)
{
    const char *base = "--method push --n 500 --diameters 0.6,0.9,1.2 --porosity 0.18 "
                       "--max-overlap 0.015";
    const char *names[] = {"push_a", "push_b", "push_c"};
    const int seeds[] = {31, 31, 32};
    char args[2048];
    for (int k = 0; k < 3; ++k) {
        clean(names[k]);
        snprintf(args, sizeof args, "%s --seed %d --out '%s'", base, seeds[k],
                 path(names[k], ".csv"));
        CHECK(run(args) == 0, "push, seed %d, failed", seeds[k]);
    }
    packing p;
    CHECK(load("push_a", &p) && p.n == 500, "cannot read the push packing");
    double pair, wall;
    size_t bad;
    push_bounds(&p, 0.015, &pair, &wall, &bad);
    CHECK(bad == 0, "%zu overlaps beyond 0.015 r_min (largest %.6g, walls %.6g)", bad, pair, wall);
    CHECK(pair > 0.5 * 0.015, "largest overlap %.6g: at porosity 0.18 discs should touch", pair);
    char line[1024];
    const char *rep = box_comment("push_a", "largest overlap / smaller radius ", line, sizeof line);
    CHECK(rep && fabs(atof(rep) - pair) <= 1e-9, "box file's largest overlap %s, measured %.17g",
          rep ? rep : "(none)", pair);
    CHECK(box_comment("push_a", "push-apart sweeps", line, sizeof line), "no sweep count");
    CHECK(fabs(porosity(&p) - 0.18) <= 1e-9, "porosity %.17g, requested 0.18", porosity(&p));
    CHECK(fabs((p.top - p.bottom) - (p.right - p.left)) <= 1e-12 * p.right, "box not square");
    const double d3[] = {0.6, 0.9, 1.2};
    check_counts("push_a", &p, 3, d3);
    unload(&p);
    CHECK(same_file(path("push_a", ".csv"), path("push_b", ".csv")) &&
              same_file(path("push_a", ".box.yaml"), path("push_b", ".box.yaml")),
          "push: same seed, different files");
    CHECK(!same_file(path("push_a", ".csv"), path("push_c", ".csv")),
          "push: different seeds, identical CSV files");

    /* other options: sizes 1 and 2 by --fractions, a tall box, a larger allowance */
    clean("push_d");
    snprintf(args, sizeof args,
             "--method push --n 400 --diameters 1,2 --fractions 0.7,0.3 --porosity 0.25 "
             "--aspect 2 --max-overlap 0.05 --seed 3 --out '%s'",
             path("push_d", ".csv"));
    CHECK(run(args) == 0, "push with --fractions, --aspect 2, --max-overlap 0.05 failed");
    CHECK(load("push_d", &p) && p.n == 400, "cannot read the second push packing");
    push_bounds(&p, 0.05, &pair, &wall, &bad);
    CHECK(bad == 0, "%zu overlaps beyond 0.05 r_min (largest %.6g, walls %.6g)", bad, pair, wall);
    CHECK(fabs(porosity(&p) - 0.25) <= 1e-9, "porosity %.17g, requested 0.25", porosity(&p));
    CHECK(fabs((p.top - p.bottom) / (p.right - p.left) - 2.0) <= 1e-12, "aspect not 2");
    const double d2[] = {1.0, 2.0}, f2[] = {0.7, 0.3};
    check_shares(&p, 2, d2, f2);
    unload(&p);

    /* the cap: too few sweeps is a failure (status 1) that leaves no file */
    clean("push_capped");
    snprintf(args, sizeof args, "%s --seed 31 --max-sweeps 3 --out '%s'", base,
             path("push_capped", ".csv"));
    CHECK(run(args) == 1, "push capped at 3 sweeps: expected exit status 1");
    CHECK(!exists(path("push_capped", ".csv")) && !exists(path("push_capped", ".box.yaml")) &&
              !exists(path("push_capped", ".csv.tmp")),
          "push capped at 3 sweeps left a file");
}

static void case_refuse(void)
{
    const char *bad[] = {
        "--n 500 --diameters 0.6,0.9,1.2 --porosity 0.05 --out '%s'", /* below the densest */
        "--n 500 --diameters 0.6,-0.9,1.2 --out '%s'",                /* negative diameter */
        "--n 500 --diameters 0.6,0.9,1.2 --porosity 0.3",             /* missing --out */
        "--n 0 --diameters 1 --out '%s'",
        "--n 10 --diameters 1,0 --out '%s'",
        "--n 10 --diameters 1,2 --fractions 0.5,0.4 --out '%s'",
        "--n 10 --diameters 1,2 --fractions 0.5 --out '%s'",
        "--n 10 --diameters 1 --porosity 1 --out '%s'",
        "--n 10 --diameters 1 --porosity 0 --out '%s'",
        "--n 10 --diameters 1 --aspect -1 --out '%s'",
        "--n 10 --diameters 1 --seed -3 --out '%s'",
        "--n 10 --diameters 1 --bogus 3 --out '%s'",
        "--n 10 --diameters 1,,2 --out '%s'",
        "--n 10x --diameters 1 --out '%s'",
        "--diameters 1 --out '%s'",
        "--n 10 --out '%s'",
        "--n 10 --diameters 1 --out '%s' --porosity",
        "--method push --n 500 --diameters 0.6,0.9,1.2 --out '%s'", /* push needs --porosity */
        "--method push --n 500 --diameters 1 --porosity 0.2 --min-gap 0.1 --out '%s'",
        "--method push --n 500 --diameters 1 --porosity 0.2 --max-overlap 0 --out '%s'",
        "--method push --n 500 --diameters 1 --porosity 0.2 --max-sweeps 0 --out '%s'",
        "--n 500 --diameters 1 --max-overlap 0.1 --out '%s'", /* push options with deposit */
        "--method pull --n 500 --diameters 1 --porosity 0.2 --out '%s'",
        "--method push --n 1 --diameters 1 --porosity 0.2 --out '%s'", /* box below a diameter */
    };
    for (size_t k = 0; k < sizeof bad / sizeof *bad; ++k) {
        char fmtd[2048], args[2048];
        clean("refused");
        snprintf(fmtd, sizeof fmtd, "%s", bad[k]);
        snprintf(args, sizeof args, fmtd, path("refused", ".csv"));
        const int st = run(args);
        CHECK(st == 2, "'%s': exit status %d, expected 2", args, st);
        CHECK(!exists(path("refused", ".csv")) && !exists(path("refused", ".csv.tmp")) &&
                  !exists(path("refused", ".box.yaml")) &&
                  !exists(path("refused", ".box.yaml.tmp")),
              "'%s' left a file", args);
    }
    CHECK(run("--help") == 0, "--help should exit 0");
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: test_packgen GB_PACKGEN WORKDIR CASE\n");
        return 2;
    }
    exe = argv[1];
    dir = argv[2];
    const char *c = argv[3];
    if (!strcmp(c, "overlap"))
        case_overlap();
    else if (!strcmp(c, "porosity"))
        case_porosity();
    else if (!strcmp(c, "box"))
        case_box();
    else if (!strcmp(c, "seed"))
        case_seed();
    else if (!strcmp(c, "shares"))
        case_shares();
    else if (!strcmp(c, "refuse"))
        case_refuse();
    else if (!strcmp(c, "push"))
        case_push();
    else {
        fprintf(stderr, "unknown case %s\n", c);
        return 2;
    }
    if (failures)
        fprintf(stderr, "%d check(s) failed\n", failures);
    else
        printf("packgen %s: ok\n", c);
    return failures ? 1 : 0;
}
