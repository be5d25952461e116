/* The geometric admission of a scene: before any computation, every grain's disc (not
 * only its centre) lies in the box or in the host's cavity, and no two grains overlap, within
 * grains.max_overlap of the (smaller) radius; a grain that does not fit the space at all is refused
 * whatever the tolerance. A grain refused is named by its file, line and column. The overlaps
 * accepted are counted for run_info.yaml. */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact/pairs.h"
#include "scene/admit.h"
#include "scene/grains_file.h"
#include "scene/state_read.h"

/* A grain touches a neighbour or its boundary when the gap is below this share of its radius:
 * the round-off of hand-placed touching grains (the three discs: 4e-16), not a gap to close. */
#define TOUCH_GAP 1e-9

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
static gb_status crossing(gb_scene *s, int i, double c, const char *where, const char *fix, gb_error *err)
{
    double r = s->grains[i].r, f = s->max_overlap;
    if (c > f * r)
        return grain_fail(s, i, err, "crosses %s by %g (%.3g of its radius); expected its disc inside within "
                                     "grains.max_overlap = %g of its radius: move it inwards by %.3g or more%s",
                          where, c, c / r, f, c - f * r, fix);
    if (c > 0) {
        s->overlaps.boundary++;
        s->overlaps.boundary_largest = fmax(s->overlaps.boundary_largest, c / r);
    }
    return GB_OK;
}

/* A grain that cannot fit its space: its diameter, less `slack` on each side, not below the space's
 * width and height. Walls take slack = grains.max_overlap of the radius, the crossing admitted on
 * each side: a disc pressed between two walls (a state gembem wrote after a compression) is
 * admitted as its crossings are. */
static gb_status too_large(const gb_scene *s, int i, double w, double h, double slack, const char *space,
                           gb_error *err)
{
    double d = 2 * (s->grains[i].r - slack);
    if (d < w && d < h) return GB_OK;
    return grain_fail(s, i, err, "is larger than %s (%g x %g); expected a diameter below its width and height%s: "
                      "check that r is in the same unit as the positions and %s (units.length: %s)",
                      space, w, h, slack > 0 ? " with grains.max_overlap of its radius on each side" : "",
                      s->host.present ? "the mesh" : "the box", s->length_unit);
}

/* A grain whose centre is outside its space: what to change, and when several are, the signature
 * of positions in another unit or about another origin than the box or the mesh. */
static gb_status outside(const gb_scene *s, int i, int n_outside, const char *what, const char *fix,
                         gb_error *err)
{
    char many[300] = "";
    if (n_outside > 1)
        snprintf(many, sizeof many, "; %d of the %d grains are outside: check that the grains and %s share their "
                 "origin and unit (units.length: %s)", n_outside, s->n_grains, s->host.present ? "the mesh" : "the box",
                 s->length_unit);
    return grain_fail(s, i, err, "has its centre outside %s: %s%s", what, fix, many);
}

/* The wall nearest a grain's centre (beyond which it is, if outside) and the gaps to the four. */
static int nearest_wall(const gb_box *b, const gb_grain *g, double gap[4])
{
    gap[0] = g->x - b->left, gap[1] = b->right - g->x, gap[2] = g->y - b->bottom, gap[3] = b->top - g->y;
    int w = 0;
    for (int k = 1; k < 4; k++)
        if (gap[k] < gap[w]) w = k;
    return w;
}

static gb_status admit_box(gb_scene *s, unsigned char *touch, gb_error *err)
{
    static const char *const walls[4] = {"the left wall", "the right wall", "the bottom wall", "the top wall"};
    const gb_box *b = &s->box;
    gb_status st = GB_OK;
    for (int i = 0; !st && i < s->n_grains; i++) {
        const gb_grain *g = &s->grains[i];
        double gap[4];
        int w = nearest_wall(b, g, gap);
        /* the wall moved to hold the whole disc */
        double edge[4] = {g->x - g->r, g->x + g->r, g->y - g->r, g->y + g->r};
        char fix[160], wall[64];
        snprintf(wall, sizeof wall, "box.%s: %g%s", gb_wall_name(w), edge[w], w % 2 ? " or more" : " or less");
        if ((st = too_large(s, i, b->right - b->left, b->top - b->bottom, s->max_overlap * g->r, "the box", err)))
            return st;
        if (!(gap[w] > 0)) {
            int n = 0;
            for (int k = 0; k < s->n_grains; k++) {
                double gk[4];
                n += !(gk[nearest_wall(b, &s->grains[k], gk)] > 0);
            }
            char what[160];
            snprintf(what, sizeof what, "the box [%g, %g] x [%g, %g] (beyond %s)", b->left, b->right, b->bottom,
                     b->top, walls[w]);
            snprintf(fix, sizeof fix, "move it inside or give %s", wall);
            return outside(s, i, n, what, fix, err);
        }
        snprintf(fix, sizeof fix, ", or give %s", wall);
        st = crossing(s, i, g->r - gap[w], walls[w], fix, err);
        touch[i] = gap[w] - g->r < TOUCH_GAP * g->r;
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
static gb_status admit_host(gb_scene *s, const gb_bem_mesh *mesh, unsigned char *touch, gb_error *err)
{
    int cavity = gb_bem_mesh_group(mesh, s->host.cavity);
    double box[4];
    gb_bem_mesh_group_box(mesh, cavity, box);
    char where[GB_BEM_NAME_MAX + 64];
    snprintf(where, sizeof where, "the boundary of the host's cavity '%s'", s->host.cavity);
    gb_status st = GB_OK;
    for (int i = 0; !st && i < s->n_grains; i++) {
        double p[2];
        gb_host_state_at_rest(&s->restart.host, s->grains[i].x, s->grains[i].y, p);
        if ((st = too_large(s, i, box[1] - box[0], box[3] - box[2], 0, "the host's cavity", err))) return st;
        if (!gb_bem_mesh_in_cavity(mesh, cavity, p[0], p[1])) {
            int n = 0;
            for (int k = 0; k < s->n_grains; k++) {
                double q[2];
                gb_host_state_at_rest(&s->restart.host, s->grains[k].x, s->grains[k].y, q);
                n += !gb_bem_mesh_in_cavity(mesh, cavity, q[0], q[1]);
            }
            char what[GB_BEM_NAME_MAX + 160], fix[160];
            snprintf(what, sizeof what, "the host's cavity '%s'%s", s->host.cavity,
                     s->restart.host.present ? " (moved back as the state's cavity moved)" : "");
            snprintf(fix, sizeof fix, "move it into the cavity (its bounding box: [%g, %g] x [%g, %g])", box[0], box[1],
                     box[2], box[3]);
            return outside(s, i, n, what, fix, err);
        }
        double gap = gb_bem_mesh_distance(mesh, p[0], p[1]) - s->grains[i].r;
        st = crossing(s, i, -gap, where, "", err);
        touch[i] = gap < TOUCH_GAP * s->grains[i].r;
        particle_overlap(s, mesh, cavity, i, p);
    }
    return st;
}

/* What the scan of the pairs finds: the first pair beyond the tolerance (its smaller grain first,
 * then its partner's index), how many are beyond, and the touches. */
typedef struct {
    gb_scene *s;
    unsigned char *touch;
    int first_i, first_j, beyond;
    double first_d;
} pair_scan;

static int visit_pair(void *user, int i, int j, double d)
{
    pair_scan *c = user;
    gb_scene *s = c->s;
    double rmin = fmin(s->grains[i].r, s->grains[j].r);
    c->touch[i] = c->touch[j] = 1;
    s->overlaps.grain_pairs++;
    s->overlaps.grain_largest = fmax(s->overlaps.grain_largest, d / rmin);
    if (!(d > s->max_overlap * rmin)) return 0;
    c->beyond++;
    if (c->first_i < 0 || (i == c->first_i && j < c->first_j)) c->first_i = i, c->first_j = j, c->first_d = d;
    return 1; /* the rest of grain i's pairs, then stop: coincident grains make N^2 / 2 pairs */
}

/* Pairs of grains through the contact module's cell grid, without a pair list: the scan stops at
 * the first grain with a partner beyond the tolerance, so that a million coincident grains are
 * refused in the time of one pass; marks the grains that touch one another in touch[]. */
static gb_status admit_pairs(gb_scene *s, unsigned char *touch, gb_error *err)
{
    gb_pair_search S = {0};
    gb_world w = {s->grains, s->n_grains, NULL, NULL};
    pair_scan c = {s, touch, -1, -1, 0, 0};
    gb_status st = gb_pairs_scan_overlaps(&S, &w, visit_pair, &c, err);
    gb_pair_search_free(&S);
    if (st || c.first_i < 0) return st;
    int i = c.first_i, j = c.first_j;
    double f = s->max_overlap, ratio = c.first_d / fmin(s->grains[i].r, s->grains[j].r);
    char fix[300], pairs[96] = "", partner[64] = "";
    if (c.beyond > 1) snprintf(pairs, sizeof pairs, " (grain %d overlaps %d grains beyond it)", i, c.beyond);
    if (s->grain_line) snprintf(partner, sizeof partner, " (line %d)", s->grain_line[i]);
    /* a centre inside the other disc: no packing does that, radii in another unit do */
    if (s->overlaps.grain_largest > 1)
        snprintf(fix, sizeof fix, "overlaps of more than a radius (up to %.3g) put centres inside other grains: "
                 "check that the radii are in the same unit as the positions (units.length: %s)",
                 s->overlaps.grain_largest, s->length_unit);
    else
        snprintf(fix, sizeof fix, "move the grains apart (gembem pack places grains without such overlaps), or "
                 "give grains.max_overlap: %.2f if the packing is jammed on purpose",
                 ceil(20 * s->overlaps.grain_largest) / 20);
    return grain_fail(s, j, err, "overlaps grain %d%s by %g (%.3g of the smaller radius); expected at most "
                                 "grains.max_overlap = %g of it%s: %s", i, partner, c.first_d, ratio, f, pairs, fix);
}

void gb_scene_warn(gb_scene *s, const char *fmt, ...)
{
    size_t used = strlen(s->warning);
    if (used) used += (size_t)snprintf(s->warning + used, sizeof s->warning - used, "; also ");
    if (used >= sizeof s->warning) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s->warning + used, sizeof s->warning - used, fmt, ap);
    va_end(ap);
}

/* The coupling through half-disc particles is resolved as validated (validation/cavity_packing:
 * the longest cavity element 1.98 mean radii) up to GB_ELEMENT_RATIO_WARN: a grain in the notch
 * between two particles of length L sits L/2 + r - sqrt(r^2 + r L) deeper than on a flat
 * boundary, 0.27 r at L = 2 r, 0.38 r at 2.5 r, 0.5 r at 3 r. The count suggested makes the
 * cavity's elements 2 mean radii long on average, as validated. */
static void warn_elements(gb_scene *s, const gb_bem_mesh *mesh)
{
    double ratio = s->host.cavity_max / s->overlaps.mean_radius;
    if (!(ratio > GB_ELEMENT_RATIO_WARN)) return;
    char inside[128] = "", fix[200];
    if (s->overlaps.particles)
        snprintf(inside, sizeof inside, ", and %d grains start inside a particle by up to %.2g of their radius",
                 s->overlaps.particles, s->overlaps.particle_largest);
    int cavity = gb_bem_mesh_group(mesh, s->host.cavity);
    double perimeter = 0;
    for (int e = 0; e < mesh->n; e++)
        if (mesh->group[e] == cavity) perimeter += mesh->length[e];
    int n = (int)ceil(perimeter / (2 * s->overlaps.mean_radius));
    if (gb_bem_mesh_file_is_msh(s->host.mesh))
        snprintf(fix, sizeof fix, "mesh the cavity finer (elements of at most %.3g, about %d on it)",
                 2 * s->overlaps.mean_radius, n);
    else
        snprintf(fix, sizeof fix, "host.elements: {%s: %d} (elements of 2 mean radii)", s->host.cavity, n);
    gb_scene_warn(s, "the host's longest cavity element (%g) is %.3g mean grain radii (%g) long, more than %g: grains "
                  "sit in notches between its boundary particles up to %.2g of a radius deep%s; give the cavity more "
                  "elements: %s", s->host.cavity_max, ratio, s->overlaps.mean_radius, GB_ELEMENT_RATIO_WARN,
                  0.5 * ratio + 1 - sqrt(1 + ratio), inside, fix);
}

/* A packing whose grains mostly touch nothing, no body force to bring them together and a first
 * load that cannot either (a strain or a host stage; a stress stage closes the gaps itself): the
 * load reaches no grain until the walls or the cavity do, and then only a few. */
static void warn_loose(gb_scene *s, const unsigned char *touch)
{
    int loose = 0;
    for (int i = 0; i < s->n_grains; i++) loose += !touch[i];
    /* (one grain alone is a host's probe, as in tests/hybrid) */
    if (s->body_force_per_area[0] != 0 || s->body_force_per_area[1] != 0 || 2 * loose <= s->n_grains || loose < 2)
        return;
    int k = 0;
    while (k < s->n_stages && s->stages[k].kind == GB_STAGE_RELAX) k++;
    if (k == s->n_stages) return;
    gb_stage_kind kind = s->stages[k].kind;
    if (kind != GB_STAGE_STRAIN && kind != GB_STAGE_HOST_DISPLACEMENT && kind != GB_STAGE_HOST_LOAD) return;
    gb_scene_warn(s, "%d of the %d grains touch neither another grain nor %s, and no body force moves them: the "
                  "packing is not jammed and loading[%d] loads only the grains its boundary reaches; %s, or check "
                  "that r is in the same unit as the positions (units.length: %s)", loose, s->n_grains,
                  s->host.present ? "the cavity" : "a wall", k,
                  s->host.present ? "pack them with gembem pack (docs/packing.md) first"
                                  : "compress them first (a stage '- isotropic: {stress: ..., steps: ...}') or pack "
                                    "them with gembem pack (docs/packing.md)",
                  s->length_unit);
}

/* Strain stages are compression positive: a stage that compresses in no direction and extends the
 * box beyond its start, as a sign mix-up does, leaves the grains behind (an unloading within the
 * compression before it, or the lateral extension of a biaxial stage, is not warned). */
static void warn_extension(gb_scene *s)
{
    double e[2] = {0, 0}; /* the box's strain from the start, by the strain stages */
    for (int k = 0; k < s->n_stages; k++) {
        const gb_stage *sg = &s->stages[k];
        if (sg->kind != GB_STAGE_STRAIN) continue;
        e[0] += sg->steps * sg->de1, e[1] += sg->steps * sg->de2;
        if (sg->de1 <= 0 && sg->de2 <= 0 && ((sg->de1 < 0 && e[0] < 0) || (sg->de2 < 0 && e[1] < 0))) {
            gb_scene_warn(s, "loading[%d].strain: de1 %g and de2 %g extend the box beyond its start (compression is "
                          "positive in gembem): the walls leave the grains, which carry no stress; for a compression "
                          "give de1: %g, de2: %g", k, sg->de1, sg->de2, 0 - sg->de1, 0 - sg->de2);
            return;
        }
    }
}

static const double DEGREES = 57.295779513082321; /* in a radian */

/* Contact laws that the readers accept but that are likely mistakes. */
static void warn_material(gb_scene *s, const char *name, const gb_material *m)
{
    /* Mindlin's elastic discs: kt/kn = 2(1 - nu)/(2 - nu), 1 at nu = 0 down to 2/3 at nu = 0.5 */
    if (m->kt > m->kn)
        gb_scene_warn(s, "materials.%s: kt %g is larger than kn %g; elastic grains have kt/kn from 2/3 to 1 "
                      "(Kishino: 0.7): check kt", name, m->kt, m->kn);
    /* a coefficient (0.5) or an angle in radians (0.44) where degrees are expected */
    if (m->friction_deg > 0 && m->friction_deg <= 1)
        gb_scene_warn(s, "materials.%s.friction_deg %g is an angle in degrees, almost no friction; for a friction "
                      "coefficient mu give friction_deg: atan(mu) in degrees (mu %g: %.3g), for radians times 57.3 "
                      "(%.3g)", name, m->friction_deg, m->friction_deg, atan(m->friction_deg) * DEGREES,
                      m->friction_deg * DEGREES);
}

/* A coordinate near X is held to the spacing of doubles there, between eps X / 2 and eps X: as a
 * grain moves from one double to the next, each of its contacts' forces jumps by up to kn eps X,
 * and its fixing force (their sum, all moving with the one position) cannot be brought below about
 * half a jump. The grains of the scene's outer half (|x| >= X / 2) have jumps of at least kn eps X
 * / 4, so no iteration takes them all below kn eps X / 8. Measured (the three discs of
 * validation/three_discs in their box [0, 4]^2, three contacts a grain): the reference iteration
 * stalls at 0.56 kn eps X, the global solver at 0.25; shifted to x = 1000, at 0.51. The contacts
 * per grain do not multiply it: their errors move together with the grain. */
double gb_scene_force_resolution(const gb_scene *s, double *kn, double *x)
{
    const gb_box *b = &s->box; /* with a host, the grains' bounding box */
    *x = fmax(fmax(fabs(b->left), fabs(b->right)), fmax(fabs(b->bottom), fabs(b->top)));
    *kn = fmax(s->grain_grain.kn, s->host.present ? s->grain_boundary.kn : s->grain_wall.kn);
    return *kn * DBL_EPSILON * *x;
}

/* 10 times the resolution: a stall there is a tenth of the accuracy. */
double gb_scene_suggested_accuracy(double resolution)
{
    return pow(10, ceil(log10(10 * resolution)));
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
    unsigned char *touch = calloc((size_t)s->n_grains, 1);
    if (!touch) return gb_fail(err, GB_ENOMEM, "out of memory for %d grains", s->n_grains);
    gb_status st = mesh ? admit_host(s, mesh, touch, err) : admit_box(s, touch, err);
    if (!st) st = admit_pairs(s, touch, err);
    if (!st) {
        if (mesh) warn_elements(s, mesh);
        warn_loose(s, touch);
        warn_extension(s);
        warn_material(s, "grain_grain", &s->grain_grain);
        if (mesh) warn_material(s, "grain_boundary", &s->grain_boundary);
        else warn_material(s, "grain_wall", &s->grain_wall);
    }
    free(touch);
    return st;
}
