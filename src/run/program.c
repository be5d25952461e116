/* A run of a simulation's loading program: its stages' load steps, cut back when they do not
 * converge, each step's work and report; a step in progress is held in the run's progress
 * (run->p.cur), so that a run resumed from a checkpoint within it (src/io/checkpoint.c) goes on
 * from there. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/clock.h"
#include "gembem/run.h"
#include "io/run_output.h"
#include "measure/step_measures.h"
#include "run/loads.h"
#include "run/run.h"
#include "run/step_failure.h"
#include "solver/solver.h"

static void save_state(gb_run *run, gb_error *err, gb_status *st)
{
    *st = gb_sim_state_save(run->sim, &run->p.saved, err);
}

/* From now on the run's time goes to `phase`, one of run->profile's fields (NULL: none, between
 * two calls of the library); the time since the last switch to the one before. So every second of
 * a run is in exactly one phase, each timed where it starts. */
static void enter(gb_run *run, double *phase)
{
    double now = gb_clock_seconds();
    if (run->phase) *run->phase += now - run->phase_since;
    run->phase = phase, run->phase_since = now;
}

/* External work of a converged step, as a quasi-static test measures it: the walls' mean force at
 * the start and the end of the step times their inward displacement, and the body forces times
 * the grains' displacement (the saved state is the start of the step; both states' wall_force
 * hold the converged forces). */
static void add_step_work(gb_run *run)
{
    const gb_sim *sim = run->sim;
    const gb_state *s0 = &run->p.saved, *s1 = &sim->state;
    gb_work_accounts *acc = &run->p.work;
    const gb_box *a = &s0->box, *b = &s1->box;
    double inward[GB_N_WALLS] = {b->left - a->left, a->right - b->right, b->bottom - a->bottom, a->top - b->top};
    for (int w = 0; w < GB_N_WALLS; w++) acc->walls += 0.5 * (s0->wall_force[w] + s1->wall_force[w]) * inward[w];
    for (int i = 0; i < s1->n; i++)
        acc->body += sim->body[2 * i] * (s1->g[i].x - s0->g[i].x) + sim->body[2 * i + 1] * (s1->g[i].y - s0->g[i].y);
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

/* Between two iterations of a relaxation: a checkpoint within the step when one is due
 * (gb_run_output_within_step). */
static gb_status between_iterations(void *user, gb_error *err)
{
    const gb_run *run = user;
    return gb_run_output_within_step(run->out, run->sim, &run->p, err);
}

/* The solve phase: a relaxation of the sub-step in progress, in the run's context (its place, the
 * step's work so far, the hooks); what it did in *res and added to the step's (run->p.cur). */
static gb_status relax(gb_run *run, const gb_wall_control *wc, long cap, gb_solve_result *res, gb_error *err)
{
    gb_run_step *c = &run->p.cur;
    int history = run->out && run->sim->scene->solver.history;
    gb_relax_context ctx = {.step = run->p.pos.step + 1, .attempt = &c->attempt, .iterations = &c->relax_iters,
                            .step_iterations = c->iters + c->phase_iters, .step_sweeps = c->work.sweeps,
                            .on_iteration = history ? gb_run_output_iteration : run->on_iteration,
                            .on_iteration_user = history ? run->out : run->on_iteration_user,
                            .between = run->out ? between_iterations : NULL, .between_user = run,
                            .poll = gb_run_poll, .poll_user = run};
    enter(run, &run->profile.solve);
    gb_status st = gb_solver_relax_within(run->sim, wc, cap, &ctx, res, err);
    enter(run, &run->profile.control);
    c->phase_iters += res->iterations;
    c->work = gb_solver_work_plus(c->work, res->work);
    return st;
}

/* The sub-step in progress (run->p.cur: from fraction t to t + h of the step's increment; the whole
 * step: t = 0, h = 1): its loads, unless a checkpoint within it has them applied already, then
 * relaxation to equilibrium; shear_mean_stress relaxes with the walls held, then restores the mean
 * stress by an isotropic strain under stress control (K section 2.6). */
static gb_status load_step(gb_run *run, const gb_stage *sg, gb_solve_result *res, gb_error *err)
{
    gb_sim *sim = run->sim;
    gb_run_step *c = &run->p.cur;
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
            if ((st = relax(run, &wc, cap, res, err))) return st;
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
    return relax(run, &wc, cap - c->phase_iters, res, err);
}

/* The step in progress (run->p.cur). A step that does not converge is cut back, as nonlinear finite
 * element codes do: taken again from its start in two halves, a half that fails in two quarters,
 * and so on down to 1/2^cutbacks of the step (solver.cutbacks). The granular path is
 * path-dependent, so a smaller sub-step is a finer, not a different, loading; a stall of the global
 * solver (a grain that must roll out of a squeeze, a slip that moves many grains) can be a load
 * step too large for one Newton path. Leaves the iterations of all attempts, the sub-steps taken
 * and the finest sub-step tried in run->p.cur. */
static gb_status cut_back_step(gb_run *run, const gb_stage *sg, gb_solve_result *res, gb_error *err)
{
    gb_sim *sim = run->sim;
    gb_run_step *c = &run->p.cur;
    gb_status st;
    for (;;) {
        /* the sub-step's start (one resumed within has it from its checkpoint) */
        if (c->phase == GB_PHASE_LOAD && c->cuts > 0 && (st = gb_sim_state_save(sim, &run->p.substep, err))) return st;
        st = load_step(run, sg, res, err);
        c->iters += c->phase_iters;
        c->phase = GB_PHASE_LOAD, c->phase_iters = 0;
        c->finest = c->h;
        /* past the step's time limit a cut-back would only take longer */
        gb_solve_stop stop = res->stop;
        if (st == GB_ENOCONV && c->cut_by == GB_STOP_CONVERGED) c->cut_by = stop;
        if (st == GB_ENOCONV && c->cuts > 0 && stop != GB_STOP_TIME) {
            restore_state(sim, &run->p.substep);
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

/* The measure and output phases of a step (or of the initial state, step 0), its report made: with
 * an output the step's measures from its start (the saved state, not yet replaced by the end) and
 * end, its files, then on_step. */
static gb_status measure_and_output(gb_run *run, gb_step_fn on_step, void *user, const gb_step_report *rep,
                                    gb_error *err)
{
    gb_sim *sim = run->sim;
    gb_run_output *out = run->out;
    gb_status st = GB_OK;
    gb_step_measures m;
    memset(&m, 0, sizeof m);
    enter(run, &run->profile.measure);
    if (out)
        st = gb_step_measure(&run->p.saved, sim, &run->p.work, rep->step, gb_run_output_fields_due(out, rep->step),
                             sim->scene->localisation, &m, err);
    enter(run, &run->profile.output);
    if (!st && out) st = gb_run_output_step(out, sim, &run->p, rep, &m, err);
    gb_step_measures_free(&m);
    if (!st && on_step) st = on_step(user, sim, rep, err);
    return st;
}

/* Where the program goes on from, the one place that reads a resume: a new run from its initial
 * state (step 0); a run resumed from a checkpoint (src/io/checkpoint.c) within the step in progress
 * (run->p.cur, whose start is in run->p.saved) until that step is done; otherwise the step after the
 * last completed one (run->p.pos: a resumed run's outputs, energy0 and stage's start are those of
 * the run it continues). */
typedef enum { START_NEW, START_WITHIN, START_AFTER } start_point;
static start_point start_of(const gb_run *run)
{
    const gb_run_progress *p = &run->p;
    if (!run->begun && !p->pos.resume) return START_NEW;
    return p->pos.resume && p->cur.active ? START_WITHIN : START_AFTER;
}

/* The program's start (start_of): a new run's initial state (step 0: its report in *rep, and its
 * output and on_step), or a resumed run's place. */
static gb_status begin(gb_run *run, gb_step_fn on_step, void *user, gb_step_report *rep, gb_error *err)
{
    gb_sim *sim = run->sim;
    gb_status st = GB_OK;
    enter(run, &run->profile.measure); /* the initial report */
    memset(rep, 0, sizeof *rep);
    rep->stage = -1;
    rep->total_steps = gb_scene_total_steps(sim->scene);
    gb_sim_resolve_accuracy(sim, sim->state.pairs.p, sim->state.pairs.n, 0);
    fill_report(sim, rep, NAN);
    start_point from = start_of(run);
    if (from == START_NEW) {
        memset(&run->p.pos, 0, sizeof run->p.pos);
        run->p.work.energy0 = gb_sim_elastic_energy(sim);
    }
    if (from != START_WITHIN) save_state(run, err, &st);
    if (!st && from == START_NEW) st = measure_and_output(run, on_step, user, rep, err);
    run->begun = !st;
    return st;
}

/* The stage s and the number k in it of the load step after the last completed (run->p.pos);
 * s = n_stages when there is none. */
static void next_place(const gb_run *run, int *s, int *k)
{
    const gb_scene *sc = run->sim->scene;
    *s = run->p.pos.stage, *k = run->p.pos.stage_step + 1;
    while (*s < sc->n_stages && *k > sc->stages[*s].steps) ++*s, *k = 1;
}

/* Whether the loading program has no step left (a step resumed within is one). */
static int finished(const gb_run *run)
{
    int s, k;
    next_place(run, &s, &k);
    return start_of(run) != START_WITHIN && s >= run->sim->scene->n_stages;
}

/* Where the next load step starts (there is one: !finished), into run->p.cur: the step a checkpoint
 * was taken within, as the checkpoint left it; else the step after the last completed one, from its
 * start (at its stage's start: the strain reference and the start stresses of a stress ramp). Its
 * stage. */
static const gb_stage *start_step(gb_run *run)
{
    gb_sim *sim = run->sim;
    const gb_scene *sc = sim->scene;
    if (start_of(run) == START_WITHIN) return &sc->stages[run->p.cur.stage];
    int s, k;
    double start[2];
    next_place(run, &s, &k);
    const gb_stage *sg = &sc->stages[s];
    if (k == 1) {
        if (sg->reset_strain) {
            sim->ref_width = sim->state.box.right - sim->state.box.left;
            sim->ref_height = sim->state.box.top - sim->state.box.bottom;
        }
        gb_gem_forces(sim);
        gb_gem_stress(sim, &start[0], &start[1]);
    } else memcpy(start, run->p.pos.start, sizeof start);
    gb_run_step c = {.active = 1, .stage = s, .stage_step = k, .step = run->p.pos.step + 1,
                     .start = {start[0], start[1]}, .h = 1, .cuts = sg->kind == GB_STAGE_RELAX ? 0 : sc->solver.cutbacks,
                     .finest = 1, .phase = GB_PHASE_LOAD};
    run->p.cur = c;
    return sg;
}

/* A host that follows its deformed boundary (host.updated_lagrangian) is rebased after every k-th
 * load step, at the start of the next: the state saved then is of the rebased host, so a failed
 * step and its cut-backs go back to the host they started with, and a run resumed between steps
 * rebases where the run it continues would have. */
static gb_status follow_boundary(gb_run *run, gb_error *err)
{
    gb_sim *sim = run->sim;
    gb_host *h = sim->host;
    int every = sim->scene->host.follow_every, step = run->p.pos.step;
    if (!h || !every || step - h->rebase_step < every) return GB_OK;
    gb_status st = gb_host_rebase(h, &sim->state.host, step, err);
    if (st == GB_EINPUT) { /* the mesh would fold: too much travel between two rebases */
        char why[GB_ERROR_MSG_MAX];
        snprintf(why, sizeof why, "%s", err->msg);
        return gb_fail(err, GB_ENUMERIC, "the host cannot follow its boundary after step %d (%s): rebase it more "
                       "often (host.updated_lagrangian.every: now %d) or load it in smaller steps", step, why, every);
    }
    if (!st) save_state(run, err, &st);
    return st;
}

/* The control and solve phases of the step in progress (run->p.cur), from its start (the saved
 * state): its accuracy, then its loads and relaxations, cut back where they fail. */
static gb_status solve_step(gb_run *run, const gb_stage *sg, gb_solve_result *res, gb_error *err)
{
    gb_sim *sim = run->sim;
    gb_sim_resolve_accuracy(sim, run->p.saved.pairs.p, run->p.saved.pairs.n, run->p.cur.stage);
    if (!(sim->accuracy > 0))
        return gb_fail(err, GB_ENUMERIC, "the relative accuracy has no force scale: the step starts with no "
                       "contact force, and no body force or stress target loads the grains; give "
                       "solver.accuracy as a force");
    return cut_back_step(run, sg, res, err);
}

/* The measure phase's start for a converged step begun at t0: its report, the external work, the
 * run's place. */
static gb_status step_done(gb_run *run, const gb_stage *sg, const gb_solve_result *res, double t0,
                           gb_step_report *rep, gb_error *err)
{
    const gb_run_step *c = &run->p.cur;
    rep->stage = c->stage;
    rep->step = c->step;
    rep->total_steps = gb_scene_total_steps(run->sim->scene);
    rep->iterations = c->iters;
    rep->substeps = c->substeps;
    rep->work = c->work;
    rep->cut_by = c->cut_by;
    fill_report(run->sim, rep, stress_controlled(sg) ? res->wall_residual : NAN);
    add_step_work(run);
    rep->seconds = gb_clock_seconds() - t0;
    gb_run_position at = {c->stage, c->stage_step, c->step, {c->start[0], c->start[1]}, 0};
    run->p.pos = at;
    return gb_run_watch_done(run, rep->seconds) ? gb_fail(err, GB_ENOMEM, "out of memory") : GB_OK;
}

/* The next load step (there is one: !finished): control, solve, measure, output; its report in
 * *rep. A step that fails leaves the state of the last completed one. */
static gb_status next_step(gb_run *run, gb_step_fn on_step, void *user, gb_step_report *rep, gb_error *err)
{
    enter(run, &run->profile.control);
    double t0 = gb_clock_seconds();
    int within = start_of(run) == START_WITHIN;
    const gb_stage *sg = start_step(run);
    gb_run_watch_step(run, t0);
    gb_solve_result res = {0};
    gb_status st = within ? GB_OK : follow_boundary(run, err);
    if (!st) st = solve_step(run, sg, &res, err);
    run->p.cur.active = 0;
    run->p.iterations_total += run->p.cur.iters;
    run->watch.t0 = 0; /* no step is watched until the next starts */
    if (st) {
        st = gb_run_step_failed(run->sim, &run->p.cur, sg, st, &res, err);
        restore_state(run->sim, &run->p.saved);
        return st;
    }
    enter(run, &run->profile.measure);
    st = step_done(run, sg, &res, t0, rep, err);
    /* measure and output see the step's start in the saved state; then it becomes the next's */
    if (!st) st = measure_and_output(run, on_step, user, rep, err);
    /* with an output, gb_run_output_step has checked for a stop (and checkpointed) */
    if (!st && !run->out && gb_run_stop_requested()) {
        char name[32];
        st = gb_fail(err, GB_EINTERRUPTED, "interrupted by %s after step %d",
                     gb_run_signal_name(gb_run_stop_requested(), name, sizeof name), rep->step);
    }
    enter(run, &run->profile.control);
    if (!st) save_state(run, err, &st);
    return st;
}

/* A call of the library ends (it began with run->out set to its output, if any): its time, and its
 * output's record of the run's time split (for run_info.yaml). */
static void call_ends(gb_run *run)
{
    enter(run, NULL);
    if (run->out) gb_run_output_phases(run->out, &run->profile);
    run->out = NULL; /* the caller closes (frees) the output next */
}

gb_status gb_run_program(gb_run *run, gb_run_output *out, gb_step_fn on_step, void *user, gb_error *err)
{
    gb_step_report rep;
    run->out = out;
    gb_status st = begin(run, on_step, user, &rep, err);
    while (!st && !finished(run)) st = next_step(run, on_step, user, &rep, err);
    call_ends(run);
    return st;
}

gb_status gb_run_advance(gb_run *run, gb_run_output *out, gb_step_report *rep, gb_error *err)
{
    gb_status st = GB_OK;
    run->out = out;
    int fresh = start_of(run) == START_NEW; /* a new run's first step is step 0; a resumed run's, the next */
    if (!run->begun) st = begin(run, NULL, NULL, rep, err);
    if (!st && !fresh) {
        if (finished(run))
            st = gb_fail(err, GB_EINPUT, "the loading program is finished: its %d load steps are taken",
                         gb_scene_total_steps(run->sim->scene));
        else st = next_step(run, NULL, NULL, rep, err);
    }
    call_ends(run);
    return st;
}

int gb_run_finished(const gb_run *run) { return run->begun && finished(run); }

gb_run_place gb_run_where(const gb_run *run)
{
    const gb_scene *sc = run->sim->scene;
    gb_run_place p = {-1, -1, 0, 0, gb_scene_total_steps(sc), sc->n_stages};
    if (!run->begun) return p;
    p.step = run->p.pos.step;
    if (p.step > 0) {
        p.stage = run->p.pos.stage, p.stage_step = run->p.pos.stage_step;
        p.stage_steps = sc->stages[p.stage].steps;
    }
    return p;
}
