/* Boundary meshes from closed polygons: checks (zero-length elements, crossings, nesting) and
 * orientation by the body's outward normal from each loop's signed area. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bem/kernel.h"
#include "gembem/bem.h"

gb_bem_mesh_opts gb_bem_mesh_opts_default(void)
{
    gb_bem_mesh_opts o;
    memset(&o, 0, sizeof o);
    return o;
}

void gb_bem_mesh_free(gb_bem_mesh *m)
{
    if (!m) return;
    free(m->p0);
    free(m->p1);
    free(m->mid);
    free(m->tangent);
    free(m->normal);
    free(m->length);
    free(m->group);
    free(m->loop);
    free(m->loop_start);
    free(m->loop_outer);
    free(m->group_name);
    memset(m, 0, sizeof *m);
}

int gb_bem_mesh_group(const gb_bem_mesh *m, const char *name)
{
    for (int g = 0; g < m->n_groups; g++)
        if (!strcmp(m->group_name[g], name)) return g;
    return -1;
}

static double cross3(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/* Crossing-number test of a point against one closed polygon (vertices v, m of them). */
static int in_polygon(const double *v, int m, double x, double y)
{
    int in = 0;
    for (int i = 0, j = m - 1; i < m; j = i++) {
        const double *a = v + 2 * i, *b = v + 2 * j;
        if ((a[1] > y) != (b[1] > y) && x < (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
    }
    return in;
}

int gb_bem_mesh_inside(const gb_bem_mesh *m, double x, double y)
{
    for (int k = 0; k < m->n_loops; k++) {
        int s = m->loop_start[k], cnt = m->loop_start[k + 1] - s;
        int in = in_polygon(m->p0 + 2 * s, cnt, x, y);
        if (m->loop_outer[k] ? !in : in) return 0;
    }
    return 1;
}

int gb_bem_mesh_in_cavity(const gb_bem_mesh *m, int group, double x, double y)
{
    if (gb_bem_mesh_inside(m, x, y)) return 0;
    double box[4];
    gb_bem_mesh_group_box(m, group, box);
    return x > box[0] && x < box[1] && y > box[2] && y < box[3];
}

void gb_bem_mesh_group_box(const gb_bem_mesh *m, int group, double box[4])
{
    box[0] = box[2] = HUGE_VAL, box[1] = box[3] = -HUGE_VAL;
    for (int e = 0; e < m->n; e++)
        if (m->group[e] == group)
            for (int c = 0; c < 2; c++) {
                box[2 * c] = fmin(box[2 * c], fmin(m->p0[2 * e + c], m->p1[2 * e + c]));
                box[2 * c + 1] = fmax(box[2 * c + 1], fmax(m->p0[2 * e + c], m->p1[2 * e + c]));
            }
}

double gb_bem_mesh_distance(const gb_bem_mesh *m, double x, double y)
{
    double best = INFINITY;
    for (int e = 0; e < m->n; e++) {
        const double *a = m->p0 + 2 * e, *b = m->p1 + 2 * e;
        double d[2] = {b[0] - a[0], b[1] - a[1]}, w[2] = {x - a[0], y - a[1]};
        double s = (w[0] * d[0] + w[1] * d[1]) / (d[0] * d[0] + d[1] * d[1]);
        s = s < 0 ? 0 : s > 1 ? 1 : s;
        best = fmin(best, hypot(w[0] - s * d[0], w[1] - s * d[1]));
    }
    return best;
}

/* Do segments [a,b] and [c,d] share any point (touching included)? eps: a length tolerance. */
static int segments_meet(const double *a, const double *b, const double *c, const double *d, double eps)
{
    double lo1[2], hi1[2];
    for (int i = 0; i < 2; i++) {
        lo1[i] = fmin(a[i], b[i]) - eps;
        hi1[i] = fmax(a[i], b[i]) + eps;
        if (fmax(c[i], d[i]) < lo1[i] || fmin(c[i], d[i]) > hi1[i]) return 0;
    }
    double lab = hypot(b[0] - a[0], b[1] - a[1]), lcd = hypot(d[0] - c[0], d[1] - c[1]);
    double d1 = cross3(a, b, c) / lab, d2 = cross3(a, b, d) / lab; /* signed distances to line ab */
    double d3 = cross3(c, d, a) / lcd, d4 = cross3(c, d, b) / lcd;
    if (((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) && ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps)))
        return 1; /* proper crossing */
    /* an end point within eps of the other segment */
    const double *pts[4] = {c, d, a, b};
    const double *s0[4] = {a, a, c, c}, *s1[4] = {b, b, d, d};
    for (int i = 0; i < 4; i++) {
        const double *p = pts[i], *u = s0[i], *v = s1[i];
        double e[2] = {v[0] - u[0], v[1] - u[1]}, w[2] = {p[0] - u[0], p[1] - u[1]};
        double s = (w[0] * e[0] + w[1] * e[1]) / (e[0] * e[0] + e[1] * e[1]);
        if (s < 0) s = 0;
        if (s > 1) s = 1;
        if (hypot(w[0] - s * e[0], w[1] - s * e[1]) <= eps) return 1;
    }
    return 0;
}

typedef struct {
    double xmin;
    int e;
} sweep_item;

static int cmp_sweep(const void *a, const void *b)
{
    double x = ((const sweep_item *)a)->xmin, y = ((const sweep_item *)b)->xmin;
    return x < y ? -1 : x > y;
}

/* Refuses crossings and touchings between non-adjacent elements, and adjacent elements folding
 * back on each other; sort-and-sweep on x. */
static gb_status check_crossings(const gb_bem_mesh *m, double eps, gb_error *err)
{
    int n = m->n;
    sweep_item *it = malloc((size_t)n * sizeof *it);
    if (!it) return gb_fail(err, GB_ENOMEM, "out of memory");
    for (int e = 0; e < n; e++) {
        it[e].xmin = fmin(m->p0[2 * e], m->p1[2 * e]);
        it[e].e = e;
    }
    qsort(it, (size_t)n, sizeof *it, cmp_sweep);
    gb_status st = GB_OK;
    for (int a = 0; a < n && !st; a++) {
        int i = it[a].e;
        double xmax = fmax(m->p0[2 * i], m->p1[2 * i]) + eps;
        for (int b = a + 1; b < n && it[b].xmin <= xmax && !st; b++) {
            int j = it[b].e;
            int adjacent = 0, first = i, second = j;
            if (m->loop[i] == m->loop[j]) {
                int s = m->loop_start[m->loop[i]], c = m->loop_start[m->loop[i] + 1] - s;
                int di = i - s, dj = j - s;
                if ((di + 1) % c == dj)
                    adjacent = 1;
                else if ((dj + 1) % c == di)
                    adjacent = 1, first = j, second = i;
            }
            if (adjacent) {
                /* the shared vertex is fine; a fold-back (the two elements overlap) is not */
                const double *t1 = m->tangent + 2 * first, *t2 = m->tangent + 2 * second;
                if (fabs(t1[0] * t2[1] - t1[1] * t2[0]) < 1e-12 && t1[0] * t2[0] + t1[1] * t2[1] < 0)
                    st = gb_fail(err, GB_EINPUT, "the boundary folds back on itself at (%.6g, %.6g) (group '%s')",
                                 m->p1[2 * first], m->p1[2 * first + 1], m->group_name[m->group[first]]);
                continue;
            }
            if (segments_meet(m->p0 + 2 * i, m->p1 + 2 * i, m->p0 + 2 * j, m->p1 + 2 * j, eps))
                st = gb_fail(err, GB_EINPUT,
                             "the boundary crosses or touches itself near (%.6g, %.6g): elements %d (group '%s') "
                             "and %d (group '%s')",
                             m->mid[2 * i], m->mid[2 * i + 1], i, m->group_name[m->group[i]], j,
                             m->group_name[m->group[j]]);
        }
    }
    free(it);
    return st;
}

static void fill_geometry(gb_bem_mesh *m, int e)
{
    double *a = m->p0 + 2 * e, *b = m->p1 + 2 * e;
    double L = hypot(b[0] - a[0], b[1] - a[1]);
    m->length[e] = L;
    m->mid[2 * e] = 0.5 * (a[0] + b[0]);
    m->mid[2 * e + 1] = 0.5 * (a[1] + b[1]);
    m->tangent[2 * e] = L > 0 ? (b[0] - a[0]) / L : 0;
    m->tangent[2 * e + 1] = L > 0 ? (b[1] - a[1]) / L : 0;
    m->normal[2 * e] = m->tangent[2 * e + 1];
    m->normal[2 * e + 1] = -m->tangent[2 * e];
}

/* The mesh's arrays for n elements in n_loops loops and its groups' names (given, or group<k>). */
static gb_status alloc_mesh(gb_bem_mesh *m, int n, int n_loops, int n_groups, const char *const *names,
                            gb_error *err)
{
    m->n = n;
    m->n_loops = n_loops;
    m->n_groups = n_groups;
    m->p0 = malloc(sizeof(double) * 2 * (size_t)n);
    m->p1 = malloc(sizeof(double) * 2 * (size_t)n);
    m->mid = malloc(sizeof(double) * 2 * (size_t)n);
    m->tangent = malloc(sizeof(double) * 2 * (size_t)n);
    m->normal = malloc(sizeof(double) * 2 * (size_t)n);
    m->length = malloc(sizeof(double) * (size_t)n);
    m->group = malloc(sizeof(int) * (size_t)n);
    m->loop = malloc(sizeof(int) * (size_t)n);
    m->loop_start = malloc(sizeof(int) * (size_t)(n_loops + 1));
    m->loop_outer = calloc((size_t)n_loops, sizeof(int));
    m->group_name = calloc((size_t)n_groups, sizeof *m->group_name);
    if (!m->p0 || !m->p1 || !m->mid || !m->tangent || !m->normal || !m->length || !m->group || !m->loop ||
        !m->loop_start || !m->loop_outer || !m->group_name)
        return gb_fail(err, GB_ENOMEM, "out of memory for %d boundary elements", n);
    for (int g = 0; g < n_groups; g++) {
        if (names)
            snprintf(m->group_name[g], GB_BEM_NAME_MAX, "%s", names[g]);
        else
            snprintf(m->group_name[g], GB_BEM_NAME_MAX, "group%d", g);
    }
    return GB_OK;
}

/* The diagonal of the n vertices' bounding box (the size of the problem, for tolerances); an error
 * for a vertex that is not finite. */
static gb_status extent(const double *xy, int n, double *diag, gb_error *err)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < n; v++)
        for (int c = 0; c < 2; c++) {
            if (!isfinite(xy[2 * v + c])) return gb_fail(err, GB_EINPUT, "boundary vertex %d is not finite", v);
            lo[c] = fmin(lo[c], xy[2 * v + c]);
            hi[c] = fmax(hi[c], xy[2 * v + c]);
        }
    *diag = hypot(hi[0] - lo[0], hi[1] - lo[1]);
    return GB_OK;
}

/* Each loop's signed area, and how many other loops hold its first vertex (loops do not cross,
 * checked later). */
static void loop_areas(const double *xy, int n_loops, const int *loop_n, const int *start, double *area,
                       int *inside_count)
{
    for (int k = 0; k < n_loops; k++) {
        double A = 0;
        for (int i = 0; i < loop_n[k]; i++) {
            const double *a = xy + 2 * (start[k] + i), *b = xy + 2 * (start[k] + (i + 1) % loop_n[k]);
            A += a[0] * b[1] - a[1] * b[0];
        }
        area[k] = 0.5 * A;
        for (int j = 0; j < n_loops; j++)
            if (j != k && in_polygon(xy + 2 * start[j], loop_n[j], xy[2 * start[k]], xy[2 * start[k] + 1]))
                inside_count[k]++;
    }
}

/* The loops' nesting: every loop encloses an area; a bounded body has one outermost loop (*outer)
 * around its cavities and no islands, an infinite plane only cavities. */
static gb_status check_nesting(const gb_bem_mesh *m, const int *edge_group, const int *start, const double *area,
                               const int *inside_count, double eps, double diag, int *outer, gb_error *err)
{
    int n_loops = m->n_loops, unbounded = m->unbounded;
    *outer = -1;
    for (int k = 0; k < n_loops; k++) {
        const char *name = m->group_name[edge_group[start[k]]];
        if (!(fabs(area[k]) > eps * diag))
            return gb_fail(err, GB_EINPUT, "loop %d (group '%s') encloses no area (does it cross itself?)", k, name);
        if (unbounded && inside_count[k] > 0)
            return gb_fail(err, GB_EINPUT,
                           "loop %d (group '%s') lies inside another loop: an infinite plane holds cavities only", k,
                           name);
        if (!unbounded && inside_count[k] == 0) {
            if (*outer >= 0)
                return gb_fail(err, GB_EINPUT,
                               "loops %d and %d (groups '%s', '%s') are both outermost: a bounded body needs one "
                               "outer boundary enclosing its cavities (or set the mesh unbounded)",
                               *outer, k, m->group_name[edge_group[start[*outer]]], name);
            *outer = k;
        } else if (!unbounded && inside_count[k] > 1)
            return gb_fail(err, GB_EINPUT, "loop %d (group '%s') lies inside a cavity: islands are not supported", k,
                           name);
    }
    if (!unbounded && *outer < 0) return gb_fail(err, GB_EINPUT, "no outer boundary found");
    if (!unbounded && n_loops > 1 && fabs(area[*outer]) <= 0)
        return gb_fail(err, GB_EINPUT, "the outer boundary encloses no area");
    return GB_OK;
}

/* Loop k's elements in body orientation (the outer loop counter-clockwise, cavities clockwise),
 * from its vertices and their groups; an error for an element shorter than eps. */
static gb_status orient_loop(gb_bem_mesh *m, int k, const double *xy, const int *edge_group, const int *start,
                             int count, double area, int outer, double eps, gb_error *err)
{
    gb_status st = GB_OK;
    int want_ccw = !m->unbounded && k == outer;
    int reverse = want_ccw ? area < 0 : area > 0;
    m->loop_start[k] = start[k];
    m->loop_outer[k] = want_ccw;
    for (int j = 0; j < count; j++) {
        int e = start[k] + j, src, va, vb;
        if (!reverse) {
            src = j;
            va = j;
            vb = (j + 1) % count;
        } else {
            src = count - 1 - j;
            va = (src + 1) % count;
            vb = src;
        }
        m->p0[2 * e] = xy[2 * (start[k] + va)];
        m->p0[2 * e + 1] = xy[2 * (start[k] + va) + 1];
        m->p1[2 * e] = xy[2 * (start[k] + vb)];
        m->p1[2 * e + 1] = xy[2 * (start[k] + vb) + 1];
        m->group[e] = edge_group[start[k] + src];
        m->loop[e] = k;
        fill_geometry(m, e);
        if (!(m->length[e] > eps) && !st)
            st = gb_fail(err, GB_EINPUT, "zero-length element at (%.6g, %.6g) in group '%s'", m->p0[2 * e],
                         m->p0[2 * e + 1], m->group_name[m->group[e]]);
    }
    return st;
}

gb_status gb_bem_mesh_from_polygons(int n_loops, const int *loop_n, const double *xy, const int *edge_group,
                                    int n_groups, const char *const *names, int unbounded, gb_bem_mesh *m,
                                    gb_error *err)
{
    memset(m, 0, sizeof *m);
    if (n_loops < 1) return gb_fail(err, GB_EINPUT, "the boundary has no closed loop");
    if (n_groups < 1 || n_groups > GB_BEM_MAX_GROUPS)
        return gb_fail(err, GB_EINPUT, "%d boundary groups; expected 1 to %d", n_groups, GB_BEM_MAX_GROUPS);
    int n = 0;
    for (int k = 0; k < n_loops; k++) {
        if (loop_n[k] < 3)
            return gb_fail(err, GB_EINPUT, "loop %d has %d element(s); a closed loop needs at least 3", k, loop_n[k]);
        n += loop_n[k];
    }
    for (int e = 0; e < n; e++)
        if (edge_group[e] < 0 || edge_group[e] >= n_groups)
            return gb_fail(err, GB_EINPUT, "element %d: group %d out of range", e, edge_group[e]);
    m->unbounded = unbounded ? 1 : 0;
    double diag = 0;
    gb_status st = alloc_mesh(m, n, n_loops, n_groups, names, err);
    if (!st) st = extent(xy, n, &diag, err);
    double eps = 1e-10 * diag;
    double *area = malloc(sizeof(double) * (size_t)n_loops);
    int *inside_count = calloc((size_t)n_loops, sizeof(int));
    int *start = malloc(sizeof(int) * (size_t)(n_loops + 1));
    if (!st && (!area || !inside_count || !start)) st = gb_fail(err, GB_ENOMEM, "out of memory");
    int outer = -1;
    if (!st) {
        start[0] = 0;
        for (int k = 0; k < n_loops; k++) start[k + 1] = start[k] + loop_n[k];
        loop_areas(xy, n_loops, loop_n, start, area, inside_count);
        st = check_nesting(m, edge_group, start, area, inside_count, eps, diag, &outer, err);
    }
    for (int k = 0; k < n_loops && !st; k++)
        st = orient_loop(m, k, xy, edge_group, start, loop_n[k], area[k], outer, eps, err);
    if (!st) m->loop_start[n_loops] = n;
    free(area);
    free(inside_count);
    free(start);
    if (!st) st = check_crossings(m, eps, err);
    if (st) gb_bem_mesh_free(m);
    return st;
}

gb_status gb_bem_mesh_circle(double cx, double cy, double r, int n, int unbounded, gb_bem_mesh *mesh, gb_error *err)
{
    if (n < 3) return gb_fail(err, GB_EINPUT, "a circle needs at least 3 elements");
    double *xy = malloc(sizeof(double) * 2 * (size_t)n);
    int *grp = calloc((size_t)n, sizeof(int));
    if (!xy || !grp) {
        free(xy);
        free(grp);
        return gb_fail(err, GB_ENOMEM, "out of memory");
    }
    for (int i = 0; i < n; i++) {
        double a = 2 * GB_PI * i / n;
        xy[2 * i] = cx + r * cos(a);
        xy[2 * i + 1] = cy + r * sin(a);
    }
    const char *names[1] = {unbounded ? "cavity" : "outer"};
    int ln[1] = {n};
    gb_status st = gb_bem_mesh_from_polygons(1, ln, xy, grp, 1, names, unbounded, mesh, err);
    free(xy);
    free(grp);
    return st;
}

/* Signed area of loop k from its elements' start points. */
static double loop_area(const gb_bem_mesh *m, int k)
{
    double A = 0;
    for (int e = m->loop_start[k]; e < m->loop_start[k + 1]; e++)
        A += m->p0[2 * e] * m->p1[2 * e + 1] - m->p0[2 * e + 1] * m->p1[2 * e];
    return 0.5 * A;
}

/* The node between elements ep and e (p1 of ep, p0 of e) takes the displacement interpolated
 * linearly along the boundary between their midpoints, which lie L_ep / 2 and L_e / 2 from it. */
static void node_displacement(const gb_bem_mesh *m, const double *u, int ep, int e, double v[2])
{
    double w = m->length[e] / (m->length[ep] + m->length[e]);
    for (int c = 0; c < 2; c++) v[c] = w * u[2 * ep + c] + (1 - w) * u[2 * e + c];
}

gb_status gb_bem_mesh_place(gb_bem_mesh *m, const double *p0, const double *p1, gb_error *err)
{
    size_t n2 = 2 * (size_t)m->n;
    double *old = malloc(sizeof(double) * 2 * n2), *area = malloc(sizeof(double) * (size_t)m->n_loops);
    if (!old || !area) {
        free(old), free(area);
        return gb_fail(err, GB_ENOMEM, "out of memory");
    }
    memcpy(old, m->p0, sizeof(double) * n2);
    memcpy(old + n2, m->p1, sizeof(double) * n2);
    for (int k = 0; k < m->n_loops; k++) area[k] = loop_area(m, k);
    memcpy(m->p0, p0, sizeof(double) * n2);
    memcpy(m->p1, p1, sizeof(double) * n2);
    double diag = 0;
    gb_status st = extent(m->p0, m->n, &diag, err);
    if (!st) st = extent(m->p1, m->n, &diag, err);
    for (int e = 0; e < m->n; e++) fill_geometry(m, e);
    for (int e = 0; e < m->n && !st; e++) {
        /* a turn past a right angle in one move is no small rotation (a point reflection through a
         * cavity's centre keeps every loop's orientation and crosses nothing) */
        double dx = old[2 * e + n2] - old[2 * e], dy = old[2 * e + 1 + n2] - old[2 * e + 1];
        if (!(m->length[e] > 1e-10 * diag))
            st = gb_fail(err, GB_EINPUT, "moved by its displacement, element %d (group '%s') has no length left", e,
                         m->group_name[m->group[e]]);
        else if (!(dx * m->tangent[2 * e] + dy * m->tangent[2 * e + 1] > 0))
            st = gb_fail(err, GB_EINPUT,
                         "moved by its displacement, element %d (group '%s') turns by more than a right angle: "
                         "too large a displacement for one move",
                         e, m->group_name[m->group[e]]);
    }
    for (int e = 0; e < m->n && !st; e++) { /* a loop stays closed: each element ends where the next starts */
        int k = m->loop[e], next = e + 1 < m->loop_start[k + 1] ? e + 1 : m->loop_start[k];
        if (m->p1[2 * e] != m->p0[2 * next] || m->p1[2 * e + 1] != m->p0[2 * next + 1])
            st = gb_fail(err, GB_EINPUT, "element %d (group '%s') does not end where the next starts", e,
                         m->group_name[m->group[e]]);
    }
    for (int k = 0; k < m->n_loops && !st; k++)
        if (!(loop_area(m, k) * area[k] > 0))
            st = gb_fail(err, GB_EINPUT, "moved by its displacement, loop %d (group '%s') turns inside out", k,
                         m->group_name[m->group[m->loop_start[k]]]);
    if (!st) st = check_crossings(m, 1e-10 * diag, err);
    if (st) { /* back to where it was: the caller keeps a valid mesh */
        memcpy(m->p0, old, sizeof(double) * n2);
        memcpy(m->p1, old + n2, sizeof(double) * n2);
        for (int e = 0; e < m->n; e++) fill_geometry(m, e);
    }
    free(old);
    free(area);
    return st;
}

gb_status gb_bem_mesh_move(gb_bem_mesh *m, const double *u, gb_error *err)
{
    size_t n2 = 2 * (size_t)m->n;
    double *p = malloc(sizeof(double) * 2 * n2);
    if (!p) return gb_fail(err, GB_ENOMEM, "out of memory");
    memcpy(p, m->p0, sizeof(double) * n2);
    memcpy(p + n2, m->p1, sizeof(double) * n2);
    for (int k = 0; k < m->n_loops; k++) {
        int s0 = m->loop_start[k], c = m->loop_start[k + 1] - s0;
        for (int j = 0; j < c; j++) {
            int e = s0 + j, ep = s0 + (j + c - 1) % c;
            double v[2];
            node_displacement(m, u, ep, e, v);
            for (int q = 0; q < 2; q++) {
                p[2 * e + q] = m->p0[2 * e + q] + v[q];
                p[n2 + 2 * ep + q] = m->p1[2 * ep + q] + v[q];
            }
        }
    }
    gb_status st = gb_bem_mesh_place(m, p, p + n2, err);
    free(p);
    return st;
}

gb_status gb_bem_mesh_copy(const gb_bem_mesh *src, gb_bem_mesh *dst, gb_error *err)
{
    memset(dst, 0, sizeof *dst);
    gb_status st = alloc_mesh(dst, src->n, src->n_loops, src->n_groups, NULL, err);
    if (st) {
        gb_bem_mesh_free(dst);
        return st;
    }
    size_t n = (size_t)src->n;
    memcpy(dst->p0, src->p0, 2 * n * sizeof(double)), memcpy(dst->p1, src->p1, 2 * n * sizeof(double));
    memcpy(dst->mid, src->mid, 2 * n * sizeof(double)), memcpy(dst->tangent, src->tangent, 2 * n * sizeof(double));
    memcpy(dst->normal, src->normal, 2 * n * sizeof(double)), memcpy(dst->length, src->length, n * sizeof(double));
    memcpy(dst->group, src->group, n * sizeof(int)), memcpy(dst->loop, src->loop, n * sizeof(int));
    memcpy(dst->loop_start, src->loop_start, (size_t)(src->n_loops + 1) * sizeof(int));
    memcpy(dst->loop_outer, src->loop_outer, (size_t)src->n_loops * sizeof(int));
    memcpy(dst->group_name, src->group_name, (size_t)src->n_groups * sizeof *src->group_name);
    dst->unbounded = src->unbounded;
    return GB_OK;
}
