/* The grains' and contacts' snapshots, VTK XML PolyData for ParaView (snapshots/ of a run). */
#include <math.h>
#include <stdlib.h>

#include "gembem/output.h"
#include "io/contacts_file.h"
#include "io/file_util.h"
#include "io/vtk.h"

/* The grains as points with their radius, rotation, |fixing force| and number. */
static void write_grains(FILE *f, const void *data)
{
    const gb_sim *sim = data;
    int n = gb_sim_n_grains(sim);
    gb_vtk_begin(f, GB_VTK_POLYDATA, n, "NumberOfVerts", n);
    for (int i = 0; i < n; i++) {
        gb_grain g = gb_sim_grain(sim, i);
        fprintf(f, "%.17g %.17g 0\n", g.x, g.y);
    }
    gb_vtk_end_points(f);
    gb_vtk_open(f, "PointData", "Scalars=\"radius\"");
    gb_vtk_array(f, "Float64", "radius", 1);
    for (int i = 0; i < n; i++) fprintf(f, "%.17g\n", gb_sim_grain(sim, i).r);
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Float64", "rotation", 1);
    for (int i = 0; i < n; i++) fprintf(f, "%.17g\n", gb_sim_grain(sim, i).rot);
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Float64", "fixing_force", 1);
    for (int i = 0; i < n; i++) {
        double F[3];
        gb_sim_fixing_force(sim, i, F);
        fprintf(f, "%.6e\n", sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]));
    }
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Int32", "id", 1);
    for (int i = 0; i < n; i++) fprintf(f, "%d\n", i);
    gb_vtk_array_end(f);
    gb_vtk_close(f, "PointData");
    gb_vtk_open(f, "Verts", NULL);
    gb_vtk_array(f, "Int32", "connectivity", 1);
    for (int i = 0; i < n; i++) fprintf(f, "%d\n", i);
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Int32", "offsets", 1);
    for (int i = 0; i < n; i++) fprintf(f, "%d\n", i + 1);
    gb_vtk_array_end(f);
    gb_vtk_close(f, "Verts");
    gb_vtk_end(f, GB_VTK_POLYDATA);
}

gb_status gb_vtk_write_grains(const char *path, const gb_sim *sim, gb_error *err)
{
    return gb_atomic_write(path, write_grains, sim, err);
}

/* The contacts as lines from grain i's centre to the contact's far end, and the box's four sides. */
static void write_contacts(FILE *f, const gb_sim *sim, const gb_contact *c, int m)
{
    gb_box b = gb_sim_box(sim);
    int lines = m + 4, points = 2 * m + 4;
    gb_vtk_begin(f, GB_VTK_POLYDATA, points, "NumberOfLines", lines);
    for (int k = 0; k < m; k++) {
        double x, y;
        gb_contact_far_end(sim, &c[k], &x, &y);
        gb_grain gi = gb_sim_grain(sim, c[k].i);
        fprintf(f, "%.17g %.17g 0\n%.17g %.17g 0\n", gi.x, gi.y, x, y);
    }
    fprintf(f, "%.17g %.17g 0\n%.17g %.17g 0\n%.17g %.17g 0\n%.17g %.17g 0\n", b.left, b.bottom, b.right, b.bottom,
            b.right, b.top, b.left, b.top);
    gb_vtk_end_points(f);
    /* the box's four sides last: forces 0, kind 2 */
    gb_vtk_open(f, "CellData", "Scalars=\"pn\"");
    gb_vtk_array(f, "Float64", "pn", 1);
    for (int k = 0; k < m; k++) fprintf(f, "%.17g\n", c[k].pn);
    fprintf(f, "0\n0\n0\n0\n");
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Float64", "pt", 1);
    for (int k = 0; k < m; k++) fprintf(f, "%.17g\n", c[k].pt);
    fprintf(f, "0\n0\n0\n0\n");
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Int32", "kind", 1);
    for (int k = 0; k < m; k++) fprintf(f, "%d\n", c[k].j >= 0 ? 0 : 1);
    fprintf(f, "2\n2\n2\n2\n");
    gb_vtk_array_end(f);
    gb_vtk_close(f, "CellData");
    gb_vtk_open(f, "Lines", NULL);
    gb_vtk_array(f, "Int32", "connectivity", 1);
    for (int k = 0; k < m; k++) fprintf(f, "%d %d\n", 2 * k, 2 * k + 1);
    int q = 2 * m;
    fprintf(f, "%d %d\n%d %d\n%d %d\n%d %d\n", q, q + 1, q + 1, q + 2, q + 2, q + 3, q + 3, q);
    gb_vtk_array_end(f);
    gb_vtk_array(f, "Int32", "offsets", 1);
    for (int k = 0; k < lines; k++) fprintf(f, "%d\n", 2 * (k + 1));
    gb_vtk_array_end(f);
    gb_vtk_close(f, "Lines");
    gb_vtk_end(f, GB_VTK_POLYDATA);
}

gb_status gb_vtk_write_contacts(const char *path, const gb_sim *sim, gb_error *err)
{
    return gb_contacts_file_write(path, sim, write_contacts, err);
}
