/* The measure phase of a load step: everything docs/measures.md lists, from the step's start and
 * end states passed in (nothing read from the simulation's saved states). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "measure/step_measures.h"

#define LOC_FRACTION 0.1 /* the most strained 10 % of the area */

static void zone_free(gb_zone_measures *z)
{
    free(z->x0), free(z->x1), free(z->r), free(z->tri), free(z->grain), free(z->grain_tri), free(z->d2);
    gb_triangulation_free(&z->t);
}

static gb_status zone_measure(const gb_state *start, const gb_sim *sim, gb_zone_measures *z, gb_error *err)
{
    memset(z, 0, sizeof *z);
    int n = z->n = sim->state.n;
    size_t m = (size_t)(n > 0 ? n : 1);
    z->x0 = malloc(2 * m * sizeof(double)), z->x1 = malloc(2 * m * sizeof(double)), z->r = malloc(m * sizeof(double));
    z->grain = malloc(m * sizeof *z->grain), z->grain_tri = malloc(m * sizeof(int)), z->d2 = calloc(m, sizeof *z->d2);
    if (!z->x0 || !z->x1 || !z->r || !z->grain || !z->grain_tri || !z->d2)
        return gb_fail(err, GB_ENOMEM, "out of memory for the measures of %d grains", n);
    double dmax = 0;
    for (int i = 0; i < n; i++) { /* numbered as in the scene: the files' order */
        const gb_grain *g0 = &start->g[sim->grain_place[i]], *g1 = &sim->state.g[sim->grain_place[i]];
        z->x0[2 * i] = g0->x, z->x0[2 * i + 1] = g0->y;
        z->x1[2 * i] = g1->x, z->x1[2 * i + 1] = g1->y;
        z->r[i] = g1->r;
        dmax = fmax(dmax, 2 * z->r[i]);
    }
    /* The triangulation drops edges with a gap wider than the largest diameter (gap < 0). A zone
     * that cannot be triangulated (fewer than 3 grains, collinear, qhull's precision failure) has
     * no triangles: a measure, not a reason to stop the run. */
    gb_error terr = {0};
    gb_status st = gb_triangulate(n, z->x0, z->r, -1, &z->t, &terr);
    if (st && st != GB_EINPUT && st != GB_ENUMERIC) return gb_fail(err, st, "%s", terr.msg);
    z->tri_ok = !st && z->t.n > 0;
    z->tri = malloc((size_t)(z->t.n > 0 ? z->t.n : 1) * sizeof *z->tri);
    if (!z->tri) return gb_fail(err, GB_ENOMEM, "out of memory for %d triangles", z->t.n);
    gb_strain_triangles(&z->t, z->x0, z->x1, z->tri);
    gb_strain_points(&z->t, z->tri, n, z->grain, z->grain_tri);
    gb_strain_mean(z->t.n, z->tri, &z->mean);
    if (z->tri_ok && (st = gb_localisation_index(z->t.n, z->tri, LOC_FRACTION, &z->loc, err))) return st;
    /* The index is a share of the zone's shear: undefined where that shear is noise (a relaxation,
     * step 0), not a ratio of two roundings. A grain's place is known to the step's accuracy over
     * its stiffness, a / kn, a strain to that over a diameter; and to the rounding of coordinates. */
    double dmean = 0;
    for (int i = 0; i < n; i++) dmean += 2 * z->r[i] / n;
    double noise = n > 0 ? fmax(sim->accuracy / sim->scene->grain_grain.kn, 1e3 * DBL_EPSILON * gb_sim_extent(sim)) / dmean : 0;
    if (!(z->loc.mean_gamma > noise)) z->loc.index = NAN;
    /* D2min over the first shell and near contacts: touching grains are at most the largest
     * diameter apart. */
    z->d2_range = 1.5 * dmax;
    return n > 0 && dmax > 0 ? gb_d2min_points(n, z->x0, z->x1, z->d2_range, z->d2, err) : GB_OK;
}

gb_status gb_step_measure(const gb_state *start, const gb_sim *end, const gb_work_accounts *work, int step,
                          int fields, int row, gb_step_measures *m, gb_error *err)
{
    memset(m, 0, sizeof *m);
    m->step = step, m->fields = fields, m->row = row;
    gb_micro_measure(end, work, &m->micro);
    m->micro.dissipation_step_k28 = gb_micro_step_dissipation(start, end);
    if (!row && !fields) return GB_OK;
    /* the sliding contacts, for the row's count and fields/: in the scene's numbering and order */
    int nc;
    gb_contact *c = gb_sim_contacts_copy(end, &nc, err);
    if (!c) return err->code;
    m->sliding = malloc((size_t)(nc > 0 ? nc : 1) * sizeof *m->sliding);
    if (!m->sliding) {
        free(c);
        return gb_fail(err, GB_ENOMEM, "out of memory for %d sliding contacts", nc);
    }
    m->n_sliding = gb_measure_sliding(end, c, nc, m->sliding);
    free(c);
    gb_status st = zone_measure(start, end, &m->zone, err);
    /* the row needs the host's wall only; the empty cavity and the ring are for the files */
    m->has_host = end->host != NULL;
    if (!st && m->has_host) st = gb_host_measure(end, !fields, &m->host, err);
    return st;
}

void gb_step_measures_free(gb_step_measures *m)
{
    free(m->sliding);
    zone_free(&m->zone);
    gb_host_measures_free(&m->host);
    memset(m, 0, sizeof *m);
}
