/* Delaunay triangulation of grain centres with qhull's reentrant library (libqhull_r). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <libqhull_r/libqhull_r.h>

#include "gembem/strain_field.h"

void gb_triangulation_free(gb_triangulation *t)
{
    free(t->v);
    memset(t, 0, sizeof *t);
}

/* Twice the signed area of the triangle (a, b, c). */
static double cross3(const double *xy, int a, int b, int c)
{
    return (xy[2 * b] - xy[2 * a]) * (xy[2 * c + 1] - xy[2 * a + 1]) -
           (xy[2 * b + 1] - xy[2 * a + 1]) * (xy[2 * c] - xy[2 * a]);
}

/* Refuses what qhull cannot triangulate, with a message that says why. */
static gb_status check_input(int n, const double *xy, gb_error *err)
{
    if (n < 3) return gb_fail(err, GB_EINPUT, "triangulation: %d point(s), at least 3 needed", n);
    for (int i = 0; i < 2 * n; i++)
        if (!isfinite(xy[i])) return gb_fail(err, GB_EINPUT, "triangulation: point %d is not finite", i / 2);
    /* The farthest point from the first, then the largest area with both. */
    int far = 0;
    double d2max = 0;
    for (int i = 1; i < n; i++) {
        double dx = xy[2 * i] - xy[0], dy = xy[2 * i + 1] - xy[1];
        if (dx * dx + dy * dy > d2max) d2max = dx * dx + dy * dy, far = i;
    }
    double amax = 0;
    for (int i = 1; i < n; i++) amax = fmax(amax, fabs(cross3(xy, 0, far, i)));
    if (!(amax > 1e-12 * d2max))
        return gb_fail(err, GB_EINPUT, "triangulation: the %d points are collinear (or coincide)", n);
    return GB_OK;
}

/* Keeps a triangle unless it has (almost) no area, or, with radii, it bridges a void: an edge
 * longer than r_a + r_b + gap, or a circumradius R larger than r_max + gap/2. The circumcircle
 * holds no other centre (Delaunay), so no grain reaches nearer than R - r_max to its centre: a
 * larger R leaves a hole that holds a grain of diameter gap. This drops the flat triangles along
 * the convex hull, whose strain is ill-conditioned, as well as those across a notch. */
static int keep(const double *xy, const double *r, double gap, double r_max, const int v[3])
{
    double lmax2 = 0, lprod = 1;
    for (int k = 0; k < 3; k++) {
        int a = v[k], b = v[(k + 1) % 3];
        double dx = xy[2 * b] - xy[2 * a], dy = xy[2 * b + 1] - xy[2 * a + 1], l2 = dx * dx + dy * dy;
        lmax2 = fmax(lmax2, l2);
        lprod *= sqrt(l2);
        if (r && sqrt(l2) > r[a] + r[b] + gap) return 0;
    }
    double cross = fabs(cross3(xy, v[0], v[1], v[2]));
    if (!(cross > 1e-10 * lmax2)) return 0;
    return !r || lprod / (2 * cross) <= r_max + 0.5 * gap; /* R = abc / (4 area) */
}

gb_status gb_triangulate(int n, const double *xy, const double *r, double gap, gb_triangulation *t,
                         gb_error *err)
{
    memset(t, 0, sizeof *t);
    gb_status st = check_input(n, xy, err);
    if (st) return st;
    double r_max = 0;
    for (int i = 0; r && i < n; i++) r_max = fmax(r_max, r[i]);
    if (r && gap < 0) gap = 2 * r_max;
    /* qhull reports on a stream: a memory one, so that its message goes into err, never to stderr. */
    char *msg = NULL;
    size_t msg_len = 0;
    FILE *errfile = open_memstream(&msg, &msg_len);
    coordT *pts = malloc(2 * (size_t)n * sizeof *pts);
    if (!errfile || !pts) {
        if (errfile) fclose(errfile);
        free(msg), free(pts);
        return gb_fail(err, GB_ENOMEM, "out of memory for the triangulation of %d points", n);
    }
    memcpy(pts, xy, 2 * (size_t)n * sizeof *pts);
    qhT qh_qh, *qh = &qh_qh;
    QHULL_LIB_CHECK
    qh_zero(qh, errfile);
    char flags[] = "qhull d Qt Qbb Qc Qz";
    int exitcode = qh_new_qhull(qh, 2, n, pts, False, flags, NULL, errfile);
    if (exitcode) {
        fflush(errfile);
        st = gb_fail(err, GB_ENUMERIC, "triangulation: qhull failed (%d): %.300s", exitcode, msg ? msg : "");
    } else {
        facetT *facet;
        vertexT *vertex, **vertexp;
        int cap = 0;
        FORALLfacets {
            if (!facet->upperdelaunay) cap++;
        }
        t->v = malloc(3 * (size_t)(cap > 0 ? cap : 1) * sizeof *t->v);
        if (!t->v) st = gb_fail(err, GB_ENOMEM, "out of memory for %d triangles", cap);
        FORALLfacets {
            if (st || facet->upperdelaunay) continue;
            int v[3], k = 0;
            FOREACHvertex_(facet->vertices) {
                if (k < 3) v[k] = qh_pointid(qh, vertex->point);
                k++;
            }
            if (k != 3) continue; /* not a triangle: cannot happen with Qt */
            t->n_delaunay++;
            if (cross3(xy, v[0], v[1], v[2]) < 0) { /* counter-clockwise */
                int s = v[1];
                v[1] = v[2], v[2] = s;
            }
            if (!keep(xy, r, gap, r_max, v)) continue;
            memcpy(&t->v[3 * t->n], v, sizeof v);
            t->n++;
        }
    }
    int curlong, totlong;
    qh_freeqhull(qh, !qh_ALL);
    qh_memfreeshort(qh, &curlong, &totlong);
    fclose(errfile);
    free(msg), free(pts);
    if (st) gb_triangulation_free(t);
    return st;
}
