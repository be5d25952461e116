/* Contacts at the Coulomb limit (K 13). */
#include <math.h>

#include "gem/sim.h"
#include "measure/step_measures.h"

int gb_measure_sliding(const gb_sim *sim, const gb_contact *c, int m, gb_sliding_contact *out)
{
    int count = 0;
    for (int k = 0; k < m; k++) {
        const gb_contact *p = &c[k];
        if (!(p->pn > 0)) continue;
        const gb_material *mat = gb_sim_material(sim, p->j);
        double limit = p->pn * gb_sim_tan_phi(sim, p->j) + mat->cohesion;
        if (!(mat->kt > 0) || !(limit > 0) || fabs(p->pt) < limit * (1 - 1e-9)) continue;
        out[count++] = (gb_sliding_contact){p->i, p->j, p->pn, p->pt, limit, p->nx, p->ny};
    }
    return count;
}
