/* The global solver's Newton iteration with a line search (solver.newton: line_search).
 *
 * The direction is Newton's on the exact tangent (assemble.c: sliding contacts and the
 * contacts' rotation included), solved once per iteration. Its whole step is taken alone if it
 * lowers the merit (the squared fixing forces) tenfold. If it does not, the step has met contacts
 * that the tangent of the start does not know (grains that must rearrange: contacts that open,
 * close or slide), and the inertial smoother, which sees them at every step (inertial.c:
 * FIRE on the reference moves, K 9-12), moves the grains, boundary particles and servo walls until
 * the merit has fallen to a millionth, from the whole step's end if that lowered the merit at all,
 * else from the iteration's start. Newton resumes from there. Only where the smoother does not
 * lower the merit either (in its 5 000 steps) is the step shortened by backtracking (every trial
 * from the iteration's start, so that the merit along the direction is a function of the length
 * alone: the incremental law, K 6 and 13, sees one move).
 * Measured (docs/solver-design.md; the 1e3 path from one start): the smoother to a thousandth
 * of the merit 58 Newton iterations, to a millionth 30; the jammed 1e4 path 58 -> 39. An inertial
 * smoother needs no shortened lengths first, as Gauss-Seidel sweeps of the unbalanced grains did.
 * Once a whole step has failed the smoother goes first (the next iterations and load steps) and
 * Newton runs only where it stalls: on the jammed 1e4 path of tools/bench_peer.sh every whole step
 * failed, and 36 factorisations, 11.4 s became 2, 7.5 s. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "solver/solver_impl.h"

enum {
    MAX_HALVINGS = 12,  /* a trial length of 1/4096 of Newton's step: the direction is not a descent one */
    MAX_SMOOTHING = 5000 /* smoother steps per stall; the load step's iteration cap bounds the stalls */
};
static const double ARMIJO = 1e-4;   /* sufficient decrease of a shortened step: m1 <= (1 - ARMIJO alpha) m0 */
static const double CONVERGING = 0.1; /* Newton's whole step is taken alone if m1 <= CONVERGING m0 */
static const double SMOOTHED = 1e-6;  /* the smoother stops when the merit (squared) has fallen to this */
static const double FLOPS_PER_PAIR_STEP = 100; /* a smoother step's cost a pair, in a factorisation's flops */

/* Grains, particles and walls moved by alpha times the direction; grains outside the system move
 * by their whole reference move (global.c). */
static void set_move(const gb_solver *s, gb_sim *sim, const double *dir, double alpha)
{
    int n = sim->state.n, np = sim->bp.n;
    for (int i = 0; i < n; i++) {
        double f = s->in_system[i] ? alpha : 1;
        for (int q = 0; q < 3; q++) sim->scratch.dX[3 * i + q] = f * dir[3 * i + q];
    }
    for (int k = 0; k < 2 * np; k++) sim->bp.dx[k] = alpha * dir[3 * n + k];
    for (int k = 0; k < 2 * GB_N_WALLS; k++) (&sim->scratch.wall_dx[0][0])[k] = alpha * dir[3 * n + 2 * np + k];
}

/* Applies the move in sim->scratch.dX, bp.dx and wall_dx, and evaluates the forces after it. */
static gb_status take_move(gb_sim *sim, gb_error *err)
{
    sim->state.acc.relaxation -= 0.5 * gb_gem_fixing_work(sim);
    sim->state.acc.half_pending = 1;
    return gb_gem_move_and_forces(sim, err);
}

/* Tries lengths 1/2^first .. 1/2^last of Newton's step, every trial from the iteration's start;
 * *found is set at the first whose merit passes Armijo's rule (the move then taken). */
static gb_status backtrack(gb_solver *s, gb_sim *sim, const gb_wall_control *wc, double m0, const double *dir, int first, int last,
                           int *found, gb_error *err)
{
    *found = 0;
    double alpha = ldexp(1, -first);
    for (int h = first; h <= last; h++, alpha *= 0.5) {
        set_move(s, sim, dir, alpha);
        s->work.trials++;
        gb_status st = take_move(sim, err);
        if (st) return st;
        if (gb_gem_merit(sim, s->in_system, gb_gem_wall_moves(sim, wc)) <= (1 - ARMIJO * alpha) * m0) {
            s->length = alpha;
            *found = 1;
            return GB_OK;
        }
        gb_sim_state_restore(sim, &s->trial);
        gb_gem_forces(sim);
    }
    return GB_OK;
}

/* What a factorisation with its solve costs, in smoother steps: its flops over FLOPS_PER_PAIR_STEP
 * a candidate pair (0 where the linear solver does not count its flops: PETSc). The smoother's
 * step is an evaluation of every pair; on the 1e4-disc path of tools/bench_peer.sh (2-core AMD
 * EPYC, one thread) a factorisation (3.6e8 flops) with its solve and assembly took about 0.15 s and
 * a smoother step 1.1 ms for 24 500 pairs: about 150 flops a pair. 100 errs towards the smoother. */
static double factorisation_in_smoother_steps(const gb_solver *s, const gb_sim *sim)
{
    const gb_global_stats *g = gb_global_statistics(s->global);
    int pairs = sim->state.pairs.n;
    return g && g->factor_flops > 0 && pairs > 0 ? g->factor_flops / (FLOPS_PER_PAIR_STEP * pairs) : 0;
}

gb_status gb_solver_line_search_move(gb_solver *s, gb_sim *sim, const gb_wall_control *wc, double m0,
                                     gb_error *err)
{
    int n = sim->state.n, np = sim->bp.n, found, stalled;
    gb_solver_damping *d = &s->damping;
    gb_status st;
    /* While Newton's whole steps fail, the smoother goes first and Newton only where it stalls. */
    if (d->smoother_first > 0 && !d->newton_due) {
        s->length = 0;
        /* checked at least once a stretch: beyond it no check would ever be made, and a smoother
         * stuck short of its target ran stretch after stretch without Newton (an L-shaped
         * cavity's step: 30 stretches at 250 times the accuracy, docs/solver-design.md) */
        double check = fmin(ldexp(d->smoother_first, d->newton_failures), MAX_SMOOTHING / 2);
        st = gb_solver_inertial(s, sim, wc, SMOOTHED * m0, MAX_SMOOTHING, check, &stalled, err);
        d->newton_due = stalled;
        return st;
    }
    d->newton_due = 0;
    /* The smallest damping: Newton's direction (the system regularises only a singular matrix). */
    st = gb_global_moves(s->global, sim, s->in_system, wc, 0, err);
    if (st) return st;
    double *dir = s->direction;
    memcpy(dir, sim->scratch.dX, 3 * (size_t)n * sizeof(double));
    if (np) memcpy(dir + 3 * n, sim->bp.dx, 2 * (size_t)np * sizeof(double));
    memcpy(dir + 3 * n + 2 * np, sim->scratch.wall_dx, sizeof sim->scratch.wall_dx);
    /* Newton's whole step, alone if it converges (the merit falls tenfold: with Armijo's rule
     * alone, on the perturbed 1e4 protocol packing's friction relaxation, 33 whole steps each
     * lowered the merit by a few per cent and left the largest force at 2e6 dyn). */
    set_move(s, sim, dir, 1);
    s->work.trials++;
    if ((st = take_move(sim, err))) return st;
    double m1 = gb_gem_merit(sim, s->in_system, gb_gem_wall_moves(sim, wc));
    if (m1 <= CONVERGING * m0) {
        s->length = 1;
        d->smoother_first = 0, d->newton_failures = 0;
        return GB_OK;
    }
    /* A failed whole step wasted its factorisation: from the next iteration on (and in the next
     * load steps) the smoother goes first, checked for a stall every so many steps as cost about
     * one factorisation, times 2^k after k failures in this relaxation (so that the
     * factorisations of failed steps cost at most about what the smoother does). A failure says
     * the next whole step on this packing, still rearranging, is likely to fail too, so the
     * doubling starts at the first: the 1e6 peer relaxation (docs/benchmarks.md)
     * tried a second whole step after 2 043 smoother steps, which failed, and the smoother
     * finished 540 steps later; with 4 086 it finished without it (463 -> 268 s). A new
     * relaxation starts from one factorisation's cost again: Newton's steps may work there (a
     * loose packing pressed in 5 steps: after 10 failures in the first, the later steps' stall
     * checks came too seldom for Newton to be tried, 63 699 smoother steps against 14 025). */
    double cost = factorisation_in_smoother_steps(s, sim);
    if (cost > 0) d->smoother_first = cost, d->newton_failures++;
    /* If not, the step met contacts that its tangent did not know: the smoother, which knows them
     * at every step, from the step's end if it lowered the merit at all, else from its start. */
    if (!(m1 < m0)) {
        gb_sim_state_restore(sim, &s->trial);
        gb_gem_forces(sim);
    }
    s->length = 0;
    if ((st = gb_solver_inertial(s, sim, wc, SMOOTHED * m0, MAX_SMOOTHING, 0, &stalled, err))) return st;
    if (gb_gem_merit(sim, s->in_system, gb_gem_wall_moves(sim, wc)) <= (1 - ARMIJO) * m0) return GB_OK;
    /* The smoother did not lower the merit either: a shorter Newton step, and if none lowers the
     * merit, the smoother's configuration after all (kept, not smoothed again: a deposit settling
     * under its weight, where Newton's steps raise the merit 1e2-1e6 times and the smoother's
     * merit rises and falls as the grains rearrange, spent a third of its smoother steps on such
     * repeats: tools/settle_packing.sh's 1e3 discs 85 866 steps -> 60 433, the same state;
     * docs/solver-design.md). */
    if ((st = gb_sim_state_save(sim, &s->smoothed, err))) return st;
    gb_sim_state_restore(sim, &s->trial);
    gb_gem_forces(sim);
    if ((st = backtrack(s, sim, wc, m0, dir, 1, MAX_HALVINGS, &found, err)) || found) return st;
    s->length = 0;
    gb_sim_state_restore(sim, &s->smoothed);
    gb_gem_forces(sim);
    /* as the smoother leaves them: no move pending (its fixing work is accounted) */
    memset(sim->scratch.dX, 0, 3 * (size_t)n * sizeof(double));
    if (np) memset(sim->bp.dx, 0, 2 * (size_t)np * sizeof(double));
    memset(sim->scratch.wall_dx, 0, sizeof sim->scratch.wall_dx);
    return GB_OK;
}
