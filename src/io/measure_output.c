/* The step's measures (src/measure/step.c) in the run directory: localisation.csv (a row per step)
 * and, in fields/, the grains' strain and D2min, the triangulation for ParaView, the sliding
 * contacts and the host's stress around its cavity. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "io/file_util.h"
#include "io/measure_output.h"
#include "io/vtk.h"

static gb_status write_grains(const char *path, const gb_zone_measures *z, gb_error *err)
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

static void vtu_cell_array(FILE *f, const char *name, const gb_zone_measures *z, size_t offset)
{
    gb_vtk_array(f, "Float64", name, 1);
    for (int k = 0; k < z->t.n; k++) fprintf(f, "%.10e\n", *(const double *)((const char *)&z->tri[k] + offset));
    gb_vtk_array_end(f);
}

/* The triangles on the grains' centres at the step's end, their strain as cell data. */
static gb_status write_triangles(const char *path, const gb_zone_measures *z, gb_error *err)
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
static gb_status write_row(const char *dir, int step, const gb_zone_measures *z, int n_sliding, const gb_host_measures *hm,
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

gb_status gb_measure_write_step(const char *dir, const gb_step_measures *m, gb_error *err)
{
    char path[1200];
    int step = m->step, fields = m->fields;
    snprintf(path, sizeof path, "%s/fields", dir);
    if (fields && mkdir(path, 0777) != 0 && errno != EEXIST)
        return gb_fail(err, GB_EIO, "%s: %s", path, strerror(errno));
    gb_status st = GB_OK;
    if (fields) {
        snprintf(path, sizeof path, "%s/fields/grains_%06d.csv", dir, step);
        st = write_grains(path, &m->zone, err);
    }
    if (!st && fields && m->zone.tri_ok) {
        snprintf(path, sizeof path, "%s/fields/triangles_%06d.vtu", dir, step);
        if (!(st = write_triangles(path, &m->zone, err))) st = add_to_pvd(dir, step, err);
    }
    if (!st && fields) {
        snprintf(path, sizeof path, "%s/fields/sliding_%06d.csv", dir, step);
        st = write_sliding(path, m->sliding, m->n_sliding, err);
    }
    if (!st && fields && m->has_host) st = write_host(dir, step, &m->host, err);
    if (!st && m->row) st = write_row(dir, step, &m->zone, m->n_sliding, m->has_host ? &m->host : NULL, err);
    return st;
}
