/* The geometric admission of a scene (issue 23): before any computation, every grain's disc (not
 * only its centre) lies in the box or in the host's cavity, and no two grains overlap, within
 * grains.max_overlap of the (smaller) radius; a grain that does not fit the space at all is refused
 * whatever the tolerance. A grain refused is named by its file, line and column. The overlaps
 * accepted are counted for run_info.yaml. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>

#include "contact/pairs.h"
#include "scene/admit.h"
#include "scene/state_read.h"

static gb_status grain_fail(const gb_scene *s, int i, gb_error *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static gb_status grain_fail(const gb_scene *s, int i, gb_error *err, const char *fmt, ...)
{
    char what[GB_ERROR_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    const gb_grain *g = &s->grains[i];
    if (s->grain_line)
        return gb_fail(err, GB_EINPUT, "%s:%d:%d: grain %d (x %g, y %g, r %g) %s", s->grains_file, s->grain_line[i],
                       s->grain_col[i], i, g->x, g->y, g->r, what);
    return gb_fail(err, GB_EINPUT, "%s: grain %d (x %g, y %g, r %g) %s", s->grains_file, i, g->x, g->y, g->r, what);
}

/* A crossing c of the grain's disc over the boundary of its space: refused beyond the tolerance,
 * counted if positive. */
static gb_status crossing(gb_scene *s, int i, double c, const char *where, gb_error *err)
{
    double r = s->grains[i].r, f = s->max_overlap;
    if (c > f * r)
        return grain_fail(s, i, err, "crosses %s by %g (%.3g of its radius); expected its disc inside within "
                                     "grains.max_overlap = %g of its radius", where, c, c / r, f);
    if (c > 0) {
        s->overlaps.boundary++;
        s->overlaps.boundary_largest = fmax(s->overlaps.boundary_largest, c / r);
    }
    return GB_OK;
}

static gb_status too_large(const gb_scene *s, int i, double w, double h, const char *space, gb_error *err)
{
    if (2 * s->grains[i].r < w && 2 * s->grains[i].r < h) return GB_OK;
    return grain_fail(s, i, err, "is larger than %s (%g x %g); expected a diameter below its width and height",
                      space, w, h);
}

static gb_status admit_box(gb_scene *s, gb_error *err)
{
    static const char *const walls[4] = {"the left wall", "the right wall", "the bottom wall", "the top wall"};
    const gb_box *b = &s->box;
    gb_status st = GB_OK;
    for (int i = 0; !st && i < s->n_grains; i++) {
        const gb_grain *g = &s->grains[i];
        double gap[4] = {g->x - b->left, b->right - g->x, g->y - b->bottom, b->top - g->y};
        int w = 0;
        for (int k = 1; k < 4; k++)
            if (gap[k] < gap[w]) w = k;
        if ((st = too_large(s, i, b->right - b->left, b->top - b->bottom, "the box", err))) return st;
        if (!(gap[w] > 0))
            return grain_fail(s, i, err, "has its centre outside the box [%g, %g] x [%g, %g] (beyond %s)", b->left,
                              b->right, b->bottom, b->top, walls[w]);
        st = crossing(s, i, g->r - gap[w], walls[w], err);
    }
    return st;
}

/* The grain's overlap with the boundary particles of the cavity (half-discs of diameter the
 * element's length on its midpoint, bulging into the cavity): reported, not refused; the run
 * relaxes it, but a coarse cavity makes it large (docs/hybrid.md, "Meshes"). */
static void particle_overlap(gb_scene *s, const gb_bem_mesh *mesh, int cavity, int i, const double p[2])
{
    double worst = 0, r = s->grains[i].r;
    for (int e = 0; e < mesh->n; e++) {
        if (mesh->group[e] != cavity) continue;
        double dx = p[0] - mesh->mid[2 * e], dy = p[1] - mesh->mid[2 * e + 1];
        if (dx * mesh->normal[2 * e] + dy * mesh->normal[2 * e + 1] <= 0) continue; /* behind its flat side */
        worst = fmax(worst, r + 0.5 * mesh->length[e] - hypot(dx, dy));
    }
    if (worst > 0) s->overlaps.particles++;
    s->overlaps.particle_largest = fmax(s->overlaps.particle_largest, worst / r);
}

/* Against the host's cavity at rest (a restarted run's grains moved back as the cavity moved). */
static gb_status admit_host(gb_scene *s, const gb_bem_mesh *mesh, gb_error *err)
{
    int cavity = gb_bem_mesh_group(mesh, s->host.cavity);
    double box[4];
    gb_bem_mesh_group_box(mesh, cavity, box);
    char where[GB_BEM_NAME_MAX + 64];
    snprintf(where, sizeof where, "the boundary of the host's cavity '%s'", s->host.cavity);
    gb_status st = GB_OK;
    for (int i = 0; !st && i < s->n_grains; i++) {
        double p[2];
        gb_host_state_at_rest(&s->host_state, s->grains[i].x, s->grains[i].y, p);
        if ((st = too_large(s, i, box[1] - box[0], box[3] - box[2], "the host's cavity", err))) return st;
        if (!gb_bem_mesh_in_cavity(mesh, cavity, p[0], p[1]))
            return grain_fail(s, i, err, "has its centre outside the host's cavity '%s'%s", s->host.cavity,
                              s->host_state.present ? " (moved back as the state's cavity moved)" : "");
        st = crossing(s, i, s->grains[i].r - gb_bem_mesh_distance(mesh, p[0], p[1]), where, err);
        particle_overlap(s, mesh, cavity, i, p);
    }
    return st;
}

/* Pairs of grains through the contact module's cell list (no O(N^2) loop). */
static gb_status admit_pairs(gb_scene *s, gb_error *err)
{
    gb_pair_list L = {0};
    gb_world w = {s->grains, s->n_grains, NULL, NULL};
    gb_status st = gb_pairs_rebuild(&L, &w, err);
    for (int k = 0; !st && k < L.n; k++) {
        gb_pair *p = &L.p[k];
        gb_pair_geometry(p, &w);
        double rmin = fmin(s->grains[p->i].r, s->grains[p->j].r), f = s->max_overlap;
        if (!(p->d > 0)) continue;
        if (p->d > f * rmin)
            st = grain_fail(s, p->j, err, "overlaps grain %d by %g (%.3g of the smaller radius); expected at most "
                                          "grains.max_overlap = %g of it (the key allows up to 1 for jammed inputs)",
                            p->i, p->d, p->d / rmin, f);
        s->overlaps.grain_pairs++;
        s->overlaps.grain_largest = fmax(s->overlaps.grain_largest, p->d / rmin);
    }
    gb_pairs_free(&L);
    return st;
}

/* The coupling through half-disc particles is resolved as validated (validation/cavity_packing:
 * the longest cavity element 1.98 mean radii) up to GB_ELEMENT_RATIO_WARN: a grain in the notch
 * between two particles of length L sits L/2 + r - sqrt(r^2 + r L) deeper than on a flat
 * boundary, 0.27 r at L = 2 r, 0.38 r at 2.5 r, 0.5 r at 3 r. */
static void warn_elements(gb_scene *s)
{
    double ratio = s->host.cavity_max / s->overlaps.mean_radius;
    if (!(ratio > GB_ELEMENT_RATIO_WARN)) return;
    char inside[128] = "";
    if (s->overlaps.particles)
        snprintf(inside, sizeof inside, ", and %d grains start inside a particle by up to %.2g of their radius",
                 s->overlaps.particles, s->overlaps.particle_largest);
    snprintf(s->warning, sizeof s->warning, "the host's longest cavity element (%g) is %.3g mean grain radii (%g) "
             "long, more than %g: grains sit in notches between its boundary particles up to %.2g of a radius "
             "deep%s; give the cavity more elements", s->host.cavity_max, ratio, s->overlaps.mean_radius,
             GB_ELEMENT_RATIO_WARN, 0.5 * ratio + 1 - sqrt(1 + ratio), inside);
}

gb_status gb_scene_admit(gb_scene *s, const gb_bem_mesh *mesh, gb_error *err)
{
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL}, rsum = 0, rmax = 0;
    for (int i = 0; i < s->n_grains; i++) {
        const gb_grain *g = &s->grains[i];
        lo[0] = fmin(lo[0], g->x), hi[0] = fmax(hi[0], g->x), lo[1] = fmin(lo[1], g->y), hi[1] = fmax(hi[1], g->y);
        rsum += g->r, rmax = fmax(rmax, g->r);
    }
    s->overlaps.mean_radius = rsum / s->n_grains;
    /* the cell list differences coordinates: a span beyond the doubles' range has no cells */
    if (!isfinite(4 * (hi[0] - lo[0] + hi[1] - lo[1] + rmax)))
        return gb_fail(err, GB_EINPUT, "%s: the grains span more than a double can hold", s->grains_file);
    gb_status st = mesh ? admit_host(s, mesh, err) : admit_box(s, err);
    if (!st && mesh) warn_elements(s);
    return st ? st : admit_pairs(s, err);
}
