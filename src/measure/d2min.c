/* The non-affine displacement D2min of each point (Falk & Langer 1998, eqs. 2.11-2.14). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gembem/strain_field.h"

/* Points by cell of a grid of side >= range over their bounding box (linked lists), so that the
 * neighbours of a point are in its own cell and the 8 around it. */
typedef struct {
    int nx, ny, *head, *next;
    double x0, y0, h;
} cell_grid;

static int cell_of(const cell_grid *g, double x, double y, int *cx, int *cy)
{
    *cx = (int)((x - g->x0) / g->h), *cy = (int)((y - g->y0) / g->h);
    if (*cx >= g->nx) *cx = g->nx - 1;
    if (*cy >= g->ny) *cy = g->ny - 1;
    return *cy * g->nx + *cx;
}

static gb_status grid_build(cell_grid *g, int n, const double *x, double range, gb_error *err)
{
    double xmin = x[0], xmax = x[0], ymin = x[1], ymax = x[1];
    for (int i = 1; i < n; i++) {
        xmin = fmin(xmin, x[2 * i]), xmax = fmax(xmax, x[2 * i]);
        ymin = fmin(ymin, x[2 * i + 1]), ymax = fmax(ymax, x[2 * i + 1]);
    }
    /* No more cells than about 4 per point: a sparse zone gets larger cells. */
    g->h = range;
    while (((xmax - xmin) / g->h + 1) * ((ymax - ymin) / g->h + 1) > 4.0 * n + 16) g->h *= 2;
    g->nx = (int)((xmax - xmin) / g->h) + 1, g->ny = (int)((ymax - ymin) / g->h) + 1;
    g->x0 = xmin, g->y0 = ymin;
    g->head = malloc((size_t)g->nx * (size_t)g->ny * sizeof *g->head);
    g->next = malloc((size_t)n * sizeof *g->next);
    if (!g->head || !g->next) return gb_fail(err, GB_ENOMEM, "out of memory for the neighbours of %d points", n);
    for (int c = 0; c < g->nx * g->ny; c++) g->head[c] = -1;
    for (int i = 0; i < n; i++) {
        int cx, cy, c = cell_of(g, x[2 * i], x[2 * i + 1], &cx, &cy);
        g->next[i] = g->head[c];
        g->head[c] = i;
    }
    return GB_OK;
}

/* The fit for point i from its neighbours in the grid. */
static void fit_point(const cell_grid *g, int i, const double *x0, const double *x1, double range, gb_d2min *o)
{
    memset(o, 0, sizeof *o);
    double ui[2] = {x1[2 * i] - x0[2 * i], x1[2 * i + 1] - x0[2 * i + 1]};
    double X[4] = {0}, Y[4] = {0}; /* sum du d0^t, sum d0 d0^t */
    int cx, cy;
    cell_of(g, x0[2 * i], x0[2 * i + 1], &cx, &cy);
    /* Two passes over the same neighbours: the sums, then the residuals of the fit. */
    for (int pass = 0; pass < 2; pass++) {
        for (int ky = cy - 1; ky <= cy + 1; ky++)
            for (int kx = cx - 1; kx <= cx + 1; kx++) {
                if (kx < 0 || ky < 0 || kx >= g->nx || ky >= g->ny) continue;
                for (int j = g->head[ky * g->nx + kx]; j >= 0; j = g->next[j]) {
                    double d0[2] = {x0[2 * j] - x0[2 * i], x0[2 * j + 1] - x0[2 * i + 1]};
                    if (j == i || d0[0] * d0[0] + d0[1] * d0[1] > range * range) continue;
                    /* du = d - d0 = u_j - u_i: fitting the displacement keeps small steps precise. */
                    double du[2] = {x1[2 * j] - x0[2 * j] - ui[0], x1[2 * j + 1] - x0[2 * j + 1] - ui[1]};
                    if (pass == 0) {
                        o->neighbours++;
                        X[0] += du[0] * d0[0], X[1] += du[0] * d0[1], X[2] += du[1] * d0[0], X[3] += du[1] * d0[1];
                        Y[0] += d0[0] * d0[0], Y[1] += d0[0] * d0[1], Y[3] += d0[1] * d0[1];
                    } else {
                        double rx = du[0] - o->G[0] * d0[0] - o->G[1] * d0[1];
                        double ry = du[1] - o->G[2] * d0[0] - o->G[3] * d0[1];
                        o->d2min += rx * rx + ry * ry; /* (FL 2.11) at its minimum */
                    }
                }
            }
        if (pass == 1) break;
        Y[2] = Y[1];
        double det = Y[0] * Y[3] - Y[1] * Y[2], tr = Y[0] + Y[3];
        if (!(det > 1e-12 * tr * tr)) return; /* neighbours on one line through i: no fit */
        o->ok = 1;
        /* G = X Y^-1 (FL 2.12-2.14, with J = I + G) */
        double inv[4] = {Y[3] / det, -Y[1] / det, -Y[2] / det, Y[0] / det};
        o->G[0] = X[0] * inv[0] + X[1] * inv[2], o->G[1] = X[0] * inv[1] + X[1] * inv[3];
        o->G[2] = X[2] * inv[0] + X[3] * inv[2], o->G[3] = X[2] * inv[1] + X[3] * inv[3];
    }
}

gb_status gb_d2min_points(int n, const double *x0, const double *x1, double range, gb_d2min *out, gb_error *err)
{
    if (n < 0) return gb_fail(err, GB_EINPUT, "D2min: %d points", n);
    if (!(range > 0 && isfinite(range))) return gb_fail(err, GB_EINPUT, "D2min: range %g is not positive", range);
    if (n == 0) return GB_OK;
    for (int i = 0; i < 2 * n; i++)
        if (!isfinite(x0[i]) || !isfinite(x1[i])) return gb_fail(err, GB_EINPUT, "D2min: point %d is not finite", i / 2);
    cell_grid g = {0};
    gb_status st = grid_build(&g, n, x0, range, err);
    if (!st)
        for (int i = 0; i < n; i++) fit_point(&g, i, x0, x1, range, &out[i]);
    free(g.head), free(g.next);
    return st;
}
