#include "contact/pairs.h"

#include <math.h>
#include <stdio.h>
#ifdef _OPENMP
#include <omp.h>
static int gb_pairs_thread(void) { return omp_get_thread_num(); }
#else
static int gb_pairs_thread(void) { return 0; }
#endif
#include <stdlib.h>
#include <string.h>

#include "core/memory.h"

void gb_pair_set_free(gb_pair_set *P)
{
    free(P->p);
    free(P->x0);
    free(P->px0);
    memset(P, 0, sizeof *P);
}

void gb_pair_search_free(gb_pair_search *S)
{
    free(S->tmp);
    free(S->cell_start);
    free(S->cell_grains);
    free(S->grain_cell);
    for (int t = 0; t < GB_PAIRS_MAX_THREADS; t++) free(S->tcand[t]);
    free(S->count);
    free(S->old_start);
    free(S->pcell_head);
    free(S->pcell_next);
    memset(S, 0, sizeof *S);
}

gb_status gb_particles_create(gb_particles *bp, const gb_bem_mesh *mesh, const int *elem, int m, gb_error *err)
{
    memset(bp, 0, sizeof *bp);
    bp->n = m;
    size_t k = (size_t)(m > 0 ? m : 1);
    bp->x = malloc(k * sizeof(double)), bp->y = malloc(k * sizeof(double)), bp->r = malloc(k * sizeof(double));
    bp->nx = malloc(k * sizeof(double)), bp->ny = malloc(k * sizeof(double)), bp->dx = calloc(2 * k, sizeof(double));
    if (!bp->x || !bp->y || !bp->r || !bp->nx || !bp->ny || !bp->dx) {
        gb_particles_free(bp);
        return gb_fail(err, GB_ENOMEM, "out of memory for %d boundary particles", m);
    }
    for (int q = 0; q < m; q++) {
        int e = elem[q];
        bp->x[q] = mesh->mid[2 * e], bp->y[q] = mesh->mid[2 * e + 1];
        bp->r[q] = 0.5 * mesh->length[e];
        bp->nx[q] = mesh->normal[2 * e], bp->ny[q] = mesh->normal[2 * e + 1];
    }
    return GB_OK;
}

void gb_particles_free(gb_particles *bp)
{
    free(bp->x), free(bp->y), free(bp->r), free(bp->nx), free(bp->ny), free(bp->dx);
    memset(bp, 0, sizeof *bp);
}

static gb_status grow(void **buf, int *cap, int need, size_t size, gb_error *err)
{
    if (need <= *cap) return GB_OK;
    long long c = *cap ? *cap : 64; /* doubled past INT_MAX, then cut back to it */
    while (c < need) c *= 2;
    if (c > INT_MAX) c = INT_MAX;
    void *q = realloc(*buf, (size_t)c * size);
    if (!q) return gb_fail(err, GB_ENOMEM, "out of memory for %lld contact pairs", c);
    *buf = q;
    *cap = (int)c;
    return GB_OK;
}

/* m: the pairs counted, 0 if a thread's count passed GB_PAIRS_MAX before all were counted. */
static gb_status too_many(int n, long long m, gb_error *err)
{
    char counted[48] = "";
    if (m > 0) snprintf(counted, sizeof counted, " (%lld)", m);
    return gb_fail(err, GB_ENOMEM, "%d grains have more candidate pairs%s than the %d a pair list can count; use "
                   "fewer grains, or radii less spread (the pairs are searched within the grains' reach)",
                   n, counted, GB_PAIRS_MAX);
}

gb_status gb_pairs_offsets(int *count, int n, gb_error *err)
{
    long long m = 0;
    for (int i = 0; i < n; i++) m += count[i];
    if (m > GB_PAIRS_MAX) return too_many(n, m, err);
    int at = 0;
    for (int i = 0; i < n; i++) {
        int c = count[i];
        count[i] = at, at += c;
    }
    count[n] = at;
    return GB_OK;
}

/* The cell grid of a rebuild: cells of side h from (x0, y0), nx by ny. */
typedef struct {
    double x0, y0, h;
    int nx, ny;
} gb_grid;

static void cell_of(const gb_grid *G, double x, double y, int *cx, int *cy)
{
    int a = (int)((x - G->x0) / G->h), b = (int)((y - G->y0) / G->h);
    *cx = a < 0 ? 0 : a >= G->nx ? G->nx - 1 : a;
    *cy = b < 0 ? 0 : b >= G->ny ? G->ny - 1 : b;
}

/* Insertion sort: a grain's candidates are a dozen or two (qsort's calls cost more). */
static void sort_ints(int *a, int n)
{
    for (int k = 1; k < n; k++) {
        int v = a[k], q = k;
        for (; q > 0 && a[q - 1] > v; q--) a[q] = a[q - 1];
        a[q] = v;
    }
}

/* What a candidate search ran out of (bits: threads may run out of both): memory, or the ints that
 * count the pairs. */
enum { OUT_OF_MEMORY = 1, TOO_MANY = 2 };

/* Appends one candidate to thread t's buffer at position at; 0, or -OUT_OF_MEMORY, -TOO_MANY. */
static int push(gb_pair_search *S, int t, long long at, int j)
{
    if (at >= S->tcand_cap[t]) {
        if (at >= GB_PAIRS_MAX) return -TOO_MANY;
        long long c = S->tcand_cap[t] ? 2LL * S->tcand_cap[t] : 1024;
        if (c > GB_PAIRS_MAX) c = GB_PAIRS_MAX;
        int *q = realloc(S->tcand[t], (size_t)c * sizeof(int));
        if (!q) return -OUT_OF_MEMORY;
        S->tcand[t] = q, S->tcand_cap[t] = (int)c;
    }
    S->tcand[t][at] = j;
    return 0;
}

/* Grain i's candidates appended to thread t's buffer at position at: the boundary particles and
 * walls within reach (their indices are negative), then the grains j > i, each part sorted, so
 * that the list is sorted by (i, j). Returns their count, or push's negative code. */
static int candidates(gb_pair_search *S, const gb_grid *G, const gb_world *w, int i, int t, long long at)
{
    const gb_grain *g = w->g, *a = &g[i];
    const gb_box *box = w->box;
    const gb_particles *bp = w->bp;
    int np = bp ? bp->n : 0, nc = 0, cx, cy, st;
    cell_of(G, a->x, a->y, &cx, &cy);
    for (int y = cy - 1; np > 0 && y <= cy + 1; y++) {
        if (y < 0 || y >= G->ny) continue;
        for (int x = cx - 1; x <= cx + 1; x++) {
            if (x < 0 || x >= G->nx) continue;
            for (int e = S->pcell_head[y * G->nx + x]; e >= 0; e = S->pcell_next[e]) {
                double dx = bp->x[e] - a->x, dy = bp->y[e] - a->y, reach = a->r + bp->r[e] + S->skin;
                if (dx * dx + dy * dy >= reach * reach) continue;
                if ((st = push(S, t, at + nc++, GB_PARTICLE_J(e)))) return st;
            }
        }
    }
    for (int wl = GB_N_WALLS - 1; box && wl >= 0; wl--) {
        double gap[GB_N_WALLS] = {a->x - box->left, box->right - a->x, a->y - box->bottom, box->top - a->y};
        if (gap[wl] < a->r + S->skin && (st = push(S, t, at + nc++, -1 - wl))) return st;
    }
    int first_grain = nc;
    for (int y = cy - 1; y <= cy + 1; y++) {
        if (y < 0 || y >= G->ny) continue;
        for (int x = cx - 1; x <= cx + 1; x++) {
            if (x < 0 || x >= G->nx) continue;
            int c = y * G->nx + x;
            const gb_cell_entry *e = &S->cell_grains[S->cell_start[c]], *end = &S->cell_grains[S->cell_start[c + 1]];
            for (; e < end; e++) {
                if (e->j <= i) continue;
                double dx = e->x - a->x, dy = e->y - a->y, reach = a->r + e->r + S->skin;
                if (dx * dx + dy * dy >= reach * reach) continue;
                if ((st = push(S, t, at + nc++, e->j))) return st;
            }
        }
    }
    sort_ints(S->tcand[t] + at, first_grain);
    sort_ints(S->tcand[t] + at + first_grain, nc - first_grain);
    return nc;
}

/* The grid over the world (cells of side 2 rmax + skin) and the grains sorted by cell into
 * S->cell_grains, S->cell_start; the boundary particles by cell into S->pcell_head, pcell_next. */
static gb_status cells_fill(gb_pair_search *S, const gb_world *w, gb_grid *grid, gb_error *err)
{
    gb_status st;
    const gb_grain *g = w->g;
    const gb_box *box = w->box;
    const gb_particles *bp = w->bp;
    int n = w->n, np = bp ? bp->n : 0;
    double rmax = 0, xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
    if (box) xmin = box->left, xmax = box->right, ymin = box->bottom, ymax = box->top;
    for (int e = 0; e < np; e++) {
        if (bp->r[e] > rmax) rmax = bp->r[e];
        xmin = fmin(xmin, bp->x[e]), xmax = fmax(xmax, bp->x[e]);
        ymin = fmin(ymin, bp->y[e]), ymax = fmax(ymax, bp->y[e]);
    }
    for (int i = 0; i < n; i++) {
        if (g[i].r > rmax) rmax = g[i].r;
        if (g[i].x < xmin) xmin = g[i].x;
        if (g[i].x > xmax) xmax = g[i].x;
        if (g[i].y < ymin) ymin = g[i].y;
        if (g[i].y > ymax) ymax = g[i].y;
    }
    /* Cells of side 2 rmax + skin: every candidate lies in the 3 x 3 cells around a grain. Grids
     * far finer than the grain count only cost memory, so the cell count is kept near n. */
    double h = 2 * rmax + S->skin;
    double span = fmax(xmax - xmin, ymax - ymin);
    if (span / h > 4.0 * sqrt((double)n) + 4) h = span / (4.0 * sqrt((double)n) + 4);
    int ncx = (int)((xmax - xmin) / h) + 1, ncy = (int)((ymax - ymin) / h) + 1;
    int ncells = ncx * ncy;
    const gb_grid G = {xmin, ymin, h, ncx, ncy};
    *grid = G;
    if ((st = grow((void **)&S->cell_start, &S->n_cells_cap, ncells + 1, sizeof(int), err))) return st;
    size_t nn = (size_t)(n > 0 ? n : 1);
    if ((!S->cell_grains && !(S->cell_grains = malloc(nn * sizeof *S->cell_grains))) ||
        (!S->grain_cell && !(S->grain_cell = malloc(nn * sizeof(int)))))
        return gb_fail(err, GB_ENOMEM, "out of memory for the cell list");
    memset(S->cell_start, 0, (size_t)(ncells + 1) * sizeof(int));
    if (np > 0) {
        if ((st = grow((void **)&S->pcell_head, &S->n_pcells_cap, ncells, sizeof(int), err)) ||
            (st = grow((void **)&S->pcell_next, &S->n_particles_cap, np, sizeof(int), err)))
            return st;
        for (int c = 0; c < ncells; c++) S->pcell_head[c] = -1;
        for (int e = np - 1; e >= 0; e--) {
            int cx, cy;
            cell_of(&G, bp->x[e], bp->y[e], &cx, &cy);
            S->pcell_next[e] = S->pcell_head[cy * ncx + cx];
            S->pcell_head[cy * ncx + cx] = e;
        }
    }
    /* The grains by cell (a counting sort, each cell's in increasing order), with their centres
     * and radii: a cell's grains are then read one after the other, not by following links. */
    for (int i = 0; i < n; i++) {
        int cx, cy;
        cell_of(&G, g[i].x, g[i].y, &cx, &cy);
        S->grain_cell[i] = cy * ncx + cx;
        S->cell_start[cy * ncx + cx + 1]++;
    }
    for (int c = 0; c < ncells; c++) S->cell_start[c + 1] += S->cell_start[c];
    for (int i = 0; i < n; i++) {
        gb_cell_entry *e = &S->cell_grains[S->cell_start[S->grain_cell[i]]++];
        e->x = g[i].x, e->y = g[i].y, e->r = g[i].r, e->j = i;
    }
    for (int c = ncells; c > 0; c--) S->cell_start[c] = S->cell_start[c - 1]; /* back to each cell's start */
    S->cell_start[0] = 0;
    return GB_OK;
}

gb_status gb_grains_cell_order(const gb_grain *g, int n, int *order, gb_error *err)
{
    if (n <= 0) return GB_OK;
    gb_pair_search S = {0};
    gb_world w = {g, n, NULL, NULL};
    gb_grid G;
    gb_status st = cells_fill(&S, &w, &G, err);
    for (int k = 0; !st && k < n; k++) order[k] = S.cell_grains[k].j;
    gb_pair_search_free(&S);
    return st;
}

gb_status gb_pairs_scan_overlaps(gb_pair_search *S, const gb_world *w, gb_pair_visit visit, void *user,
                                 gb_error *err)
{
    double skin = S->skin;
    S->skin = 0;
    gb_grid G;
    gb_status st = cells_fill(S, w, &G, err);
    S->skin = skin;
    for (int i = 0, stop = 0; !st && !stop && i < w->n; i++) {
        const gb_grain *a = &w->g[i];
        int cx, cy;
        cell_of(&G, a->x, a->y, &cx, &cy);
        for (int y = cy - 1; y <= cy + 1; y++) {
            if (y < 0 || y >= G.ny) continue;
            for (int x = cx - 1; x <= cx + 1; x++) {
                if (x < 0 || x >= G.nx) continue;
                int c = y * G.nx + x;
                const gb_cell_entry *e = &S->cell_grains[S->cell_start[c]], *end = &S->cell_grains[S->cell_start[c + 1]];
                for (; e < end; e++) {
                    if (e->j <= i) continue;
                    double dx = e->x - a->x, dy = e->y - a->y, reach = a->r + e->r;
                    if (dx * dx + dy * dy >= reach * reach) continue;
                    stop |= visit(user, i, e->j, reach - sqrt(dx * dx + dy * dy));
                }
            }
        }
    }
    return st;
}

/* The first pass: each grain's sorted candidates into its thread's buffer (T threads), their
 * counts S->count turned into offsets (gb_pairs_offsets: S->count[n] pairs in all). */
static gb_status count_candidates(gb_pair_search *S, const gb_grid *G, const gb_world *w, int T, gb_error *err)
{
    int n = w->n, failed = 0;
#pragma omp parallel num_threads(T) if (T > 1) reduction(| : failed)
    {
        int t = T > 1 ? gb_pairs_thread() : 0, i0 = (int)((long)n * t / T), i1 = (int)((long)n * (t + 1) / T);
        long long at = 0;
        for (int i = i0; i < i1 && !failed; i++) {
            int nc = candidates(S, G, w, i, t, at);
            if (nc < 0) failed |= -nc;
            else S->count[i] = nc, at += nc;
        }
    }
    if (failed & TOO_MANY) return too_many(n, 0, err);
    if (failed) return gb_fail(err, GB_ENOMEM, "out of memory for the candidate pairs");
    return gb_pairs_offsets(S->count, n, err);
}

/* A list the machine cannot hold (the grains admitted, but far more pairs than their count) is
 * refused with its size rather than left to the kernel's out-of-memory killer; checked only when
 * the list grows by much, as reading the kernel's count costs a file. Then room for m pairs in
 * S->tmp. */
static gb_status room_for_pairs(gb_pair_search *S, int n, int m, gb_error *err)
{
    double grows = ((double)m - S->tmp_cap) * sizeof(gb_pair);
    if (grows > 64e6) {
        double have = gb_memory_available();
        if (have > 0 && grows > have)
            return gb_fail(err, GB_EINPUT, "%d grains have %d candidate pairs, whose list needs %.3g GB more, more "
                           "than the %.3g GB this machine has available; use fewer grains, or radii less spread "
                           "(the pairs are searched within the largest grain's reach)", n, m, grows / 1e9, have / 1e9);
    }
    return grow((void **)&S->tmp, &S->tmp_cap, m, sizeof(gb_pair), err);
}

/* The second pass: the candidates merged with the old list P (both sorted by (i, j)) into S->tmp,
 * on the same threads' ranges: a pair kept keeps its contact, a new one starts apart. */
static void merge_pairs(const gb_pair_set *P, gb_pair_search *S, const gb_world *w, int T)
{
    int n = w->n;
#pragma omp parallel num_threads(T) if (T > 1)
    {
        int t = T > 1 ? gb_pairs_thread() : 0, i0 = (int)((long)n * t / T), i1 = (int)((long)n * (t + 1) / T);
        const int *c = S->tcand[t];
        for (int i = i0; i < i1; i++) {
            int old = S->old_start[i], end = S->old_start[i + 1];
            for (int k = S->count[i]; k < S->count[i + 1]; k++) {
                int j = *c++;
                while (old < end && P->p[old].j < j) old++;
                gb_pair *q = &S->tmp[k];
                if (old < end && P->p[old].j == j) {
                    *q = P->p[old++];
                } else {
                    memset(q, 0, sizeof *q);
                    q->i = i;
                    q->j = j;
                    gb_pair_geometry(q, w);
                    q->d = 0; /* not yet a contact: its forces start at the next update */
                }
            }
        }
    }
}

/* The new list (S->tmp, m pairs) becomes P's, at least as long as the old (a state saved before
 * fits in it), which becomes the next rebuild's buffer; the positions it was built at. */
static gb_status swap_lists(gb_pair_set *P, gb_pair_search *S, const gb_world *w, int m, gb_error *err)
{
    int n = w->n, np = w->bp ? w->bp->n : 0;
    if (S->tmp_cap < P->cap) {
        gb_pair *q = realloc(S->tmp, (size_t)P->cap * sizeof *q);
        if (!q) return gb_fail(err, GB_ENOMEM, "out of memory for %d contact pairs", P->cap);
        S->tmp = q, S->tmp_cap = P->cap;
    }
    gb_pair *p = P->p;
    int cap = P->cap;
    P->p = S->tmp;
    P->cap = S->tmp_cap;
    P->n = m;
    S->tmp = p;
    S->tmp_cap = cap;
    for (int i = 0; i < n; i++) {
        P->x0[2 * i] = w->g[i].x;
        P->x0[2 * i + 1] = w->g[i].y;
    }
    if (np > 0 && !P->px0 && !(P->px0 = malloc(2 * (size_t)np * sizeof(double))))
        return gb_fail(err, GB_ENOMEM, "out of memory for the cell list");
    for (int e = 0; e < np; e++) P->px0[2 * e] = w->bp->x[e], P->px0[2 * e + 1] = w->bp->y[e];
    if (w->box) P->box0 = *w->box;
    return GB_OK;
}

gb_status gb_pairs_rebuild(gb_pair_set *P, gb_pair_search *S, const gb_world *w, gb_error *err)
{
    int n = w->n;
    gb_grid G;
    gb_status st = cells_fill(S, w, &G, err);
    if (st) return st;
    if (!P->x0 && !(P->x0 = malloc((size_t)(2 * (n > 0 ? n : 1)) * sizeof(double))))
        return gb_fail(err, GB_ENOMEM, "out of memory for the cell list");
    /* The candidates in two passes over the grains, each thread on one contiguous range of them
     * (the same in both): their sorted candidates into the thread's buffer, then, after the
     * offsets, the pairs merged with the old list into theirs. The list is the same whatever the
     * number of threads: the thread count only splits the work. */
    int T = S->threads > 1 && n >= GB_PAIRS_PARALLEL ? S->threads : 1;
    if (T > GB_PAIRS_MAX_THREADS) T = GB_PAIRS_MAX_THREADS;
    if ((st = grow((void **)&S->count, &S->count_cap, n + 1, sizeof(int), err)) ||
        (st = grow((void **)&S->old_start, &S->old_start_cap, n + 1, sizeof(int), err)) ||
        (st = count_candidates(S, &G, w, T, err)))
        return st;
    int m = S->count[n];
    for (int k = 0, i = 0; i <= n; i++) { /* the old list's first pair of each grain */
        while (k < P->n && P->p[k].i < i) k++;
        S->old_start[i] = k;
    }
    if ((st = room_for_pairs(S, n, m, err))) return st;
    merge_pairs(P, S, w, T);
    if ((st = swap_lists(P, S, w, m, err))) return st;
    P->rebuilds++;
    P->generation = ++S->generations;
    return GB_OK;
}

double gb_pairs_wall_drift(const gb_pair_set *P, const gb_world *w)
{
    const gb_box *box = w->box;
    double wall = 0;
    if (box)
        wall = fmax(fmax(fabs(box->left - P->box0.left), fabs(box->right - P->box0.right)),
                    fmax(fabs(box->bottom - P->box0.bottom), fabs(box->top - P->box0.top)));
    for (int e = 0; w->bp && e < w->bp->n; e++)
        wall = fmax(wall, hypot(w->bp->x[e] - P->px0[2 * e], w->bp->y[e] - P->px0[2 * e + 1]));
    return wall;
}

int gb_pairs_drift_stale(const gb_pair_search *S, double grain, double wall)
{
    /* A pair's gap shrinks by at most the sum of both sides' displacements. */
    return 2 * grain >= S->skin || grain + wall >= S->skin;
}

int gb_pairs_stale(const gb_pair_set *P, const gb_pair_search *S, const gb_world *w)
{
    double max2 = 0;
    for (int i = 0; i < w->n; i++) {
        double d2 = gb_pairs_grain_drift2(P, w, i);
        if (d2 > max2) max2 = d2;
    }
    return gb_pairs_drift_stale(S, sqrt(max2), gb_pairs_wall_drift(P, w));
}

int gb_pairs_brute_force(const gb_grain *g, int n, double range, int *out_i, int *out_j, int cap)
{
    int m = 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            double dx = g[j].x - g[i].x, dy = g[j].y - g[i].y, reach = g[i].r + g[j].r + range;
            if (dx * dx + dy * dy >= reach * reach) continue;
            if (m < cap) {
                out_i[m] = i;
                out_j[m] = j;
            }
            m++;
        }
    return m;
}
