/* Reference sweeps of the unbalanced grains (K 9-12), the line-search iteration's smoother for the
 * clusters that Newton's step does not settle when servo walls move (src/gem/line_search.c; with
 * the walls held the inertial smoother of src/gem/inertial.c does that work).
 *
 * A sweep moves the grains whose fixing force exceeds the accuracy and the grains in contact with
 * them, each by its own case of K section 2.5 from the same forces (a Jacobi sweep), the others
 * held, and the walls by their servo move (K section 2.6); every contact is then updated. Until
 * session 9 the held case was a Gauss-Seidel sweep over-relaxed by 1.65 that updated only the moved
 * grains' contacts (docs/solver/research.md, fourth round): the inertial smoother took the 1e3 path
 * in half its time and the friction relaxations in a tenth (sixth round). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gem/sim.h"

enum { MOVER = 1, UNBALANCED = 2 };

static void free_scratch(gb_sweep_scratch *w)
{
    free(w->start), free(w->adj), free(w->f2), free(w->flag), free(w->movers), free(w->fill);
    free(w->unbalanced), free(w->velocity), free(w->acceleration);
    memset(w, 0, sizeof *w);
}

void gb_gem_sweeps_free(gb_sim *sim) { free_scratch(&sim->sweeps); }

/* The pairs of each grain (CSR; a grain-grain pair in both ends' lists, others in the grain's),
 * rebuilt with the pair list. */
static gb_status build_adjacency(gb_sim *sim, gb_error *err)
{
    gb_sweep_scratch *w = &sim->sweeps;
    const gb_pair_list *P = &sim->pairs;
    int n = sim->n;
    if (w->adj_of == P->generation && w->adj) return GB_OK;
    if (2 * (size_t)P->n > (size_t)w->adj_cap) {
        int *adj = realloc(w->adj, 2 * (size_t)P->n * sizeof(int));
        if (!adj) return gb_fail(err, GB_ENOMEM, "out of memory for the sweeps' pair lists");
        w->adj = adj, w->adj_cap = 2 * P->n;
    }
    memset(w->start, 0, (size_t)(n + 1) * sizeof(int));
    for (int k = 0; k < P->n; k++) {
        w->start[P->p[k].i + 1]++;
        if (P->p[k].j >= 0) w->start[P->p[k].j + 1]++;
    }
    for (int i = 0; i < n; i++) w->start[i + 1] += w->start[i];
    int *fill = w->fill;
    memcpy(fill, w->start, (size_t)n * sizeof(int));
    for (int k = 0; k < P->n; k++) {
        w->adj[fill[P->p[k].i]++] = k;
        if (P->p[k].j >= 0) w->adj[fill[P->p[k].j]++] = k;
    }
    w->adj_of = P->generation;
    return GB_OK;
}

/* Everything a sweep phase keeps, from the current forces: the squared forces and the unbalanced
 * list. */
static gb_status start_phase(gb_sim *sim, double a2, gb_error *err)
{
    gb_sweep_scratch *w = &sim->sweeps;
    gb_status st = build_adjacency(sim, err);
    if (st) return st;
    w->n_unbalanced = 0;
    for (int i = 0; i < sim->n; i++) {
        w->f2[i] = gb_gem_force2(sim, i);
        w->flag[i] = 0;
        if (w->f2[i] > a2) w->flag[i] = UNBALANCED, w->unbalanced[w->n_unbalanced++] = i;
    }
    return GB_OK;
}

/* The movers: the unbalanced grains (the list pruned of those balanced since) and their
 * neighbours in contact. Returns their count. */
static int pick_movers(gb_sim *sim, double a2)
{
    gb_sweep_scratch *w = &sim->sweeps;
    int kept = 0, count = 0;
    for (int u = 0; u < w->n_unbalanced; u++) {
        int i = w->unbalanced[u];
        if (w->f2[i] > a2) w->unbalanced[kept++] = i;
        else w->flag[i] &= ~UNBALANCED;
    }
    w->n_unbalanced = kept;
    for (int u = 0; u < kept; u++) {
        int i = w->unbalanced[u];
        if (!(w->flag[i] & MOVER)) w->flag[i] |= MOVER, w->movers[count++] = i;
    }
    for (int u = 0; u < kept; u++)
        for (int q = w->start[w->unbalanced[u]]; q < w->start[w->unbalanced[u] + 1]; q++) {
            const gb_pair *p = &sim->pairs.p[w->adj[q]];
            if (!(p->d > 0) || p->j < 0) continue;
            int o = p->i == w->unbalanced[u] ? p->j : p->i;
            if (!(w->flag[o] & MOVER)) w->flag[o] |= MOVER, w->movers[count++] = o;
        }
    return count;
}

static double movers_work(const gb_sim *sim, int count)
{
    double work = 0;
    for (int m = 0; m < count; m++) work += gb_gem_grain_work(sim, sim->sweeps.movers[m]);
    return work;
}

gb_status gb_gem_sweeps(gb_sim *sim, const gb_wall_control *wc, double target, int max_sweeps, gb_error *err)
{
    gb_sweep_scratch *w = &sim->sweeps;
    int n = sim->n;
    double a = sim->accuracy, a2 = a * a;
    memset(sim->dX, 0, 3 * (size_t)n * sizeof(double));
    if (sim->bp.n) memset(sim->bp.dx, 0, 2 * (size_t)sim->bp.n * sizeof(double));
    gb_status st = start_phase(sim, a2, err);
    for (int it = 0; !st && it < max_sweeps; it++) {
        double wall_residual = gb_gem_wall_moves(sim, wc);
        if (gb_gem_merit(sim, sim->in_system, wall_residual) <= target) break;
        int count = pick_movers(sim, a2);
        if (!count && wall_residual <= a) break; /* what is left is on the particles */
        for (int m = 0; m < count; m++) gb_gem_grain_move(sim, w->movers[m], &sim->dX[3 * w->movers[m]]);
        sim->work.sweeps++;
        sim->relaxation -= 0.5 * movers_work(sim, count);
        if ((st = gb_gem_apply_moves(sim, err))) break;
        gb_gem_forces(sim);
        for (int i = 0; i < n; i++) w->f2[i] = gb_gem_force2(sim, i);
        sim->relaxation -= 0.5 * movers_work(sim, count);
        for (int m = 0; m < count; m++) {
            memset(&sim->dX[3 * w->movers[m]], 0, 3 * sizeof(double));
            w->flag[w->movers[m]] &= ~MOVER;
        }
        for (int i = 0; i < n; i++) /* the unbalanced list from scratch: any grain may have changed */
            if (w->f2[i] > a2 && !(w->flag[i] & UNBALANCED))
                w->flag[i] |= UNBALANCED, w->unbalanced[w->n_unbalanced++] = i;
    }
    sim->half_pending = 0;
    /* The forces summed afresh: Newton resumes from the same numbers whatever the sweeps' order. */
    if (!st) gb_gem_forces(sim);
    return st;
}

gb_status gb_gem_sweeps_create(gb_sim *sim, gb_error *err)
{
    gb_sweep_scratch *w = &sim->sweeps;
    size_t n = (size_t)sim->n;
    w->start = malloc((n + 1) * sizeof(int));
    w->f2 = malloc((n ? n : 1) * sizeof(double));
    w->flag = calloc(n ? n : 1, 1);
    w->movers = malloc((n + 1) * sizeof(int));
    w->fill = malloc((n + 1) * sizeof(int));
    w->unbalanced = malloc((n + 1) * sizeof(int));
    w->velocity = malloc((3 * n + 1) * sizeof(double));
    w->acceleration = malloc((3 * n + 1) * sizeof(double));
    w->adj_of = -1;
    if (!w->start || !w->f2 || !w->flag || !w->movers || !w->fill || !w->unbalanced || !w->velocity ||
        !w->acceleration) {
        free_scratch(w);
        return gb_fail(err, GB_ENOMEM, "out of memory for the sweeps of %d grains", sim->n);
    }
    return GB_OK;
}
