/* The global solver's damped iteration (solver.newton: damped): Levenberg-Marquardt damping with
 * non-monotone acceptance; and which grains the global system moves, for both iterations. */
#include <math.h>

#include "solver/solver_impl.h"

/* Levenberg-Marquardt damping: its range, and the trials per iteration. The damping is a relative
 * diagonal shift, so mu = 10 already shortens a step to about 1/11 of the per-grain (Jacobi) move;
 * at the cap a move is taken whatever the merit. With a cap of 1e4 a load step whose packing must
 * rearrange (a grain rolling out of a squeeze: its force grows before it falls) crept by 1e-8 cm
 * per iteration and stalled. The 8 cases of the localisation sweep (validation/localisation,
 * CHOLMOD): with the cap at 1e4, 2 converge over their whole loading, also with load-step
 * cut-backs (src/run/program.c); with the cap at 10 and cut-backs, 7. */
static const double MU_MIN = 1e-8, MU_MAX = 10;
enum { MAX_TRIALS = 6, LM_STALL = 50 };
static const double LM_STALL_FACTOR = 0.5;

/* Those with two contacts or more, and (GB_IN_SYSTEM_NO_ROTATION) a grain without body force with
 * a single contact. Its only zero mode is rolling over its neighbour (with kt) or sliding along it
 * (without), which its contact force cannot drive, so the system holds its rotation and moves it
 * with its neighbours (its contact with kt in K even if it slides: the grain must unload it; a
 * frictionless one with a tangent stiffness of its own, see gb_global_tangents in assemble.c),
 * where moved apart by the reference case c) it would trade its force back and forth with the
 * system every iteration (a two-cycle that decays by a few per cent per iteration). With a body
 * force it rolls: case c). With rolling resistance (docs/method.md section 3.1) on its contact the
 * rolling spring holds that mode, with or without a body force: the grain moves with the system,
 * its rotation too (GB_IN_SYSTEM_SINGLE), its contact's kt and kr kept in K even at their limits
 * (its block stays regular). */
void gb_solver_mark_system(gb_solver *s, const gb_sim *sim)
{
    for (int i = 0; i < sim->state.n; i++) s->in_system[i] = sim->scratch.nc[i] >= 2 ? GB_IN_SYSTEM : 0;
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        if (!(p->d > 0)) continue;
        int ends[2] = {p->i, p->j >= 0 ? p->j : -1};
        for (int e = 0; e < 2; e++) {
            int i = ends[e];
            if (i < 0 || sim->scratch.nc[i] != 1) continue;
            if (gb_sim_material(sim, p->j)->kr > 0) s->in_system[i] = GB_IN_SYSTEM_SINGLE;
            else if (sim->body[2 * i] == 0 && sim->body[2 * i + 1] == 0) s->in_system[i] = GB_IN_SYSTEM_NO_ROTATION;
        }
    }
}

/* The damped Newton step is taken if it lowers the merit; if not, the configuration is restored
 * and the step retried with eight times the damping. Far from equilibrium (a packing that
 * rearranges) the steps shorten towards the reference iteration's, near it they lengthen to
 * Newton's. */
gb_status gb_solver_damped_move(gb_solver *s, gb_sim *sim, const gb_wall_control *wc, double m0, gb_error *err)
{
    gb_solver_damping *d = &s->damping;
    /* Non-monotone acceptance (Grippo, Lampariello and Lucidi): a move may raise the merit above
     * the current one but not above the largest of the last few accepted, so that grains moved by
     * the reference cases (a grain rolling over a neighbour) cannot lock the damping. */
    double bound = m0;
    for (int k = 0; k < GB_SOLVER_HISTORY; k++) bound = fmax(bound, d->history[k]);
    /* A cycle: a grain whose contact switches between sticking and sliding (the sliding contact has
     * no tangential stiffness in K) can alternate between two configurations whose merits both
     * stay under the non-monotone bound, slowly or never converging (seen in the localisation
     * study's cavity packings). When no move of the last LM_STALL has brought the merit below
     * LM_STALL_FACTOR times the lowest merit of the load step so far, the acceptance turns monotone
     * (the damping grows until a move lowers the merit) until one does. A Newton phase halves the
     * merit in a few moves and never meets this. */
    if (!(m0 >= d->best * LM_STALL_FACTOR)) d->since = 0;
    else d->since++;
    if (m0 < d->best) d->best = m0;
    if (d->since > LM_STALL) bound = m0;
    for (int trial = 0;; trial++) {
        s->work.trials++;
        gb_status st = gb_global_moves(s->global, sim, s->in_system, wc, d->mu, err);
        if (st) return st;
        sim->state.acc.relaxation -= 0.5 * gb_gem_fixing_work(sim);
        sim->state.acc.half_pending = 1;
        if ((st = gb_gem_move_and_forces(sim, err))) return st;
        double m1 = gb_gem_merit(sim, s->in_system, gb_gem_wall_moves(sim, wc));
        if (m1 <= bound || trial == MAX_TRIALS || d->mu >= MU_MAX) {
            d->mu = fmax(d->mu / 4, MU_MIN);
            d->history[d->next++ % GB_SOLVER_HISTORY] = m0;
            return GB_OK;
        }
        gb_sim_state_restore(sim, &s->trial);
        gb_gem_forces(sim);
        d->mu = fmin(d->mu * 8, MU_MAX);
    }
}
