/* Contacts at the Coulomb limit (K 13). */
#include <math.h>

#include "gem/sim.h"
#include "measure/step_measures.h"

/* Whether contact p is at its limit pn tan(phi) + c (into *limit). */
static int at_limit(const gb_sim *sim, const gb_contact *p, double *limit)
{
    if (!(p->pn > 0)) return 0;
    const gb_material *mat = gb_sim_material(sim, p->j);
    *limit = p->pn * gb_sim_tan_phi(sim, p->j) + mat->cohesion;
    return mat->kt > 0 && *limit > 0 && !(fabs(p->pt) < *limit * (1 - 1e-9));
}

int gb_measure_sliding(const gb_sim *sim, const gb_contact *c, int m, gb_sliding_contact *out)
{
    int count = 0;
    double limit;
    for (int k = 0; k < m; k++) {
        const gb_contact *p = &c[k];
        if (at_limit(sim, p, &limit)) out[count++] = (gb_sliding_contact){p->i, p->j, p->pn, p->pt, limit, p->nx, p->ny};
    }
    return count;
}

void gb_contacts_sliding(const gb_sim *sim, const gb_contact *c, int m, int *sliding)
{
    double limit;
    for (int k = 0; k < m; k++) sliding[k] = at_limit(sim, &c[k], &limit);
}
