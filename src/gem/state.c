/* A simulation's state as one value: copied whole for a rejected trial (the global solver), a
 * failed step or sub-step (src/run/program.c) and a checkpoint (src/io/checkpoint.c). */
#include <stdlib.h>
#include <string.h>

#include "gem/sim.h"

void gb_state_free(gb_state *s)
{
    free(s->g);
    gb_pair_set_free(&s->pairs);
    free(s->bp_x), free(s->bp_y);
    gb_host_vars_free(&s->host);
    memset(s, 0, sizeof *s);
}

gb_status gb_state_alloc(gb_state *s, int n, int np, int m, int pairs, gb_error *err)
{
    memset(s, 0, sizeof *s);
    size_t nn = (size_t)(n > 0 ? n : 1), nb = (size_t)(np > 0 ? np : 1), nm = (size_t)(m > 0 ? m : 1);
    s->n = n, s->n_particles = np, s->host_m = m;
    s->g = malloc(nn * sizeof *s->g);
    s->pairs.x0 = malloc(2 * nn * sizeof(double));
    s->pairs.p = malloc((size_t)(pairs > 0 ? pairs : 1) * sizeof *s->pairs.p);
    s->pairs.cap = pairs > 0 ? pairs : 1;
    int ok = s->g && s->pairs.x0 && s->pairs.p;
    if (np) {
        s->bp_x = malloc(nb * sizeof(double)), s->bp_y = malloc(nb * sizeof(double));
        s->pairs.px0 = malloc(2 * nb * sizeof(double));
        ok = ok && s->bp_x && s->bp_y && s->pairs.px0;
    }
    if (m) {
        s->host.u = calloc(nm, sizeof(double)), s->host.f0 = calloc(nm, sizeof(double));
        ok = ok && s->host.u && s->host.f0;
    }
    if (!ok) {
        gb_state_free(s);
        return gb_fail(err, GB_ENOMEM, "out of memory for a state of %d grains", n);
    }
    return GB_OK;
}

gb_status gb_state_copy(gb_state *dst, const gb_state *src, gb_error *err)
{
    gb_status st;
    if (!dst->g && (st = gb_state_alloc(dst, src->n, src->n_particles, src->host_m, src->pairs.n, err))) return st;
    if (src->pairs.n > dst->pairs.cap) {
        gb_pair *p = realloc(dst->pairs.p, (size_t)src->pairs.n * sizeof *p);
        if (!p) return gb_fail(err, GB_ENOMEM, "out of memory for a copy of %d pairs", src->pairs.n);
        dst->pairs.p = p, dst->pairs.cap = src->pairs.n;
    }
    size_t n = (size_t)src->n, np = (size_t)src->n_particles, m = (size_t)src->host_m;
    memcpy(dst->g, src->g, n * sizeof *dst->g);
    if (src->pairs.n > 0) memcpy(dst->pairs.p, src->pairs.p, (size_t)src->pairs.n * sizeof *dst->pairs.p);
    dst->pairs.n = src->pairs.n;
    memcpy(dst->pairs.x0, src->pairs.x0, 2 * n * sizeof(double));
    if (np) {
        memcpy(dst->pairs.px0, src->pairs.px0, 2 * np * sizeof(double));
        memcpy(dst->bp_x, src->bp_x, np * sizeof(double));
        memcpy(dst->bp_y, src->bp_y, np * sizeof(double));
    }
    dst->pairs.box0 = src->pairs.box0;
    dst->pairs.rebuilds = src->pairs.rebuilds;
    dst->pairs.generation = src->pairs.generation;
    if (m) {
        memcpy(dst->host.u, src->host.u, m * sizeof(double));
        memcpy(dst->host.f0, src->host.f0, m * sizeof(double));
    }
    memcpy(dst->host.bc, src->host.bc, sizeof dst->host.bc);
    memcpy(dst->host.remote, src->host.remote, sizeof dst->host.remote);
    dst->box = src->box;
    memcpy(dst->wall_force, src->wall_force, sizeof dst->wall_force);
    dst->acc = src->acc;
    return GB_OK;
}

gb_status gb_sim_state_save(const gb_sim *sim, gb_state *st, gb_error *err)
{
    return gb_state_copy(st, &sim->state, err);
}

void gb_sim_state_restore(gb_sim *sim, const gb_state *st)
{
    gb_error err; /* none: the live arrays have the sizes, and its pair list never shrinks (contact/pairs.h) */
    gb_state_copy(&sim->state, st, &err);
    if (sim->host) gb_host_update_force(sim->host, &sim->state.host);
}
