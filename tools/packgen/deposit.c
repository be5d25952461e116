/* deposit.c - sequential deposition under gravity (see deposit.h).
 *
 * Geometry, for a disc i of contact radius a_i (= r_i + pad_i):
 *  - fall: i moves straight down from (x, y) until it meets the floor (y = a_i) or a disc j with
 *    |x - x_j| < a_i + a_j, at height y_j + sqrt((a_i + a_j)^2 - (x - x_j)^2); the highest wins.
 *  - roll: i, touching j, turns about j's centre on the circle of radius R = a_i + a_j, away from
 *    the top of j on side s (= +1 right, -1 left), down to j's equator. The arc is parametrised by
 *    p = s dx / (s dx + dy), (dx, dy) = centre of i - centre of j, which grows from 0 (on top) to 1
 *    (equator) and is well conditioned everywhere (unlike sin or cos of the angle). Events along
 *    the arc: the wall on side s, the floor, or the entry into the contact circle of another disc
 *    k (intersection of two circles). The first one decides:
 *      wall or floor        -> rest (stable: j on one side, the wall or floor on the other);
 *      k ahead (s side)     -> rest in the pocket of j and k (gravity lies in the cone of the two
 *                              contact normals exactly when the arc enters k from behind it);
 *      k behind or below    -> unstable on j and k: gravity lifts i off j, i rolls on k, same s;
 *      equator of j         -> i falls freely again (j excluded from that fall: it is tangent).
 *  Every move lowers i, so the loop ends; a cap guards against a numerical cycle. */
#include "deposit.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>

#define PG_MAX_MOVES 100000L
#define PG_ARC_TOL 1e-9 /* arc parameter slack for an event at the current position */

typedef struct {
    pg_disc *d;
    double *a; /* contact radius per disc */
    double width;
    double h; /* grid cell size, >= the largest contact diameter */
    int ncol;
    long nrow;    /* rows allocated */
    int *head;    /* head[row * ncol + col]: first disc in the cell, -1 if none */
    int *next;    /* next disc in the same cell */
    long *colmax; /* highest occupied row per column, -1 if none */
} pg_ctx;

static int col_of(const pg_ctx *c, double x)
{
    long k = (long)(x / c->h);
    if (k < 0)
        k = 0;
    if (k > c->ncol - 1)
        k = c->ncol - 1;
    return (int)k;
}

static long row_of(const pg_ctx *c, double y)
{
    return y > 0.0 ? (long)(y / c->h) : 0;
}

static int grid_insert(pg_ctx *c, int i)
{
    const long r = row_of(c, c->d[i].y);
    const int k = col_of(c, c->d[i].x);
    if (r >= c->nrow) {
        long nr = 2 * c->nrow;
        if (nr < r + 1)
            nr = r + 1;
        int *h = realloc(c->head, (size_t)nr * (size_t)c->ncol * sizeof *h);
        if (!h)
            return 0;
        for (size_t q = (size_t)c->nrow * (size_t)c->ncol; q < (size_t)nr * (size_t)c->ncol; ++q)
            h[q] = -1;
        c->head = h;
        c->nrow = nr;
    }
    const size_t cell = (size_t)r * (size_t)c->ncol + (size_t)k;
    c->next[i] = c->head[cell];
    c->head[cell] = i;
    if (r > c->colmax[k])
        c->colmax[k] = r;
    return 1;
}

/* Fall of disc i from (x, y): returns the disc it lands on (-1: the floor) and the landing height.
 * limited = 0: dropped from above everything. Otherwise only discs with centres at or below ylim
 * count (those above separate from a falling disc) and disc `exclude` is skipped. */
static int fall(const pg_ctx *c, int i, double x, int limited, double ylim, int exclude,
                double *yout)
{
    const double ai = c->a[i];
    double best = ai; /* the floor */
    int who = -1;
    const int k = col_of(c, x);
    const int k0 = k > 0 ? k - 1 : 0, k1 = k + 1 < c->ncol ? k + 1 : c->ncol - 1;
    long rtop = -1;
    for (int q = k0; q <= k1; ++q)
        if (c->colmax[q] > rtop)
            rtop = c->colmax[q];
    if (limited && row_of(c, ylim) < rtop)
        rtop = row_of(c, ylim);
    for (long r = rtop; r >= 0; --r) {
        /* a disc centred in row r gives a landing height below (r + 1) h + (a_i + a_j) <= (r + 2) h
         */
        if (best >= (double)(r + 2) * c->h)
            break;
        for (int q = k0; q <= k1; ++q)
            for (int j = c->head[(size_t)r * (size_t)c->ncol + (size_t)q]; j >= 0; j = c->next[j]) {
                if (j == exclude || (limited && c->d[j].y > ylim))
                    continue;
                const double D = ai + c->a[j], dx = x - c->d[j].x, s2 = D * D - dx * dx;
                if (s2 <= 0.0)
                    continue;
                const double yc = c->d[j].y + sqrt(s2);
                if (yc > best) {
                    best = yc;
                    who = j;
                }
            }
    }
    *yout = best;
    return who;
}

/* arc parameter of a point at (sx, dy) from the support's centre, sx = s dx >= 0, dy >= 0 */
static double arc(double sx, double dy)
{
    return sx / (sx + dy);
}

enum { EV_EQUATOR, EV_WALL, EV_FLOOR, EV_DISC };

/* One roll of disc i at (*px, *py) on support j towards side s; moves i to the first event and
 * returns it (*hit: the disc met, for EV_DISC). */
static int roll(const pg_ctx *c, int i, double *px, double *py, int j, int s, int prev, int *hit)
{
    const double ai = c->a[i], xj = c->d[j].x, yj = c->d[j].y;
    const double R1 = ai + c->a[j];
    const double sx0 = s * (*px - xj), dy0 = *py - yj;
    if (dy0 <= 0.0 || sx0 < 0.0 || sx0 + dy0 <= 0.0) { /* already at (or below) the equator */
        return EV_EQUATOR;
    }
    const double t0 = arc(sx0, dy0);
    double tbest = 1.0, bx = xj + s * R1, by = yj;
    int ev = EV_EQUATOR;

    /* the wall on side s */
    const double xw = s > 0 ? c->width - ai : ai;
    const double sxw = s * (xw - xj);
    if (sxw >= 0.0 && sxw <= R1) {
        const double dyw = sqrt(R1 * R1 - sxw * sxw);
        const double t = dyw > 0.0 ? arc(sxw, dyw) : 1.0;
        if (t < tbest || (t == tbest && ev == EV_EQUATOR)) {
            tbest = t;
            bx = xw;
            by = yj + dyw;
            ev = EV_WALL;
        }
    }
    /* the floor: y = a_i is on the arc when y_j <= a_i */
    if (yj <= ai) {
        const double dyf = ai - yj;
        const double sxf = R1 > dyf ? sqrt(R1 * R1 - dyf * dyf) : 0.0;
        const double t = sxf + dyf > 0.0 ? arc(sxf, dyf) : 1.0;
        if (t >= t0 - PG_ARC_TOL && t < tbest) {
            tbest = t;
            bx = xj + s * sxf;
            by = ai;
            ev = EV_FLOOR;
        }
    }
    /* other discs: neighbours of j within R1 + a_i + a_k <= 2 h */
    const int k = col_of(c, xj);
    const long r = row_of(c, yj);
    const int k0 = k > 1 ? k - 2 : 0, k1 = k + 2 < c->ncol ? k + 2 : c->ncol - 1;
    const long r0 = r > 1 ? r - 2 : 0, r1 = r + 2 < c->nrow ? r + 2 : c->nrow - 1;
    for (long rr = r0; rr <= r1; ++rr)
        for (int q = k0; q <= k1; ++q)
            for (int m = c->head[(size_t)rr * (size_t)c->ncol + (size_t)q]; m >= 0;
                 m = c->next[m]) {
                if (m == j || m == prev)
                    continue;
                const double R2 = ai + c->a[m];
                const double dx = c->d[m].x - xj, dy = c->d[m].y - yj;
                const double L2 = dx * dx + dy * dy;
                if (L2 >= (R1 + R2) * (R1 + R2))
                    continue;
                const double L = sqrt(L2);
                if (L <= fabs(R1 - R2))
                    continue;
                const double al = (R1 * R1 - R2 * R2 + L2) / (2.0 * L);
                double h2 = R1 * R1 - al * al;
                const double hh = h2 > 0.0 ? sqrt(h2) : 0.0;
                const double ex = dx / L, ey = dy / L;
                for (int sg = -1; sg <= 1; sg += 2) {
                    const double ux = al * ex - sg * hh * ey, uy = al * ey + sg * hh * ex;
                    const double sx = s * ux;
                    if (uy < 0.0 || sx < 0.0 || sx + uy <= 0.0)
                        continue;
                    const double t = arc(sx, uy);
                    if (t < t0 - PG_ARC_TOL || t >= tbest)
                        continue;
                    /* entering: the motion (s uy, -s ux) points towards m's centre */
                    const double vx = s * uy, vy = -s * ux;
                    if ((dx - ux) * vx + (dy - uy) * vy <= 0.0)
                        continue;
                    tbest = t;
                    bx = xj + ux;
                    by = yj + uy;
                    ev = EV_DISC;
                    *hit = m;
                }
            }
    *px = bx;
    *py = by;
    return ev;
}

/* Drops disc i and leaves it where it is stable. */
static pg_dep_status place(pg_ctx *c, int i, gb_rng *rng)
{
    const double ai = c->a[i];
    double x = ai + gb_rng_uniform(rng) * (c->width - 2.0 * ai), y = 0.0;
    int limited = 0, exclude = -1;
    double ylim = 0.0;
    long moves = 0;
    for (;;) {
        const int j0 = fall(c, i, x, limited, ylim, exclude, &y);
        if (j0 < 0)
            break; /* on the floor */
        int j = j0, prev = -1;
        const int s = x >= c->d[j].x ? 1 : -1;
        int falls = 0;
        while (!falls) {
            if (++moves > PG_MAX_MOVES)
                return PG_DEP_STUCK;
            int hit = -1;
            const int ev = roll(c, i, &x, &y, j, s, prev, &hit);
            if (ev == EV_EQUATOR) {
                falls = 1;
                limited = 1;
                ylim = y;
                exclude = j;
            } else if (ev == EV_DISC && s * (c->d[hit].x - x) <= 0.0) {
                prev = j; /* hit is behind or below: roll on it */
                j = hit;
            } else {
                goto rest; /* wall, floor, or a pocket */
            }
        }
        if (++moves > PG_MAX_MOVES)
            return PG_DEP_STUCK;
    }
rest:
    c->d[i].x = x;
    c->d[i].y = y;
    return grid_insert(c, i) ? PG_DEP_OK : PG_DEP_NOMEM;
}

pg_dep_status pg_deposit(pg_disc *d, size_t n, double width, double rel_pad, double abs_pad,
                         gb_rng *rng, double *height)
{
    pg_ctx c = {0};
    pg_dep_status st = PG_DEP_OK;
    if (n > (size_t)INT_MAX - 1)
        return PG_DEP_NOMEM;
    double amax = 0.0;
    c.d = d;
    c.width = width;
    c.a = malloc(n * sizeof *c.a);
    c.next = malloc(n * sizeof *c.next);
    if (!c.a || !c.next) {
        st = PG_DEP_NOMEM;
        goto done;
    }
    for (size_t i = 0; i < n; ++i) {
        c.a[i] = d[i].r + d[i].r * rel_pad + abs_pad;
        if (c.a[i] > amax)
            amax = c.a[i];
    }
    c.h = 2.0 * amax;
    c.ncol = (int)ceil(width / c.h);
    if (c.ncol < 1)
        c.ncol = 1;
    c.colmax = malloc((size_t)c.ncol * sizeof *c.colmax);
    c.nrow = 16;
    c.head = malloc((size_t)c.nrow * (size_t)c.ncol * sizeof *c.head);
    if (!c.colmax || !c.head) {
        st = PG_DEP_NOMEM;
        goto done;
    }
    for (int q = 0; q < c.ncol; ++q)
        c.colmax[q] = -1;
    for (size_t q = 0; q < (size_t)c.nrow * (size_t)c.ncol; ++q)
        c.head[q] = -1;
    double top = 0.0;
    for (size_t i = 0; i < n; ++i) {
        st = place(&c, (int)i, rng);
        if (st != PG_DEP_OK)
            goto done;
        if (d[i].y + c.a[i] > top)
            top = d[i].y + c.a[i];
    }
    *height = top;
done:
    free(c.a);
    free(c.next);
    free(c.colmax);
    free(c.head);
    return st;
}
