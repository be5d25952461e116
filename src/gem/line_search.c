/* The global solver's Newton iteration with a line search (solver.newton: line_search).
 *
 * The direction is Newton's on the exact tangent (src/global/assemble.c: sliding contacts and the
 * contacts' rotation included), solved once per iteration; the step length is found by
 * backtracking on the merit (the squared fixing forces, Armijo's rule), every trial taken from the
 * iteration's start so that the merit along the direction is a function of the length alone
 * (the incremental law, K 6 and 13, sees one move). Where no length lowers the merit (a cluster of
 * grains that must rearrange: the tangent of the start does not know the contacts it will open,
 * close or slide), the reference iteration moves the unbalanced grains and their neighbours
 * (K 9-12: each grain by its own stiffness, no global tangent) until the merit has fallen by a
 * tenth, and Newton resumes from there. docs/solver/research.md records the measurements that led
 * to each part. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gem/sim.h"

enum {
    MAX_HALVINGS = 12,  /* a trial length of 1/4096 of Newton's step: the direction is not a descent one */
    MAX_SWEEPS = 5000   /* reference sweeps per stall; the load step's iteration cap bounds the stalls */
};
static const double ARMIJO = 1e-4;          /* sufficient decrease: m1 <= (1 - ARMIJO alpha) m0 */
static const double SWEEP_DECREASE = 0.81;  /* the sweeps stop when the merit (squared) has fallen to this */

/* Grains, particles and walls moved by alpha times the direction; grains outside the system move
 * by their whole reference move (src/global/global.c). */
static void set_move(gb_sim *sim, const double *dir, double alpha)
{
    int n = sim->n, np = sim->bp.n;
    for (int i = 0; i < n; i++) {
        double f = sim->in_system[i] ? alpha : 1;
        for (int q = 0; q < 3; q++) sim->dX[3 * i + q] = f * dir[3 * i + q];
    }
    for (int k = 0; k < 2 * np; k++) sim->bp.dx[k] = alpha * dir[3 * n + k];
    for (int k = 0; k < 2 * GB_N_WALLS; k++) (&sim->wall_dx[0][0])[k] = alpha * dir[3 * n + 2 * np + k];
}

/* Applies the move in sim->dX, bp.dx and wall_dx, and evaluates the forces after it. */
static gb_status take_move(gb_sim *sim, gb_error *err)
{
    sim->relaxation -= 0.5 * gb_gem_fixing_work(sim);
    sim->half_pending = 1;
    gb_status st = gb_gem_apply_moves(sim, err);
    if (!st) gb_gem_forces(sim);
    return st;
}

/* Reference iterations (K 9-12) of the grains whose fixing force exceeds the accuracy and of the
 * grains in contact with them, the others held, until the merit falls to SWEEP_DECREASE m0. */
static gb_status sweep_unbalanced(gb_sim *sim, const gb_wall_control *wc, double m0, gb_error *err)
{
    int n = sim->n;
    double a2 = sim->scene->solver.accuracy * sim->scene->solver.accuracy;
    unsigned char *moves = sim->sweep_mask;
    for (int it = 0; it < MAX_SWEEPS; it++) {
        double wall_residual = gb_gem_wall_moves(sim, wc);
        if (gb_gem_merit(sim, sim->in_system, wall_residual) <= SWEEP_DECREASE * m0) return GB_OK;
        memset(moves, 0, (size_t)n);
        for (int i = 0; i < n; i++) {
            const double *F = &sim->F[3 * i];
            if (F[0] * F[0] + F[1] * F[1] + F[2] * F[2] > a2) moves[i] = 2;
        }
        for (int k = 0; k < sim->pairs.n; k++) {
            const gb_pair *p = &sim->pairs.p[k];
            if (!(p->d > 0) || p->j < 0) continue;
            if (moves[p->i] == 2 && !moves[p->j]) moves[p->j] = 1;
            if (moves[p->j] == 2 && !moves[p->i]) moves[p->i] = 1;
        }
        for (int i = 0; i < n; i++) {
            if (moves[i]) gb_gem_grain_move(sim, i, &sim->dX[3 * i]);
            else memset(&sim->dX[3 * i], 0, 3 * sizeof(double));
        }
        if (sim->bp.n) memset(sim->bp.dx, 0, 2 * (size_t)sim->bp.n * sizeof(double));
        sim->work.sweeps++;
        gb_status st = take_move(sim, err);
        if (st) return st;
    }
    return GB_OK;
}

gb_status gb_gem_line_search_move(gb_sim *sim, const gb_wall_control *wc, double m0, gb_error *err)
{
    int n = sim->n, np = sim->bp.n;
    /* The smallest damping: Newton's direction (the system regularises only a singular matrix). */
    gb_status st = gb_global_moves(sim->global, sim, wc, 0, err);
    if (st) return st;
    double *dir = sim->ls_dir;
    memcpy(dir, sim->dX, 3 * (size_t)n * sizeof(double));
    if (np) memcpy(dir + 3 * n, sim->bp.dx, 2 * (size_t)np * sizeof(double));
    memcpy(dir + 3 * n + 2 * np, sim->wall_dx, sizeof sim->wall_dx);
    double alpha = 1;
    for (int h = 0; h <= MAX_HALVINGS; h++, alpha *= 0.5) {
        set_move(sim, dir, alpha);
        sim->work.trials++;
        if ((st = take_move(sim, err))) return st;
        double m1 = gb_gem_merit(sim, sim->in_system, gb_gem_wall_moves(sim, wc));
        if (m1 <= (1 - ARMIJO * alpha) * m0) {
            sim->ls_length = alpha;
            return GB_OK;
        }
        gb_sim_state_restore(sim, &sim->trial);
        gb_gem_forces(sim);
    }
    sim->ls_length = 0;
    return sweep_unbalanced(sim, wc, m0, err);
}
