/* push.c - random sequential addition and push-apart sweeps (see push.h and README.md). */
#include "push.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The working set of the sweeps. The discs are kept sorted by cell (a stable counting sort at
 * every sweep), so that a cell's discs and its neighbours' lie close together in memory: at 1e4
 * discs and more the arrays leave the first cache levels, and a sweep in the input's random order
 * spends its time on cache misses. perm[k] is the input index of the disc at position k. */
typedef struct {
    pg_disc *d, *spare;
    size_t *perm, *spare_perm;
    size_t n;
    double width, height, tol;
    long nx, ny;
    double wx, wy;
    size_t *start; /* discs of cell c: d[start[c] .. start[c + 1] - 1] */
    long *cell;
    long pushes; /* pairs and walls moved in this sweep */
    double worst_pair, worst_wall;
} pg_sweep;

void pg_rsa_place(pg_disc *d, size_t n, double width, double height, gb_rng *rng)
{
    for (size_t i = 0; i < n; ++i) {
        const double r = d[i].r;
        d[i].x = r + gb_rng_uniform(rng) * (width - 2.0 * r);
        d[i].y = r + gb_rng_uniform(rng) * (height - 2.0 * r);
    }
}

static long clamp_index(double v, double w, long count)
{
    const long k = (long)(v / w);
    return k < 0 ? 0 : k >= count ? count - 1 : k;
}

/* Stable counting sort of the discs (and perm) into cells: O(n) per sweep. */
static void sort_into_cells(pg_sweep *S)
{
    const size_t nc = (size_t)(S->nx * S->ny);
    memset(S->start, 0, (nc + 1) * sizeof *S->start);
    for (size_t i = 0; i < S->n; ++i) {
        const long c = clamp_index(S->d[i].y, S->wy, S->ny) * S->nx +
                       clamp_index(S->d[i].x, S->wx, S->nx);
        S->cell[i] = c;
        ++S->start[c + 1];
    }
    for (size_t c = 0; c < nc; ++c)
        S->start[c + 1] += S->start[c];
    for (size_t i = 0; i < S->n; ++i) {
        const size_t k = S->start[S->cell[i]]++;
        S->spare[k] = S->d[i];
        S->spare_perm[k] = S->perm[i];
    }
    for (size_t c = nc; c > 0; --c) /* the fill advanced every start by its cell's count */
        S->start[c] = S->start[c - 1];
    S->start[0] = 0;
    pg_disc *t = S->d;
    S->d = S->spare;
    S->spare = t;
    size_t *p = S->perm;
    S->perm = S->spare_perm;
    S->spare_perm = p;
}

/* One coordinate against its two walls [0, L]: a disc past its allowance goes back to touching
 * the wall (the whole overlap, as for pairs). */
static void wall_1d(pg_sweep *S, double *x, double r, double L)
{
    const double low = r - *x, high = *x + r - L; /* overlaps with the two walls */
    const double over = low > high ? low : high;
    if (over <= 0.0)
        return;
    if (over > S->worst_wall * r)
        S->worst_wall = over / r;
    if (over <= S->tol * r)
        return;
    *x = low > high ? r : L - r;
    ++S->pushes;
}

/* One pair: if it overlaps by more than the allowance, both discs move apart along the line of
 * centres by half of the whole overlap, so that they end touching (see README.md for why not
 * only the excess over the allowance). */
static void pair(pg_sweep *S, pg_disc *a, pg_disc *b)
{
    const double dx = b->x - a->x, dy = b->y - a->y, s = a->r + b->r;
    const double dist2 = dx * dx + dy * dy;
    if (dist2 >= s * s)
        return;
    const double rmin = a->r < b->r ? a->r : b->r;
    const double dist = sqrt(dist2), over = s - dist;
    if (over > S->worst_pair * rmin)
        S->worst_pair = over / rmin;
    if (over <= S->tol * rmin)
        return;
    /* coincident centres: apart along x, a fixed choice that keeps the run reproducible */
    const double ux = dist > 0.0 ? dx / dist : 1.0, uy = dist > 0.0 ? dy / dist : 0.0;
    const double move = 0.5 * over;
    a->x -= move * ux;
    a->y -= move * uy;
    b->x += move * ux;
    b->y += move * uy;
    ++S->pushes;
}

/* Disc k of cell (cx, cy) against the later discs of its own cell and all discs of the four
 * cells after it (right, and the three above): every pair of neighbouring cells once. */
static void disc_neighbours(pg_sweep *S, size_t k, long cx, long cy)
{
    static const long off[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
    const size_t c = (size_t)(cy * S->nx + cx);
    for (size_t q = k + 1; q < S->start[c + 1]; ++q)
        pair(S, &S->d[k], &S->d[q]);
    for (int o = 0; o < 4; ++o) {
        const long x = cx + off[o][0], y = cy + off[o][1];
        if (x < 0 || x >= S->nx || y >= S->ny)
            continue;
        const size_t cn = (size_t)(y * S->nx + x);
        for (size_t q = S->start[cn]; q < S->start[cn + 1]; ++q)
            pair(S, &S->d[k], &S->d[q]);
    }
}

/* One Gauss-Seidel sweep, cell by cell: positions change in place, so later pairs see earlier
 * moves. Discs that leave their cell during the sweep are placed again by the next sweep's sort;
 * a sweep that moves nothing has seen every pair as it is (cells >= the largest diameter), which
 * ends the loop. */
static void sweep(pg_sweep *S)
{
    S->pushes = 0;
    S->worst_pair = 0.0;
    S->worst_wall = 0.0;
    sort_into_cells(S);
    for (long cy = 0; cy < S->ny; ++cy)
        for (long cx = 0; cx < S->nx; ++cx) {
            const size_t c = (size_t)(cy * S->nx + cx);
            for (size_t k = S->start[c]; k < S->start[c + 1]; ++k) {
                pg_disc *p = &S->d[k];
                wall_1d(S, &p->x, p->r, S->width);
                wall_1d(S, &p->y, p->r, S->height);
                disc_neighbours(S, k, cx, cy);
            }
        }
}

/* The sweeps until one moves nothing or max_sweeps; PG_DEBUG=1 prints every power of two. */
static pg_push_status run_sweeps(pg_sweep *S, long max_sweeps, pg_push_stats *stats)
{
    const int debug = getenv("PG_DEBUG") != NULL;
    long k = 0;
    do {
        sweep(S);
        ++k;
        if (debug && (k & (k - 1)) == 0)
            fprintf(stderr, "sweep %ld: %ld pushes, worst pair %.4g, worst wall %.4g\n", k,
                    S->pushes, S->worst_pair, S->worst_wall);
    } while (S->pushes > 0 && k < max_sweeps);
    stats->sweeps = k;
    stats->worst_pair = S->worst_pair;
    stats->worst_wall = S->worst_wall;
    return S->pushes > 0 ? PG_PUSH_CAPPED : PG_PUSH_OK;
}

pg_push_status pg_push_apart(pg_disc *d, size_t n, double width, double height,
                             double max_overlap, long max_sweeps, pg_push_stats *stats)
{
    double rmax = 0.0;
    for (size_t i = 0; i < n; ++i)
        if (d[i].r > rmax)
            rmax = d[i].r;
    pg_sweep S = {.n = n, .width = width, .height = height, .tol = max_overlap};
    /* cells at least one largest diameter wide: only discs of neighbouring cells can overlap */
    S.nx = (long)(width / (2.0 * rmax));
    S.ny = (long)(height / (2.0 * rmax));
    S.nx = S.nx < 1 ? 1 : S.nx;
    S.ny = S.ny < 1 ? 1 : S.ny;
    S.wx = width / (double)S.nx;
    S.wy = height / (double)S.ny;
    S.start = malloc(((size_t)(S.nx * S.ny) + 1) * sizeof *S.start);
    S.cell = malloc(n * sizeof *S.cell);
    S.d = malloc(n * sizeof *S.d);
    S.spare = malloc(n * sizeof *S.spare);
    S.perm = malloc(n * sizeof *S.perm);
    S.spare_perm = malloc(n * sizeof *S.spare_perm);
    pg_push_status st = PG_PUSH_NOMEM;
    if (S.start && S.cell && S.d && S.spare && S.perm && S.spare_perm) {
        for (size_t i = 0; i < n; ++i) {
            S.d[i] = d[i];
            S.perm[i] = i;
        }
        st = run_sweeps(&S, max_sweeps, stats);
        for (size_t k = 0; k < n; ++k) /* back to the input's order */
            d[S.perm[k]] = S.d[k];
    }
    free(S.start);
    free(S.cell);
    free(S.d);
    free(S.spare);
    free(S.perm);
    free(S.spare_perm);
    return st;
}
