/* The packing protocols (docs/packing.md): the radii drawn, placed at random (scaled down so that
 * they fit), grown by FIRE stages to their size or to the target, settled by FIRE to the accuracy,
 * then brought to equilibrium by gembem's own solver with the scene's friction. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/clock.h"
#include "gembem/pack.h"
#include "pack/fire.h"
#include "pack/place.h"
#include "pack/region.h"
#include "pack/sizes.h"
#include "scene/admit.h"

static const double PI = 3.14159265358979323846;

/* Random sequential addition jams near 0.55 for discs: placing at 0.35 of the region is quick,
 * and each growth stage then adds at most PHI_STEP (finer near jamming, where a stage's overlaps
 * need the longest relaxation). */
static const double PLACE_PHI = 0.35, PHI_STEP = 0.02, PHI_STEP_DENSE = 0.005, PHI_DENSE = 0.78;
/* A growth stage is relaxed until overlaps are about this share of a radius (forces kn d); the
 * last relaxation goes to half the scene's accuracy, so that gembem's solver starts converged. */
static const double STAGE_OVERLAP = 1e-3;
/* A target stress is reached within this share of it. */
static const double STRESS_TOL = 0.01;

typedef struct {
    gb_scene *s;
    const gb_pack_def *d;
    gb_region rg;
    gb_fire_world w;
    gb_particles bp;
    double *r;          /* drawn radii */
    double grain_area;  /* of the drawn radii */
    double tol;         /* the final relaxations' */
    gb_pack_result *res;
} packer;

static void set_scale(packer *P, double scale)
{
    for (int i = 0; i < P->w.n; i++) P->w.g[i].r = scale * P->r[i];
}

static double phi_of(const packer *P, double scale) { return scale * scale * P->grain_area / P->rg.area; }
static double scale_of(const packer *P, double phi) { return sqrt(phi * P->rg.area / P->grain_area); }

/* One FIRE relaxation at this scale; its iterations are counted in the phase. */
static gb_status relax(packer *P, double scale, int body, double tol, int phase, gb_fire_report *rep, gb_error *err)
{
    set_scale(P, scale);
    gb_fire_world w = P->w;
    if (!body) w.body[0] = w.body[1] = 0;
    gb_status st = gb_fire_relax(&w, tol, P->d->max_iterations, rep, err);
    P->res->fire_iterations[phase] += rep->iterations;
    return st;
}

static double stage_tol(const packer *P, double scale)
{
    double rsum = 0;
    for (int i = 0; i < P->w.n; i++) rsum += P->r[i];
    return fmax(P->tol, STAGE_OVERLAP * P->w.kn_gg * scale * rsum / P->w.n);
}

static double mean_stress(const packer *P, const gb_fire_report *rep) { return rep->virial / (2 * P->rg.area); }

/* Grows from scale s0 in stages of solid fraction to `target` (a scale), or, with a target stress,
 * until the mean stress passes it: *s_lo, *p_lo are then the last stage below it, *s, *p the first
 * above. body: under the scene's body force. */
static gb_status grow(packer *P, double s0, double target, int body, double *s, double *s_lo, double *p_lo,
                      double *p, gb_error *err)
{
    gb_fire_report rep;
    *s = s0, *s_lo = s0, *p_lo = 0, *p = 0;
    while (target ? *s < target : *p < P->d->stress) {
        double phi = phi_of(P, *s), next = phi + (phi < PHI_DENSE ? PHI_STEP : PHI_STEP_DENSE);
        if (!target && next > GB_PACK_MAX_SOLID_FRACTION)
            return gb_fail(err, GB_EINPUT, "%s: pack.stress: the grains reach a mean stress of %g at solid fraction "
                                           "%.3f; the stress %g needs more than %.2f, the densest the growth protocol "
                                           "makes", P->s->path, *p, phi, P->d->stress, GB_PACK_MAX_SOLID_FRACTION);
        double sn = target ? fmin(target, scale_of(P, next)) : scale_of(P, next);
        gb_status st = relax(P, sn, body, stage_tol(P, sn), GB_PACK_GROW, &rep, err);
        if (st) return st;
        *s_lo = *s, *p_lo = *p;
        *s = sn, *p = mean_stress(P, &rep);
    }
    return GB_OK;
}

/* Between the stage below the stress (lo) and the one above (hi): regula falsi (Illinois) on the
 * scale, each trial relaxed to the accuracy, until the mean stress is within STRESS_TOL of it. */
static gb_status find_stress(packer *P, double s_lo, double p_lo, double s_hi, double p_hi, double *s,
                             gb_error *err)
{
    double target = P->d->stress;
    int side = 0;
    gb_fire_report rep;
    gb_status st;
    /* the growth stages' stresses are those of overlaps relaxed loosely: the upper end relaxed to
     * the accuracy may still lie below the target, then the grains grow on in small steps */
    for (;;) {
        if ((st = relax(P, s_hi, 1, P->tol, GB_PACK_SETTLE, &rep, err))) return st;
        p_hi = mean_stress(P, &rep);
        *s = s_hi;
        if (fabs(p_hi - target) <= STRESS_TOL * target) return GB_OK;
        if (p_hi > target) break;
        if (phi_of(P, s_hi) > GB_PACK_MAX_SOLID_FRACTION)
            return gb_fail(err, GB_EINPUT, "%s: pack.stress: the grains reach a mean stress of %g at solid fraction "
                                           "%.3f; the stress %g needs more than %.2f, the densest the growth protocol "
                                           "makes", P->s->path, p_hi, phi_of(P, s_hi), target,
                           GB_PACK_MAX_SOLID_FRACTION);
        s_lo = s_hi, p_lo = p_hi;
        s_hi *= 1 + 0.5 * PHI_STEP_DENSE;
    }
    for (int k = 0; k < 60; k++) {
        double sn = s_lo + (target - p_lo) * (s_hi - s_lo) / (p_hi - p_lo);
        if (!(sn > s_lo && sn < s_hi)) sn = 0.5 * (s_lo + s_hi);
        if ((st = relax(P, sn, 1, P->tol, GB_PACK_SETTLE, &rep, err))) return st;
        double pn = mean_stress(P, &rep);
        *s = sn;
        if (fabs(pn - target) <= STRESS_TOL * target) return GB_OK;
        if (pn < target) {
            s_lo = sn, p_lo = pn;
            if (side == -1) p_hi = target + 0.5 * (p_hi - target);
            side = -1;
        } else {
            s_hi = sn, p_hi = pn;
            if (side == 1) p_lo = target - 0.5 * (target - p_lo);
            side = 1;
        }
    }
    return gb_fail(err, GB_ENOCONV, "%s: pack.stress: the mean stress %g was not reached within %g %% in 60 "
                                    "relaxations", P->s->path, target, 100 * STRESS_TOL);
}

/* The drawn radii, placed at the largest scale up to `scale` that lets them in loose. */
static gb_status place(packer *P, double scale, double *s0, gb_error *err)
{
    double t0 = gb_clock_seconds();
    *s0 = fmin(scale, scale_of(P, PLACE_PHI));
    gb_status st = GB_OK;
    for (int k = 0; k < 6; k++, *s0 *= 0.85) { /* a narrow cavity takes them smaller */
        st = gb_place_random(&P->rg, P->r, P->w.n, *s0, P->d->seed, 2000, P->w.g, err);
        if (st != GB_EINPUT) break;
    }
    P->res->seconds[GB_PACK_PLACE] = gb_clock_seconds() - t0;
    return st;
}

static gb_status protocol(packer *P, gb_error *err)
{
    const gb_pack_def *d = P->d;
    double s0, s, s_lo, p_lo, p, t0;
    gb_fire_report rep;
    gb_status st;
    if (d->protocol == GB_PACK_DEPOSITION) {
        if (!(P->grain_area <= GB_PACK_MAX_FILL * P->rg.area))
            return gb_fail(err, GB_EINPUT, "%s: pack: the region (area %g) is too small for the %d grains drawn: "
                                           "their area %g is %.3g of it; a deposit holds at most %.2f of its region",
                           P->s->path, P->rg.area, P->w.n, P->grain_area, P->grain_area / P->rg.area,
                           GB_PACK_MAX_FILL);
        if ((st = place(P, 1, &s0, err))) return st;
        t0 = gb_clock_seconds();
        if (s0 < 1 && (st = grow(P, s0, 1, 0, &s, &s_lo, &p_lo, &p, err))) return st;
        P->res->seconds[GB_PACK_GROW] = gb_clock_seconds() - t0;
        t0 = gb_clock_seconds();
        st = relax(P, 1, 1, P->tol, GB_PACK_SETTLE, &rep, err);
        P->res->radius_scale = 1;
    } else if (!d->stress) {
        double target = scale_of(P, d->solid_fraction);
        if ((st = place(P, target, &s0, err))) return st;
        t0 = gb_clock_seconds();
        if ((st = grow(P, s0, target, 1, &s, &s_lo, &p_lo, &p, err))) return st;
        P->res->seconds[GB_PACK_GROW] = gb_clock_seconds() - t0;
        t0 = gb_clock_seconds();
        st = relax(P, target, 1, P->tol, GB_PACK_SETTLE, &rep, err);
        P->res->radius_scale = target;
    } else {
        if ((st = place(P, HUGE_VAL, &s0, err))) return st;
        t0 = gb_clock_seconds();
        if ((st = grow(P, s0, 0, 1, &s, &s_lo, &p_lo, &p, err))) return st;
        P->res->seconds[GB_PACK_GROW] = gb_clock_seconds() - t0;
        t0 = gb_clock_seconds();
        st = find_stress(P, s_lo, p_lo, s, p, &P->res->radius_scale, err);
    }
    P->res->seconds[GB_PACK_SETTLE] = gb_clock_seconds() - t0;
    return st;
}

/* Grains with fewer than `least` contacts carry no load: 3 in a frictionless packing without body
 * force (2D: d + 1), 2 under one (a grain rests on two); removed again and again, their contacts
 * with the others too; the coordination of those left. */
static void rattlers(const gb_contact *c, int m, int n, int least, gb_pack_result *res)
{
    int *k = calloc((size_t)n + 1, sizeof(int));
    unsigned char *gone = calloc((size_t)n + 1, 1);
    if (!k || !gone) {
        free(k), free(gone);
        res->rattlers = -1;
        return;
    }
    for (int q = 0; q < m; q++) {
        k[c[q].i]++;
        if (c[q].j >= 0) k[c[q].j]++;
    }
    for (int changed = 1; changed;) { /* gone: 0 in, 1 removed in this pass, 2 before */
        changed = 0;
        for (int i = 0; i < n; i++)
            if (!gone[i] && k[i] < least) gone[i] = 1, changed = 1;
        for (int q = 0; q < m; q++) {
            int i = c[q].i, j = c[q].j;
            if (j < 0) continue;
            if (!gone[i] && gone[j] == 1) k[i]--;
            if (!gone[j] && gone[i] == 1) k[j]--;
        }
        for (int i = 0; i < n; i++)
            if (gone[i]) gone[i] = 2;
    }
    long sum = 0;
    int left = 0;
    for (int i = 0; i < n; i++)
        if (!gone[i]) sum += k[i], left++;
    res->rattlers = n - left;
    res->coordination_nonrattlers = left ? (double)sum / left : 0;
    free(k), free(gone);
}

/* What pack_info.yaml reports of the final state. */
static gb_status measure(const gb_sim *sim, gb_pack_result *res, gb_error *err)
{
    int m;
    gb_contact *c = gb_sim_contacts_copy(sim, &m, err);
    if (!c) return err->code;
    const gb_grain *g = gb_sim_grains(sim);
    double virial = 0;
    res->contacts_grains = res->contacts_boundary = 0;
    res->largest_overlap = 0;
    for (int q = 0; q < m; q++) {
        const gb_grain *a = &g[c[q].i];
        if (c[q].j >= 0) {
            const gb_grain *b = &g[c[q].j];
            res->contacts_grains++;
            virial += c[q].pn * hypot(b->x - a->x, b->y - a->y);
            res->largest_overlap = fmax(res->largest_overlap, c[q].overlap / fmin(a->r, b->r));
        } else {
            res->contacts_boundary++;
            virial += c[q].pn * (a->r - 0.5 * c[q].overlap);
        }
    }
    res->mean_stress = virial / (2 * res->area);
    res->coordination = (2.0 * res->contacts_grains + res->contacts_boundary) / res->n;
    const double *b = gb_sim_scene(sim)->body_force_per_area;
    rattlers(c, m, res->n, b[0] == 0 && b[1] == 0 ? 3 : 2, res);
    free(c);
    return res->rattlers < 0 ? gb_fail(err, GB_ENOMEM, "out of memory counting rattlers") : GB_OK;
}

static gb_status on_step(void *user, const gb_sim *sim, const gb_step_report *rep, gb_error *err)
{
    (void)sim, (void)err;
    gb_pack_result *res = user;
    res->equilibrium_iterations = rep->iterations;
    res->max_fixing_force = rep->max_fixing_force;
    return GB_OK;
}

/* The packing as the scene's grains, admitted, then gembem's relax with friction (host rigid). */
static gb_status equilibrium(packer *P, const gb_bem_mesh *mesh, gb_sim **sim, gb_error *err)
{
    gb_scene *s = P->s;
    double t0 = gb_clock_seconds();
    snprintf(s->grains_file, sizeof s->grains_file, "%s (the packing)", s->path);
    if (mesh) { /* as a run scene's: the box only bounds the grains for reports */
        s->box.left = s->box.bottom = HUGE_VAL, s->box.right = s->box.top = -HUGE_VAL;
        for (int i = 0; i < s->n_grains; i++) {
            const gb_grain *q = &s->grains[i];
            s->box.left = fmin(s->box.left, q->x - q->r), s->box.right = fmax(s->box.right, q->x + q->r);
            s->box.bottom = fmin(s->box.bottom, q->y - q->r), s->box.top = fmax(s->box.top, q->y + q->r);
        }
        s->host.rigid = 1; /* the walls of the packing: the boundary particles held */
    }
    if (!(s->stages = calloc(1, sizeof *s->stages))) return gb_fail(err, GB_ENOMEM, "out of memory");
    s->n_stages = 1;
    s->stages[0].kind = GB_STAGE_RELAX, s->stages[0].steps = 1;
    s->checkpoint_every = 0;
    gb_status st = gb_scene_admit(s, mesh, err);
    if (!st) st = gb_sim_create(s, sim, err);
    if (!st) st = gb_sim_run(*sim, on_step, P->res, err);
    if (!st) st = measure(*sim, P->res, err);
    P->res->seconds[GB_PACK_EQUILIBRIUM] = gb_clock_seconds() - t0;
    return st;
}

gb_status gb_pack_make(gb_scene *scene, const gb_bem_mesh *mesh, const gb_pack_def *def, gb_pack_result *res,
                       gb_sim **sim, gb_error *err)
{
    *sim = NULL;
    memset(res, 0, sizeof *res);
    packer P;
    memset(&P, 0, sizeof P);
    P.s = scene, P.d = def, P.res = res;
    gb_region_init(&P.rg, scene, mesh);
    int n = (int)def->count;
    P.r = malloc((size_t)n * sizeof(double));
    scene->grains = calloc((size_t)n, sizeof(gb_grain));
    if (!P.r || !scene->grains) {
        free(P.r);
        return gb_fail(err, GB_ENOMEM, "out of memory for %d grains", n);
    }
    scene->n_grains = n;
    gb_sizes_draw(&def->sizes, n, def->seed, P.r);
    for (int i = 0; i < n; i++) P.grain_area += PI * P.r[i] * P.r[i];
    gb_status st = GB_OK;
    if (mesh) {
        int *elem = malloc((size_t)mesh->n * sizeof(int)), m = 0;
        if (!elem) st = gb_fail(err, GB_ENOMEM, "out of memory");
        for (int e = 0; !st && e < mesh->n; e++)
            if (mesh->group[e] == P.rg.cavity) elem[m++] = e;
        if (!st) st = gb_particles_create(&P.bp, mesh, elem, m, err);
        free(elem);
    }
    gb_fire_world w = {scene->grains, n, mesh ? NULL : &scene->box, mesh ? &P.bp : NULL, scene->grain_grain.kn,
                       scene->grain_wall.kn, scene->grain_boundary.kn,
                       {scene->body_force_per_area[0], scene->body_force_per_area[1]}};
    P.w = w;
    P.tol = 0.5 * scene->solver.accuracy;
    res->n = n;
    res->area = P.rg.area;
    if (!st) st = protocol(&P, err);
    if (!st) st = equilibrium(&P, mesh, sim, err);
    for (int i = 0; i < n; i++) res->grain_area += PI * scene->grains[i].r * scene->grains[i].r;
    res->solid_fraction = res->grain_area / res->area;
    gb_particles_free(&P.bp);
    free(P.r);
    if (st) {
        gb_sim_free(*sim);
        *sim = NULL;
    }
    return st;
}
