/* A simulation: the problem of a scene (src/gem) with the solver its settings name (src/solver);
 * and a run of it, what the loading program carries from step to step (program.c). */
#include <stdlib.h>

#include "io/run_output.h"
#include "run/run.h"
#include "solver/solver.h"

void gb_sim_free(gb_sim *sim)
{
    if (!sim) return;
    gb_solver_free(sim->solver);
    gb_gem_problem_free(sim);
}

gb_status gb_sim_create(const gb_scene *scene, gb_sim **out, gb_error *err)
{
    gb_status st = gb_gem_problem_create(scene, out, err);
    if (!st && (st = gb_solver_create(*out, &scene->solver, err))) {
        gb_sim_free(*out);
        *out = NULL;
    }
    return st;
}

gb_status gb_run_create(gb_sim *sim, gb_run **out, gb_error *err)
{
    *out = calloc(1, sizeof **out);
    if (!*out) return gb_fail(err, GB_ENOMEM, "out of memory");
    (*out)->sim = sim;
    return GB_OK;
}

void gb_run_free(gb_run *run)
{
    if (!run) return;
    gb_state_free(&run->p.saved);
    gb_state_free(&run->p.substep);
    free(run->watch.seconds);
    free(run);
}

gb_sim *gb_run_sim(const gb_run *run) { return run->sim; }

gb_status gb_sim_run(gb_sim *sim, gb_run_output *out, gb_step_fn on_step, void *user, gb_error *err)
{
    gb_run *run;
    gb_status st = gb_run_create(sim, &run, err);
    if (!st) st = gb_run_program(run, out, on_step, user, err);
    gb_run_free(run);
    return st;
}

gb_status gb_run_resume(gb_run *run, const char *dir, const char *command, gb_run_output **out, gb_error *err)
{
    if (run->begun) return gb_fail(err, GB_EINPUT, "%s: a run resumes into a new run, not one that has begun", dir);
    return gb_run_output_resume(dir, run->sim, &run->p, command, out, err);
}

void gb_run_on_iteration(gb_run *run, gb_iteration_fn fn, void *user)
{
    run->on_iteration = fn;
    run->on_iteration_user = user;
}

gb_run_profile gb_run_phases(const gb_run *run) { return run->profile; }

gb_work_accounts gb_run_work(const gb_run *run) { return run->p.work; }
