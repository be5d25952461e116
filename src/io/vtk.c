/* VTK XML PolyData (ASCII) snapshots for ParaView. */
#include <stdlib.h>

#include "gembem/output.h"
#include "io/file_util.h"

#include <math.h>

gb_status gb_vtk_write_grains(const char *path, const gb_sim *sim, gb_error *err)
{
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) return st;
    int n = gb_sim_n_grains(sim);
    const gb_grain *g = gb_sim_grains(sim);
    FILE *f = a.f;
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<PolyData>\n<Piece NumberOfPoints=\"%d\" NumberOfVerts=\"%d\">\n<Points>\n"
               "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n", n, n);
    for (int i = 0; i < n; i++) fprintf(f, "%.17g %.17g 0\n", g[i].x, g[i].y);
    fprintf(f, "</DataArray>\n</Points>\n<PointData Scalars=\"radius\">\n"
               "<DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n");
    for (int i = 0; i < n; i++) fprintf(f, "%.17g\n", g[i].r);
    fprintf(f, "</DataArray>\n<DataArray type=\"Float64\" Name=\"rotation\" format=\"ascii\">\n");
    for (int i = 0; i < n; i++) fprintf(f, "%.17g\n", g[i].rot);
    fprintf(f, "</DataArray>\n<DataArray type=\"Float64\" Name=\"fixing_force\" format=\"ascii\">\n");
    for (int i = 0; i < n; i++) {
        double F[3];
        gb_sim_fixing_force(sim, i, F);
        fprintf(f, "%.6e\n", sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]));
    }
    fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"id\" format=\"ascii\">\n");
    for (int i = 0; i < n; i++) fprintf(f, "%d\n", i);
    fprintf(f, "</DataArray>\n</PointData>\n<Verts>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n");
    for (int i = 0; i < n; i++) fprintf(f, "%d\n", i);
    fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n");
    for (int i = 0; i < n; i++) fprintf(f, "%d\n", i + 1);
    fprintf(f, "</DataArray>\n</Verts>\n</Piece>\n</PolyData>\n</VTKFile>\n");
    return gb_atomic_commit(&a, err);
}

/* Contact points on the walls, for drawing grain-wall contacts as lines. */
static void wall_point(const gb_grain *a, const gb_contact *c, double *x, double *y)
{
    *x = a->x + c->nx * (a->r - c->overlap);
    *y = a->y + c->ny * (a->r - c->overlap);
}

gb_status gb_vtk_write_contacts(const char *path, const gb_sim *sim, gb_error *err)
{
    int m;
    gb_contact *c = gb_sim_contacts_copy(sim, &m, err);
    if (!c) return err->code;
    gb_atomic_file a;
    gb_status st = gb_atomic_open(&a, path, err);
    if (st) {
        free(c);
        return st;
    }
    const gb_grain *g = gb_sim_grains(sim);
    gb_box b = gb_sim_box(sim);
    FILE *f = a.f;
    int lines = m + 4, points = 2 * m + 4;
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<PolyData>\n<Piece NumberOfPoints=\"%d\" NumberOfLines=\"%d\">\n<Points>\n"
               "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n", points, lines);
    for (int k = 0; k < m; k++) {
        const gb_grain *p = &g[c[k].i];
        double x, y;
        if (c[k].j >= 0) x = g[c[k].j].x, y = g[c[k].j].y;
        else wall_point(p, &c[k], &x, &y);
        fprintf(f, "%.17g %.17g 0\n%.17g %.17g 0\n", p->x, p->y, x, y);
    }
    fprintf(f, "%.17g %.17g 0\n%.17g %.17g 0\n%.17g %.17g 0\n%.17g %.17g 0\n", b.left, b.bottom, b.right, b.bottom,
            b.right, b.top, b.left, b.top);
    fprintf(f, "</DataArray>\n</Points>\n<CellData Scalars=\"pn\">\n<DataArray type=\"Float64\" Name=\"pn\" format=\"ascii\">\n");
    for (int k = 0; k < m; k++) fprintf(f, "%.17g\n", c[k].pn);
    fprintf(f, "0\n0\n0\n0\n</DataArray>\n<DataArray type=\"Float64\" Name=\"pt\" format=\"ascii\">\n");
    for (int k = 0; k < m; k++) fprintf(f, "%.17g\n", c[k].pt);
    fprintf(f, "0\n0\n0\n0\n</DataArray>\n<DataArray type=\"Int32\" Name=\"kind\" format=\"ascii\">\n");
    for (int k = 0; k < m; k++) fprintf(f, "%d\n", c[k].j >= 0 ? 0 : 1);
    fprintf(f, "2\n2\n2\n2\n</DataArray>\n</CellData>\n<Lines>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n");
    for (int k = 0; k < m; k++) fprintf(f, "%d %d\n", 2 * k, 2 * k + 1);
    int q = 2 * m;
    fprintf(f, "%d %d\n%d %d\n%d %d\n%d %d\n", q, q + 1, q + 1, q + 2, q + 2, q + 3, q + 3, q);
    fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n");
    for (int k = 0; k < lines; k++) fprintf(f, "%d\n", 2 * (k + 1));
    fprintf(f, "</DataArray>\n</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n");
    free(c);
    return gb_atomic_commit(&a, err);
}
