/* The step's measures in the run directory: localisation.csv (a row per step) and, in fields/,
 * the grains' strain and D2min, the triangulation for ParaView, the sliding contacts and the
 * host's stress around its cavity. Stateless: the step's start is the simulation's saved state. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "gem/sim.h"
#include "gembem/strain_field.h"
#include "io/file_util.h"
#include "io/vtk.h"
#include "measure/step_measures.h"

#define LOC_FRACTION 0.1 /* the most strained 10 % of the area */

/* The granular zone's measures of one step. */
typedef struct {
    int n;
    double *x0, *x1, *r;
    gb_triangulation t;
    gb_strain *tri, *grain;
    int *grain_tri;
    gb_d2min *d2;
    gb_localisation loc;
    gb_strain mean; /* of the triangulated zone */
    double d2_range;
    int tri_ok; /* 0: too few or collinear grains, no triangles */
} zone;

static void zone_free(zone *z)
{
    free(z->x0), free(z->x1), free(z->r), free(z->tri), free(z->grain), free(z->grain_tri), free(z->d2);
    gb_triangulation_free(&z->t);
}

static gb_status zone_measure(const gb_sim *sim, zone *z, gb_error *err)
{
    memset(z, 0, sizeof *z);
    int n = z->n = sim->n;
    size_t m = (size_t)(n > 0 ? n : 1);
    z->x0 = malloc(2 * m * sizeof(double)), z->x1 = malloc(2 * m * sizeof(double)), z->r = malloc(m * sizeof(double));
    z->grain = malloc(m * sizeof *z->grain), z->grain_tri = malloc(m * sizeof(int)), z->d2 = calloc(m, sizeof *z->d2);
    if (!z->x0 || !z->x1 || !z->r || !z->grain || !z->grain_tri || !z->d2)
        return gb_fail(err, GB_ENOMEM, "out of memory for the measures of %d grains", n);
    double dmax = 0;
    for (int i = 0; i < n; i++) {
        z->x0[2 * i] = sim->saved.g[i].x, z->x0[2 * i + 1] = sim->saved.g[i].y;
        z->x1[2 * i] = sim->g[i].x, z->x1[2 * i + 1] = sim->g[i].y;
        z->r[i] = sim->g[i].r;
        dmax = fmax(dmax, 2 * z->r[i]);
    }
    /* The triangulation drops edges with a gap wider than the largest diameter (gap < 0). A zone
     * that cannot be triangulated (fewer than 3 grains, collinear, qhull's precision failure) has
     * no triangles: a measure, not a reason to stop the run. */
    gb_error terr = {0};
    gb_status st = gb_triangulate(n, z->x0, z->r, -1, &z->t, &terr);
    if (st && st != GB_EINPUT && st != GB_ENUMERIC) return gb_fail(err, st, "%s", terr.msg);
    z->tri_ok = !st && z->t.n > 0;
    z->tri = malloc((size_t)(z->t.n > 0 ? z->t.n : 1) * sizeof *z->tri);
    if (!z->tri) return gb_fail(err, GB_ENOMEM, "out of memory for %d triangles", z->t.n);
    gb_strain_triangles(&z->t, z->x0, z->x1, z->tri);
    gb_strain_points(&z->t, z->tri, n, z->grain, z->grain_tri);
    gb_strain_mean(z->t.n, z->tri, &z->mean);
    if (z->tri_ok && (st = gb_localisation_index(z->t.n, z->tri, LOC_FRACTION, &z->loc, err))) return st;
    /* The index is a share of the zone's shear: undefined where that shear is noise (a relaxation,
     * step 0), not a ratio of two roundings. A grain's place is known to the step's accuracy over
     * its stiffness, a / kn, a strain to that over a diameter; and to the rounding of coordinates. */
    double dmean = 0;
    for (int i = 0; i < n; i++) dmean += 2 * z->r[i] / n;
    double noise = n > 0 ? fmax(sim->accuracy / sim->scene->grain_grain.kn, 1e3 * DBL_EPSILON * gb_sim_extent(sim)) / dmean : 0;
    if (!(z->loc.mean_gamma > noise)) z->loc.index = NAN;
    /* D2min over the first shell and near contacts: touching grains are at most the largest
     * diameter apart. */
    z->d2_range = 1.5 * dmax;
    return n > 0 && dmax > 0 ? gb_d2min_points(n, z->x0, z->x1, z->d2_range, z->d2, err) : GB_OK;
}

static gb_status write_grains(const char *path, const zone *z, gb_error *err)
{
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) return st;
    fprintf(a.f, "grain,x0,y0,x,y,ux,uy,triangles,area,exx,eyy,exy,ev,gamma,rotation,d2min,neighbours,d2min_ok\n");
    for (int i = 0; i < z->n; i++) {
        const gb_strain *s = &z->grain[i];
        const gb_d2min *d = &z->d2[i];
        fprintf(a.f, "%d,%.17g,%.17g,%.17g,%.17g,%.10e,%.10e,%d,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%d,%d\n", i,
                z->x0[2 * i], z->x0[2 * i + 1], z->x1[2 * i], z->x1[2 * i + 1], z->x1[2 * i] - z->x0[2 * i],
                z->x1[2 * i + 1] - z->x0[2 * i + 1], z->grain_tri[i], s->area, s->exx, s->eyy, s->exy, s->ev, s->gamma,
                s->rotation, d->d2min, d->neighbours, d->ok);
    }
    return gb_atomic_commit(&a, err);
}

static void vtu_cell_array(FILE *f, const char *name, const zone *z, size_t offset)
{
    gb_vtk_array(f, "Float64", name, 1);
    for (int k = 0; k < z->t.n; k++) fprintf(f, "%.10e\n", *(const double *)((const char *)&z->tri[k] + offset));
    gb_vtk_array_end(f);
}

/* The triangles on the grains' centres at the step's end, their strain as cell data. */
static gb_status write_triangles(const char *path, const zone *z, gb_error *err)
{
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) return st;
    FILE *f = a.f;
    gb_vtk_begin(f, GB_VTK_UNSTRUCTURED_GRID, z->n, "NumberOfCells", z->t.n);
    for (int i = 0; i < z->n; i++) fprintf(f, "%.17g %.17g 0\n", z->x1[2 * i], z->x1[2 * i + 1]);
    gb_vtk_end_points(f);
    gb_vtk_open(f, "Cells", NULL);
    gb_vtk_array(f, "Int32", "connectivity", 1);
    for (int k = 0; k < z->t.n; k++) fprintf(f, "%d %d %d\n", z->t.v[3 * k], z->t.v[3 * k + 1], z->t.v[3 * k + 2]);
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Int32", "offsets", 1);
    for (int k = 0; k < z->t.n; k++) fprintf(f, "%d\n", 3 * (k + 1));
    gb_vtk_array_end(f);
    gb_vtk_array(f, "UInt8", "types", 1);
    for (int k = 0; k < z->t.n; k++) fprintf(f, "5\n"); /* VTK_TRIANGLE */
    gb_vtk_array_end(f);
    gb_vtk_close(f, "Cells");
    gb_vtk_open(f, "CellData", "Scalars=\"gamma\"");
    vtu_cell_array(f, "gamma", z, offsetof(gb_strain, gamma));
    vtu_cell_array(f, "ev", z, offsetof(gb_strain, ev));
    vtu_cell_array(f, "exx", z, offsetof(gb_strain, exx));
    vtu_cell_array(f, "eyy", z, offsetof(gb_strain, eyy));
    vtu_cell_array(f, "exy", z, offsetof(gb_strain, exy));
    vtu_cell_array(f, "rotation", z, offsetof(gb_strain, rotation));
    vtu_cell_array(f, "area", z, offsetof(gb_strain, area));
    gb_vtk_close(f, "CellData");
    gb_vtk_open(f, "PointData", "Vectors=\"displacement\"");
    gb_vtk_array(f, "Float64", "displacement", 3);
    for (int i = 0; i < z->n; i++)
        fprintf(f, "%.10e %.10e 0\n", z->x1[2 * i] - z->x0[2 * i], z->x1[2 * i + 1] - z->x0[2 * i + 1]);
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Float64", "d2min", 1);
    for (int i = 0; i < z->n; i++) fprintf(f, "%.10e\n", z->d2[i].d2min);
    gb_vtk_array_end(f);
    gb_vtk_close(f, "PointData");
    gb_vtk_end(f, GB_VTK_UNSTRUCTURED_GRID);
    return gb_atomic_commit(&a, err);
}

/* fields/triangles.pvd, for ParaView's time bar: created at step 0, then each written step's
 * entry goes in before the closing tags (a seek back over them: constant time per step). */
static gb_status add_to_pvd(const char *dir, int step, gb_error *err)
{
    static const char close_tags[] = GB_VTK_PVD_TAIL;
    char path[1200], file[32];
    snprintf(path, sizeof path, "%s/fields/triangles.pvd", dir);
    FILE *f = fopen(path, step == 0 ? "w" : "r+");
    if (!f && step > 0) f = fopen(path, "w"); /* no triangulation until now */
    if (!f) return gb_fail(err, GB_EIO, "%s: %s", path, strerror(errno));
    fseek(f, 0, SEEK_END);
    long end = ftell(f), tail = (long)strlen(close_tags);
    if (end >= tail) fseek(f, -tail, SEEK_END), gb_test_kill_point(f);
    else gb_vtk_pvd_head(f);
    snprintf(file, sizeof file, "triangles_%06d.vtu", step);
    gb_vtk_pvd_dataset(f, step, file);
    fputs(close_tags, f);
    if (ferror(f) | fclose(f)) return gb_fail(err, GB_EIO, "%s: write failed", path);
    return GB_OK;
}

static gb_status write_sliding(const char *path, const gb_sliding_contact *c, int n, gb_error *err)
{
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) return st;
    fprintf(a.f, "i,j,with,pn,pt,limit,nx,ny\n");
    for (int k = 0; k < n; k++) {
        const char *with = c[k].j >= 0 ? "grain" : GB_IS_PARTICLE(c[k].j) ? "particle" : "wall";
        int j = c[k].j >= 0 ? c[k].j : GB_IS_PARTICLE(c[k].j) ? GB_PARTICLE_OF(c[k].j) : -1 - c[k].j;
        fprintf(a.f, "%d,%d,%s,%.10e,%.10e,%.10e,%.17g,%.17g\n", c[k].i, j, with, c[k].pn, c[k].pt, c[k].limit, c[k].nx,
                c[k].ny);
    }
    return gb_atomic_commit(&a, err);
}

static gb_status write_host(const char *dir, int step, const gb_host_measures *m, gb_error *err)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/fields/host_wall_%06d.csv", dir, step);
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) return st;
    fprintf(a.f, "element,x,y,hoop,hoop_empty,normal,concentration\n");
    for (int k = 0; k < m->n_wall; k++) {
        fprintf(a.f, "%d,%.17g,%.17g,%.10e,%.10e,%.10e,", m->elem[k], m->wall_xy[2 * k], m->wall_xy[2 * k + 1], m->hoop[k],
                m->hoop_empty[k], m->normal[k]);
        gb_csv_put(a.f, "%.10e\n", isnan(m->max_concentration) ? NAN : m->hoop[k] / m->s_ref);
    }
    if ((st = gb_atomic_commit(&a, err))) return st;
    snprintf(path, sizeof path, "%s/fields/host_ring_%06d.csv", dir, step);
    if ((st = gb_atomic_open(&a, path, err))) return st;
    fprintf(a.f, "x,y,sxx,syy,sxy,exx,eyy,exy\n");
    for (int q = 0; q < m->n_ring; q++) {
        const double *s = &m->ring_stress[3 * q], *e = &m->ring_strain[3 * q];
        fprintf(a.f, "%.17g,%.17g,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e\n", m->ring_xy[2 * q], m->ring_xy[2 * q + 1], s[0],
                s[1], s[2], e[0], e[1], e[2]);
    }
    return gb_atomic_commit(&a, err);
}

/* One row of localisation.csv, the file created (with its header) at step 0. */
static gb_status write_row(const char *dir, int step, const zone *z, int n_sliding, const gb_host_measures *hm,
                           gb_error *err)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/localisation.csv", dir);
    FILE *f = fopen(path, step == 0 ? "w" : "a");
    if (!f) return gb_fail(err, GB_EIO, "%s: %s", path, strerror(errno));
    gb_test_kill_point(f);
    if (step == 0)
        fprintf(f, "step,grains,triangles,triangles_delaunay,area,mean_gamma,max_gamma,localisation_index,"
                   "zone_exx,zone_eyy,zone_exy,zone_ev,mean_d2min,max_d2min,d2min_range,sliding_contacts%s\n",
                hm ? ",s_ref,s_ref_kind,max_concentration" : "");
    double d2sum = 0, d2max = 0;
    int nd = 0;
    for (int i = 0; i < z->n; i++)
        if (z->d2[i].ok) d2sum += z->d2[i].d2min, d2max = fmax(d2max, z->d2[i].d2min), nd++;
    fprintf(f, "%d,%d,%d,%d,%.10e,%.10e,%.10e,", step, z->n, z->t.n, z->t.n_delaunay, z->loc.area, z->loc.mean_gamma,
            z->loc.max_gamma);
    gb_csv_put(f, "%.10e", z->tri_ok ? z->loc.index : NAN);
    fprintf(f, ",%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%d", z->mean.exx, z->mean.eyy, z->mean.exy, z->mean.ev,
            nd ? d2sum / nd : 0, d2max, z->d2_range, n_sliding);
    if (hm) {
        fprintf(f, ",%.10e,%s", hm->s_ref, hm->s_ref_kind);
        gb_csv_put(f, ",%.10e", hm->max_concentration);
    }
    fprintf(f, "\n");
    if (ferror(f) | fclose(f)) return gb_fail(err, GB_EIO, "%s: write failed", path);
    return GB_OK;
}

gb_status gb_measure_write_step(const char *dir, const gb_sim *sim, int step, int fields, gb_error *err)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/fields", dir);
    if (fields && mkdir(path, 0777) != 0 && errno != EEXIST)
        return gb_fail(err, GB_EIO, "%s: %s", path, strerror(errno));
    zone z;
    gb_host_measures hm;
    memset(&hm, 0, sizeof hm);
    int n_sliding = gb_measure_sliding(sim, NULL, 0);
    gb_sliding_contact *sl = malloc((size_t)(n_sliding > 0 ? n_sliding : 1) * sizeof *sl);
    gb_status st = sl ? zone_measure(sim, &z, err) : gb_fail(err, GB_ENOMEM, "out of memory");
    if (!sl) memset(&z, 0, sizeof z);
    if (!st) gb_measure_sliding(sim, sl, n_sliding);
    /* the row needs the host's wall only; the empty cavity and the ring are for the files */
    if (!st && sim->host) st = gb_host_measure(sim, !fields, &hm, err);
    if (!st && fields) {
        snprintf(path, sizeof path, "%s/fields/grains_%06d.csv", dir, step);
        st = write_grains(path, &z, err);
    }
    if (!st && fields && z.tri_ok) {
        snprintf(path, sizeof path, "%s/fields/triangles_%06d.vtu", dir, step);
        if (!(st = write_triangles(path, &z, err))) st = add_to_pvd(dir, step, err);
    }
    if (!st && fields) {
        snprintf(path, sizeof path, "%s/fields/sliding_%06d.csv", dir, step);
        st = write_sliding(path, sl, n_sliding, err);
    }
    if (!st && fields && sim->host) st = write_host(dir, step, &hm, err);
    if (!st) st = write_row(dir, step, &z, n_sliding, sim->host ? &hm : NULL, err);
    free(sl);
    zone_free(&z);
    gb_host_measures_free(&hm);
    return st;
}
