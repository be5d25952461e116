/* Fabric, energy, work and dissipation of a granular state (Kishino 1989, section 4). */
#include <math.h>
#include <string.h>

#include "measure/step_measures.h"

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

/* du_t of the whole step (K 25) in the tangent at the start, its elastic part dpt/kt (K 26), the
 * slip (K 27) times the mean tangential force, zero if either end is zero (K 28). */
double gb_micro_step_dissipation(const gb_state *start, const gb_sim *sim)
{
    const gb_pair *a = start->pairs.p, *b = sim->state.pairs.p;
    int na = start->pairs.n, nb = sim->state.pairs.n, ia = 0;
    const gb_box *b0 = &start->box, *b1 = &sim->state.box;
    double wall_dx[GB_N_WALLS][2] = {{b1->left - b0->left, 0}, {b1->right - b0->right, 0},
                                     {0, b1->bottom - b0->bottom}, {0, b1->top - b0->top}};
    double total = 0;
    for (int k = 0; k < nb; k++) {
        const gb_pair *q = &b[k];
        if (!(q->d > 0) || q->pt == 0) continue;
        while (ia < na && (a[ia].i < q->i || (a[ia].i == q->i && a[ia].j < q->j))) ia++;
        if (ia >= na || a[ia].i != q->i || a[ia].j != q->j) continue;
        const gb_pair *p = &a[ia];
        if (!(p->d > 0) || p->pt == 0) continue;
        const gb_material *mat = gb_sim_material(sim, q->j);
        if (!(mat->kt > 0) || GB_IS_PARTICLE(q->j)) continue; /* particles: not in a start state */
        const gb_grain *g0 = &start->g[q->i], *g1 = &sim->state.g[q->i];
        double dx = g1->x - g0->x, dy = g1->y - g0->y, rot = g1->r * (g1->rot - g0->rot);
        if (q->j >= 0) {
            const gb_grain *h0 = &start->g[q->j], *h1 = &sim->state.g[q->j];
            dx -= h1->x - h0->x, dy -= h1->y - h0->y, rot += h1->r * (h1->rot - h0->rot);
        } else {
            dx -= wall_dx[-1 - q->j][0], dy -= wall_dx[-1 - q->j][1];
        }
        double du_t = -dx * p->ny + dy * p->nx + rot;
        total += 0.5 * (p->pt + q->pt) * (du_t - (q->pt - p->pt) / mat->kt);
    }
    return total;
}

void gb_micro_measure(const gb_sim *sim, const gb_work_accounts *work, gb_micro *m)
{
    memset(m, 0, sizeof *m);
    const gb_box *b = &sim->state.box;
    m->area = (b->right - b->left) * (b->top - b->bottom);
    double max_diss = 0;
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        if (p->diss > max_diss) max_diss = p->diss;
        if (!(p->d > 0) || !(p->pn > 0)) continue;
        const gb_material *mat = gb_sim_material(sim, p->j);
        double e = gb_spring_energy(p->pn, p->pt, p->mr, mat); /* (K 22) */
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
    int n = sim->state.n;
    m->coordination = (2.0 * (m->n_contacts - m->n_wall_contacts) + m->n_wall_contacts) / n;
    m->fabric.xx /= n, m->fabric.yy /= n, m->fabric.xy /= n;
    m->energy.xx /= 2 * m->area, m->energy.yy /= 2 * m->area, m->energy.xy /= 2 * m->area;
    gb_tensor2_principal(&m->fabric);
    gb_tensor2_principal(&m->energy);
    m->elastic_energy = gb_sim_elastic_energy(sim);
    gb_work_accounts none = {NAN, NAN, NAN};
    const gb_work_accounts *w = work ? work : &none;
    m->work_walls = w->walls;
    m->work_body = w->body;
    m->work = w->walls + w->body;
    m->dissipation = sim->state.acc.dissipation;
    m->dissipation_step = sim->state.acc.dissipation_step;
    m->p_max = sim->state.acc.dissipation_step > 0 ? max_diss / sim->state.acc.dissipation_step : 0;
    m->dissipation_step_k28 = NAN; /* of a step: gb_step_measure, from its start */
    m->balance = m->work - m->dissipation - (m->elastic_energy - w->energy0);
    m->work_walls_iter = sim->state.acc.work_walls_iter;
    m->relaxation = sim->state.acc.relaxation;
    m->balance_iter = sim->state.acc.work_walls_iter + w->body - m->dissipation - sim->state.acc.relaxation -
                      (m->elastic_energy - w->energy0);
}

void gb_micro_rose(const gb_sim *sim, int nbins, double *count, double *energy)
{
    for (int b = 0; b < nbins; b++) count[b] = energy[b] = 0;
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        if (!(p->d > 0) || !(p->pn > 0)) continue;
        const gb_material *mat = gb_sim_material(sim, p->j);
        double e = gb_spring_energy(p->pn, p->pt, p->mr, mat);
        /* Seen from grain i the normal is n; from grain j (if a grain) it is -n. */
        for (int side = 0; side < (p->j >= 0 ? 2 : 1); side++) {
            double a = atan2(side ? -p->ny : p->ny, side ? -p->nx : p->nx);
            if (a < 0) a += 2 * PI;
            int b = (int)(a / (2 * PI) * nbins);
            if (b >= nbins) b = nbins - 1;
            count[b] += 1;
            energy[b] += e;
        }
    }
}
