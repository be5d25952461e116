/* A granular simulation: set-up from a scene, the loading program, and read access to its state. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "core/memory.h"
#include "gem/sim.h"

static const double PI = 3.14159265358979323846;


void gb_sim_free(gb_sim *sim)
{
    if (!sim) return;
    free(sim->g);
    free(sim->body);
    free(sim->F);
    free(sim->S);
    free(sim->dX);
    free(sim->nc);
    free(sim->one);
    free(sim->in_system);
    free(sim->ls_dir);
    gb_gem_sweeps_free(sim);
    gb_sim_state_free(&sim->saved);
    gb_sim_state_free(&sim->trial);
    gb_sim_state_free(&sim->substep);
    gb_pairs_free(&sim->pairs);
    gb_global_free(sim->global);
    gb_host_free(sim->host);
    gb_particles_free(&sim->bp);
    free(sim->bp_F), free(sim->bp_S);
    free(sim);
}

static int pair_cmp(const gb_pair *p, int i, int j) { return p->i != i ? (p->i > i) - (p->i < i) : (p->j > j) - (p->j < j); }

/* The pair (i, j) in the sorted list, or NULL. */
static gb_pair *find_pair(gb_pair_list *L, int i, int j)
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
    const gb_host *h = sim->host;
    int m = h->m / 2;
    gb_particles *bp = &sim->bp;
    if ((st = gb_particles_create(bp, &h->mesh, h->K.elem, m, err))) return st;
    sim->bp_F = calloc(2 * (size_t)m, sizeof(double));
    sim->bp_S = calloc(3 * (size_t)m, sizeof(double));
    if (!sim->bp_F || !sim->bp_S) return gb_fail(err, GB_ENOMEM, "out of memory for %d boundary particles", m);
    /* A restart: the host where the earlier run left it. Created as that run's host was (f0's base
     * and unit responses for the scene's values), then its values, cavity displacements and
     * particles set, so that f0 and the force are the ones the run had. */
    const gb_host_state *hs = &sim->scene->host_state;
    if (hs->present) {
        gb_host *hw = sim->host;
        if (hs->n_cavity != m)
            return gb_fail(err, GB_EINPUT, "%s: the state's host has %d cavity elements, the scene's %d",
                           sim->scene->path, hs->n_cavity, m);
        for (int k = 0; k < sim->scene->host.n_bcs; k++) {
            int g = gb_bem_mesh_group(&hw->mesh, sim->scene->host.bc_group[k]);
            hw->prob.bc[g].value[0] = hs->bc[k].value[0], hw->prob.bc[g].value[1] = hs->bc[k].value[1];
        }
        if (hw->mesh.unbounded) memcpy(hw->prob.remote_stress, hs->remote_stress, sizeof hw->prob.remote_stress);
        memcpy(hw->u, hs->u, 2 * (size_t)m * sizeof(double));
        for (int k = 0; k < m; k++) bp->x[k] = hs->xy[2 * k], bp->y[k] = hs->xy[2 * k + 1];
        gb_host_update_f0(hw);
    }
    /* that every grain lies in the cavity was checked when the scene was read (src/scene/admit.c) */
    sim->world.box = NULL;
    sim->world.bp = bp;
    return GB_OK;
}

/* A lower bound of the memory a simulation allocates, to refuse one that cannot fit before the
 * kernel's out-of-memory killer ends it (issue 14): per grain, its copies (the scene's, the
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

gb_status gb_sim_create(const gb_scene *scene, gb_sim **out, gb_error *err)
{
    *out = NULL;
    double need = memory_need(scene), have = gb_memory_physical();
    if (have > 0 && need > have)
        return gb_fail(err, GB_EINPUT,
                       "%d grains need at least %.3g GB with the %s solver, more than this machine's %.3g GB of "
                       "physical memory; use fewer grains", scene->n_grains, need / 1e9,
                       scene->solver.method == GB_METHOD_GLOBAL ? "global" : "reference", have / 1e9);
    gb_sim *sim = calloc(1, sizeof *sim);
    if (!sim) return gb_fail(err, GB_ENOMEM, "out of memory");
    int n = scene->n_grains;
    size_t nn = (size_t)(n > 0 ? n : 1);
    sim->scene = scene;
    sim->n = n;
    sim->g = malloc(nn * sizeof *sim->g);
    sim->body = malloc(nn * 2 * sizeof(double));
    sim->F = calloc(nn * 3, sizeof(double));
    sim->S = calloc(nn * 6, sizeof(double));
    sim->dX = calloc(nn * 3, sizeof(double));
    sim->nc = calloc(nn, sizeof(int));
    sim->one = calloc(nn * 3, sizeof(double));
    sim->in_system = calloc(nn, 1);
    if (!sim->g || !sim->body || !sim->F || !sim->S || !sim->dX || !sim->nc || !sim->one || !sim->in_system) {
        gb_sim_free(sim);
        return gb_fail(err, GB_ENOMEM, "out of memory for %d grains", n);
    }
    memcpy(sim->g, scene->grains, (size_t)n * sizeof *sim->g);
    double rsum = 0;
    for (int i = 0; i < n; i++) {
        double area = PI * sim->g[i].r * sim->g[i].r;
        sim->body[2 * i] = scene->body_force_per_area[0] * area;
        sim->body[2 * i + 1] = scene->body_force_per_area[1] * area;
        rsum += sim->g[i].r;
    }
    sim->box = scene->box;
    sim->ref_width = scene->box.right - scene->box.left;
    sim->ref_height = scene->box.top - scene->box.bottom;
    sim->lm_mu = 1e-6;
    sim->lm_best = INFINITY; /* reset at every load step (gb_gem_relax): a restart needs no more */
    if (scene->solver_state.present) { /* a restart continues the damping of the run it continues */
        sim->lm_mu = scene->solver_state.mu;
        memcpy(sim->lm_history, scene->solver_state.history, sizeof sim->lm_history);
        sim->lm_next = scene->solver_state.next;
    }
    sim->tan_phi_gg = tan(scene->grain_grain.friction_deg * PI / 180);
    sim->tan_phi_gw = tan(scene->grain_wall.friction_deg * PI / 180);
    sim->tan_phi_gb = tan(scene->grain_boundary.friction_deg * PI / 180);
    /* The skin trades list length against rebuilds; a fifth of the mean radius keeps both small. */
    sim->pairs.skin = 0.2 * rsum / n;
    sim->world.g = sim->g;
    sim->world.n = n;
    sim->world.box = &sim->box;
    sim->world.bp = NULL;
    gb_status st = scene->host.present ? add_host(sim, err) : GB_OK;
    if (!st) st = gb_pairs_rebuild(&sim->pairs, &sim->world, err);
    if (st) {
        gb_sim_free(sim);
        return st;
    }
    /* Initial contacts: pn from the overlap, pt from the scene. */
    for (int k = 0; k < sim->pairs.n; k++) {
        gb_pair *p = &sim->pairs.p[k];
        gb_pair_geometry(p, &sim->world);
        p->pn = p->d > 0 ? gb_sim_material(sim, p->j)->kn * p->d : 0;
        p->pt = 0;
    }
    for (int c = 0; c < scene->n_contacts; c++) {
        const gb_contact_init *ci = &scene->contacts[c];
        int i = ci->i, j = ci->j;
        if (j >= 0 && j < i) i = ci->j, j = ci->i;
        gb_pair *p = find_pair(&sim->pairs, i, j);
        if (!p || !(p->d > 0)) {
            gb_sim_free(sim);
            if (GB_IS_PARTICLE(ci->j))
                return gb_fail(err, GB_EINPUT, "initial contact %d (grain %d, boundary particle p%d) does not overlap",
                               c, ci->i, GB_PARTICLE_OF(ci->j));
            return gb_fail(err, GB_EINPUT, "initial contact %d (grains %d, %d) does not overlap", c, ci->i, ci->j);
        }
        /* Seen from the lower index the tangential force keeps its sign (K 25). */
        p->pt = ci->pt;
    }
    if (scene->solver.method == GB_METHOD_GLOBAL &&
        (st = gb_global_create((gb_linear_kind)scene->solver.linear, n, sim->bp.n, &sim->global, err))) {
        gb_sim_free(sim);
        return st;
    }
    if (scene->solver.method == GB_METHOD_GLOBAL && scene->solver.newton == GB_NEWTON_LINE_SEARCH) {
        sim->ls_dir = malloc((3 * nn + 2 * (size_t)sim->bp.n + 2 * GB_N_WALLS) * sizeof(double));
        if (!sim->ls_dir) {
            gb_sim_free(sim);
            return gb_fail(err, GB_ENOMEM, "out of memory for %d grains", n);
        }
        if ((st = gb_gem_sweeps_create(sim, err))) {
            gb_sim_free(sim);
            return st;
        }
    }
    *out = sim;
    return GB_OK;
}

const gb_scene *gb_sim_scene(const gb_sim *sim) { return sim->scene; }
int gb_sim_n_grains(const gb_sim *sim) { return sim->n; }
const gb_grain *gb_sim_grains(const gb_sim *sim) { return sim->g; }
gb_box gb_sim_box(const gb_sim *sim) { return sim->box; }

int gb_sim_contacts(const gb_sim *sim, gb_contact *out, int cap)
{
    int m = 0;
    for (int k = 0; k < sim->pairs.n; k++) {
        const gb_pair *p = &sim->pairs.p[k];
        if (!(p->d > 0)) continue;
        if (out && m < cap) {
            gb_contact c = {p->i, p->j, p->nx, p->ny, p->d, p->pn, p->pt, p->diss};
            out[m] = c;
        }
        m++;
    }
    return m;
}

double gb_sim_elastic_energy(const gb_sim *sim)
{
    double e = 0;
    for (int k = 0; k < sim->pairs.n; k++) {
        const gb_pair *p = &sim->pairs.p[k];
        if (!(p->d > 0)) continue;
        const gb_material *m = gb_sim_material(sim, p->j);
        e += 0.5 * p->pn * p->pn / m->kn + (m->kt > 0 ? 0.5 * p->pt * p->pt / m->kt : 0); /* (K 22) */
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
    memcpy(F, &sim->F[3 * i], 3 * sizeof(double));
}

void gb_gem_stress(const gb_sim *sim, double *s1, double *s2)
{
    /* (K section 4.1): the forces on the two walls of a direction over twice the other side. */
    const gb_box *b = &sim->box;
    *s1 = (sim->wall_force[GB_WALL_BOTTOM] + sim->wall_force[GB_WALL_TOP]) / (2 * (b->right - b->left));
    *s2 = (sim->wall_force[GB_WALL_LEFT] + sim->wall_force[GB_WALL_RIGHT]) / (2 * (b->top - b->bottom));
}

void gb_gem_strain(const gb_sim *sim, double *e1, double *e2)
{
    const gb_box *b = &sim->box;
    *e1 = (sim->ref_height - (b->top - b->bottom)) / sim->ref_height;
    *e2 = (sim->ref_width - (b->right - b->left)) / sim->ref_width;
}

static void save_state(gb_sim *sim, gb_error *err, gb_status *st)
{
    *st = gb_sim_state_save(sim, &sim->saved, err);
}

/* External work of a converged step, as a quasi-static test measures it: the walls' mean force at
 * the start and the end of the step times their inward displacement, and the body forces times
 * the grains' displacement (the saved state is the start of the step; sim->wall_force and
 * sim->saved.wall_force hold the converged forces). */
static void add_step_work(gb_sim *sim)
{
    const gb_box *a = &sim->saved.box, *b = &sim->box;
    double inward[GB_N_WALLS] = {b->left - a->left, a->right - b->right, b->bottom - a->bottom, a->top - b->top};
    for (int w = 0; w < GB_N_WALLS; w++)
        sim->work_walls += 0.5 * (sim->saved.wall_force[w] + sim->wall_force[w]) * inward[w];
    for (int i = 0; i < sim->n; i++)
        sim->work_body += sim->body[2 * i] * (sim->g[i].x - sim->saved.g[i].x) +
                          sim->body[2 * i + 1] * (sim->g[i].y - sim->saved.g[i].y);
}

/* Back to a saved state, with its forces. */
static void restore_state(gb_sim *sim, const gb_sim_state *state)
{
    gb_sim_state_restore(sim, state);
    gb_gem_forces(sim);
}

/* Imposes a strain increment (compression positive) on the walls, symmetrically, grains held. */
static gb_status impose_strain(gb_sim *sim, double de1, double de2, gb_error *err)
{
    gb_gem_forces(sim); /* the walls' forces before the move, for their work */
    sim->half_pending = 0;
    memset(sim->dX, 0, (size_t)sim->n * 3 * sizeof(double));
    if (sim->bp.n) memset(sim->bp.dx, 0, 2 * (size_t)sim->bp.n * sizeof(double));
    memset(sim->wall_dx, 0, sizeof sim->wall_dx);
    double dy = 0.5 * de1 * sim->ref_height, dx = 0.5 * de2 * sim->ref_width;
    sim->wall_dx[GB_WALL_BOTTOM][1] = dy;
    sim->wall_dx[GB_WALL_TOP][1] = -dy;
    sim->wall_dx[GB_WALL_LEFT][0] = dx;
    sim->wall_dx[GB_WALL_RIGHT][0] = -dx;
    if (sim->global && sim->scene->solver.newton == GB_NEWTON_LINE_SEARCH) {
        /* The grains follow the box affinely, the prediction of a homogeneous strain: Newton
         * starts with the increment spread over the packing instead of concentrated at the walls
         * (FIRE-jammed 1e3 discs, 1 % oedometric in 20 steps: 7.7 iterations a step against 8.3,
         * docs/solver/research.md). */
        const gb_box *b = &sim->box;
        double xc = 0.5 * (b->left + b->right), yc = 0.5 * (b->bottom + b->top);
        double sx = 2 * dx / (b->right - b->left), sy = 2 * dy / (b->top - b->bottom);
        for (int i = 0; i < sim->n; i++) {
            sim->dX[3 * i] = -sx * (sim->g[i].x - xc);
            sim->dX[3 * i + 1] = -sy * (sim->g[i].y - yc);
        }
        /* a move of the grains like an iteration's: the fixing forces' work, by the trapezoid rule */
        sim->relaxation -= 0.5 * gb_gem_fixing_work(sim);
        sim->half_pending = 1;
    }
    return gb_gem_apply_moves(sim, err);
}

static void fill_report(gb_sim *sim, gb_step_report *r)
{
    gb_gem_forces(sim);
    double max2 = 0;
    for (int i = 0; i < sim->n; i++) {
        const double *F = &sim->F[3 * i];
        double f2 = F[0] * F[0] + F[1] * F[1] + F[2] * F[2];
        if (f2 > max2) max2 = f2;
    }
    r->max_fixing_force = sqrt(max2);
    gb_gem_stress(sim, &r->s1, &r->s2);
    gb_gem_strain(sim, &r->e1, &r->e2);
    r->ev = r->e1 + r->e2;
    double sum = r->s1 + r->s2;
    r->stress_ratio = sum != 0 ? (r->s1 - r->s2) / sum : 0;
    r->n_contacts = gb_sim_contacts(sim, NULL, 0);
    r->width = sim->box.right - sim->box.left;
    r->height = sim->box.top - sim->box.bottom;
}

static const char *stage_name(gb_stage_kind k)
{
    switch (k) {
    case GB_STAGE_ISOTROPIC: return "isotropic";
    case GB_STAGE_STRAIN: return "strain";
    case GB_STAGE_SHEAR_MEAN: return "shear_mean_stress";
    case GB_STAGE_RELAX: return "relax";
    case GB_STAGE_HOST_DISPLACEMENT: return "host_displacement";
    case GB_STAGE_HOST_LOAD: return "host_load";
    default: return "biaxial_stress";
    }
}

/* The part of load step k of a stage from fraction t to t + h of its increment (the whole step:
 * t = 0, h = 1): the walls' control or the host's loads, then relaxation to equilibrium. */
static gb_status load_step(gb_sim *sim, const gb_stage *sg, int k, double t, double h, const double start[2],
                           long *iters, double *max_force, double *residual, gb_error *err)
{
    long cap = sim->scene->solver.max_iterations;
    gb_wall_control wc = {GB_WALLS_FIXED, 0, 0, 0};
    gb_status st;
    double f = (k - 1 + t + h) / sg->steps;
    sim->dissipation_step = 0;
    for (int q = 0; q < sim->pairs.n; q++) sim->pairs.p[q].diss = 0;
    switch (sg->kind) {
    case GB_STAGE_ISOTROPIC:
        wc.mode = GB_WALLS_STRESS;
        wc.s1 = start[0] + (sg->stress - start[0]) * f;
        wc.s2 = start[1] + (sg->stress - start[1]) * f;
        return gb_gem_relax(sim, &wc, cap, iters, max_force, residual, err);
    case GB_STAGE_BIAXIAL_STRESS:
        wc.mode = GB_WALLS_STRESS;
        wc.s1 = start[0] + (sg->s1 - start[0]) * f;
        wc.s2 = start[1] + (sg->s2 - start[1]) * f;
        return gb_gem_relax(sim, &wc, cap, iters, max_force, residual, err);
    case GB_STAGE_RELAX:
        return gb_gem_relax(sim, &wc, cap, iters, max_force, residual, err);
    case GB_STAGE_HOST_DISPLACEMENT:
    case GB_STAGE_HOST_LOAD:
        /* The host's loads grow (grains and cavity held: f0 changes), then the grains and the
         * cavity relax. */
        for (int q = 0; q < sg->n_host_groups; q++) {
            double inc[2] = {h * sg->host_increment[q][0], h * sg->host_increment[q][1]};
            if ((st = gb_host_add_load(sim->host, sg->host_group[q], inc, err))) return st;
        }
        double remote[3] = {h * sg->host_remote_increment[0], h * sg->host_remote_increment[1],
                            h * sg->host_remote_increment[2]};
        if (sim->host->mesh.unbounded && (st = gb_host_add_remote(sim->host, remote, err))) return st;
        return gb_gem_relax(sim, &wc, cap, iters, max_force, residual, err);
    case GB_STAGE_STRAIN:
        if ((st = impose_strain(sim, h * sg->de1, h * sg->de2, err))) return st;
        return gb_gem_relax(sim, &wc, cap, iters, max_force, residual, err);
    case GB_STAGE_SHEAR_MEAN:
        /* The shear increment, equilibrium with the walls held, then the mean stress restored by an
         * isotropic strain under stress control (K section 2.6). */
        if ((st = impose_strain(sim, 0.5 * h * sg->d_shear, -0.5 * h * sg->d_shear, err))) return st;
        if ((st = gb_gem_relax(sim, &wc, cap, iters, max_force, residual, err))) return st;
        wc.mode = GB_WALLS_MEAN;
        wc.mean = sg->mean_stress;
        return gb_gem_relax(sim, &wc, cap - *iters, iters, max_force, residual, err);
    }
    return GB_EINTERNAL;
}

/* Load step k of a stage. A step that does not converge is cut back, as nonlinear finite element
 * codes do: taken again from its start in two halves, a half that fails in two quarters, and so on
 * down to 1/2^cutbacks of the step (solver.cutbacks). The granular path is path-dependent, so a
 * smaller sub-step is a finer, not a different, loading; a stall of the global solver (a grain that
 * must roll out of a squeeze, a slip that moves many grains) can be a load step too large for one
 * Newton path. Returns the iterations of all attempts in *iters, the sub-steps taken in *substeps,
 * and on failure the finest sub-step tried in *finest. */
static gb_status cut_back_step(gb_sim *sim, const gb_stage *sg, int k, const double start[2], long *iters,
                               int *substeps, double *finest, double *max_force, double *residual, gb_error *err)
{
    int cuts = sg->kind == GB_STAGE_RELAX ? 0 : sim->scene->solver.cutbacks;
    double t = 0, h = 1;
    gb_status st;
    *substeps = 0;
    for (;;) {
        if (cuts > 0 && (st = gb_sim_state_save(sim, &sim->substep, err))) return st;
        long it = 0;
        st = load_step(sim, sg, k, t, h, start, &it, max_force, residual, err);
        *iters += it;
        *finest = h;
        if (st == GB_ENOCONV && cuts > 0) {
            restore_state(sim, &sim->substep);
            cuts--;
            h /= 2;
            continue;
        }
        if (st) return st;
        ++*substeps;
        t += h; /* sums of powers of two: exact */
        if (t >= 1) return GB_OK;
        if (h > 1 - t) h = 1 - t;
    }
}

void gb_sim_on_iteration(gb_sim *sim, gb_iteration_fn fn, void *user)
{
    sim->on_iteration = fn;
    sim->on_iteration_user = user;
}

/* The global solver's work since the start of the run. */
static gb_solver_work solver_work(const gb_sim *sim)
{
    gb_solver_work w = sim->work;
    if (sim->global) w.factorisations = gb_global_statistics(sim->global)->factorisations;
    return w;
}

gb_status gb_sim_run(gb_sim *sim, gb_step_fn on_step, void *user, gb_error *err)
{
    const gb_scene *sc = sim->scene;
    gb_status st = GB_OK;
    gb_step_report rep;
    memset(&rep, 0, sizeof rep);
    rep.stage = -1;
    rep.total_steps = gb_scene_total_steps(sc);
    fill_report(sim, &rep);
    /* A resumed run (src/io/checkpoint.c) continues after the checkpoint's step: its outputs,
     * energy0 and the stage's start are those of the run it continues. */
    gb_sim_position from = sim->pos;
    if (!from.resume) {
        memset(&sim->pos, 0, sizeof sim->pos);
        sim->energy0 = gb_sim_elastic_energy(sim);
    }
    save_state(sim, err, &st);
    if (!st && on_step && !from.resume) st = on_step(user, sim, &rep, err);
    int step = sim->pos.step;
    for (int s = from.resume ? from.stage : 0; s < sc->n_stages && !st; s++) {
        const gb_stage *sg = &sc->stages[s];
        int first = from.resume && s == from.stage ? from.stage_step + 1 : 1;
        double start[2] = {from.start[0], from.start[1]};
        if (first == 1) {
            if (sg->reset_strain) {
                sim->ref_width = sim->box.right - sim->box.left;
                sim->ref_height = sim->box.top - sim->box.bottom;
            }
            gb_gem_forces(sim);
            gb_gem_stress(sim, &start[0], &start[1]);
        }
        for (int k = first; k <= sg->steps && !st; k++) {
            double t0 = gb_clock_seconds(), max_force = 0, residual = 0, finest = 1;
            long iters = 0;
            int substeps = 0;
            step++;
            gb_solver_work work0 = solver_work(sim);
            sim->attempt = 0;
            st = cut_back_step(sim, sg, k, start, &iters, &substeps, &finest, &max_force, &residual, err);
            sim->iterations_total += iters;
            if (st == GB_ENOCONV) {
                char cut[96] = "";
                if (finest < 1) snprintf(cut, sizeof cut, ", nor in sub-steps down to 1/%.0f of the step", 1 / finest);
                st = gb_fail(err, GB_ENOCONV,
                             "step %d (stage %d '%s', step %d of %d) did not converge in %ld iterations: largest "
                             "fixing force %.6g, walls off their target by %.6g (accuracy a = %g)%s; the outputs "
                             "hold the %d completed steps",
                             step, s + 1, stage_name(sg->kind), k, sg->steps, sc->solver.max_iterations, max_force,
                             residual, sc->solver.accuracy, cut, step - 1);
            } else if (st) {
                char msg[GB_ERROR_MSG_MAX];
                snprintf(msg, sizeof msg, "%s", err->msg);
                st = gb_fail(err, st, "step %d (stage %d '%s', step %d of %d): %s", step, s + 1,
                             stage_name(sg->kind), k, sg->steps, msg);
            }
            if (st) {
                restore_state(sim, &sim->saved);
                break;
            }
            rep.stage = s;
            rep.step = step;
            rep.iterations = iters;
            rep.substeps = substeps;
            gb_solver_work work1 = solver_work(sim);
            rep.work.trials = work1.trials - work0.trials;
            rep.work.factorisations = work1.factorisations - work0.factorisations;
            rep.work.sweeps = work1.sweeps - work0.sweeps;
            fill_report(sim, &rep);
            add_step_work(sim);
            rep.seconds = gb_clock_seconds() - t0;
            gb_sim_position at = {s, k, step, {start[0], start[1]}, 0};
            sim->pos = at;
            /* The output sees the step's start in the saved state; then it becomes the start of the next. */
            if (on_step) st = on_step(user, sim, &rep, err);
            if (!st) save_state(sim, err, &st);
        }
    }
    return st;
}
