/* The strain field of a granular zone between two states of its grain centres: a
 * Delaunay triangulation of the reference centres (qhull), the deformation of each triangle under
 * the linear interpolation of the centres' displacements, its area-weighted mean per grain, the
 * non-affine displacement of each grain (D2min, Falk & Langer 1998) and a localisation index.
 * Pure functions on arrays of positions (2 per point: x, y), so that they can be tested alone.
 *
 * Signs follow the papers' soil mechanics (docs/method.md section 2): strains compression positive.
 * The strain is Green-Lagrange's, E = (F^t F - I)/2 with F = I + grad u the deformation gradient
 * (reported as e = -E): to first order the small strain -(grad u + grad u^t)/2, and exactly zero
 * for a rigid motion of any size. */
#ifndef GEMBEM_STRAIN_FIELD_H
#define GEMBEM_STRAIN_FIELD_H

#include "gembem/status.h"

typedef struct {
    int n;          /* triangles kept */
    int *v;         /* 3 point indices per triangle, counter-clockwise */
    int n_delaunay; /* triangles of the Delaunay triangulation, before dropping */
} gb_triangulation;

/* Delaunay triangulation of n points (qhull "d Qt Qbb Qc Qz": triangulated output, so cocircular
 * points, as in a regular grid, still give triangles). Dropped: triangles of zero area (the
 * triangulated output may make them out of cocircular points) and, when radii r are given (NULL:
 * keep every other triangle), the triangles that bridge a void where a grain of diameter `gap`
 * would fit (gap < 0: the largest diameter): an edge a-b longer than r_a + r_b + gap (the space
 * between the two surfaces), or a circumradius larger than r_max + gap/2 (the empty circumcircle,
 * less the grains that reach into it). These are the triangles outside a non-convex zone, across
 * large pores, and the flat ones along the convex hull. Fewer than 3 points, non-finite or
 * collinear points: GB_EINPUT and an empty triangulation. */
gb_status gb_triangulate(int n, const double *xy, const double *r, double gap, gb_triangulation *t,
                         gb_error *err);
void gb_triangulation_free(gb_triangulation *t);

/* The deformation of a triangle, or the area-weighted mean of a grain's triangles. */
typedef struct {
    double H[4];          /* displacement gradient du_i/dX_j, row-major: du_x/dX, du_x/dY, du_y/dX, du_y/dY */
    double exx, eyy, exy; /* strain (tensor components), e = -(H + H^t + H^t H)/2, compression positive */
    double ev;            /* volumetric strain exx + eyy (compression positive) */
    double gamma;         /* maximum shear strain 2 sqrt(((exx - eyy)/2)^2 + exy^2) = e1 - e2 */
    double rotation;      /* rotation of the polar decomposition F = R U, counter-clockwise [rad] */
    double area;          /* reference area (a grain: of all its triangles) */
} gb_strain;

/* Per triangle, from the reference positions x0 (those triangulated) to the current x1: H is the
 * gradient of the linear interpolation, H = [u1-u0, u2-u0] [X1-X0, X2-X0]^-1, exact for an affine
 * displacement. */
void gb_strain_triangles(const gb_triangulation *t, const double *x0, const double *x1, gb_strain *out);

/* Per point (n points): the area-weighted mean of H and of the strain over the triangles that
 * share the point; gamma from the mean strain, rotation from the mean H. n_tri (may be NULL)
 * counts them; a point in no triangle gets zeros. */
void gb_strain_points(const gb_triangulation *t, const gb_strain *tri, int n, gb_strain *out, int *n_tri);

/* The zone's mean: the area-weighted mean of H and of the strain over the n triangles (for a
 * piecewise linear field the mean of H is the deformation of the triangulated zone's outline). */
void gb_strain_mean(int n, const gb_strain *tri, gb_strain *out);

typedef struct {
    double index;      /* share of the total shear, sum(gamma area), carried by the most strained
                          `fraction` of the area; 0 when nothing shears */
    double fraction;   /* of the area, e.g. 0.1 */
    double mean_gamma; /* area-weighted mean of gamma */
    double max_gamma;
    double area;       /* triangulated area */
} gb_localisation;

/* Sorts the triangles by gamma (largest first) and adds their areas until `fraction` of the total,
 * the last one in part: the index is fraction for a uniform strain and 1 when all the shear is in
 * that fraction of the area. No triangles or fraction outside (0, 1]: GB_EINPUT. */
gb_status gb_localisation_index(int n, const gb_strain *tri, double fraction, gb_localisation *out, gb_error *err);

/* The non-affine displacement of point i (Falk & Langer 1998, eqs. 2.11-2.14): with d0_j and d_j
 * the reference and current vectors from i to each neighbour j (|d0_j| <= range),
 * D2min = min_J sum_j |d_j - J d0_j|^2, reached at J = I + G, G = (sum du_j d0_j^t)(sum d0_j d0_j^t)^-1,
 * du_j = d_j - d0_j. Zero for an affine motion. */
typedef struct {
    double d2min;   /* [length^2], the sum (not divided by the neighbours) */
    double G[4];    /* best affine fit of the displacement gradient, row-major */
    int neighbours; /* within range */
    int ok;         /* 1: the fit is defined (neighbours not all on one line through i); else d2min = 0 */
} gb_d2min;

/* For all n points (neighbours found with a cell grid). range <= 0 or non-finite, n < 0: GB_EINPUT. */
gb_status gb_d2min_points(int n, const double *x0, const double *x1, double range, gb_d2min *out, gb_error *err);

#endif
