/* The elastic body's files (io/bem_output.h). Written in place, as before they moved here from
 * src/bem, not through io/file_util's atomic files: a run's files and its test kill points
 * (GB_TEST_KILL_AT) stay as they were. */
#include "io/bem_output.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/vtk.h"

static gb_status open_out(const char *path, FILE **f, gb_error *err)
{
    *f = fopen(path, "w");
    if (!*f) return gb_fail(err, GB_EIO, "%s: cannot write: %s", path, strerror(errno));
    return GB_OK;
}

static gb_status close_out(const char *path, FILE *f, gb_error *err)
{
    int bad = ferror(f);
    if (fclose(f) || bad) return gb_fail(err, GB_EIO, "%s: write failed", path);
    return GB_OK;
}

gb_status gb_bem_write_boundary_csv(const char *path, const gb_bem_mesh *m, const gb_bem_solution *sol,
                                    const double *bs, gb_error *err)
{
    FILE *f;
    gb_status st = open_out(path, &f, err);
    if (st) return st;
    fprintf(f, "element,group,loop,x,y,nx,ny,length,ux,uy,tx,ty,un,ut,tn,tt,sxx,syy,sxy\n");
    for (int e = 0; e < m->n; e++) {
        const double *n = m->normal + 2 * e, *t = m->tangent + 2 * e, *u = sol->u + 2 * e, *tr = sol->t + 2 * e;
        fprintf(f,
                "%d,%s,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%."
                "17g\n",
                e, m->group_name[m->group[e]], m->loop[e], m->mid[2 * e], m->mid[2 * e + 1], n[0], n[1], m->length[e],
                u[0], u[1], tr[0], tr[1], u[0] * n[0] + u[1] * n[1], u[0] * t[0] + u[1] * t[1],
                tr[0] * n[0] + tr[1] * n[1], tr[0] * t[0] + tr[1] * t[1], bs[3 * e], bs[3 * e + 1], bs[3 * e + 2]);
    }
    return close_out(path, f, err);
}

gb_status gb_bem_write_boundary_vtp(const char *path, const gb_bem_mesh *m, const gb_bem_solution *sol, gb_error *err)
{
    FILE *f;
    gb_status st = open_out(path, &f, err);
    if (st) return st;
    gb_vtk_begin(f, GB_VTK_POLYDATA, 2 * m->n, "NumberOfLines", m->n);
    for (int e = 0; e < m->n; e++)
        fprintf(f, "%.17g %.17g 0\n%.17g %.17g 0\n", m->p0[2 * e], m->p0[2 * e + 1], m->p1[2 * e], m->p1[2 * e + 1]);
    gb_vtk_end_points(f);
    gb_vtk_open(f, "Lines", NULL);
    gb_vtk_array(f, "Int64", "connectivity", 1);
    for (int e = 0; e < m->n; e++) fprintf(f, "%d %d\n", 2 * e, 2 * e + 1);
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Int64", "offsets", 1);
    for (int e = 0; e < m->n; e++) fprintf(f, "%d\n", 2 * e + 2);
    gb_vtk_array_end(f);
    gb_vtk_close(f, "Lines");
    gb_vtk_open(f, "CellData", "Vectors=\"displacement\"");
    const char *names[3] = {"displacement", "traction", "normal"};
    const double *arr[3] = {sol->u, sol->t, m->normal};
    for (int a = 0; a < 3; a++) {
        gb_vtk_array(f, "Float64", names[a], 3);
        for (int e = 0; e < m->n; e++) fprintf(f, "%.17g %.17g 0\n", arr[a][2 * e], arr[a][2 * e + 1]);
        gb_vtk_array_end(f);
    }
    gb_vtk_array(f, "Int32", "group", 1);
    for (int e = 0; e < m->n; e++) fprintf(f, "%d\n", m->group[e]);
    gb_vtk_array_end(f);
    gb_vtk_close(f, "CellData");
    gb_vtk_end(f, GB_VTK_POLYDATA);
    return close_out(path, f, err);
}

gb_status gb_bem_write_interior_vtu(const char *path, const gb_bem_scene *sc, const double *u, const double *s,
                                    gb_error *err)
{
    int n = sc->npts, nin = 0;
    int *id = malloc(sizeof(int) * (size_t)(n ? n : 1));
    if (!id) return gb_fail(err, GB_ENOMEM, "out of memory");
    for (int i = 0; i < n; i++) id[i] = sc->pt_inside[i] ? nin++ : -1;
    int ngrid = sc->grid_nx * sc->grid_ny, nquad = 0, nvert = 0;
    for (int j = 0; j + 1 < sc->grid_ny; j++)
        for (int i = 0; i + 1 < sc->grid_nx; i++) {
            int a = j * sc->grid_nx + i;
            nquad += id[a] >= 0 && id[a + 1] >= 0 && id[a + sc->grid_nx] >= 0 && id[a + sc->grid_nx + 1] >= 0;
        }
    for (int i = ngrid; i < n; i++) nvert += id[i] >= 0;
    FILE *f;
    gb_status st = open_out(path, &f, err);
    if (st) {
        free(id);
        return st;
    }
    gb_vtk_begin(f, GB_VTK_UNSTRUCTURED_GRID, nin, "NumberOfCells", nquad + nvert);
    for (int i = 0; i < n; i++)
        if (id[i] >= 0) fprintf(f, "%.17g %.17g 0\n", sc->pts[2 * i], sc->pts[2 * i + 1]);
    gb_vtk_end_points(f);
    gb_vtk_open(f, "Cells", NULL);
    gb_vtk_array(f, "Int64", "connectivity", 1);
    for (int j = 0; j + 1 < sc->grid_ny; j++)
        for (int i = 0; i + 1 < sc->grid_nx; i++) {
            int a = j * sc->grid_nx + i, b = a + 1, c = a + sc->grid_nx + 1, d = a + sc->grid_nx;
            if (id[a] >= 0 && id[b] >= 0 && id[c] >= 0 && id[d] >= 0)
                fprintf(f, "%d %d %d %d\n", id[a], id[b], id[c], id[d]);
        }
    for (int i = ngrid; i < n; i++)
        if (id[i] >= 0) fprintf(f, "%d\n", id[i]);
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Int64", "offsets", 1);
    for (int c = 0; c < nquad; c++) fprintf(f, "%d\n", 4 * (c + 1));
    for (int c = 0; c < nvert; c++) fprintf(f, "%d\n", 4 * nquad + c + 1);
    gb_vtk_array_end(f);
    gb_vtk_array(f, "UInt8", "types", 1);
    for (int c = 0; c < nquad; c++) fprintf(f, "9\n"); /* VTK_QUAD */
    for (int c = 0; c < nvert; c++) fprintf(f, "1\n"); /* VTK_VERTEX */
    gb_vtk_array_end(f);
    gb_vtk_close(f, "Cells");
    gb_vtk_open(f, "PointData", "Vectors=\"displacement\" Tensors=\"stress\"");
    gb_vtk_array(f, "Float64", "displacement", 3);
    for (int i = 0; i < n; i++)
        if (id[i] >= 0) fprintf(f, "%.17g %.17g 0\n", u[2 * i], u[2 * i + 1]);
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Float64", "stress", 9);
    for (int i = 0; i < n; i++)
        if (id[i] >= 0) {
            const double *q = s + 3 * i;
            fprintf(f, "%.17g %.17g 0 %.17g %.17g 0 0 0 0\n", q[0], q[2], q[2], q[1]);
        }
    gb_vtk_array_end(f);
    const char *sn[4] = {"sxx", "syy", "sxy", "von_mises_inplane"};
    for (int c = 0; c < 4; c++) {
        gb_vtk_array(f, "Float64", sn[c], 1);
        for (int i = 0; i < n; i++)
            if (id[i] >= 0) {
                const double *q = s + 3 * i;
                double v = c < 3 ? q[c] : sqrt(q[0] * q[0] - q[0] * q[1] + q[1] * q[1] + 3 * q[2] * q[2]);
                fprintf(f, "%.17g\n", v);
            }
        gb_vtk_array_end(f);
    }
    gb_vtk_close(f, "PointData");
    gb_vtk_end(f, GB_VTK_UNSTRUCTURED_GRID);
    free(id);
    return close_out(path, f, err);
}

gb_status gb_bem_write_interior_csv(const char *path, const gb_bem_scene *sc, const double *u, const double *s,
                                    gb_error *err)
{
    FILE *f;
    gb_status st = open_out(path, &f, err);
    if (st) return st;
    fprintf(f, "x,y,ux,uy,sxx,syy,sxy\n");
    for (int i = 0; i < sc->npts; i++)
        if (sc->pt_inside[i])
            fprintf(f, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", sc->pts[2 * i], sc->pts[2 * i + 1], u[2 * i],
                    u[2 * i + 1], s[3 * i], s[3 * i + 1], s[3 * i + 2]);
    return close_out(path, f, err);
}

gb_status gb_bem_write_stiffness_csv(const char *path, const gb_bem_mesh *m, const gb_bem_stiffness *k, gb_error *err)
{
    FILE *f;
    gb_status st = open_out(path, &f, err);
    if (st) return st;
    fprintf(f, "# K (row i, column j): force on DOF i per unit displacement of DOF j; DOF 2q+c = component c of "
               "element elem[q]\n# elements:");
    for (int q = 0; q < k->m / 2; q++) fprintf(f, " %d", k->elem[q]);
    fprintf(f, "\n# f0:");
    for (int i = 0; i < k->m; i++) fprintf(f, " %.17g", k->f0[i]);
    fprintf(f, "\n");
    (void)m;
    for (int i = 0; i < k->m; i++)
        for (int j = 0; j < k->m; j++)
            fprintf(f, "%.17g%c", k->K[(size_t)j * (size_t)k->m + (size_t)i], j + 1 < k->m ? ',' : '\n');
    return close_out(path, f, err);
}
