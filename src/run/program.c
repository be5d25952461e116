/* The loading program of a simulation: its stages' load steps, cut back when they do not converge,
 * each step's work and report; a step in progress is held in sim->cur, so that a run resumed from
 * a checkpoint within it (src/io/checkpoint.c) goes on from there. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/clock.h"
#include "gembem/run.h"
#include "io/run_output.h"
#include "measure/step_measures.h"
#include "run/loads.h"
#include "run/step_failure.h"
#include "solver/solver.h"

static void save_state(gb_sim *sim, gb_error *err, gb_status *st)
{
    *st = gb_sim_state_save(sim, &sim->saved, err);
}

/* From now on the run's time goes to `phase`, one of sim->profile's fields (NULL: none, between
 * two calls of the library); the time since the last switch to the one before. So every second of
 * a run is in exactly one phase, each timed where it starts. */
static void enter(gb_sim *sim, double *phase)
{
    double now = gb_clock_seconds();
    if (sim->phase) *sim->phase += now - sim->phase_since;
    sim->phase = phase, sim->phase_since = now;
}

/* External work of a converged step, as a quasi-static test measures it: the walls' mean force at
 * the start and the end of the step times their inward displacement, and the body forces times
 * the grains' displacement (the saved state is the start of the step; sim->state.wall_force and
 * sim->saved.wall_force hold the converged forces). */
static void add_step_work(gb_sim *sim)
{
    const gb_box *a = &sim->saved.box, *b = &sim->state.box;
    double inward[GB_N_WALLS] = {b->left - a->left, a->right - b->right, b->bottom - a->bottom, a->top - b->top};
    for (int w = 0; w < GB_N_WALLS; w++)
        sim->work_walls += 0.5 * (sim->saved.wall_force[w] + sim->state.wall_force[w]) * inward[w];
    for (int i = 0; i < sim->state.n; i++)
        sim->work_body += sim->body[2 * i] * (sim->state.g[i].x - sim->saved.g[i].x) +
                          sim->body[2 * i + 1] * (sim->state.g[i].y - sim->saved.g[i].y);
}

/* Back to a saved state, with its forces. */
static void restore_state(gb_sim *sim, const gb_state *state)
{
    gb_sim_state_restore(sim, state);
    gb_gem_forces(sim);
}

/* The step's state and error; residual: the walls' under stress control, NaN where walls are not
 * stress-controlled (strain, relax, hosts). */
static void fill_report(gb_sim *sim, gb_step_report *r, double residual)
{
    gb_sim_step_error(sim, r);
    r->force_scale = sim->force_scale;
    r->accuracy = sim->accuracy;
    r->wall_residual = residual;
    r->n_contacts = gb_sim_contacts(sim, NULL, 0);
    if (sim->host) {
        /* no walls: the box's quantities are not the host's (its load curve: host_steps.csv) */
        r->s1 = r->s2 = r->e1 = r->e2 = r->ev = r->stress_ratio = r->width = r->height = NAN;
        return;
    }
    gb_gem_stress(sim, &r->s1, &r->s2);
    gb_gem_strain(sim, &r->e1, &r->e2);
    r->ev = r->e1 + r->e2;
    double sum = r->s1 + r->s2;
    r->stress_ratio = sum != 0 ? (r->s1 - r->s2) / sum : 0;
    r->width = sim->state.box.right - sim->state.box.left;
    r->height = sim->state.box.top - sim->state.box.bottom;
}

/* Whether a stage's walls are under stress control, where their residual is part of the test. */
static int stress_controlled(const gb_stage *sg)
{
    gb_stage_kind k = sg->kind;
    return k == GB_STAGE_ISOTROPIC || k == GB_STAGE_BIAXIAL_STRESS || k == GB_STAGE_SHEAR_MEAN ||
           (k == GB_STAGE_RELAX && sg->mean_stress > 0);
}

/* The solve phase: a relaxation of the sub-step in progress, what it did in *res and added to the
 * step's (sim->cur). */
static gb_status relax(gb_sim *sim, const gb_wall_control *wc, long cap, gb_solve_result *res, gb_error *err)
{
    enter(sim, &sim->profile.solve);
    gb_status st = gb_solver_relax(sim, wc, cap, res, err);
    enter(sim, &sim->profile.control);
    sim->cur.phase_iters += res->iterations;
    sim->cur.work = gb_solver_work_plus(sim->cur.work, res->work);
    return st;
}

/* The sub-step in progress (sim->cur: from fraction t to t + h of the step's increment; the whole
 * step: t = 0, h = 1): its loads, unless a checkpoint within it has them applied already, then
 * relaxation to equilibrium; shear_mean_stress relaxes with the walls held, then restores the mean
 * stress by an isotropic strain under stress control (K section 2.6). */
static gb_status load_step(gb_sim *sim, const gb_stage *sg, gb_solve_result *res, gb_error *err)
{
    gb_sim_step *c = &sim->cur;
    long cap = sim->scene->solver.max_iterations;
    gb_wall_control wc = {GB_WALLS_FIXED, 0, 0, 0};
    gb_status st;
    if (c->phase == GB_PHASE_LOAD) {
        if ((st = gb_run_apply_loads(sim, sg, c->h, err))) return st;
        c->phase = GB_PHASE_RELAX;
    }
    double f = (c->stage_step - 1 + c->t + c->h) / sg->steps;
    switch (sg->kind) {
    case GB_STAGE_ISOTROPIC:
        wc.mode = GB_WALLS_STRESS;
        wc.s1 = c->start[0] + (sg->stress - c->start[0]) * f;
        wc.s2 = c->start[1] + (sg->stress - c->start[1]) * f;
        break;
    case GB_STAGE_BIAXIAL_STRESS:
        wc.mode = GB_WALLS_STRESS;
        wc.s1 = c->start[0] + (sg->s1 - c->start[0]) * f;
        wc.s2 = c->start[1] + (sg->s2 - c->start[1]) * f;
        break;
    case GB_STAGE_SHEAR_MEAN:
        if (c->phase == GB_PHASE_RELAX) {
            if ((st = relax(sim, &wc, cap, res, err))) return st;
            c->phase = GB_PHASE_MEAN;
        }
        wc.mode = GB_WALLS_MEAN;
        wc.mean = sg->mean_stress;
        break;
    case GB_STAGE_RELAX: /* a packing's equilibrium at its target stress (src/pack/pack.c) */
        if (sg->mean_stress > 0) wc.mode = GB_WALLS_MEAN, wc.mean = sg->mean_stress;
        break;
    default: break;
    }
    /* a whole step only: a cut-back's sub-steps of a ramp from zero can start below the weight,
     * where the step they split was above it (they fail as not converged, as before) */
    if (c->h == 1 && (st = gb_run_weight_reachable(sim, sg, &wc, err))) return st;
    return relax(sim, &wc, cap - c->phase_iters, res, err);
}

/* The step in progress (sim->cur). A step that does not converge is cut back, as nonlinear finite
 * element codes do: taken again from its start in two halves, a half that fails in two quarters,
 * and so on down to 1/2^cutbacks of the step (solver.cutbacks). The granular path is
 * path-dependent, so a smaller sub-step is a finer, not a different, loading; a stall of the global
 * solver (a grain that must roll out of a squeeze, a slip that moves many grains) can be a load
 * step too large for one Newton path. Leaves the iterations of all attempts, the sub-steps taken
 * and the finest sub-step tried in sim->cur. */
static gb_status cut_back_step(gb_sim *sim, const gb_stage *sg, gb_solve_result *res, gb_error *err)
{
    gb_sim_step *c = &sim->cur;
    gb_status st;
    for (;;) {
        /* the sub-step's start (one resumed within has it from its checkpoint) */
        if (c->phase == GB_PHASE_LOAD && c->cuts > 0 && (st = gb_sim_state_save(sim, &sim->substep, err))) return st;
        st = load_step(sim, sg, res, err);
        c->iters += c->phase_iters;
        c->phase = GB_PHASE_LOAD, c->phase_iters = 0;
        c->finest = c->h;
        /* past the step's time limit a cut-back would only take longer */
        gb_solve_stop stop = res->stop;
        if (st == GB_ENOCONV && c->cut_by == GB_STOP_CONVERGED) c->cut_by = stop;
        if (st == GB_ENOCONV && c->cuts > 0 && stop != GB_STOP_TIME) {
            restore_state(sim, &sim->substep);
            c->cuts--;
            c->h /= 2;
            continue;
        }
        if (st) return st;
        c->substeps++;
        c->t += c->h; /* sums of powers of two: exact */
        if (c->t >= 1) return GB_OK;
        if (c->h > 1 - c->t) c->h = 1 - c->t;
    }
}

void gb_sim_on_iteration(gb_sim *sim, gb_iteration_fn fn, void *user)
{
    sim->on_iteration = fn;
    sim->on_iteration_user = user;
}

void gb_sim_on_within_step(gb_sim *sim, gb_within_step_fn fn, void *user)
{
    sim->on_within_step = fn;
    sim->on_within_step_user = user;
}

gb_run_profile gb_sim_profile(const gb_sim *sim) { return sim->profile; }

/* The measure and output phases of a step (or of the initial state, step 0), its report made: with
 * an output the step's measures from its start (the saved state, not yet replaced by the end) and
 * end, its files, then on_step. */
static gb_status measure_and_output(gb_sim *sim, gb_run_output *out, gb_step_fn on_step, void *user,
                                    const gb_step_report *rep, gb_error *err)
{
    gb_status st = GB_OK;
    gb_step_measures m;
    memset(&m, 0, sizeof m);
    enter(sim, &sim->profile.measure);
    if (out)
        st = gb_step_measure(&sim->saved, sim, rep->step, gb_run_output_fields_due(out, rep->step),
                             sim->scene->localisation, &m, err);
    enter(sim, &sim->profile.output);
    if (!st && out) st = gb_run_output_step(out, sim, rep, &m, err);
    gb_step_measures_free(&m);
    if (!st && on_step) st = on_step(user, sim, rep, err);
    return st;
}

/* The output's hooks within a step (checkpoints, solver.history), for the calls that write into it. */
static void output_hooks(gb_sim *sim, gb_run_output *out, int on)
{
    if (!out) return;
    gb_sim_on_within_step(sim, on ? gb_run_output_within_step : NULL, on ? out : NULL);
    if (sim->scene->solver.history) gb_sim_on_iteration(sim, on ? gb_run_output_iteration : NULL, on ? out : NULL);
}

/* Where the program goes on from, the one place that reads a resume: a new run from its initial
 * state (step 0); a run resumed from a checkpoint (src/io/checkpoint.c) within the step in progress
 * (sim->cur, whose start is in sim->saved) until that step is done; otherwise the step after the
 * last completed one (sim->pos: a resumed run's outputs, energy0 and stage's start are those of the
 * run it continues). */
typedef enum { START_NEW, START_WITHIN, START_AFTER } start_point;
static start_point start_of(const gb_sim *sim)
{
    if (!sim->begun && !sim->pos.resume) return START_NEW;
    return sim->pos.resume && sim->cur.active ? START_WITHIN : START_AFTER;
}

/* The program's start (start_of): a new run's initial state (step 0: its report in *rep, and its
 * output and on_step), or a resumed run's place. */
static gb_status begin(gb_sim *sim, gb_run_output *out, gb_step_fn on_step, void *user, gb_step_report *rep,
                       gb_error *err)
{
    gb_status st = GB_OK;
    enter(sim, &sim->profile.measure); /* the initial report */
    memset(rep, 0, sizeof *rep);
    rep->stage = -1;
    rep->total_steps = gb_scene_total_steps(sim->scene);
    gb_sim_resolve_accuracy(sim, sim->state.pairs.p, sim->state.pairs.n, 0);
    fill_report(sim, rep, NAN);
    start_point from = start_of(sim);
    if (from == START_NEW) {
        memset(&sim->pos, 0, sizeof sim->pos);
        sim->energy0 = gb_sim_elastic_energy(sim);
    }
    if (from != START_WITHIN) save_state(sim, err, &st);
    if (!st && from == START_NEW) st = measure_and_output(sim, out, on_step, user, rep, err);
    sim->begun = !st;
    return st;
}

/* The stage s and the number k in it of the load step after the last completed (sim->pos);
 * s = n_stages when there is none. */
static void next_place(const gb_sim *sim, int *s, int *k)
{
    *s = sim->pos.stage, *k = sim->pos.stage_step + 1;
    while (*s < sim->scene->n_stages && *k > sim->scene->stages[*s].steps) ++*s, *k = 1;
}

/* Whether the loading program has no step left (a step resumed within is one). */
static int finished(const gb_sim *sim)
{
    int s, k;
    next_place(sim, &s, &k);
    return start_of(sim) != START_WITHIN && s >= sim->scene->n_stages;
}

/* Where the next load step starts (there is one: !finished), into sim->cur: the step a checkpoint
 * was taken within, as the checkpoint left it; else the step after the last completed one, from its
 * start (at its stage's start: the strain reference and the start stresses of a stress ramp). Its
 * stage. */
static const gb_stage *start_step(gb_sim *sim)
{
    const gb_scene *sc = sim->scene;
    if (start_of(sim) == START_WITHIN) return &sc->stages[sim->cur.stage];
    int s, k;
    double start[2];
    next_place(sim, &s, &k);
    const gb_stage *sg = &sc->stages[s];
    if (k == 1) {
        if (sg->reset_strain) {
            sim->ref_width = sim->state.box.right - sim->state.box.left;
            sim->ref_height = sim->state.box.top - sim->state.box.bottom;
        }
        gb_gem_forces(sim);
        gb_gem_stress(sim, &start[0], &start[1]);
    } else memcpy(start, sim->pos.start, sizeof start);
    gb_sim_step c = {.active = 1, .stage = s, .stage_step = k, .step = sim->pos.step + 1,
                     .start = {start[0], start[1]}, .h = 1, .cuts = sg->kind == GB_STAGE_RELAX ? 0 : sc->solver.cutbacks,
                     .finest = 1, .phase = GB_PHASE_LOAD};
    sim->cur = c;
    sim->attempt = 0;
    return sg;
}

/* The control and solve phases of the step in progress (sim->cur), from its start (the saved
 * state): its accuracy, then its loads and relaxations, cut back where they fail. */
static gb_status solve_step(gb_sim *sim, const gb_stage *sg, gb_solve_result *res, gb_error *err)
{
    gb_sim_resolve_accuracy(sim, sim->saved.pairs.p, sim->saved.pairs.n, sim->cur.stage);
    if (!(sim->accuracy > 0))
        return gb_fail(err, GB_ENUMERIC, "the relative accuracy has no force scale: the step starts with no "
                       "contact force, and no body force or stress target loads the grains; give "
                       "solver.accuracy as a force");
    return cut_back_step(sim, sg, res, err);
}

/* The measure phase's start for a converged step begun at t0: its report, the external work, the
 * run's place. */
static gb_status step_done(gb_sim *sim, const gb_stage *sg, const gb_solve_result *res, double t0,
                           gb_step_report *rep, gb_error *err)
{
    const gb_sim_step *c = &sim->cur;
    rep->stage = c->stage;
    rep->step = c->step;
    rep->total_steps = gb_scene_total_steps(sim->scene);
    rep->iterations = c->iters;
    rep->substeps = c->substeps;
    rep->work = c->work;
    rep->cut_by = c->cut_by;
    fill_report(sim, rep, stress_controlled(sg) ? res->wall_residual : NAN);
    add_step_work(sim);
    rep->seconds = gb_clock_seconds() - t0;
    gb_sim_position at = {c->stage, c->stage_step, c->step, {c->start[0], c->start[1]}, 0};
    sim->pos = at;
    return gb_sim_watch_done(sim, rep->seconds) ? gb_fail(err, GB_ENOMEM, "out of memory") : GB_OK;
}

/* The next load step (there is one: !finished): control, solve, measure, output; its report in
 * *rep. A step that fails leaves the state of the last completed one. */
static gb_status next_step(gb_sim *sim, gb_run_output *out, gb_step_fn on_step, void *user, gb_step_report *rep,
                           gb_error *err)
{
    enter(sim, &sim->profile.control);
    double t0 = gb_clock_seconds();
    const gb_stage *sg = start_step(sim);
    gb_sim_watch_step(sim, t0);
    gb_solve_result res = {0};
    gb_status st = solve_step(sim, sg, &res, err);
    sim->cur.active = 0;
    sim->iterations_total += sim->cur.iters;
    sim->watch.t0 = 0; /* no step is watched until the next starts */
    if (st) {
        st = gb_run_step_failed(sim, sg, st, &res, err);
        restore_state(sim, &sim->saved);
        return st;
    }
    enter(sim, &sim->profile.measure);
    st = step_done(sim, sg, &res, t0, rep, err);
    /* measure and output see the step's start in the saved state; then it becomes the next's */
    if (!st) st = measure_and_output(sim, out, on_step, user, rep, err);
    /* with an output, gb_run_output_step has checked for a stop (and checkpointed) */
    if (!st && !out && gb_run_stop_requested()) {
        char name[32];
        st = gb_fail(err, GB_EINTERRUPTED, "interrupted by %s after step %d",
                     gb_run_signal_name(gb_run_stop_requested(), name, sizeof name), rep->step);
    }
    enter(sim, &sim->profile.control);
    if (!st) save_state(sim, err, &st);
    return st;
}

gb_status gb_sim_run(gb_sim *sim, gb_run_output *out, gb_step_fn on_step, void *user, gb_error *err)
{
    gb_step_report rep;
    output_hooks(sim, out, 1);
    gb_status st = begin(sim, out, on_step, user, &rep, err);
    while (!st && !finished(sim)) st = next_step(sim, out, on_step, user, &rep, err);
    enter(sim, NULL);
    output_hooks(sim, out, 0); /* they end with the run: the caller closes (frees) the output next */
    return st;
}

gb_status gb_sim_advance(gb_sim *sim, gb_run_output *out, gb_step_report *rep, gb_error *err)
{
    gb_status st = GB_OK;
    output_hooks(sim, out, 1);
    int fresh = start_of(sim) == START_NEW; /* a new run's first step is step 0; a resumed run's, the next */
    if (!sim->begun) st = begin(sim, out, NULL, NULL, rep, err);
    if (!st && !fresh) {
        if (finished(sim))
            st = gb_fail(err, GB_EINPUT, "the loading program is finished: its %d load steps are taken",
                         gb_scene_total_steps(sim->scene));
        else st = next_step(sim, out, NULL, NULL, rep, err);
    }
    enter(sim, NULL);
    output_hooks(sim, out, 0);
    return st;
}

int gb_sim_finished(const gb_sim *sim) { return sim->begun && finished(sim); }

gb_run_place gb_sim_place(const gb_sim *sim)
{
    const gb_scene *sc = sim->scene;
    gb_run_place p = {-1, -1, 0, 0, gb_scene_total_steps(sc), sc->n_stages};
    if (!sim->begun) return p;
    p.step = sim->pos.step;
    if (p.step > 0) {
        p.stage = sim->pos.stage, p.stage_step = sim->pos.stage_step;
        p.stage_steps = sc->stages[p.stage].steps;
    }
    return p;
}
