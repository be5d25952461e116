/* A load step's error as steps.csv reports it: how far from equilibrium and from the Coulomb limit
 * its end state is, and how well jammed its packing is. */
#include <math.h>

#include "gem/sim.h"

void gb_sim_step_error(gb_sim *sim, gb_step_report *r)
{
    gb_gem_forces(sim);
    int carrying = 0;
    long contacts = 0;
    for (int i = 0; i < sim->state.n; i++)
        /* a rattler (fewer than two contacts) carries no load of the packing's */
        if (sim->scratch.nc[i] >= 2) carrying++, contacts += sim->scratch.nc[i];
    r->max_fixing_force = sqrt(gb_gem_largest_grain_force2(sim));
    r->rattlers = sim->state.n - carrying;
    r->coordination = carrying ? (double)contacts / carrying : 0;
    r->max_particle_force = NAN;
    if (sim->host && !sim->scene->host.rigid) r->max_particle_force = sqrt(gb_gem_largest_particle_force2(sim));
    r->coulomb_excess = NAN;
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        if (!(p->d > 0)) continue;
        double excess = fabs(p->pt) - (p->pn * gb_sim_tan_phi(sim, p->j) + gb_sim_material(sim, p->j)->cohesion);
        if (!(excess <= r->coulomb_excess)) r->coulomb_excess = excess;
    }
    r->mean_normal_force = gb_pairs_mean_normal_force(sim->state.pairs.p, sim->state.pairs.n, gb_sim_extent(sim));
}
