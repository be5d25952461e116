/* A simulation: the problem of a scene (src/gem) with the solver its settings name (src/solver). */
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
