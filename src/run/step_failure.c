/* The error of a load step that failed: which step, why it stopped, how far from convergence, and
 * what to change (src/run/program.c). */
#include <math.h>
#include <stdio.h>

#include "run/step_failure.h"
#include "scene/admit.h"
#include "solver/solver.h"

/* What to change after a step that did not converge. Forces within the round-off of the
 * springs and coordinates (gb_scene_force_resolution) asks for a looser accuracy; otherwise the
 * step was too large for the iterations it had: steps each the size of the finest sub-step tried
 * (each of which may still be cut back as finely again), or more iterations. */
static void failure_hint(const gb_sim *sim, const gb_run_step *c, const gb_stage *sg, const gb_solve_result *res,
                         char *hint, size_t n)
{
    const gb_solver_settings *sv = &sim->scene->solver;
    double kn, x, round_off = gb_scene_force_resolution(sim->scene, &kn, &x);
    if (fmax(res->max_force, res->wall_residual) <= round_off) {
        snprintf(hint, n, ". The largest fixing force is at the round-off of these springs and coordinates (kn eps "
                 "|x|max = %.3g): give solver.accuracy: %g or more", round_off, gb_scene_suggested_accuracy(round_off));
        return;
    }
    char more[80] = "";
    gb_solve_stop stop = res->stop;
    if (stop != GB_STOP_ITERATIONS) { /* more iterations would not help */
        const char *longer = stop == GB_STOP_TIME ? ", or a larger solver.max_step_seconds" : "";
        if (sg->kind == GB_STAGE_RELAX) snprintf(hint, n, "%s", stop == GB_STOP_TIME ? ". Give a larger "
                                                 "solver.max_step_seconds" : "");
        else snprintf(hint, n, ". Use smaller load steps: loading[%d].%s.steps: %.0f (now %d)%s", c->stage,
                      gb_stage_name(sg->kind), sg->steps * fmax(2, 1 / c->finest), sg->steps, longer);
        return;
    }
    if (sv->max_iterations < gb_solver_defaults().max_iterations)
        snprintf(more, sizeof more, " (default %ld)", gb_solver_defaults().max_iterations);
    if (sg->kind == GB_STAGE_RELAX) {
        snprintf(hint, n, ". Give solver.max_iterations more than %ld%s", sv->max_iterations, more);
        return;
    }
    double steps = sg->steps * fmax(2, 1 / c->finest); /* the finest sub-step tried, or a half without cut-backs */
    snprintf(hint, n, ". Use smaller load steps: loading[%d].%s.steps: %.0f (now %d), or give solver.max_iterations "
             "more than %ld%s", c->stage, gb_stage_name(sg->kind), steps, sg->steps, sv->max_iterations, more);
}

/* The error of a failed step, naming it and what to change. */
gb_status gb_run_step_failed(const gb_sim *sim, const gb_run_step *c, const gb_stage *sg, gb_status st,
                             const gb_solve_result *res, gb_error *err)
{
    const gb_solver_settings *sv = &sim->scene->solver;
    if (st == GB_EINTERRUPTED) return st; /* its message says where already */
    if (st == GB_ENOCONV) {
        char cut[96] = "", hint[400], why[160];
        if (c->finest < 1) snprintf(cut, sizeof cut, ", nor in sub-steps down to 1/%.0f of the step", 1 / c->finest);
        failure_hint(sim, c, sg, res, hint, sizeof hint);
        gb_solve_stop stop = res->stop;
        long work = gb_run_step_iterations(c) + c->work.sweeps; /* its iterations and smoother steps */
        if (stop == GB_STOP_TIME)
            snprintf(why, sizeof why, "reached solver.max_step_seconds (%g s) after %ld iterations and smoother "
                     "steps", sv->max_step_seconds, work);
        else if (stop == GB_STOP_STALLED)
            snprintf(why, sizeof why, "stalled (its largest fixing force stopped falling) after %ld iterations and "
                     "smoother steps", work);
        else snprintf(why, sizeof why, "did not converge in %ld iterations", sv->max_iterations);
        return gb_fail(err, GB_ENOCONV,
                       "step %d (stage %d '%s', step %d of %d) %s: largest fixing force %.6g, walls off their "
                       "target by %.6g (accuracy a = %g)%s; the outputs hold the %d completed steps%s",
                       c->step, c->stage + 1, gb_stage_name(sg->kind), c->stage_step, sg->steps, why, res->max_force,
                       res->wall_residual, sim->accuracy, cut, c->step - 1, hint);
    }
    char msg[GB_ERROR_MSG_MAX];
    snprintf(msg, sizeof msg, "%s", err->msg);
    return gb_fail(err, st, "step %d (stage %d '%s', step %d of %d): %s", c->step, c->stage + 1, gb_stage_name(sg->kind),
                   c->stage_step, sg->steps, msg);
}
