/* Reference sweeps of the unbalanced grains (K 9-12), the line-search iteration's smoother for the
 * clusters that Newton's step does not settle (src/gem/line_search.c).
 *
 * A sweep moves the grains whose fixing force exceeds the accuracy and the grains in contact with
 * them, each by its own case of K section 2.5, the others held. A stall on a loading path of a
 * packing that gembem did not make takes 1e4-1e5 sweeps of tens to hundreds of grains, so:
 * - a sweep updates only the moved grains' contacts, taking each one's old force and stiffness out
 *   of its two ends and the new in (K 5, 8), and keeps the unbalanced list, the squared forces and
 *   the merit up to date from the grains those contacts touch: its cost follows the clusters, not
 *   the packing (the forces are summed afresh when the sweeps end);
 * - with the walls held it is a Gauss-Seidel sweep, over-relaxed: each grain moves from the forces
 *   its predecessors' moves left, by SOR times its reference move at alpha = 1. On the issue's
 *   1e3-disc oedometric path (tools/bench_solver.sh's packing, one start; docs/solver/research.md)
 *   the solver took 14.7 s with Jacobi sweeps at the paper's alpha = 0.75, and with Gauss-Seidel at
 *   0.56, 0.75, 1.0, 1.35, 1.5, 1.65, 1.88 times the reference move: 33.7, 25.8, 16.6, 10.6, 5.8,
 *   6.3, 12.1 s; 1.65 also took the perturbed packing's path from 548 Newton iterations to 62.
 * Servo walls move with every sweep (K section 2.6), and then every contact may change: a Jacobi
 * sweep (every mover from the same forces) with the walls' move and every contact updated. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "gem/sim.h"

enum { MOVER = 1, TOUCHED = 2, UNBALANCED = 4 };
static const double SOR = 1.65; /* a grain's move in a held sweep, times its reference move at alpha = 1 */

/* The squared fixing force of particle e. */
static double particle_f2(const gb_sim *sim, int e)
{
    return sim->bp_F[2 * e] * sim->bp_F[2 * e] + sim->bp_F[2 * e + 1] * sim->bp_F[2 * e + 1];
}

static void free_scratch(gb_sweep_scratch *w)
{
    free(w->start), free(w->adj), free(w->f2), free(w->flag), free(w->movers), free(w->touched);
    free(w->unbalanced);
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
    int *fill = w->touched; /* as the insertion points (the movers may be in use) */
    memcpy(fill, w->start, (size_t)n * sizeof(int));
    for (int k = 0; k < P->n; k++) {
        w->adj[fill[P->p[k].i]++] = k;
        if (P->p[k].j >= 0) w->adj[fill[P->p[k].j]++] = k;
    }
    w->adj_of = P->generation;
    return GB_OK;
}

/* Everything a sweep phase keeps, from the current forces: the squared forces, the merit, the
 * unbalanced list and the pair list's drift. */
static gb_status start_phase(gb_sim *sim, double a2, double *merit, double *grain, double *wall, gb_error *err)
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
    *merit = gb_gem_merit(sim, sim->in_system, 0);
    gb_pairs_drift(&sim->pairs, &sim->world, grain, wall);
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

static void touch(gb_sweep_scratch *w, int i)
{
    if (!(w->flag[i] & TOUCHED)) w->flag[i] |= TOUCHED, w->touched[w->n_touched++] = i;
}

/* A grain left with a single contact moves by it (case c): one[] must be that contact's. */
static void fix_single(gb_sim *sim, int i)
{
    const gb_sweep_scratch *w = &sim->sweeps;
    for (int q = w->start[i]; q < w->start[i + 1] && sim->nc[i] == 1; q++) {
        const gb_pair *p = &sim->pairs.p[w->adj[q]];
        if (!(p->d > 0)) continue;
        double sign = p->i == i ? 1 : -1;
        const gb_material *m = gb_sim_material(sim, p->j);
        double *one = &sim->one[GB_ONE * i];
        one[0] = sign * p->nx, one[1] = sign * p->ny, one[2] = m->kn, one[3] = m->kr;
    }
}

/* The touched grains' squared forces, the merit and the unbalanced list brought up to date. */
static void finish_touched(gb_sim *sim, double a2, double *merit)
{
    gb_sweep_scratch *w = &sim->sweeps;
    for (int t = 0; t < w->n_touched; t++) {
        int i = w->touched[t];
        double f2 = gb_gem_force2(sim, i);
        if (sim->in_system[i]) *merit += f2 - w->f2[i];
        w->f2[i] = f2;
        w->flag[i] &= ~TOUCHED;
        if (f2 > a2 && !(w->flag[i] & UNBALANCED)) w->flag[i] |= UNBALANCED, w->unbalanced[w->n_unbalanced++] = i;
    }
}

/* One Gauss-Seidel sweep of the movers (walls held): each grain moves by its own case (K 9-12)
 * from the forces its predecessors' moves left, and its contacts follow at once. Returns 0, or
 * 1 + the grain whose move makes the pair list stale (its dX set, not applied). */
static int gauss_seidel(gb_sim *sim, int count, double a2, double omega, double *merit, double *grain, double wall)
{
    gb_sweep_scratch *w = &sim->sweeps;
    int particles_count = !sim->scene->host.rigid;
    double diss = 0;
    w->n_touched = 0;
    for (int m = 0; m < count; m++) {
        int i = w->movers[m];
        double *d = &sim->dX[3 * i];
        gb_gem_grain_move(sim, i, d);
        for (int q = 0; q < 3; q++) d[q] *= omega;
        gb_grain *g = &sim->g[i];
        g->x += d[0], g->y += d[1];
        double drift = sqrt(gb_pairs_grain_drift2(&sim->pairs, &sim->world, i));
        if (gb_pairs_drift_stale(&sim->pairs, fmax(*grain, drift), wall)) {
            g->x -= d[0], g->y -= d[1]; /* moved by the caller, with the rebuild */
            sim->dissipation += diss;
            sim->dissipation_step += diss;
            finish_touched(sim, a2, merit);
            return i + 1;
        }
        *grain = fmax(*grain, drift);
        g->rot += d[2] / g->r;
        sim->relaxation -= 0.5 * gb_gem_grain_work(sim, i);
        for (int q = w->start[i]; q < w->start[i + 1]; q++) {
            gb_pair *p = &sim->pairs.p[w->adj[q]];
            int e = GB_IS_PARTICLE(p->j) ? GB_PARTICLE_OF(p->j) : -1;
            if (e >= 0 && particles_count) *merit -= particle_f2(sim, e);
            if (p->d > 0) gb_gem_add_contact(sim, p, -1);
            diss += gb_pair_update(p, &sim->world, sim->dX, &sim->wall_dx[0][0], gb_sim_material(sim, p->j),
                                   gb_sim_tan_phi(sim, p->j));
            if (p->d > 0) gb_gem_add_contact(sim, p, 1);
            if (e >= 0 && particles_count) *merit += particle_f2(sim, e);
            touch(w, p->i);
            if (p->j >= 0) touch(w, p->j);
        }
        sim->relaxation -= 0.5 * gb_gem_grain_work(sim, i);
        memset(d, 0, 3 * sizeof(double));
        /* the grains this one's contacts touched now see their new forces (case c needs one[]) */
        for (int q = w->start[i]; q < w->start[i + 1]; q++) {
            const gb_pair *p = &sim->pairs.p[w->adj[q]];
            int o = p->i == i ? p->j : p->i;
            if (o >= 0) fix_single(sim, o);
        }
        fix_single(sim, i);
    }
    sim->dissipation += diss;
    sim->dissipation_step += diss;
    finish_touched(sim, a2, merit);
    return 0;
}

gb_status gb_gem_sweeps(gb_sim *sim, const gb_wall_control *wc, double target, int max_sweeps, gb_error *err)
{
    gb_sweep_scratch *w = &sim->sweeps;
    int n = sim->n;
    double a = sim->accuracy, a2 = a * a, merit, grain, wall;
    memset(sim->dX, 0, 3 * (size_t)n * sizeof(double));
    if (sim->bp.n) memset(sim->bp.dx, 0, 2 * (size_t)sim->bp.n * sizeof(double));
    int held = wc->mode == GB_WALLS_FIXED;
    gb_status st = start_phase(sim, a2, &merit, &grain, &wall, err);
    for (int it = 0; !st && it < max_sweeps; it++) {
        double wall_residual = gb_gem_wall_moves(sim, wc);
        if (!held) merit = gb_gem_merit(sim, sim->in_system, wall_residual);
        if (merit <= target) break;
        int count = pick_movers(sim, a2);
        if (!count && wall_residual <= a) break; /* what is left is on the particles */
        if (held) {
            sim->work.sweeps++;
            int stale = gauss_seidel(sim, count, a2, SOR / sim->scene->solver.alpha, &merit, &grain, wall);
            for (int m = 0; m < count; m++) w->flag[w->movers[m]] &= ~MOVER;
            if (!stale) continue;
            /* that grain's move with the general one, which rebuilds the pair list */
            sim->relaxation -= 0.5 * gb_gem_grain_work(sim, stale - 1);
            if ((st = gb_gem_apply_moves(sim, err))) break;
            gb_gem_forces(sim);
            sim->relaxation -= 0.5 * gb_gem_grain_work(sim, stale - 1);
            memset(&sim->dX[3 * (stale - 1)], 0, 3 * sizeof(double));
            st = start_phase(sim, a2, &merit, &grain, &wall, err);
            continue;
        }
        /* servo walls: the Jacobi sweep */
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
    w->touched = malloc((n + 1) * sizeof(int));
    w->unbalanced = malloc((n + 1) * sizeof(int));
    w->adj_of = -1;
    if (!w->start || !w->f2 || !w->flag || !w->movers || !w->touched || !w->unbalanced) {
        free_scratch(w);
        return gb_fail(err, GB_ENOMEM, "out of memory for the sweeps of %d grains", sim->n);
    }
    return GB_OK;
}
