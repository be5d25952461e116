/* Saving and restoring a simulation's state: for a failed step, and for the global solver's
 * rejected trial moves. */
#include <stdlib.h>
#include <string.h>

#include "gem/sim.h"

void gb_sim_state_free(gb_sim_state *st)
{
    free(st->g);
    free(st->p);
    free(st->x0);
    free(st->bp_xy);
    free(st->px0);
    free(st->host_u);
    free(st->host_f0);
    memset(st, 0, sizeof *st);
}

gb_status gb_sim_state_save(const gb_sim *sim, gb_sim_state *st, gb_error *err)
{
    size_t n = (size_t)(sim->n > 0 ? sim->n : 1);
    if (!st->g && (!(st->g = malloc(n * sizeof *st->g)) || !(st->x0 = malloc(2 * n * sizeof(double)))))
        return gb_fail(err, GB_ENOMEM, "out of memory for a copy of %d grains", sim->n);
    if (sim->pairs.n > st->cap) {
        gb_pair *p = realloc(st->p, (size_t)sim->pairs.n * sizeof *p);
        if (!p) return gb_fail(err, GB_ENOMEM, "out of memory for a copy of %d pairs", sim->pairs.n);
        st->p = p;
        st->cap = sim->pairs.n;
    }
    if (sim->host && !st->bp_xy &&
        (!(st->bp_xy = malloc((size_t)sim->host->m * sizeof(double))) ||
         !(st->px0 = malloc((size_t)sim->host->m * sizeof(double))) ||
         !(st->host_u = malloc((size_t)sim->host->m * sizeof(double))) ||
         !(st->host_f0 = malloc((size_t)sim->host->m * sizeof(double)))))
        return gb_fail(err, GB_ENOMEM, "out of memory for a copy of the host");
    for (int e = 0; e < sim->bp.n; e++) st->bp_xy[2 * e] = sim->bp.x[e], st->bp_xy[2 * e + 1] = sim->bp.y[e];
    if (sim->bp.n) memcpy(st->px0, sim->pairs.px0, 2 * (size_t)sim->bp.n * sizeof(double));
    if (sim->host) {
        memcpy(st->host_u, sim->host->u, (size_t)sim->host->m * sizeof(double));
        memcpy(st->host_f0, sim->host->K.f0, (size_t)sim->host->m * sizeof(double));
        for (int g = 0; g < GB_BEM_MAX_GROUPS; g++)
            st->host_bc[g][0] = sim->host->prob.bc[g].value[0], st->host_bc[g][1] = sim->host->prob.bc[g].value[1];
        memcpy(st->host_remote, sim->host->prob.remote_stress, sizeof st->host_remote);
    }
    memcpy(st->g, sim->g, (size_t)sim->n * sizeof *st->g);
    if (sim->pairs.n > 0) memcpy(st->p, sim->pairs.p, (size_t)sim->pairs.n * sizeof *st->p);
    memcpy(st->x0, sim->pairs.x0, 2 * (size_t)sim->n * sizeof(double));
    st->n_pairs = sim->pairs.n;
    st->box = sim->box;
    st->box0 = sim->pairs.box0;
    st->rebuilds = sim->pairs.rebuilds;
    st->generation = sim->pairs.generation;
    memcpy(st->wall_force, sim->wall_force, sizeof st->wall_force);
    st->acc = sim->acc;
    return GB_OK;
}

/* The pair list keeps at least the capacity it had: restoring never needs memory. */
void gb_sim_state_restore(gb_sim *sim, const gb_sim_state *st)
{
    if (st->n_pairs > sim->pairs.cap) {
        /* the list shrank in a rebuild and its spare buffer is the larger one */
        gb_pair *t = sim->pairs.p;
        int c = sim->pairs.cap;
        sim->pairs.p = sim->pairs.tmp, sim->pairs.cap = sim->pairs.tmp_cap;
        sim->pairs.tmp = t, sim->pairs.tmp_cap = c;
    }
    for (int e = 0; e < sim->bp.n; e++) sim->bp.x[e] = st->bp_xy[2 * e], sim->bp.y[e] = st->bp_xy[2 * e + 1];
    if (sim->host) {
        memcpy(sim->host->u, st->host_u, (size_t)sim->host->m * sizeof(double));
        memcpy(sim->host->K.f0, st->host_f0, (size_t)sim->host->m * sizeof(double));
        for (int g = 0; g < GB_BEM_MAX_GROUPS; g++)
            sim->host->prob.bc[g].value[0] = st->host_bc[g][0], sim->host->prob.bc[g].value[1] = st->host_bc[g][1];
        memcpy(sim->host->prob.remote_stress, st->host_remote, sizeof st->host_remote);
        gb_host_update_force(sim->host);
    }
    memcpy(sim->g, st->g, (size_t)sim->n * sizeof *st->g);
    if (st->n_pairs > 0) memcpy(sim->pairs.p, st->p, (size_t)st->n_pairs * sizeof *st->p);
    memcpy(sim->pairs.x0, st->x0, 2 * (size_t)sim->n * sizeof(double));
    /* the particles' places at the restored list's rebuild, which its staleness test measures from */
    if (sim->bp.n && st->px0) memcpy(sim->pairs.px0, st->px0, 2 * (size_t)sim->bp.n * sizeof(double));
    sim->pairs.n = st->n_pairs;
    sim->box = st->box;
    sim->pairs.box0 = st->box0;
    sim->pairs.rebuilds = st->rebuilds;
    sim->pairs.generation = st->generation;
    memcpy(sim->wall_force, st->wall_force, sizeof st->wall_force);
    sim->acc = st->acc;
}
