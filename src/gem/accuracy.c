/* The force scale of a load step and the accuracy a it is solved to (docs/solvers.md, "Accuracy").
 * The scale is the mean normal force of the contacts at the step's start, the forces that the
 * accuracy must be small against in every kind of scene (walls, host, gravity), or the force the
 * stage's loads put on a grain if that is larger (a first compression, a deposit); fixed for the
 * step, so that the convergence test (K 14) stays a comparison with one number. It is read from the
 * state the step starts from, which a checkpoint within the step holds, so that a resumed step has
 * the same a. */
#include <float.h>
#include <math.h>

#include "gem/sim.h"

double gb_pairs_mean_normal_force(const gb_pair *p, int n, double extent)
{
    /* Grains placed exactly touching overlap by a rounding of their coordinates (the three discs:
     * 2e-16): such contacts carry no force of the loads and would make the scale vanish. An overlap
     * is a difference of lengths of the order of the coordinates: below 1e3 eps of them it is
     * rounding (the bound of tools/check_equilibrium.py). */
    double floor = 1e3 * DBL_EPSILON * extent, sum = 0;
    int count = 0;
    for (int k = 0; k < n; k++)
        if (p[k].d > floor) sum += p[k].pn, count++;
    return count ? sum / count : 0;
}

double gb_sim_extent(const gb_sim *sim)
{
    const gb_box *b = &sim->state.box;
    return fmax(fmax(fabs(b->left), fabs(b->right)), fmax(fabs(b->bottom), fabs(b->top)));
}

void gb_sim_resolve_accuracy(gb_sim *sim, const gb_pair *p, int n, int stage)
{
    const gb_solver_settings *sv = &sim->scene->solver;
    double f = fmax(gb_pairs_mean_normal_force(p, n, gb_sim_extent(sim)), gb_scene_load_force(sim->scene, stage));
    sim->force_scale = f;
    sim->accuracy = sv->accuracy_relative > 0 ? sv->accuracy_relative * f : sv->accuracy;
}
