/* A granular problem: set-up from a scene and read access to its state (its solver: src/solver;
 * its loading program: src/run/program.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/memory.h"
#include "gem/sim.h"
#include "gembem/hybrid.h"

static const double PI = 3.14159265358979323846;

const char *gb_solve_stop_name(gb_solve_stop stop)
{
    static const char *const names[] = {"converged", "iterations", "stalled", "time", "error"};
    return stop >= GB_STOP_CONVERGED && stop <= GB_STOP_ERROR ? names[stop] : "unknown";
}

void gb_gem_problem_free(gb_sim *sim)
{
    if (!sim) return;
    sim->bp.x = sim->bp.y = NULL; /* the state's */
    gb_state_free(&sim->state);
    free(sim->grain_order), free(sim->grain_place);
    free(sim->body);
    free(sim->scratch.F);
    free(sim->scratch.S);
    free(sim->scratch.dX);
    free(sim->scratch.nc);
    free(sim->scratch.one);
    gb_pair_search_free(&sim->search);
    gb_host_free(sim->host);
    gb_particles_free(&sim->bp);
    free(sim->scratch.bp_F), free(sim->scratch.bp_S);
    free(sim->scratch.pair_diss);
    free(sim->scratch.chunk), free(sim->scratch.edge), free(sim->scratch.chunk_sums);
    free(sim);
}

static int pair_cmp(const gb_pair *p, int i, int j) { return p->i != i ? (p->i > i) - (p->i < i) : (p->j > j) - (p->j < j); }

/* The pair (i, j) in the sorted list, or NULL. */
static gb_pair *find_pair(gb_pair_set *L, int i, int j)
{
    int lo = 0, hi = L->n - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2, c = pair_cmp(&L->p[mid], i, j);
        if (!c) return &L->p[mid];
        if (c < 0) lo = mid + 1;
        else hi = mid - 1;
    }
    return NULL;
}

/* The host of a hybrid scene and its boundary particles: one half-disc per cavity element, of
 * diameter the element's length, on its midpoint, bulging into the cavity (docs/method.md section 10).
 * The grains touch these instead of walls. */
static gb_status add_host(gb_sim *sim, gb_error *err)
{
    gb_status st = gb_host_create(&sim->scene->host, &sim->host, err);
    if (st) return st;
    gb_host *h = sim->host;
    gb_state *s = &sim->state;
    int m = h->m / 2;
    gb_particles *bp = &sim->bp;
    if ((st = gb_particles_create(bp, &h->mesh, h->K.elem, m, err))) return st;
    /* the particles' centres are the state's: bp->x, bp->y point into it */
    s->n_particles = m;
    s->bp_x = bp->x, s->bp_y = bp->y;
    if ((st = gb_host_vars_create(h, &s->host, err))) return st;
    s->host_m = h->m;
    sim->scratch.bp_F = calloc(2 * (size_t)m, sizeof(double));
    sim->scratch.bp_S = calloc(3 * (size_t)m, sizeof(double));
    if (!sim->scratch.bp_F || !sim->scratch.bp_S) return gb_fail(err, GB_ENOMEM, "out of memory for %d boundary particles", m);
    /* A restart: the host where the earlier run left it. Created as that run's host was (f0's base
     * and unit responses for the scene's values), then its values, cavity displacements and
     * particles set, so that f0 and the force are the ones the run had. */
    const gb_host_state *hs = &sim->scene->restart.host;
    if (hs->present) {
        if (hs->n_cavity != m)
            return gb_fail(err, GB_EINPUT, "%s: the state's host has %d cavity elements, the scene's %d",
                           sim->scene->path, hs->n_cavity, m);
        for (int k = 0; k < sim->scene->host.n_bcs; k++) {
            int g = gb_bem_mesh_group(&h->mesh, sim->scene->host.bc_group[k]);
            s->host.bc[g][0] = hs->bc[k].value[0], s->host.bc[g][1] = hs->bc[k].value[1];
        }
        if (h->mesh.unbounded) memcpy(s->host.remote, hs->remote_stress, sizeof s->host.remote);
        memcpy(s->host.u, hs->u, 2 * (size_t)m * sizeof(double));
        for (int k = 0; k < m; k++) bp->x[k] = hs->xy[2 * k], bp->y[k] = hs->xy[2 * k + 1];
    }
    gb_host_update_f0(h, &s->host);
    /* that every grain lies in the cavity was checked when the scene was read (src/scene/admit.c) */
    sim->world.box = NULL;
    sim->world.bp = bp;
    return GB_OK;
}

/* A lower bound of the memory a simulation allocates, to refuse one that cannot fit before the
 * kernel's out-of-memory killer ends it: per grain, its copies (the scene's, the
 * simulation's and three saved states), its arrays (body force, F, S, dX, the last contact, the
 * contact count, the system flag), at least two candidate pairs in the list, its rebuild buffer
 * and the three saved states; with the global solver, its sparse factor, 5.3 GB at 1e6 discs
 * (docs/benchmarks.md, "Scaling to a million discs"). */
static double memory_need(const gb_scene *scene)
{
    double per_grain = 5.0 * sizeof(gb_grain) + 17.0 * sizeof(double) + sizeof(int) + 1;
    per_grain += 2.0 * 5 * sizeof(gb_pair);
    if (scene->solver.method == GB_METHOD_GLOBAL) per_grain += 5.0e3;
    return per_grain * scene->n_grains;
}

/* The problem's arrays for the scene's grains (the state's, its order, the body forces, the
 * scratch). */
static gb_status alloc_problem(gb_sim *sim, int n, gb_error *err)
{
    size_t nn = (size_t)(n > 0 ? n : 1);
    gb_status st = gb_state_alloc(&sim->state, n, 0, 0, 0, err);
    if (st) return st;
    sim->grain_order = malloc(nn * sizeof(int)), sim->grain_place = malloc(nn * sizeof(int));
    sim->body = malloc(nn * 2 * sizeof(double));
    sim->scratch.F = calloc(nn * 3, sizeof(double));
    sim->scratch.S = calloc(nn * 6, sizeof(double));
    sim->scratch.dX = calloc(nn * 3, sizeof(double));
    sim->scratch.nc = calloc(nn, sizeof(int));
    sim->scratch.one = calloc(nn * GB_ONE, sizeof(double));
    if (!sim->grain_order || !sim->grain_place || !sim->body || !sim->scratch.F || !sim->scratch.S ||
        !sim->scratch.dX || !sim->scratch.nc || !sim->scratch.one)
        return gb_fail(err, GB_ENOMEM, "out of memory for %d grains", n);
    return GB_OK;
}

/* The scene's grains into the state by cell (gb_grains_cell_order), their body forces, the box, the
 * friction and the pair search. */
static gb_status place_grains(gb_sim *sim, gb_error *err)
{
    const gb_scene *scene = sim->scene;
    int n = scene->n_grains;
    gb_status st = gb_grains_cell_order(scene->grains, n, sim->grain_order, err);
    if (st) return st;
    for (int k = 0; k < n; k++) {
        sim->state.g[k] = scene->grains[sim->grain_order[k]];
        sim->grain_place[sim->grain_order[k]] = k;
    }
    double rsum = 0;
    for (int i = 0; i < n; i++) {
        double area = PI * sim->state.g[i].r * sim->state.g[i].r;
        sim->body[2 * i] = scene->body_force_per_area[0] * area;
        sim->body[2 * i + 1] = scene->body_force_per_area[1] * area;
        rsum += sim->state.g[i].r;
    }
    sim->state.box = scene->box;
    sim->ref_width = scene->box.right - scene->box.left;
    sim->ref_height = scene->box.top - scene->box.bottom;
    sim->tan_phi_gg = tan(scene->grain_grain.friction_deg * PI / 180);
    sim->tan_phi_gw = tan(scene->grain_wall.friction_deg * PI / 180);
    sim->tan_phi_gb = tan(scene->grain_boundary.friction_deg * PI / 180);
    /* The skin trades list length against rebuilds; a fifth of the mean radius keeps both small. */
    sim->search.skin = 0.2 * rsum / n;
    sim->search.threads = scene->solver.threads;
    sim->world.g = sim->state.g;
    sim->world.n = n;
    sim->world.box = &sim->state.box;
    sim->world.bp = NULL;
    return GB_OK;
}

/* The initial contacts: pn from the overlap, pt and mr from the scene's (a restart's). */
static gb_status initial_contacts(gb_sim *sim, gb_error *err)
{
    const gb_scene *scene = sim->scene;
    for (int k = 0; k < sim->state.pairs.n; k++) {
        gb_pair *p = &sim->state.pairs.p[k];
        gb_pair_geometry(p, &sim->world);
        p->pn = p->d > 0 ? gb_sim_material(sim, p->j)->kn * p->d : 0;
        p->pt = p->mr = 0;
    }
    for (int c = 0; c < scene->restart.n_contacts; c++) {
        const gb_contact_init *ci = &scene->restart.contacts[c];
        int i = sim->grain_place[ci->i], j = ci->j >= 0 ? sim->grain_place[ci->j] : ci->j, swap = j >= 0 && j < i;
        if (swap) {
            int t = i;
            i = j, j = t;
        }
        gb_pair *p = find_pair(&sim->state.pairs, i, j);
        if (!p || !(p->d > 0)) {
            if (GB_IS_PARTICLE(ci->j))
                return gb_fail(err, GB_EINPUT, "initial contact %d (grain %d, boundary particle p%d) does not overlap",
                               c, ci->i, GB_PARTICLE_OF(ci->j));
            return gb_fail(err, GB_EINPUT, "initial contact %d (grains %d, %d) does not overlap", c, ci->i, ci->j);
        }
        /* Seen from the lower index the tangential force keeps its sign (K 25); the rolling moment
         * on the lower index is the other's with the opposite sign. */
        p->pt = ci->pt;
        p->mr = swap ? -ci->mr : ci->mr;
        if (!(gb_sim_material(sim, p->j)->kr > 0)) p->mr = 0; /* rolling switched off: no moment */
    }
    return GB_OK;
}

gb_status gb_gem_problem_create(const gb_scene *scene, gb_sim **out, gb_error *err)
{
    *out = NULL;
    double need = memory_need(scene), have = gb_memory_available();
    if (have > 0 && need > have)
        return gb_fail(err, GB_EINPUT,
                       "%d grains need at least %.3g GB with the %s solver, more than the %.3g GB of memory "
                       "this machine has available; use fewer grains", scene->n_grains, need / 1e9,
                       scene->solver.method == GB_METHOD_GLOBAL ? "global" : "reference", have / 1e9);
    gb_sim *sim = calloc(1, sizeof *sim);
    if (!sim) return gb_fail(err, GB_ENOMEM, "out of memory");
    sim->scene = scene;
    gb_status st = alloc_problem(sim, scene->n_grains, err);
    if (!st) st = place_grains(sim, err);
    if (!st && scene->host.present) st = add_host(sim, err);
    if (!st) st = gb_pairs_rebuild(&sim->state.pairs, &sim->search, &sim->world, err);
    if (!st) st = initial_contacts(sim, err);
    if (st) {
        gb_gem_problem_free(sim);
        return st;
    }
    /* the accuracy of a relaxation run outside a run (benchmarks, tests): as for a first step */
    gb_sim_resolve_accuracy(sim, sim->state.pairs.p, sim->state.pairs.n, 0);
    *out = sim;
    return GB_OK;
}

const gb_scene *gb_sim_scene(const gb_sim *sim) { return sim->scene; }
int gb_sim_n_grains(const gb_sim *sim) { return sim->state.n; }
gb_grain gb_sim_grain(const gb_sim *sim, int i) { return sim->state.g[sim->grain_place[i]]; }
gb_box gb_sim_box(const gb_sim *sim) { return sim->state.box; }

void gb_sim_grains(const gb_sim *sim, gb_grain *out)
{
    for (int i = 0; i < sim->state.n; i++) out[i] = sim->state.g[sim->grain_place[i]];
}

void gb_sim_wall_forces(const gb_sim *sim, double force[GB_N_WALLS])
{
    memcpy(force, sim->state.wall_force, sizeof sim->state.wall_force);
}

static int contact_cmp(const void *a, const void *b)
{
    const gb_contact *p = a, *q = b;
    return p->i != q->i ? (p->i > q->i) - (p->i < q->i) : (p->j > q->j) - (p->j < q->j);
}

int gb_sim_contacts(const gb_sim *sim, gb_contact *out, int cap)
{
    int m = 0;
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        if (!(p->d > 0)) continue;
        if (out && m < cap) {
            /* Seen from the other grain the normal and the rolling moment change sign, the
             * tangential force does not (K 25). */
            int i = sim->grain_order[p->i], j = p->j >= 0 ? sim->grain_order[p->j] : p->j;
            double s = j >= 0 && j < i ? -1 : 1;
            gb_contact c = {s > 0 ? i : j, s > 0 ? j : i, s * p->nx, s * p->ny, p->d, p->pn, p->pt, p->diss, s * p->mr};
            out[m] = c;
        }
        m++;
    }
    if (out && m <= cap) qsort(out, (size_t)m, sizeof *out, contact_cmp);
    return m;
}

double gb_sim_elastic_energy(const gb_sim *sim)
{
    double e = 0;
    for (int k = 0; k < sim->state.pairs.n; k++) {
        const gb_pair *p = &sim->state.pairs.p[k];
        if (!(p->d > 0)) continue;
        const gb_material *m = gb_sim_material(sim, p->j);
        e += gb_spring_energy(p->pn, p->pt, p->mr, m); /* (K 22) */
    }
    return e;
}

gb_contact *gb_sim_contacts_copy(const gb_sim *sim, int *n, gb_error *err)
{
    *n = gb_sim_contacts(sim, NULL, 0);
    gb_contact *c = malloc((size_t)(*n > 0 ? *n : 1) * sizeof *c);
    if (!c) {
        gb_fail(err, GB_ENOMEM, "out of memory for %d contacts", *n);
        return NULL;
    }
    gb_sim_contacts(sim, c, *n);
    return c;
}

void gb_sim_fixing_force(const gb_sim *sim, int i, double F[3])
{
    memcpy(F, &sim->scratch.F[3 * sim->grain_place[i]], 3 * sizeof(double));
}

void gb_sim_stress(gb_sim *sim, double *s1, double *s2)
{
    gb_gem_forces(sim);
    gb_gem_stress(sim, s1, s2);
}

double gb_sim_detect_seconds(const gb_sim *sim) { return sim->detect_seconds; }

int gb_sim_host_dofs(const gb_sim *sim) { return sim->host ? sim->host->m : 0; }

void gb_sim_host_cavity(const gb_sim *sim, double *u, double *force, double *fixing)
{
    size_t m = (size_t)gb_sim_host_dofs(sim) * sizeof(double);
    if (u && m) memcpy(u, sim->state.host.u, m);
    if (force && m) memcpy(force, sim->host->force, m);
    if (fixing && m) memcpy(fixing, sim->scratch.bp_F, m);
}

gb_status gb_sim_host_group_force(const gb_sim *sim, const char *group, double force[2], double disp[2],
                                  gb_error *err)
{
    if (!sim->host) return gb_fail(err, GB_EINPUT, "the simulation has no host");
    return gb_host_group_force(sim->host, &sim->state.host, group, force, disp, err);
}

void gb_gem_stress(const gb_sim *sim, double *s1, double *s2)
{
    /* (K section 4.1): the forces on the two walls of a direction over twice the other side. */
    const gb_box *b = &sim->state.box;
    *s1 = (sim->state.wall_force[GB_WALL_BOTTOM] + sim->state.wall_force[GB_WALL_TOP]) / (2 * (b->right - b->left));
    *s2 = (sim->state.wall_force[GB_WALL_LEFT] + sim->state.wall_force[GB_WALL_RIGHT]) / (2 * (b->top - b->bottom));
}

void gb_gem_strain(const gb_sim *sim, double *e1, double *e2)
{
    const gb_box *b = &sim->state.box;
    *e1 = (sim->ref_height - (b->top - b->bottom)) / sim->ref_height;
    *e2 = (sim->ref_width - (b->right - b->left)) / sim->ref_width;
}
