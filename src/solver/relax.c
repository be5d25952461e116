/* A solve: the relaxation loop, by the reference iteration or the global solver, and the solver's
 * life and accounts. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "solver/solver_impl.h"

void gb_solver_free(gb_solver *s)
{
    if (!s) return;
    gb_global_free(s->global);
    free(s->in_system);
    gb_state_free(&s->trial), gb_state_free(&s->smoothed);
    free(s->direction), free(s->velocity), free(s->acceleration), free(s->block_sums);
    free(s);
}

gb_status gb_solver_create(gb_sim *sim, const gb_solver_settings *set, gb_error *err)
{
    gb_solver_free(sim->solver);
    sim->solver = NULL;
    gb_solver *s = calloc(1, sizeof *s);
    if (!s) return gb_fail(err, GB_ENOMEM, "out of memory");
    s->set = set;
    s->damping.mu = GB_SOLVER_MU_START;
    s->damping.best = INFINITY; /* reset at every relaxation: a restart needs no more */
    const gb_solver_state *from = &sim->scene->restart.solver;
    if (from->present) { /* a restart continues the damping of the run it continues */
        s->damping.mu = from->mu;
        memcpy(s->damping.history, from->history, sizeof s->damping.history);
        s->damping.next = from->next;
        s->damping.smoother_first = from->smoother_first, s->damping.newton_due = from->newton_due;
    }
    size_t n = (size_t)sim->state.n + 1, np = (size_t)sim->bp.n;
    gb_status st = GB_OK;
    int ok = 1;
    if (set->method == GB_METHOD_GLOBAL) {
        st = gb_global_create(set, sim->state.n, sim->bp.n, &s->global, err);
        ok = (s->in_system = calloc(n, 1)) != NULL;
        if (set->newton == GB_NEWTON_LINE_SEARCH) {
            s->direction = malloc((3 * n + 2 * np + 2 * GB_N_WALLS) * sizeof(double));
            s->velocity = malloc((3 * n + 2 * np) * sizeof(double));
            s->acceleration = malloc((3 * n + 2 * np) * sizeof(double));
            s->block_sums = malloc(GB_SMOOTHER_SUMS * (size_t)gb_smoother_blocks((int)n) * sizeof(double));
            ok = ok && s->direction && s->velocity && s->acceleration && s->block_sums;
        }
    }
    if (!st && !ok) st = gb_fail(err, GB_ENOMEM, "out of memory for the global solver of %d grains", sim->state.n);
    if (st) {
        gb_solver_free(s);
        return st;
    }
    sim->solver = s;
    return GB_OK;
}

/* An iteration of the global solver, from the current forces. */
static gb_status global_move(gb_solver *s, gb_sim *sim, const gb_wall_control *wc, double wall_residual,
                             gb_error *err)
{
    gb_solver_mark_system(s, sim);
    double m0 = gb_gem_merit(sim, s->in_system, wall_residual);
    gb_status st = gb_sim_state_save(sim, &s->trial, err);
    if (st) return st;
    if (s->set->newton == GB_NEWTON_LINE_SEARCH) return gb_solver_line_search_move(s, sim, wc, m0, err);
    return gb_solver_damped_move(s, sim, wc, m0, err);
}

/* solver.history: what iteration `it` of this relaxation did, from `sweeps0` smoother steps. */
static void report_iteration(gb_sim *sim, long it, double max_force, double wall_residual, long sweeps0)
{
    const gb_solver *s = sim->solver;
    const gb_relax_context *c = s->ctx;
    double move = 0;
    for (int i = 0; i < sim->state.n; i++)
        move = fmax(move, hypot(sim->scratch.dX[3 * i], sim->scratch.dX[3 * i + 1]) / sim->state.g[i].r);
    int global = s->global != NULL, line_search = s->set->newton == GB_NEWTON_LINE_SEARCH;
    gb_iteration_report r = {c->step, *c->attempt, it, max_force, wall_residual, move,
                             global && !line_search ? s->damping.mu : 0, global && line_search ? s->length : 0,
                             s->work.sweeps - sweeps0, 0};
    c->on_iteration(c->on_iteration_user, &r);
}

void gb_solver_report_smoother(const gb_solver *s, gb_sim *sim, double wall_residual)
{
    const gb_relax_context *c = s->ctx;
    if (!c->on_iteration) return;
    double f2 = fmax(gb_gem_largest_grain_force2(sim), gb_gem_largest_particle_force2(sim));
    gb_iteration_report r = {c->step, *c->attempt, *c->iterations + 1, sqrt(f2), wall_residual, 0,
                             0, 0, s->work.sweeps - s->sweeps0, 1};
    c->on_iteration(c->on_iteration_user, &r);
}

/* The stall window: a relaxation stalls when its largest fixing force (or the walls' residual) has
 * not fallen below STALL_FALL times its value at the last such fall (at the start: its first
 * value) for STALL_RATIO times the work it had done then, and at least STALL_WORK (iterations
 * plus smoother steps). Relative to the work already done, so that a relaxation that keeps
 * converging, however slowly, goes on, while one that cycles or wanders ends in a bounded time
 * whatever solver.max_iterations says, and the step is cut back (src/run/program.c). Measured
 * (the longest wait for a fall in relaxations that converge): a loose 30-disc deposit pressed
 * isotropically by the reference iteration waited 50 000 iterations from its start, then 1.5 times
 * its work; the damped global solver on tests/hard's 50 % overlap case 168 000 iterations. Three
 * discs with alpha = 1.5 (the reference iteration unstable: its largest force wanders between 1e4
 * and 3e5 dyn) stall at about 250 000 iterations, where max_iterations 2e9 would take
 * hours. */
enum { STALL_WORK = 200000, STALL_RATIO = 4 };
static const double STALL_FALL = 0.5;

gb_solver_work gb_solver_relaxation_work(const gb_sim *sim)
{
    const gb_solver *s = sim->solver;
    gb_solver_work w = gb_solver_work_done(sim);
    w.trials -= s->relax_work.trials, w.factorisations -= s->relax_work.factorisations;
    w.sweeps -= s->relax_work.sweeps;
    return w;
}

/* The load step's work so far (its iterations plus the smoother's steps), the unit of the stall
 * window. */
static long step_work(const gb_sim *sim)
{
    const gb_relax_context *c = sim->solver->ctx;
    return c->step_iterations + *c->iterations + c->step_sweeps + gb_solver_relaxation_work(sim).sweeps;
}

static int stalled(gb_solver_damping *d, const gb_sim *sim, double force)
{
    long w = step_work(sim) - d->relax_work0;
    if (!(force > STALL_FALL * d->stall_ref)) {
        d->stall_ref = force, d->stall_at = w;
        return 0;
    }
    long window = STALL_RATIO * d->stall_at > STALL_WORK ? STALL_RATIO * d->stall_at : STALL_WORK;
    return w - d->stall_at > window;
}

gb_status gb_solver_poll(gb_solver *s, gb_sim *sim, double max_force)
{
    const gb_relax_context *c = s->ctx;
    if (!c->poll) return GB_OK;
    gb_solve_stop stop = c->poll(c->poll_user, c->step_sweeps + gb_solver_relaxation_work(sim).sweeps, max_force);
    if (stop == GB_STOP_CONVERGED) return GB_OK;
    s->stop = stop;
    return GB_ENOCONV;
}

gb_status gb_solver_relax(gb_sim *sim, const gb_wall_control *wc, long cap, gb_solve_result *res, gb_error *err)
{
    int attempt = 0;
    long iterations = 0;
    gb_relax_context own = {.step = 1, .attempt = &attempt, .iterations = &iterations,
                            .on_iteration = sim->solver->on_iteration, .on_iteration_user = sim->solver->on_iteration_user};
    return gb_solver_relax_within(sim, wc, cap, &own, res, err);
}

void gb_solver_on_iteration(gb_sim *sim, gb_iteration_fn fn, void *user)
{
    sim->solver->on_iteration = fn;
    sim->solver->on_iteration_user = user;
}

gb_status gb_solver_relax_within(gb_sim *sim, const gb_wall_control *wc, long cap, const gb_relax_context *ctx,
                                 gb_solve_result *res, gb_error *err)
{
    gb_solver *s = sim->solver;
    gb_solver_damping *d = &s->damping;
    double t0 = gb_clock_seconds(), *max_force = &res->max_force, *wall_residual = &res->wall_residual;
    *max_force = *wall_residual = 0;
    s->relax_work = gb_solver_work_done(sim);
    s->ctx = ctx;
    long it = *ctx->iterations;
    if (!it) {
        ++*ctx->attempt;
        d->best = INFINITY, d->since = 0; /* the damped iteration's stall detection */
        d->newton_failures = 0;           /* the line search's, within a relaxation */
        d->stall_ref = INFINITY, d->stall_at = 0, d->relax_work0 = step_work(sim);
    }
    s->stop = GB_STOP_ERROR;
    gb_status st = GB_OK;
    for (; it <= cap; it++) {
        if (gb_gem_balance(sim, wc, max_force, wall_residual, err, &st)) {
            s->stop = GB_STOP_CONVERGED;
            break;
        }
        if (st) break;
        if (stalled(d, sim, fmax(*max_force, *wall_residual))) {
            s->stop = GB_STOP_STALLED, st = GB_ENOCONV;
            break;
        }
        if ((s->global || it % GB_POLL_SWEEPS == 0) && (st = gb_solver_poll(s, sim, *max_force))) break;
        /* Every grain's move from the same configuration, then all at once (order-independent). */
        s->sweeps0 = s->work.sweeps;
        st = s->global ? global_move(s, sim, wc, *wall_residual, err) : gb_gem_reference_move(sim, err);
        if (st) break;
        if (ctx->on_iteration) report_iteration(sim, it + 1, *max_force, *wall_residual, s->sweeps0);
        *ctx->iterations = it + 1;
        /* not after the last iteration allowed: its failed attempt is undone at once */
        if (it < cap && ctx->between && (st = ctx->between(ctx->between_user, err))) {
            it++;
            break;
        }
    }
    *ctx->iterations = 0;
    if (it > cap) {
        it = cap;
        s->stop = GB_STOP_ITERATIONS, st = GB_ENOCONV;
    }
    res->stop = s->stop;
    res->iterations = it;
    res->work = gb_solver_relaxation_work(sim);
    s->relax_work = gb_solver_work_done(sim); /* none in progress now */
    s->ctx = NULL;
    res->seconds = gb_clock_seconds() - t0;
    return st;
}

gb_solver_work gb_solver_work_done(const gb_sim *sim)
{
    const gb_solver *s = sim->solver;
    gb_solver_work w = s->work;
    if (s->global) w.factorisations = gb_global_statistics(s->global)->factorisations;
    return w;
}

const gb_global_stats *gb_solver_statistics(const gb_sim *sim)
{
    return sim->solver->global ? gb_global_statistics(sim->solver->global) : NULL;
}

int gb_solver_is_global(const gb_sim *sim) { return sim->solver->global != NULL; }

gb_solver_damping *gb_solver_damping_of(const gb_sim *sim) { return &sim->solver->damping; }

int gb_solver_predicts_strain(const gb_sim *sim)
{
    return sim->solver->global && sim->solver->set->newton == GB_NEWTON_LINE_SEARCH;
}

const unsigned char *gb_solver_unloading(const gb_sim *sim)
{
    return sim->solver->global ? gb_global_unloading(sim->solver->global, &sim->state.pairs) : NULL;
}

gb_status gb_solver_resume(gb_sim *sim, const unsigned char *unloading, gb_error *err)
{
    return sim->solver->global ? gb_global_resume(sim->solver->global, &sim->state.pairs, unloading, err) : GB_OK;
}
