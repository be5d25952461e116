/* Random sequential addition (place.h), the overlaps tested on a cell grid: O(n) tries. */
#include <math.h>
#include <stdlib.h>

#include "gembem/rng.h"
#include "pack/place.h"

typedef struct {
    const double *r;
    int i;
} by_size;

static int larger_first(const void *a, const void *b)
{
    const by_size *p = a, *q = b;
    if (p->r[p->i] != q->r[q->i]) return p->r[p->i] < q->r[q->i] ? 1 : -1;
    return (p->i > q->i) - (p->i < q->i);
}

typedef struct {
    double lo[2], h;
    int nx, ny;
    int *head, *next;
} grid;

static int cell(const grid *G, double v, int axis)
{
    int c = (int)floor((v - G->lo[axis]) / G->h), n = axis ? G->ny : G->nx;
    return c < 0 ? 0 : c >= n ? n - 1 : c;
}

static int overlaps(const grid *G, const gb_grain *g, double x, double y, double r)
{
    int cx = cell(G, x, 0), cy = cell(G, y, 1);
    for (int b = cy - 1; b <= cy + 1; b++)
        for (int a = cx - 1; a <= cx + 1; a++) {
            if (a < 0 || b < 0 || a >= G->nx || b >= G->ny) continue;
            for (int j = G->head[a + G->nx * b]; j >= 0; j = G->next[j]) {
                double dx = g[j].x - x, dy = g[j].y - y, s = g[j].r + r;
                if (dx * dx + dy * dy < s * s) return 1;
            }
        }
    return 0;
}

gb_status gb_place_random(const gb_region *rg, const double *r, int n, double scale, uint64_t seed, int max_tries,
                          gb_grain *g, gb_error *err)
{
    double rmax = 0;
    for (int i = 0; i < n; i++) rmax = fmax(rmax, scale * r[i]);
    grid G = {{rg->lo[0], rg->lo[1]}, 2 * rmax, 0, 0, NULL, NULL};
    /* cells of a largest diameter, not many more than the discs */
    double w = rg->hi[0] - rg->lo[0], h = rg->hi[1] - rg->lo[1];
    if (w * h / (G.h * G.h) > 4.0 * n + 16) G.h = sqrt(w * h / (4.0 * n + 16));
    G.nx = (int)(w / G.h) + 1, G.ny = (int)(h / G.h) + 1;
    G.head = malloc((size_t)G.nx * (size_t)G.ny * sizeof(int));
    G.next = malloc(((size_t)n + 1) * sizeof(int));
    by_size *order = malloc(((size_t)n + 1) * sizeof *order);
    gb_status st = GB_OK;
    if (!G.head || !G.next || !order) {
        st = gb_fail(err, GB_ENOMEM, "out of memory placing %d grains", n);
        goto done;
    }
    for (int c = 0; c < G.nx * G.ny; c++) G.head[c] = -1;
    for (int i = 0; i < n; i++) order[i].r = r, order[i].i = i;
    qsort(order, (size_t)n, sizeof *order, larger_first);
    gb_rng rng;
    gb_rng_seed(&rng, seed, 1);
    for (int k = 0; k < n; k++) {
        int i = order[k].i, t = 0;
        double ri = scale * r[i], x = 0, y = 0;
        for (; t < max_tries; t++) {
            x = rg->lo[0] + ri + gb_rng_uniform(&rng) * (w - 2 * ri);
            y = rg->lo[1] + ri + gb_rng_uniform(&rng) * (h - 2 * ri);
            if (gb_region_fits(rg, x, y, ri) && !overlaps(&G, g, x, y, ri)) break;
        }
        if (t == max_tries) {
            st = gb_fail(err, GB_EINPUT, "grain %d (radius %g) found no place in the region in %d random tries, "
                                         "after %d grains: the region is too small or too narrow for the grains",
                         i, ri, max_tries, k);
            goto done;
        }
        g[i].x = x, g[i].y = y, g[i].r = ri, g[i].rot = 0;
        int c = cell(&G, x, 0) + G.nx * cell(&G, y, 1);
        G.next[i] = G.head[c], G.head[c] = i;
    }
done:
    free(G.head), free(G.next), free(order);
    return st;
}
