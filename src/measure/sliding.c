/* Contacts at the Coulomb limit (K 13). */
#include <math.h>

#include "gem/sim.h"
#include "measure/step_measures.h"

int gb_measure_sliding(const gb_sim *sim, gb_sliding_contact *out, int cap)
{
    int count = 0;
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        if (!(p->d > 0) || !(p->pn > 0)) continue;
        const gb_material *mat = gb_sim_material(sim, p->j);
        double limit = p->pn * gb_sim_tan_phi(sim, p->j) + mat->cohesion;
        if (!(mat->kt > 0) || !(limit > 0) || fabs(p->pt) < limit * (1 - 1e-9)) continue;
        if (out && count < cap)
            out[count] = (gb_sliding_contact){p->i, p->j, p->pn, p->pt, limit, p->nx, p->ny};
        count++;
    }
    return count;
}
