/* A state mapped onto another box by one uniform scaling: the end of a packing's equilibrium at its
 * target stress, whose walls moved, back in the box it was asked for (src/pack/pack.c). */
#include <math.h>

#include "gem/sim.h"

static const double PI = 3.14159265358979323846;

/* Coordinate v of the box that starts at `from`, in the box that starts at `to`, scaled by s. */
static double map(double v, double from, double to, double s) { return to + s * (v - from); }

/* Linear springs: a uniform scaling by s of positions and radii scales every overlap, and with them
 * the normal forces, by s; with the tangential forces (spring displacements) by s and the rolling
 * moments by s^2 every grain's forces and moments scale alike, so a balanced state stays balanced,
 * no contact crosses its Coulomb limit and Love's stress, forces times lengths over an area, is
 * unchanged. Only the body forces (s^2, the grains' areas) do not follow: their share of the
 * balance changes by s - 1. */
gb_status gb_sim_fit_box(gb_sim *sim, const gb_box *to, gb_error *err)
{
    gb_state *S = &sim->state;
    const gb_box b = S->box;
    double s = (to->right - to->left) / (b.right - b.left);
    double sy = (to->top - to->bottom) / (b.top - b.bottom);
    if (sim->host || !(fabs(sy / s - 1) <= 1e-12))
        return gb_fail(err, GB_EINPUT, "a state maps onto a box uniformly only without a host and in a box of its "
                                       "shape (width ratio %.17g, height ratio %.17g)", s, sy);
    for (int i = 0; i < S->n; i++) {
        gb_grain *g = &S->g[i];
        g->x = map(g->x, b.left, to->left, s), g->y = map(g->y, b.bottom, to->bottom, s), g->r *= s;
        double area = PI * g->r * g->r;
        sim->body[2 * i] = sim->scene->body_force_per_area[0] * area;
        sim->body[2 * i + 1] = sim->scene->body_force_per_area[1] * area;
        double *x0 = &S->pairs.x0[2 * i]; /* where the pair list was found: its drift unchanged */
        x0[0] = map(x0[0], b.left, to->left, s), x0[1] = map(x0[1], b.bottom, to->bottom, s);
    }
    for (int k = 0; k < S->pairs.n; k++) {
        gb_pair *p = &S->pairs.p[k];
        p->d *= s, p->pn *= s, p->pt *= s, p->mr *= s * s;
    }
    gb_box b0 = S->pairs.box0;
    S->pairs.box0 = (gb_box){map(b0.left, b.left, to->left, s), map(b0.right, b.left, to->left, s),
                             map(b0.bottom, b.bottom, to->bottom, s), map(b0.top, b.bottom, to->bottom, s)};
    for (int w = 0; w < GB_N_WALLS; w++) S->wall_force[w] *= s;
    S->box = *to;
    sim->ref_width *= s, sim->ref_height *= s;
    gb_gem_forces(sim);
    return GB_OK;
}
