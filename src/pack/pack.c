/* The packing protocols (docs/packing.md): the radii drawn, placed at random (scaled down so that
 * they fit), grown while FIRE relaxes them to their size or to the target, settled by FIRE to the accuracy
 * (frictionless, or with pack.friction_deg's friction), then brought to equilibrium by gembem's own
 * solver with the scene's friction. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact/pairs.h"
#include "core/clock.h"
#include "gem/sim.h"
#include "gembem/pack.h"
#include "gembem/run.h"
#include "gembem/solver.h"
#include "pack/fire.h"
#include "pack/place.h"
#include "pack/region.h"
#include "pack/sizes.h"
#include "scene/admit.h"

static const double PI = 3.14159265358979323846;

/* Random sequential addition jams near 0.55 for discs: placing at 0.35 of the region is quick. */
static const double PLACE_PHI = 0.35;
/* The radii grow in steps of RAMP in ln(scale) (1 % of a radius, 2 % in solid fraction), one per
 * FIRE iteration, whenever every disc's force is below that of an overlap of STAGE_OVERLAP of the
 * mean radius (kn d): stages of growth relaxed loosely, the next one as soon as the last is
 * (smaller steps took more iterations, docs/packing.md). */
static const double RAMP = 1e-2, STAGE_OVERLAP = 1e-3;
/* A growth to a stress ends once the stress is passed with every |F| below GROW_FORCE times the
 * contact force of the target (stress times a mean diameter): a jammed state, from which the
 * settling frees the scale under the target. Where the global solver finishes (SETTLE_FINISHED
 * below), at GROW_FORCE_FINISHED: the free relaxation at the overshoot, to 10 times the looser
 * tolerance, takes over sooner (1e5 discs at 10 degrees: a fifth fewer FIRE iterations). */
static const double GROW_FORCE = 0.1, GROW_FORCE_FINISHED = 1;
/* The growth goes to OVERSHOOT times the target stress, FIRE relaxes the packing there (the scale
 * free, every |F| below OVERSHOOT times the tolerance: the same share of the contact forces), and
 * the settling then decompresses it to the target. A packing relaxes much faster at a higher
 * stress, and one jammed at 10 times the target decompresses to it with few rearrangements: 1e4
 * discs took 17 700 FIRE iterations on average over six seeds against 30 800 growing to the
 * target itself; 3, 5 and 30 times took more, 15 and 20 as many (docs/packing.md, Measured). The
 * price: a porosity lower by about 0.002 (the structure found at the higher stress is denser). The overshoot stays below OVER_MAX kn (contacts'
 * overlaps of some 0.1 % of the diameter): at 1e-2 kn (ctest pack_make's box to 1e-3 kn, times
 * 10) the free scale's balance, sum pn (ri + rj) = 2 A p, and Love's stress with the centres'
 * distances differ by more than the 0.5 % the relaxation asks. */
static const double OVERSHOOT = 10, OVER_MAX = 1e-3;
/* FIRE settles the grains until every |F| is below SETTLE times the scene's accuracy; gembem's
 * solver, with the scene's friction, then checks them (0 iterations) or finishes. Near jamming
 * FIRE's last factors of the force are the slow ones (at 10 degrees its grains keep slipping and
 * recompacting), so where the global solver follows a growth to a stress with friction while
 * packing, FIRE stops at SETTLE_FINISHED times the accuracy and one Newton step finishes (with
 * GROW_FORCE_FINISHED, a third less time at 1e5 discs, half at 1e6). Not looser with the walls held:
 * FIRE leaves the walls' stress below Love's (by 6.6 % at 1e5 discs from 8 times the accuracy) and
 * the solver's balance at the held radii lowers Love's, by up to 0.17 % from 4 times but 3.4 % from
 * 8, past STRESS_TOL. In a box without body force the walls follow the target stress instead
 * (solve_at_stress), and FIRE stops at SETTLE_HELD (a tenth less time at 1e6 discs, both stresses
 * within 0.5 %). Not elsewhere: Kishino's reference
 * iteration (a scene's default) finishes slowly (1e6 discs: not in 14 minutes); a growth to a solid
 * fraction saves little of FIRE and pays the Newton step (1e5: 51 -> 55 s, 150 -> 910 MB); a deposit
 * costs more (1e3 discs: the solver 47 551 iterations on top); a frictionless packing would be left
 * tangential forces. The measurements: docs/packing.md, Algorithm and Measured. */
static const double SETTLE = 1, SETTLE_FINISHED = 4, SETTLE_HELD = 8;
/* A target stress is reached within this share of it (the settling aims at half of it). */
static const double STRESS_TOL = 0.01;

typedef struct {
    gb_scene *s;
    const gb_pack_def *d;
    gb_region rg;
    gb_fire_world w;
    gb_pair_set pairs;  /* with friction while packing: FIRE's pairs and their tangential forces */
    gb_material gg;     /* the grains' law while packing: the scene's with pack.friction_deg */
    gb_particles bp;
    double *r;          /* drawn radii */
    double r_mean;      /* of the drawn radii */
    double grain_area;  /* of the drawn radii */
    double tol;         /* the settling's: SETTLE, SETTLE_FINISHED or SETTLE_HELD times the accuracy */
    double grow_force;  /* GROW_FORCE or GROW_FORCE_FINISHED */
    int hold_stress;    /* the equilibrium's walls at the target stress (solve_at_stress) */
    gb_pack_result *res;
} packer;

static double phi_of(const packer *P, double scale) { return scale * scale * P->grain_area / P->rg.area; }
static double scale_of(const packer *P, double phi) { return sqrt(phi * P->rg.area / P->grain_area); }

/* One FIRE relaxation from *scale, to every |F| <= tol: the radii ramped to `target` (a scale, or 0:
 * until the mean stress passes `stress`), or with stress_tol > 0 free under `stress`, until it is
 * within stress_tol. body: under the scene's body force. Its iterations and seconds go to `phase`.
 * A stress beyond the densest packing (GB_PACK_MAX_SOLID_FRACTION) sets *capped, or without it
 * (NULL) is refused. */
static gb_status relax(packer *P, double *scale, double target, double stress, int body, double tol, double stress_tol,
                       int phase, int *capped, gb_error *err)
{
    gb_fire_world w = P->w;
    if (!body) w.body[0] = w.body[1] = 0;
    double smax = scale_of(P, GB_PACK_MAX_SOLID_FRACTION);
    double hold = STAGE_OVERLAP * P->w.kn_gg * (target ? target : *scale) * P->r_mean;
    gb_fire_goal goal = {.tol = tol, .free = stress_tol > 0, .stress = stress, .stress_tol = stress_tol,
                         .scale_max = smax, .scale_to = target ? target : smax, .ramp = RAMP,
                         .hold = fmax(tol, hold), .max_iter = P->d->max_iterations};
    gb_fire_report rep;
    double t0 = gb_clock_seconds();
    gb_status st = gb_fire_relax_scaled(&w, &goal, scale, &rep, err);
    P->res->fire_iterations[phase] += rep.iterations;
    P->res->seconds[phase] += gb_clock_seconds() - t0;
    if (!st && rep.capped && capped) *capped = 1;
    else if (!st && rep.capped)
        st = gb_fail(err, GB_EINPUT, "%s: pack.stress: the grains reach a mean stress of %g at solid fraction %.3f; "
                                     "the stress %g needs more than %.2f, the densest the growth protocol makes",
                     P->s->path, rep.virial / (2 * P->rg.area), phi_of(P, *scale), stress,
                     GB_PACK_MAX_SOLID_FRACTION);
    return st;
}

/* The grains (and their drawn radii) put in the order of cells (gb_grains_cell_order): the discs of
 * a pair then lie near each other in memory, which at 1e5 discs and more keeps the force loop in
 * the cache; the placement left them in random order. */
static gb_status sort_by_cell(packer *P, gb_error *err)
{
    int n = P->w.n;
    gb_grain *g = P->w.g;
    int *order = malloc(((size_t)n + 1) * sizeof *order);
    gb_grain *g2 = malloc(((size_t)n + 1) * sizeof *g2);
    double *r2 = malloc(((size_t)n + 1) * sizeof *r2);
    gb_status st = !order || !g2 || !r2 ? gb_fail(err, GB_ENOMEM, "out of memory for %d grains", n)
                                        : gb_grains_cell_order(g, n, order, err);
    if (!st) {
        for (int k = 0; k < n; k++) g2[k] = g[order[k]], r2[k] = P->r[order[k]];
        memcpy(g, g2, (size_t)n * sizeof *g);
        memcpy(P->r, r2, (size_t)n * sizeof *r2);
    }
    free(order), free(g2), free(r2);
    return st;
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
    if (!st) st = sort_by_cell(P, err);
    P->res->seconds[GB_PACK_PLACE] = gb_clock_seconds() - t0;
    return st;
}

/* Placed loose, grown (the grow phase: relaxed loosely while the radii grow), settled to the
 * accuracy (the settle phase) at the final radii. */
static gb_status protocol(packer *P, gb_error *err)
{
    const gb_pack_def *d = P->d;
    double s, loose = STAGE_OVERLAP * P->w.kn_gg * P->r_mean; /* at scale 1 */
    gb_status st;
    if (d->protocol == GB_PACK_DEPOSITION) {
        if (!(P->grain_area <= GB_PACK_MAX_FILL * P->rg.area))
            return gb_fail(err, GB_EINPUT, "%s: pack: the region (area %g) is too small for the %d grains drawn: "
                                           "their area %g is %.3g of it; a deposit holds at most %.2f of its region",
                           P->s->path, P->rg.area, P->w.n, P->grain_area, P->grain_area / P->rg.area,
                           GB_PACK_MAX_FILL);
        if ((st = place(P, 1, &s, err))) return st;
        if (s < 1 && (st = relax(P, &s, 1, 0, 0, fmax(P->tol, loose), 0, GB_PACK_GROW, NULL, err))) return st;
        st = relax(P, &s, 1, 0, 1, P->tol, 0, GB_PACK_SETTLE, NULL, err);
    } else if (!d->stress) {
        double target = scale_of(P, d->solid_fraction);
        if ((st = place(P, target, &s, err))) return st;
        if ((st = relax(P, &s, target, 0, 1, fmax(P->tol, target * loose), 0, GB_PACK_GROW, NULL, err))) return st;
        st = relax(P, &s, target, 0, 1, P->tol, 0, GB_PACK_SETTLE, NULL, err);
    } else {
        if ((st = place(P, HUGE_VAL, &s, err))) return st;
        /* past the target (OVERSHOOT), relaxed there; a region whose densest packing cannot reach
         * that stress goes to the settling as it is, which refuses a target beyond it */
        double over = fmax(d->stress, fmin(OVERSHOOT * d->stress, OVER_MAX * P->w.kn_gg));
        double jammed = P->grow_force * over * 2 * s * P->r_mean; /* s: the placement's scale */
        int capped = 0;
        if ((st = relax(P, &s, 0, over, 1, fmax(P->tol, jammed), 0, GB_PACK_GROW, &capped, err))) return st;
        if (!capped && over > d->stress &&
            (st = relax(P, &s, 0, over, 1, over / d->stress * P->tol, 0.5 * STRESS_TOL, GB_PACK_GROW, &capped, err)))
            return st;
        st = relax(P, &s, 0, d->stress, 1, P->tol, 0.5 * STRESS_TOL, GB_PACK_SETTLE, NULL, err);
    }
    P->res->radius_scale = s;
    return st;
}

/* Grains with fewer than `least` contacts carry no load: 3 in a frictionless packing without body
 * force (2D: d + 1), 2 under one (a grain rests on two) or with friction while packing (two
 * contacts whose forces lie on the line between them, each inside its friction cone, hold a disc);
 * removed again and again, their contacts with the others too; the coordination of those left. */
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
static gb_status measure(const gb_sim *sim, const gb_pack_def *d, gb_pack_result *res, gb_error *err)
{
    int m;
    gb_contact *c = gb_sim_contacts_copy(sim, &m, err);
    if (!c) return err->code;
    double virial = 0;
    res->contacts_grains = res->contacts_boundary = 0;
    res->largest_overlap = 0;
    for (int q = 0; q < m; q++) {
        gb_grain a = gb_sim_grain(sim, c[q].i);
        if (c[q].j >= 0) {
            gb_grain b = gb_sim_grain(sim, c[q].j);
            res->contacts_grains++;
            virial += c[q].pn * hypot(b.x - a.x, b.y - a.y);
            res->largest_overlap = fmax(res->largest_overlap, c[q].overlap / fmin(a.r, b.r));
        } else {
            res->contacts_boundary++;
            virial += c[q].pn * (a.r - 0.5 * c[q].overlap);
        }
    }
    res->mean_stress = virial / (2 * res->area);
    res->coordination = (2.0 * res->contacts_grains + res->contacts_boundary) / res->n;
    const double *b = gb_sim_scene(sim)->body_force_per_area;
    res->rattler_contacts = b[0] == 0 && b[1] == 0 && !(d->friction_deg > 0) ? 3 : 2;
    rattlers(c, m, res->n, res->rattler_contacts, res);
    free(c);
    return res->rattlers < 0 ? gb_fail(err, GB_ENOMEM, "out of memory counting rattlers") : GB_OK;
}

static gb_status on_step(void *user, const gb_sim *sim, const gb_step_report *rep, gb_error *err)
{
    (void)sim, (void)err;
    gb_pack_result *res = user;
    res->equilibrium_iterations += rep->iterations; /* over the passes of solve_at_stress */
    res->max_fixing_force = rep->max_fixing_force;
    return GB_OK;
}

/* With friction while packing, the tangential forces and rolling moments that FIRE's contacts carry at
 * the end become the scene's initial contacts (as a state's: gb_contact_init), so that gembem's
 * solver starts from the frictional state FIRE found instead of from none. */
static gb_status keep_contacts(packer *P, gb_error *err)
{
    const gb_pair_set *L = &P->pairs;
    gb_restart *r = &P->s->restart;
    if (!(P->d->friction_deg > 0)) return GB_OK;
    if (!(r->contacts = malloc(((size_t)L->n + 1) * sizeof *r->contacts)))
        return gb_fail(err, GB_ENOMEM, "out of memory for %d contacts", L->n);
    r->n_contacts = 0;
    for (int k = 0; k < L->n; k++) {
        const gb_pair *p = &L->p[k];
        if (p->d > 0 && (p->pt != 0 || p->mr != 0))
            r->contacts[r->n_contacts++] = (gb_contact_init){p->i, p->j, p->pt, p->mr};
    }
    return GB_OK;
}

/* A packing grown to a stress in a box without body force, brought to equilibrium with its walls
 * at the target stress (an isotropic strain: the relax stage's mean_stress) and then mapped back
 * onto the box it was asked for (gb_sim_fit_box: the stress and the balance unchanged), so that
 * FIRE's settling may stop at SETTLE_HELD. The solver stops at the accuracy, but a smooth residual
 * far below it (a few dyn per grain, pointing inwards) can hold Love's stress off the walls': by
 * 1.6 % for one 1e5-disc seed, under 0.1 % for two others. Then the pass is taken again at half
 * the accuracy until Love's stress is within STRESS_TOL of the target (that seed: 0.1 % after two
 * more), at most EQUILIBRIUM_PASSES times, else the packing fails as not converged. */
enum { EQUILIBRIUM_PASSES = 6 };
/* Newton's whole step from FIRE's settled state fails to lower the merit tenfold (contacts open,
 * close and slip under it: every 1e5 and 1e6 packing measured), so the solver's own rule after a
 * failed whole step (src/solver/line_search.c) is taken from the start: its smoother goes first,
 * checked for a stall every SMOOTHER_FIRST steps, and Newton only where it stalls (a tenth less
 * time at 1e5 discs, and no factorisation's memory). The check reads the merit's fall over its
 * stretch, and the smoother's merit is not monotone (FIRE): at 1e6 discs it fell tenfold in 250
 * steps and was 5 times above its start at step 1 000, which a check there took for a stall, and
 * Newton's whole step then raised it 1 000 times. Checked every 4 000 steps, the smoother alone
 * finishes (2 266 steps at 1e6 discs, in a seventh of the memory; docs/packing.md, Measured). */
static const double SMOOTHER_FIRST = 4000;
static gb_status solve_at_stress(packer *P, gb_sim *sim, const gb_box *asked, gb_error *err)
{
    gb_solver_settings *sv = &P->s->solver;
    const gb_solver_settings keep = *sv;
    gb_status st = GB_OK;
    double off = HUGE_VAL;
    for (int pass = 0; pass < EQUILIBRIUM_PASSES && !st && !(off <= STRESS_TOL); pass++) {
        if (pass) sv->accuracy *= 0.5, sv->accuracy_relative *= 0.5;
        if ((st = gb_sim_run(sim, NULL, on_step, P->res, err))) break;
        gb_box b = gb_sim_box(sim);
        P->res->radius_scale *= (asked->right - asked->left) / (b.right - b.left);
        if (!(st = gb_sim_fit_box(sim, asked, err)) && !(st = measure(sim, P->d, P->res, err)))
            off = fabs(P->res->mean_stress / P->d->stress - 1);
    }
    *sv = keep;
    if (!st && !(off <= STRESS_TOL))
        st = gb_fail(err, GB_ENOCONV,
                     "%s: pack: the packing's mean stress from its contacts is %.6g, %.2g %% off the target %g "
                     "with the walls at it, after %d equilibria down to 1/%d of the accuracy",
                     P->s->path, P->res->mean_stress, 100 * off, P->d->stress, EQUILIBRIUM_PASSES,
                     1 << (EQUILIBRIUM_PASSES - 1));
    if (!st) { /* the largest force of the state mapped back (the step's report was before) */
        gb_step_report r;
        gb_sim_step_error(sim, &r);
        P->res->max_fixing_force = r.max_fixing_force;
    }
    return st;
}

/* The packing as the scene's grains, admitted, then gembem's relax with friction (host rigid). */
static gb_status equilibrium(packer *P, const gb_bem_mesh *mesh, gb_sim **sim, gb_error *err)
{
    gb_scene *s = P->s;
    double t0 = gb_clock_seconds();
    gb_status st = keep_contacts(P, err);
    if (st) return st;
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
    if (P->hold_stress) {
        s->stages[0].mean_stress = P->d->stress;
        /* the solver as it starts, but its smoother first */
        s->restart.solver = (gb_solver_state){.present = 1, .mu = GB_SOLVER_MU_START, .smoother_first = SMOOTHER_FIRST};
    }
    s->checkpoint_every = 0;
    gb_box asked = s->box;
    st = gb_scene_admit(s, mesh, err);
    if (!st) st = gb_sim_create(s, sim, err);
    if (!st && P->hold_stress) st = solve_at_stress(P, *sim, &asked, err);
    else if (!st && !(st = gb_sim_run(*sim, NULL, on_step, P->res, err))) st = measure(*sim, P->d, P->res, err);
    P->res->seconds[GB_PACK_EQUILIBRIUM] = gb_clock_seconds() - t0;
    if (!*sim) return st;
    P->res->equilibrium_work = gb_solver_work_done(*sim); /* the simulation's solver: these passes' */
    const gb_global_stats *g = gb_solver_statistics(*sim);
    if (g) P->res->equilibrium_linear_seconds = g->assemble + g->analyse + g->factorise + g->solve;
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
    for (int i = 0; i < n; i++) P.grain_area += PI * P.r[i] * P.r[i], P.r_mean += P.r[i] / n;
    gb_status st = GB_OK;
    if (mesh) {
        int *elem = malloc((size_t)mesh->n * sizeof(int)), m = 0;
        if (!elem) st = gb_fail(err, GB_ENOMEM, "out of memory");
        for (int e = 0; !st && e < mesh->n; e++)
            if (mesh->group[e] == P.rg.cavity) elem[m++] = e;
        if (!st) st = gb_particles_create(&P.bp, mesh, elem, m, err);
        free(elem);
    }
    P.gg = scene->grain_grain;
    P.gg.friction_deg = def->friction_deg;
    gb_fire_world w = {scene->grains, n, mesh ? NULL : &scene->box, mesh ? &P.bp : NULL, scene->grain_grain.kn,
                       scene->grain_wall.kn, scene->grain_boundary.kn,
                       {scene->body_force_per_area[0], scene->body_force_per_area[1]}, P.r, P.rg.area,
                       scene->solver.threads, def->friction_deg > 0 ? &P.pairs : NULL,
                       {[GB_END_GRAIN] = &P.gg, [GB_END_WALL] = &scene->grain_wall,
                        [GB_END_PARTICLE] = &scene->grain_boundary},
                       {[GB_END_GRAIN] = tan(def->friction_deg * PI / 180),
                        [GB_END_WALL] = tan(scene->grain_wall.friction_deg * PI / 180),
                        [GB_END_PARTICLE] = tan(scene->grain_boundary.friction_deg * PI / 180)}};
    P.w = w;
    int finished = def->protocol == GB_PACK_GROWTH && def->stress > 0 && def->friction_deg > 0 &&
                   scene->solver.method == GB_METHOD_GLOBAL;
    P.hold_stress = finished && !mesh && scene->body_force_per_area[0] == 0 && scene->body_force_per_area[1] == 0;
    P.tol = (P.hold_stress ? SETTLE_HELD : finished ? SETTLE_FINISHED : SETTLE) * scene->solver.accuracy;
    P.grow_force = finished ? GROW_FORCE_FINISHED : GROW_FORCE;
    res->n = n;
    res->area = P.rg.area;
    if (!st) st = protocol(&P, err);
    if (!st) st = equilibrium(&P, mesh, sim, err);
    for (int i = 0; i < n; i++) { /* the written radii: solve_at_stress scales them */
        double r = *sim ? gb_sim_grain(*sim, i).r : scene->grains[i].r;
        res->grain_area += PI * r * r;
    }
    res->solid_fraction = res->grain_area / res->area;
    gb_particles_free(&P.bp);
    gb_pair_set_free(&P.pairs);
    free(P.r);
    if (st) {
        gb_sim_free(*sim);
        *sim = NULL;
    }
    return st;
}
