/* Fabric, energy, work and dissipation of a granular state (Kishino 1989, section 4). */
#include <math.h>
#include <string.h>

#include "gem/sim.h"
#include "gembem/measure.h"

static const double PI = 3.14159265358979323846;

void gb_tensor2_principal(gb_tensor2 *t)
{
    double mean = 0.5 * (t->xx + t->yy), half = 0.5 * (t->xx - t->yy);
    double radius = sqrt(half * half + t->xy * t->xy);
    t->major = mean + radius;
    t->minor = mean - radius;
    double a = 0.5 * atan2(2 * t->xy, t->xx - t->yy) * 180 / PI;
    t->angle_deg = a <= -90 ? a + 180 : a;
}

void gb_micro_measure(const gb_sim *sim, gb_micro *m)
{
    memset(m, 0, sizeof *m);
    const gb_box *b = &sim->box;
    m->area = (b->right - b->left) * (b->top - b->bottom);
    double max_diss = 0;
    for (int k = 0; k < sim->pairs.n; k++) {
        const gb_pair *p = &sim->pairs.p[k];
        if (p->diss > max_diss) max_diss = p->diss;
        if (!(p->d > 0) || !(p->pn > 0)) continue;
        const gb_material *mat = p->j >= 0 ? &sim->scene->grain_grain : &sim->scene->grain_wall;
        double e = 0.5 * p->pn * p->pn / mat->kn + (mat->kt > 0 ? 0.5 * p->pt * p->pt / mat->kt : 0); /* (K 22) */
        double times = p->j >= 0 ? 2 : 1; /* seen from both grains, or from one */
        m->n_contacts++;
        m->n_wall_contacts += p->j < 0;
        m->fabric.xx += times * p->nx * p->nx;
        m->fabric.yy += times * p->ny * p->ny;
        m->fabric.xy += times * p->nx * p->ny;
        m->energy.xx += times * e * p->nx * p->nx;
        m->energy.yy += times * e * p->ny * p->ny;
        m->energy.xy += times * e * p->nx * p->ny;
    }
    int n = sim->n;
    m->coordination = (2.0 * (m->n_contacts - m->n_wall_contacts) + m->n_wall_contacts) / n;
    m->fabric.xx /= n, m->fabric.yy /= n, m->fabric.xy /= n;
    m->energy.xx /= 2 * m->area, m->energy.yy /= 2 * m->area, m->energy.xy /= 2 * m->area;
    gb_tensor2_principal(&m->fabric);
    gb_tensor2_principal(&m->energy);
    m->elastic_energy = gb_sim_elastic_energy(sim);
    m->work_walls = sim->work_walls;
    m->work_body = sim->work_body;
    m->work = sim->work_walls + sim->work_body;
    m->dissipation = sim->dissipation;
    m->dissipation_step = sim->dissipation_step;
    m->p_max = sim->dissipation_step > 0 ? max_diss / sim->dissipation_step : 0;
    m->balance = m->work - m->dissipation - (m->elastic_energy - sim->energy0);
}
