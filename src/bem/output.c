#include "bem/output.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
    fprintf(f,
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "<PolyData>\n<Piece NumberOfPoints=\"%d\" NumberOfLines=\"%d\">\n<Points>\n"
            "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
            2 * m->n, m->n);
    for (int e = 0; e < m->n; e++)
        fprintf(f, "%.17g %.17g 0\n%.17g %.17g 0\n", m->p0[2 * e], m->p0[2 * e + 1], m->p1[2 * e], m->p1[2 * e + 1]);
    fprintf(f, "</DataArray>\n</Points>\n<Lines>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for (int e = 0; e < m->n; e++) fprintf(f, "%d %d\n", 2 * e, 2 * e + 1);
    fprintf(f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for (int e = 0; e < m->n; e++) fprintf(f, "%d\n", 2 * e + 2);
    fprintf(f, "</DataArray>\n</Lines>\n<CellData Vectors=\"displacement\">\n");
    const char *names[3] = {"displacement", "traction", "normal"};
    const double *arr[3] = {sol->u, sol->t, m->normal};
    for (int a = 0; a < 3; a++) {
        fprintf(f, "<DataArray type=\"Float64\" Name=\"%s\" NumberOfComponents=\"3\" format=\"ascii\">\n", names[a]);
        for (int e = 0; e < m->n; e++) fprintf(f, "%.17g %.17g 0\n", arr[a][2 * e], arr[a][2 * e + 1]);
        fprintf(f, "</DataArray>\n");
    }
    fprintf(f, "<DataArray type=\"Int32\" Name=\"group\" format=\"ascii\">\n");
    for (int e = 0; e < m->n; e++) fprintf(f, "%d\n", m->group[e]);
    fprintf(f, "</DataArray>\n</CellData>\n</Piece>\n</PolyData>\n</VTKFile>\n");
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
    fprintf(f,
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n<Points>\n"
            "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
            nin, nquad + nvert);
    for (int i = 0; i < n; i++)
        if (id[i] >= 0) fprintf(f, "%.17g %.17g 0\n", sc->pts[2 * i], sc->pts[2 * i + 1]);
    fprintf(f, "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for (int j = 0; j + 1 < sc->grid_ny; j++)
        for (int i = 0; i + 1 < sc->grid_nx; i++) {
            int a = j * sc->grid_nx + i, b = a + 1, c = a + sc->grid_nx + 1, d = a + sc->grid_nx;
            if (id[a] >= 0 && id[b] >= 0 && id[c] >= 0 && id[d] >= 0)
                fprintf(f, "%d %d %d %d\n", id[a], id[b], id[c], id[d]);
        }
    for (int i = ngrid; i < n; i++)
        if (id[i] >= 0) fprintf(f, "%d\n", id[i]);
    fprintf(f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for (int c = 0; c < nquad; c++) fprintf(f, "%d\n", 4 * (c + 1));
    for (int c = 0; c < nvert; c++) fprintf(f, "%d\n", 4 * nquad + c + 1);
    fprintf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (int c = 0; c < nquad; c++) fprintf(f, "9\n");
    for (int c = 0; c < nvert; c++) fprintf(f, "1\n");
    fprintf(f, "</DataArray>\n</Cells>\n<PointData Vectors=\"displacement\" Tensors=\"stress\">\n");
    fprintf(f, "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for (int i = 0; i < n; i++)
        if (id[i] >= 0) fprintf(f, "%.17g %.17g 0\n", u[2 * i], u[2 * i + 1]);
    fprintf(f,
            "</DataArray>\n<DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"9\" format=\"ascii\">\n");
    for (int i = 0; i < n; i++)
        if (id[i] >= 0) {
            const double *q = s + 3 * i;
            fprintf(f, "%.17g %.17g 0 %.17g %.17g 0 0 0 0\n", q[0], q[2], q[2], q[1]);
        }
    fprintf(f, "</DataArray>\n");
    const char *sn[4] = {"sxx", "syy", "sxy", "von_mises_inplane"};
    for (int c = 0; c < 4; c++) {
        fprintf(f, "<DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n", sn[c]);
        for (int i = 0; i < n; i++)
            if (id[i] >= 0) {
                const double *q = s + 3 * i;
                double v = c < 3 ? q[c] : sqrt(q[0] * q[0] - q[0] * q[1] + q[1] * q[1] + 3 * q[2] * q[2]);
                fprintf(f, "%.17g\n", v);
            }
        fprintf(f, "</DataArray>\n");
    }
    fprintf(f, "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
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
