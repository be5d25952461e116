/* The global solver's Newton iteration with a line search (solver.newton: line_search).
 *
 * The direction is Newton's on the exact tangent (src/global/assemble.c: sliding contacts and the
 * contacts' rotation included), solved once per iteration, and its whole step is taken if it lowers
 * the merit (the squared fixing forces) by Armijo's rule (or, where most of the packing is out of
 * balance, a step down to a sixteenth of it). If it does not, the step has met contacts
 * that the tangent of the start does not know (grains that must rearrange: contacts that open,
 * close or slide), and the reference iteration, which sees them at every sweep, moves the
 * unbalanced grains and their neighbours (K 9-12: each grain by its own stiffness) until the merit
 * has fallen to a thousandth (src/gem/sweeps.c); Newton resumes from there. Only where the sweeps
 * do not lower the merit either (the rest is on boundary particles, which they do not move, or
 * the cluster needs more than its neighbours) is the step shortened by backtracking (every trial
 * from the iteration's start, so that the merit along the direction is a function of the length
 * alone: the incremental law, K 6 and 13, sees one move).
 * docs/solver/research.md records the measurements that led to each part. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gem/sim.h"

enum {
    MAX_HALVINGS = 12,  /* a trial length of 1/4096 of Newton's step: the direction is not a descent one */
    GLOBAL_HALVINGS = 4, /* lengths down to 1/16 tried before the sweeps where the imbalance is global */
    MAX_SWEEPS = 5000   /* reference sweeps per stall; the load step's iteration cap bounds the stalls */
};
static const double ARMIJO = 1e-4;          /* sufficient decrease: m1 <= (1 - ARMIJO alpha) m0 */
static const double SWEEP_DECREASE = 1e-3; /* the sweeps stop when the merit (squared) has fallen to this */

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

/* Tries lengths 1/2^first .. 1/2^last of Newton's step, every trial from the iteration's start;
 * *found is set at the first whose merit passes Armijo's rule (the move then taken). */
static gb_status backtrack(gb_sim *sim, const gb_wall_control *wc, double m0, const double *dir, int first, int last,
                           int *found, gb_error *err)
{
    *found = 0;
    double alpha = ldexp(1, -first);
    for (int h = first; h <= last; h++, alpha *= 0.5) {
        set_move(sim, dir, alpha);
        sim->work.trials++;
        gb_status st = take_move(sim, err);
        if (st) return st;
        if (gb_gem_merit(sim, sim->in_system, gb_gem_wall_moves(sim, wc)) <= (1 - ARMIJO * alpha) * m0) {
            sim->ls_length = alpha;
            *found = 1;
            return GB_OK;
        }
        gb_sim_state_restore(sim, &sim->trial);
        gb_gem_forces(sim);
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
    /* Newton's whole step if it lowers the merit enough; and where the imbalance is not a few
     * clusters but the packing (more than a tenth of the grains above the accuracy: a relaxation
     * far from equilibrium, the first iterations of a load step), where sweeps would crawl, down to
     * a sixteenth of it first (a 1e4-disc friction relaxation: 48 iterations, and not converged in
     * 1 000 with sweeps at once). */
    int unbalanced = 0, found;
    double a2 = sim->accuracy * sim->accuracy;
    for (int i = 0; i < n; i++) unbalanced += gb_gem_force2(sim, i) > a2;
    int first = unbalanced > n / 10 ? GLOBAL_HALVINGS : 0;
    if ((st = backtrack(sim, wc, m0, dir, 0, first, &found, err)) || found) return st;
    /* If not, the step met contacts that its tangent did not know: the unbalanced clusters are
     * settled by the reference iteration, which knows them at every sweep. */
    sim->ls_length = 0;
    if ((st = gb_gem_sweeps(sim, wc, SWEEP_DECREASE * m0, MAX_SWEEPS, err))) return st;
    if (gb_gem_merit(sim, sim->in_system, gb_gem_wall_moves(sim, wc)) <= (1 - ARMIJO) * m0) return GB_OK;
    /* The sweeps did not lower the merit either (what is left is on the particles, which they do
     * not move, or the cluster needs more than its neighbours): a shorter Newton step, and if
     * none lowers the merit, the sweeps' configuration after all (the same sweeps again). */
    gb_sim_state_restore(sim, &sim->trial);
    gb_gem_forces(sim);
    if (first < MAX_HALVINGS && ((st = backtrack(sim, wc, m0, dir, first + 1, MAX_HALVINGS, &found, err)) || found))
        return st;
    sim->ls_length = 0;
    return gb_gem_sweeps(sim, wc, SWEEP_DECREASE * m0, MAX_SWEEPS, err);
}
